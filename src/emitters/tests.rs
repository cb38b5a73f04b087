//! Tests of light sampling: densities against hit counting, and the table
//! lookup of world hits (transforms, mesh triangles, excluded ellipsoids).

use std::f64::consts::PI;
use std::sync::Arc;

use super::*;
use crate::color::Color;
use crate::geometry::Transform;
use crate::geometry::surface_samples::uniform_sphere;
use crate::geometry::{Disk, Rectangle, Shape, Sphere, Triangle};
use crate::look::Look;
use crate::math::Ray;
use crate::math::Vec3;
use crate::render_scene::{RenderScene, SceneSettings};
use crate::rng::Rng;
use crate::scene::model::{Object, Scene};

/// `E[1 / pdf]` over light samples (the solid angle the sampler covers),
/// checking on the way that `pdf` agrees with the density of `sample`.
fn sampled_solid_angle(shape: &Shape, reference: &Point3, n: usize) -> f64 {
    let mut rng = Rng::new(3, 4);
    let mut sum = 0.0;
    for _ in 0..n {
        let Some(s) = shape.sample(reference, 0.0, [rng.next_f64(), rng.next_f64()]) else {
            continue;
        };
        assert!((s.direction.norm() - 1.0).abs() < 1e-12);
        assert!((reference + s.direction * s.distance - s.point).norm() < 1e-9);
        let normal = match shape {
            Shape::Sphere(sphere) => (s.point - sphere.center).normalize(),
            _ => {
                shape
                    .sample_area(0.0, [0.5, 0.5])
                    .expect("a sampled shape")
                    .1
            }
        };
        let pdf = shape.pdf(reference, 0.0, &s.point, &normal);
        assert!((pdf - s.pdf).abs() <= 1e-9 * s.pdf, "{pdf} vs {}", s.pdf);
        sum += 1.0 / s.pdf;
    }
    sum / n as f64
}

/// 4 pi times the fraction of uniform directions from `reference` that hit `shape`.
fn hit_solid_angle(shape: &Shape, reference: &Point3, n: usize) -> f64 {
    let mut rng = Rng::new(5, 6);
    let hits = (0..n)
        .filter(|_| {
            let d = uniform_sphere([rng.next_f64(), rng.next_f64()]);
            let ray = Ray::new(*reference, d, 0.0);
            shape.intersect(&ray, 0.0, f64::INFINITY).is_some()
        })
        .count();
    4.0 * PI * hits as f64 / n as f64
}

#[test]
fn densities_are_consistent_and_cover_the_visible_solid_angle() {
    let reference = Point3::new(0.2, -0.1, 0.0);
    let (a, b, c) = (
        Point3::new(-0.5, -0.4, -1.0),
        Point3::new(0.8, -0.2, -1.2),
        Point3::new(0.1, 0.7, -0.9),
    );
    let (origin, edge_u, edge_v) = (
        Point3::new(-0.5, 0.6, -0.5),
        Vec3::new(1.0, 0.0, -0.2),
        Vec3::new(0.3, 0.2, -1.0),
    );
    let normal = Vec3::new(0.3, 0.2, 1.0).normalize();
    let center = Point3::new(0.0, 0.0, -1.0);
    let cases = [
        Shape::Triangle(Triangle::new([a, b, c])),
        Shape::Rectangle(Rectangle::new(origin, edge_u, edge_v).unwrap()),
        Shape::Disk(Disk::new(center, normal, 0.6).unwrap()),
        Shape::Sphere(Sphere::new(center, 0.5, Vec3::zeros())),
    ];
    for shape in cases {
        let sampled = sampled_solid_angle(&shape, &reference, 100_000);
        let hit = hit_solid_angle(&shape, &reference, 400_000);
        assert!(
            (sampled - hit).abs() < 0.03 * hit,
            "{shape:?}: sampled {sampled} vs hit {hit}"
        );
    }
}

/// A disk under a non-uniform scale (an ellipse) samples in its own space
/// through its transform: its densities agree with hit counting through
/// the same transform, and its area is the ellipse's.
#[test]
fn a_transformed_disk_samples_through_its_transform() {
    let matrix = crate::math::Matrix::new(
        2.0, 0.3, 0.0, 0.1, //
        0.0, 0.5, 0.2, -0.2, //
        0.1, 0.0, 1.0, -1.5, //
        0.0, 0.0, 0.0, 1.0,
    );
    let transform = Transform::new(matrix, matrix.try_inverse().unwrap());
    let disk = Shape::Disk(Disk::new(Point3::zeros(), Vec3::new(0.2, 0.1, 1.0), 0.5).unwrap());
    let emitter = Emitter::new(&disk, Some(&transform), &[], Color::WHITE).unwrap();
    let reference = Point3::new(0.2, -0.1, 0.5);
    let mut rng = Rng::new(3, 4);
    let n = 100_000;
    let mut sampled = 0.0;
    for _ in 0..n {
        let u = [rng.next_f64(), rng.next_f64()];
        let Some(s) = emitter.sample(&reference, 0.0, u) else {
            continue;
        };
        let (_, normal) = emitter.sample_area(0.0, u).unwrap();
        let pdf = emitter.pdf(&reference, 0.0, &s.point, &normal);
        assert!((pdf - s.pdf).abs() <= 1e-9 * s.pdf, "{pdf} vs {}", s.pdf);
        sampled += 1.0 / s.pdf;
    }
    sampled /= n as f64;
    let mut rng = Rng::new(5, 6);
    let m = 400_000;
    let hits = (0..m)
        .filter(|_| {
            let d = uniform_sphere([rng.next_f64(), rng.next_f64()]);
            let ray = transform.ray_to_object(&Ray::new(reference, d, 0.0));
            disk.intersect(&ray, 0.0, f64::INFINITY).is_some()
        })
        .count();
    let hit = 4.0 * PI * hits as f64 / m as f64;
    assert!(
        (sampled - hit).abs() < 0.03 * hit,
        "sampled {sampled} vs hit {hit}"
    );
}

#[test]
fn sphere_seen_from_inside_or_its_surface_covers_all_directions() {
    let sphere = Shape::Sphere(Sphere::new(Point3::zeros(), 2.0, Vec3::zeros()));
    for reference in [Point3::new(0.3, -1.0, 0.5), Point3::new(0.0, 2.0, 0.0)] {
        let omega = sampled_solid_angle(&sphere, &reference, 200_000);
        // From inside every direction sees the sphere; from a point on it,
        // the inner half space (2 pi), sampled by area.
        let want = if reference.norm() < 2.0 { 4.0 } else { 2.0 } * PI;
        assert!((omega - want).abs() < 0.03 * want, "{omega} vs {want}");
    }
}

#[test]
fn tiny_distant_sphere_has_the_small_cone_density() {
    let sphere = Shape::Sphere(Sphere::new(Point3::new(0.0, 0.0, 1e4), 1e-3, Vec3::zeros()));
    let s = sphere.sample(&Point3::zeros(), 0.0, [0.3, 0.7]).unwrap();
    let want = 1.0 / (PI * 1e-14); // 1 / (pi (r/d)^2) in the small-angle limit
    assert!((s.pdf - want).abs() < 1e-6 * want);
    assert!((s.distance - (1e4 - 1e-3)).abs() < 1e-3);
}

/// The render-time scene of `scene` in the original look, whose world and
/// emitters these tests read.
pub(super) fn built(scene: &Scene) -> RenderScene {
    RenderScene::build(
        scene.clone(),
        &SceneSettings::defaults(scene, Look::ORIGINAL),
    )
}

fn scene(materials: Vec<crate::scene::model::Material>, root: Object) -> Scene {
    Scene::new(materials, root)
}

fn transformed(matrix: crate::math::Matrix, child: Object) -> Object {
    Object::Transform {
        matrix,
        inverse: matrix.try_inverse().unwrap(),
        child: Box::new(child),
    }
}

#[test]
fn world_hits_find_the_density_their_light_sample_had() {
    use crate::geometry::MeshData;
    use crate::math::Matrix;
    use crate::scene::model::Material;
    let emissive = Material {
        emission: Color::new(1.0, 2.0, 3.0),
        ..Material::default()
    };
    let mesh = Arc::new(MeshData {
        framework_reading: None,
        positions: vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(1.0, 1.0, 0.0),
            Point3::new(0.0, 1.0, 0.2),
        ],
        normals: None,
        uvs: None,
        triangles: vec![[0, 1, 2], [0, 2, 3], [0, 1, 9]],
    });
    let root = Object::Group(vec![
        transformed(
            Matrix::new_translation(&Vec3::new(-1.0, -0.5, -4.0))
                * Matrix::new_nonuniform_scaling(&Vec3::new(2.0, 1.0, 0.5)),
            Object::Mesh {
                mesh,
                smooth: false,
                material: 0,
                face_materials: None,
            },
        ),
        transformed(
            Matrix::new_translation(&Vec3::new(2.0, 0.0, -5.0)) * Matrix::new_scaling(2.0),
            Object::Sphere {
                center: Point3::zeros(),
                radius: 0.3,
                motion: Vec3::zeros(),
                material: 0,
            },
        ),
        transformed(
            Matrix::new_translation(&Vec3::new(-2.0, 0.0, -5.0))
                * Matrix::new_nonuniform_scaling(&Vec3::new(1.0, 3.0, 1.0)),
            Object::Sphere {
                center: Point3::zeros(),
                radius: 0.3,
                motion: Vec3::zeros(),
                material: 0,
            },
        ),
    ]);
    let scene = scene(vec![emissive], root);
    let built = built(&scene);
    let (world, emitters) = (built.world(), built.emitters());
    // Three mesh triangles (one invalid, never picked) and one sphere; the
    // ellipsoid is left to BSDF sampling.
    assert_eq!(emitters.len(), 4);
    let reference = Point3::new(0.1, 0.2, 0.5);
    let mut rng = Rng::new(9, 9);
    let mut seen = [0usize; 2];
    for _ in 0..2000 {
        let u = [rng.next_f64(), rng.next_f64()];
        let light = emitters
            .sample(&reference, 0.0, rng.next_f64(), u)
            .expect("every sample is usable from here");
        let ray = Ray::new(reference, light.direction, 0.0);
        let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert!((hit.t - light.distance).abs() < 1e-9 * light.distance.max(1.0));
        seen[hit.primitive] += 1;
        let pdf = emitters.pdf(&reference, 0.0, &hit);
        assert!(
            (pdf - light.pdf).abs() < 1e-6 * light.pdf,
            "{pdf} vs {}",
            light.pdf
        );
    }
    assert!(seen[0] > 0 && seen[1] > 0);
    let ellipsoid = Ray::new(
        reference,
        (Point3::new(-2.0, 0.0, -5.0) - reference).normalize(),
        0.0,
    );
    let hit = world.intersect(&ellipsoid, 0.0, f64::INFINITY).unwrap();
    assert_eq!(hit.primitive, 2);
    assert_eq!(emitters.pdf(&reference, 0.0, &hit), 0.0);
}

#[test]
fn light_paths_start_on_small_emitters_only_with_matching_densities() {
    use crate::scene::model::Material;
    let light = |radiance: f64| Material {
        color: Color::BLACK,
        emission: Color::gray(radiance),
        ..Material::default()
    };
    let sphere = |center: Point3, radius: f64, material: usize| Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    };
    // A sky-sized sphere and a small one, seen from the origin.
    let root = Object::Group(vec![
        sphere(Point3::new(0.0, 120.0, 0.0), 100.0, 0),
        sphere(Point3::new(10.0, 0.0, 0.0), 0.5, 1),
    ]);
    let scene = scene(vec![light(1.0), light(50.0)], root);
    let built = built(&scene);
    let (world, mut emitters) = (built.world(), built.emitters().clone());
    assert!(emitters.restrict_light_paths(&Point3::zeros()));
    let power = |radiance: f64, radius: f64| radiance * 4.0 * PI * radius * radius;
    let share = power(50.0, 0.5) / (power(50.0, 0.5) + power(1.0, 100.0));
    assert!((emitters.light_path_share() - share).abs() < 1e-12);
    let mut rng = Rng::new(9, 10);
    for _ in 0..200 {
        let u = [rng.next_f64(), rng.next_f64()];
        let start = emitters
            .sample_emission_point(&Point3::zeros(), 0.0, rng.next_f64(), u, 0.5)
            .expect("the small light starts light subpaths");
        // Always on the small sphere, with density share / area.
        assert!(((start.point - Point3::new(10.0, 0.0, 0.0)).norm() - 0.5).abs() < 1e-9);
        let expected = share / (4.0 * PI * 0.25);
        assert!((start.density / expected - 1.0).abs() < 1e-9);
        // The hit of the same point has the same density; the big light's none.
        let ray = Ray::new(start.point + start.normal, -start.normal, 0.0);
        let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let density = emitters.emission_point_density(&Point3::zeros(), 0.0, &hit, &start.normal);
        assert!((density / start.density - 1.0).abs() < 1e-9);
    }
    let down = Ray::new(Point3::zeros(), Vec3::y(), 0.0);
    let sky = world.intersect(&down, 0.0, f64::INFINITY).unwrap();
    assert_eq!(
        emitters.emission_point_density(&Point3::zeros(), 0.0, &sky, &-Vec3::y()),
        0.0
    );
}

#[test]
fn cover_means_every_emitting_surface_can_be_sampled() {
    use crate::scene::model::Material;
    let materials = vec![
        Material::default(),
        Material {
            emission: Color::gray(4.0),
            ..Material::default()
        },
    ];
    let sphere = |material: usize| Object::Sphere {
        center: Point3::new(0.0, 3.0, -5.0),
        radius: 0.5,
        motion: Vec3::zeros(),
        material,
    };
    let plane = |material: usize| Object::Plane {
        normal: Vec3::y(),
        offset: -1.0,
        material,
    };
    let covered = |objects: Vec<Object>| {
        let scene = scene(materials.clone(), Object::Group(objects));
        let built = built(&scene);
        built.emitters().cover(&scene, built.world())
    };
    // A sampled sphere light over a plain floor: light sampling finds all.
    assert!(covered(vec![sphere(1), plane(0)]));
    // No emitter at all: nothing to miss.
    assert!(covered(vec![sphere(0), plane(0)]));
    // An emissive plane is never sampled: only bounces find its light.
    assert!(!covered(vec![sphere(1), plane(1)]));
}
