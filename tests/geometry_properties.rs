//! Properties of the geometry core: BVH equals brute force on real meshes, spawned
//! rays do not re-hit their surface, transforms are exact, and degenerate rays
//! produce no NaN.

mod common;

use std::sync::Arc;

use common::*;
use pathtracer::geometry::Mesh;
use pathtracer::geometry::triangle::intersect_vertices;
use pathtracer::math::{Aabb, Matrix, Point3, Ray, Vec3, offset_origin};
use pathtracer::rng::Rng;
use pathtracer::scene::model::Object;
use pathtracer::world::World;

#[test]
fn mesh_bvh_equals_brute_force_on_reference_meshes() {
    for path in [BUNNY_1K, BUNNY] {
        let Some(data) = load_mesh(path) else { return };
        let mesh = Mesh::new(Arc::clone(&data));
        let bounds = mesh.bounds().expect("non-empty mesh");
        let mut rng = Rng::new(7, 11);
        let (mut hits, rays) = (0, 2500);
        for i in 0..rays {
            let mut ray = ray_at_box(&mut rng, &bounds);
            if i % 10 == 0 {
                // Axis-parallel rays through the box.
                let axis = i / 10 % 3;
                ray.direction = Vec3::zeros();
                ray.direction[axis] = 1.0;
                ray.origin[axis] = bounds.min[axis] - 1.0;
            }
            let brute = data
                .triangles
                .iter()
                .filter_map(|t| {
                    let p = t.map(|i| data.positions[i as usize]);
                    intersect_vertices(&p[0], &p[1], &p[2], &ray, 0.0, f64::INFINITY)
                })
                .map(|(t, _, _)| t)
                .fold(f64::INFINITY, f64::min);
            let found = mesh.intersect(&ray, 0.0, f64::INFINITY);
            assert_eq!(
                found.map_or(f64::INFINITY, |h| h.t),
                brute,
                "{path} ray {i}"
            );
            assert_eq!(mesh.occluded(&ray, 0.0, f64::INFINITY), brute.is_finite());
            // A shortened ray must agree too (the any-hit path honours t_max).
            let half = brute * 0.999;
            assert!(!mesh.occluded(&ray, 0.0, half) || !brute.is_finite());
            hits += brute.is_finite() as usize;
        }
        println!("{path}: {hits}/{rays} rays hit, BVH == brute force");
        assert!(hits > rays / 10, "test rays should mostly hit the mesh");
    }
}

#[test]
fn world_bvh_equals_linear_scan() {
    let mut rng = Rng::new(3, 5);
    let mut objects = Vec::new();
    for i in 0..300 {
        let center = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 20.0;
        objects.push(if i % 2 == 0 {
            ball(center, 0.2 + rng.next_f64(), i)
        } else {
            Object::Triangle {
                vertices: [0, 1, 2].map(|_| center + random_unit(&mut rng) * 1.5),
                material: i,
            }
        });
    }
    objects.push(Object::Plane {
        normal: Vec3::y(),
        offset: -1.0,
        material: 999,
    });
    let scene = world_of(objects);
    let world = scene.world();
    // The primitives one by one, as the world made them.
    let primitives = world.primitives();
    assert_eq!(primitives.len(), 301);
    let bounds = world.bounds();
    for _ in 0..3000 {
        let ray = ray_at_box(&mut rng, &bounds);
        let linear = primitives
            .iter()
            .filter_map(|p| p.intersect(&ray, 1e-9, f64::INFINITY).map(|h| h.t))
            .fold(f64::INFINITY, f64::min);
        let hit = world.intersect(&ray, 1e-9, f64::INFINITY);
        assert_eq!(hit.map_or(f64::INFINITY, |h| h.t), linear);
        assert_eq!(
            world.occluded(&ray, 1e-9, f64::INFINITY),
            linear.is_finite()
        );
    }
}

/// Shapes under transforms of very different scales, for the self-intersection test.
fn spawn_test_objects() -> Vec<(String, Object)> {
    let scales: [(&str, Matrix); 5] = [
        ("identity", Matrix::identity()),
        ("scale 1e-3", Matrix::new_scaling(1e-3)),
        ("scale 1e3", Matrix::new_scaling(1e3)),
        (
            "translate 1e5",
            Matrix::new_translation(&Vec3::new(1e5, -1e5, 1e5)),
        ),
        (
            "non-uniform",
            Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 0.5, 1.0))
                * Matrix::from_euler_angles(0.3, 0.5, 0.1),
        ),
    ];
    let mut shapes = vec![
        ("sphere", ball(Point3::new(0.3, -0.2, 0.1), 1.0, 0)),
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
        (
            "plane",
            Object::Plane {
                normal: Vec3::new(0.2, 1.0, -0.3),
                offset: 0.7,
                material: 0,
            },
        ),
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
    ];
    if let Some(mesh) = load_mesh(BUNNY_1K) {
        shapes.push((
            "bunny",
            Object::Mesh {
                mesh,
                smooth: false,
                material: 0,
                face_materials: None,
                overridden_mtl: None,
            },
        ));
    }
    let mut out = Vec::new();
    for (name, shape) in &shapes {
        for (label, matrix) in &scales {
            out.push((
                format!("{name}, {label}"),
                transformed(*matrix, shape.clone()),
            ));
        }
    }
    out
}

#[test]
fn spawned_rays_do_not_rehit_their_surface() {
    let mut rng = Rng::new(21, 4);
    for (name, object) in spawn_test_objects() {
        let scene = world_of(vec![object]);
        let world = scene.world();
        // Aim at the bounds (planes: at a box around a point of the plane).
        let target = world.primitive(0).bounds().unwrap_or_else(|| {
            let hit = world
                .intersect(
                    &Ray::new(Point3::new(0.0, 1e7, 0.0), -Vec3::y(), 0.0),
                    0.0,
                    f64::INFINITY,
                )
                .expect("plane below");
            Aabb::from_point(hit.point).expanded(5.0)
        });
        let size = target.extent().norm();
        let (mut trials, mut failures) = (0, 0);
        for _ in 0..2000 {
            let ray = ray_at_box(&mut rng, &target);
            let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
                continue;
            };
            assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-9, "{name}");
            // Both sides: reflection (towards the ray) and transmission.
            for side in [-1.0, 1.0] {
                let mut direction = random_unit(&mut rng);
                if direction.dot(&hit.geometric_normal) * side < 0.0 {
                    direction = -direction;
                }
                let spawned = hit.spawn_ray(direction, ray.time);
                assert_eq!(
                    spawned.origin,
                    offset_origin(&hit.point, &hit.geometric_normal, &direction)
                );
                trials += 1;
                if let Some(again) = world.intersect(&spawned, 0.0, f64::INFINITY)
                    && again.t < 1e-7 * size
                {
                    failures += 1;
                }
            }
        }
        println!("{name}: {failures} self-hits in {trials} spawned rays");
        assert!(trials > 500, "{name}: too few hits ({trials})");
        assert_eq!(failures, 0, "{name}: spawned rays re-hit their surface");
    }
}

#[test]
fn non_uniformly_scaled_sphere_is_an_ellipsoid() {
    let center = Vec3::new(1.0, 2.0, 3.0);
    let matrix = Matrix::new_translation(&center)
        * Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 1.0, 1.0));
    let scene = world_of(vec![transformed(matrix, ball(Point3::zeros(), 1.0, 0))]);
    let world = scene.world();
    let mut rng = Rng::new(5, 5);
    let mut hits = 0;
    for _ in 0..2000 {
        let ray = ray_at_box(&mut rng, &world.bounds());
        let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) else {
            continue;
        };
        hits += 1;
        let q = hit.point - center;
        let implicit = (q.x / 2.0).powi(2) + q.y * q.y + q.z * q.z;
        assert!(
            (implicit - 1.0).abs() < 1e-9,
            "point off the ellipsoid: {implicit}"
        );
        assert!(
            (ray.at(hit.t) - hit.point).norm() < 1e-9,
            "t is not world t"
        );
        let gradient = Vec3::new(q.x / 4.0, q.y, q.z).normalize();
        assert!((hit.geometric_normal - gradient).norm() < 1e-9);
        assert!(hit.dpdu.dot(&hit.geometric_normal).abs() < 1e-9 * hit.dpdu.norm());
        assert!(hit.dpdv.dot(&hit.geometric_normal).abs() < 1e-9 * hit.dpdv.norm());
    }
    assert!(hits > 500);
}

fn assert_finite_hit(world: &World, ray: &Ray, what: &str) {
    if let Some(hit) = world.intersect(ray, 0.0, f64::INFINITY) {
        let values = [hit.t, hit.uv[0], hit.uv[1]];
        let vectors = [
            hit.point,
            hit.geometric_normal,
            hit.shading_normal,
            hit.dpdu,
            hit.dpdv,
        ];
        assert!(
            values.iter().all(|v| v.is_finite())
                && vectors.iter().all(|v| v.iter().all(|c| c.is_finite())),
            "{what}: non-finite hit {hit:?} for {ray:?}"
        );
        assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-9, "{what}");
        assert!((hit.shading_normal.norm() - 1.0).abs() < 1e-9, "{what}");
    }
    let _ = world.occluded(ray, 0.0, f64::INFINITY);
}

#[test]
fn axis_parallel_and_grazing_rays_give_no_nan() {
    let revolution = |profile| Object::Revolution {
        profile,
        material: 0,
    };
    let shapes = vec![
        ball(Point3::zeros(), 1.0, 0),
        Object::Plane {
            normal: Vec3::y(),
            offset: 0.0,
            material: 0,
        },
        Object::Triangle {
            vertices: [Point3::zeros(), Point3::x(), Point3::y()],
            material: 0,
        },
        Object::Rectangle {
            origin: Point3::zeros(),
            edge_u: Vec3::x(),
            edge_v: Vec3::z(),
            material: 0,
        },
        Object::Disk {
            center: Point3::zeros(),
            normal: Vec3::y(),
            radius: 1.0,
            material: 0,
        },
        revolution(vase()),
        revolution(wine_glass()),
    ];
    for shape in shapes {
        let what = format!("{shape:?}").chars().take(40).collect::<String>();
        let scene = world_of(vec![shape]);
        let world = scene.world();
        // Axis-parallel rays from a grid that includes the axis, the box faces and
        // the surface itself (grazing: rays in the plane of flat shapes, tangent
        // to the sphere).
        let coordinates = [-2.5, -1.0, -0.5, 0.0, 0.5, 1.0, 2.2, 5.6];
        for axis in 0..3 {
            for &a in &coordinates {
                for &b in &coordinates {
                    for sign in [-1.0, 1.0] {
                        let mut origin = Point3::zeros();
                        origin[(axis + 1) % 3] = a;
                        origin[(axis + 2) % 3] = b;
                        origin[axis] = -10.0 * sign;
                        let mut direction = Vec3::zeros();
                        direction[axis] = sign;
                        assert_finite_hit(world, &Ray::new(origin, direction, 0.0), &what);
                        origin[axis] = 0.0;
                        assert_finite_hit(world, &Ray::new(origin, direction, 0.0), &what);
                    }
                }
            }
        }
    }
}
