//! Surface derivatives of every shape: moving a hit point by `eps * dpdu`
//! (resp. `eps * dpdv`) and casting a ray back onto the surface there moves
//! the hit's uv by `(eps, 0)` (resp. `(0, eps)`); both derivatives are
//! perpendicular to the normal. Under identity, uniform and non-uniform
//! transforms.

mod common;

use std::sync::Arc;

use common::*;
use pathtracer::geometry::MeshData;
use pathtracer::geometry::UvMapping;
use pathtracer::math::{Aabb, Matrix, Point3, Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::scene::model::Object;
use pathtracer::world::{World, WorldHit};

/// A curved 8x8 grid patch `z = 0.3 (x^2 + y^2)`, with an oblique affine uv
/// map when `with_uv` (else uv are the barycentrics of each triangle).
fn patch(with_uv: bool) -> MeshData {
    let n = 8;
    let mut data = MeshData::default();
    let mut uvs = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let x = 2.0 * i as f64 / n as f64 - 1.0;
            let y = 2.0 * j as f64 / n as f64 - 1.0;
            data.positions
                .push(Point3::new(x, y, 0.3 * (x * x + y * y)));
            uvs.push([0.5 + 0.4 * x + 0.1 * y, 0.2 + 0.3 * y - 0.05 * x]);
        }
    }
    let index = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (
                index(i, j),
                index(i + 1, j),
                index(i + 1, j + 1),
                index(i, j + 1),
            );
            data.triangles.push([a, b, c]);
            data.triangles.push([a, c, d]);
        }
    }
    data.uvs = with_uv.then_some(uvs);
    data
}

fn shapes() -> Vec<(&'static str, Object)> {
    let mesh = |data| Object::Mesh {
        mesh: Arc::new(data),
        smooth: false,
        material: 0,
        face_materials: None,
        overridden_mtl: None,
    };
    vec![
        ("sphere", ball(Point3::new(0.3, -0.2, 0.1), 1.2, 0)),
        (
            "plane",
            Object::Plane {
                normal: Vec3::new(0.2, 1.0, -0.3),
                offset: 0.7,
                material: 0,
            },
        ),
        (
            "triangle",
            Object::Triangle {
                vertices: [
                    Point3::new(-1.0, 0.0, 0.2),
                    Point3::new(1.5, -0.5, 0.0),
                    Point3::new(0.2, 1.3, -0.4),
                ],
                material: 0,
            },
        ),
        (
            "rectangle",
            Object::Rectangle {
                origin: Point3::new(-1.0, 0.2, -1.0),
                edge_u: Vec3::new(2.0, 0.1, 0.0),
                edge_v: Vec3::new(0.3, 0.0, 2.0),
                material: 0,
            },
        ),
        (
            "disk",
            Object::Disk {
                center: Point3::new(0.1, 0.2, 0.3),
                normal: Vec3::new(1.0, 2.0, 3.0),
                radius: 1.5,
                material: 0,
            },
        ),
        ("mesh with vt", mesh(patch(true))),
        ("mesh without vt", mesh(patch(false))),
        (
            "vase",
            Object::Revolution {
                profile: vase(),
                material: 0,
            },
        ),
        (
            "glass",
            Object::Revolution {
                profile: wine_glass(),
                material: 0,
            },
        ),
    ]
}

fn transforms() -> [(&'static str, Matrix); 3] {
    [
        ("identity", Matrix::identity()),
        (
            "uniform",
            Matrix::new_translation(&Vec3::new(3.0, -2.0, 1.0)) * Matrix::new_scaling(1e-2),
        ),
        (
            "non-uniform",
            Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 0.5, 1.0))
                * Matrix::from_euler_angles(0.3, 0.5, 0.1),
        ),
    ]
}

/// Where rays are aimed: the bounds, or (planes) a box around a point of
/// it, 40 texels wide.
fn target_box(world: &World) -> Aabb {
    world.primitive(0).bounds().unwrap_or_else(|| {
        let down = Ray::new(Point3::new(0.0, 1e4, 0.0), -Vec3::y(), 0.0);
        let hit = world
            .intersect(&down, 0.0, f64::INFINITY)
            .expect("plane below");
        Aabb::from_point(hit.point).expanded(20.0 * hit.dpdu.norm())
    })
}

/// The uv change from `hit` to the surface point under `hit.point + step`,
/// found by a ray along the normal; `None` when that ray finds another
/// triangle of a mesh (the derivatives are per triangle) or nothing.
fn uv_step(world: &World, hit: &WorldHit, step: Vec3, size: f64) -> Option<[f64; 2]> {
    let n = hit.geometric_normal;
    let height = 1e-3 * size;
    let ray = Ray::new(hit.point + step + n * height, -n, 0.0);
    let again = world.intersect(&ray, 0.0, 2.0 * height)?;
    if again.element != hit.element || again.primitive != hit.primitive {
        return None;
    }
    let mut delta = [again.uv[0] - hit.uv[0], again.uv[1] - hit.uv[1]];
    if hit.uv_mapping == UvMapping::Unit {
        // Angles wrap around (sphere, disk, revolution).
        delta[0] -= delta[0].round();
    }
    Some(delta)
}

#[test]
fn moving_along_a_derivative_moves_uv_by_one_coordinate() {
    let mut rng = Rng::new(31, 7);
    for (name, shape) in shapes() {
        for (label, matrix) in transforms() {
            let scene = world_of(vec![transformed(matrix, shape.clone())]);
            let world = scene.world();
            let target = target_box(world);
            let size = target.extent().norm();
            let mut checked = 0;
            for _ in 0..600 {
                let ray = ray_at_box(&mut rng, &target);
                let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
                    continue;
                };
                for (axis, derivative) in [(0, hit.dpdu), (1, hit.dpdv)] {
                    let length = derivative.norm();
                    assert!(length.is_finite() && length > 0.0, "{name}, {label}");
                    let normal_part = derivative.dot(&hit.geometric_normal);
                    assert!(
                        normal_part.abs() < 1e-9 * length,
                        "{name}, {label}: derivative {axis} is not in the tangent plane"
                    );
                    // Near a singular point (pole, disk centre) the second
                    // order term dominates: skip those.
                    if length < 1e-2 * size {
                        continue;
                    }
                    let eps = 1e-5 * size / length;
                    let Some(delta) = uv_step(world, &hit, derivative * eps, size) else {
                        continue;
                    };
                    let mut expected = [0.0; 2];
                    expected[axis] = eps;
                    let error = (delta[0] - expected[0]).hypot(delta[1] - expected[1]);
                    assert!(
                        error < 1e-2 * eps,
                        "{name}, {label}: d{axis} moved uv by {delta:?}, expected {expected:?} \
                         (uv {:?})",
                        hit.uv
                    );
                    checked += 1;
                }
            }
            println!("{name}, {label}: {checked} derivative steps checked");
            assert!(checked > 200, "{name}, {label}: only {checked} checks");
        }
    }
}

#[test]
fn derivatives_are_finite_at_singular_points() {
    // The pole of a sphere, the centre of a disk, the axis of a revolution.
    let cases: [(Object, Ray); 3] = [
        (
            ball(Point3::zeros(), 1.0, 0),
            Ray::new(Point3::new(0.0, 5.0, 0.0), -Vec3::y(), 0.0),
        ),
        (
            Object::Disk {
                center: Point3::zeros(),
                normal: Vec3::y(),
                radius: 1.0,
                material: 0,
            },
            Ray::new(Point3::new(0.0, 5.0, 0.0), -Vec3::y(), 0.0),
        ),
        (
            Object::Revolution {
                profile: vase(),
                material: 0,
            },
            Ray::new(Point3::new(0.0, -5.0, 0.0), Vec3::y(), 0.0),
        ),
    ];
    for (object, ray) in cases {
        let hit = world_of(vec![object]).intersect(&ray).expect("hit");
        for d in [hit.dpdu, hit.dpdv] {
            assert!(d.iter().all(|c| c.is_finite()) && d.norm() > 0.0, "{hit:?}");
            assert!(
                d.dot(&hit.geometric_normal).abs() < 1e-9 * d.norm(),
                "{hit:?}"
            );
        }
        assert!(hit.dpdu.cross(&hit.dpdv).norm() > 1e-9 * hit.dpdu.norm() * hit.dpdv.norm());
    }
}
