//! Tests of the world: building, instancing, and queries against brute force.

use super::*;

use crate::math::Matrix;
use std::sync::Arc;

use crate::geometry::MeshData;
use crate::scene::model::Object;

fn scene(root: Object) -> Scene {
    Scene::new(Vec::new(), root)
}

fn translate(offset: Vec3, child: Object) -> Object {
    let matrix = Matrix::new_translation(&offset);
    Object::Transform {
        matrix,
        inverse: Matrix::new_translation(&-offset),
        child: Box::new(child),
    }
}

#[test]
fn build_composes_transforms_and_shares_meshes() {
    let data = Arc::new(MeshData {
        framework_reading: None,
        positions: vec![Point3::zeros(), Point3::x(), Point3::y()],
        normals: None,
        uvs: None,
        triangles: vec![[0, 1, 2]],
    });
    let mesh = |material| Object::Mesh {
        mesh: Arc::clone(&data),
        smooth: false,
        material,
        face_materials: None,
        overridden_mtl: None,
    };
    let root = Object::Group(vec![
        translate(
            Vec3::new(0.0, 0.0, -5.0),
            translate(Vec3::new(10.0, 0.0, 0.0), mesh(1)),
        ),
        translate(Vec3::zeros(), mesh(2)),
        Object::Sphere {
            center: Point3::zeros(),
            radius: 0.0,
            motion: Vec3::zeros(),
            material: 3,
        },
        Object::Plane {
            normal: Vec3::y(),
            offset: -1.0,
            material: 4,
        },
    ]);
    let world = World::build(&scene(root), ShapeRules::default());
    // The zero-radius sphere is dropped; the identity transform is not stored.
    assert_eq!(world.primitives().len(), 3);
    assert!(world.primitive(1).transform.is_none());
    let (Shape::Mesh { mesh: a, .. }, Shape::Mesh { mesh: b, .. }) =
        (&world.primitive(0).shape, &world.primitive(1).shape)
    else {
        panic!("meshes expected");
    };
    assert!(Arc::ptr_eq(a, b), "one geometry mesh per MeshData");
    // Nested translations compose: the first instance sits at (10, 0, -5).
    let ray = Ray::new(Point3::new(10.25, 0.25, 0.0), -Vec3::z(), 0.0);
    let hit = world.intersect(&ray, 0.0, f64::INFINITY).unwrap();
    assert_eq!(hit.material, 1);
    assert!((hit.t - 5.0).abs() < 1e-12);
    assert!((hit.point - Point3::new(10.25, 0.25, -5.0)).norm() < 1e-12);
    let down = Ray::new(Point3::new(3.0, 0.0, 3.0), -Vec3::y(), 0.0);
    assert_eq!(
        world.intersect(&down, 0.0, f64::INFINITY).unwrap().material,
        4
    );
    assert!(world.occluded(&down, 0.0, 2.0));
    assert!(!world.occluded(&down, 0.0, 0.5));
    assert!((world.bounds().max.x - 11.0).abs() < 1e-12);
}

/// Spheres (some moving, some transformed), triangles and planes.
fn random_primitives(rng: &mut crate::rng::Rng, count: usize) -> Vec<Primitive> {
    use crate::geometry::{Plane, Sphere, Triangle};
    let mut point = |scale: f64| {
        Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * scale
            - Vec3::repeat(scale / 2.0)
    };
    let mut primitives = Vec::new();
    // A little mesh (a tetrahedron's four faces) for the instances.
    let tetrahedron = Arc::new(crate::geometry::Mesh::new(Arc::new(
        crate::geometry::MeshData {
            framework_reading: None,
            positions: vec![
                Point3::new(0.0, 0.0, 0.0),
                Point3::new(1.5, 0.0, 0.2),
                Point3::new(0.1, 1.4, 0.0),
                Point3::new(0.3, 0.2, 1.6),
            ],
            normals: None,
            uvs: None,
            triangles: vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
        },
    )));
    for i in 0..count {
        let center = point(10.0);
        let (shape, transform) = match i % 5 {
            4 => {
                // Rotated and scaled: its world box is looser than its faces.
                let matrix = Matrix::new_translation(&center)
                    * Matrix::new_rotation(point(3.0))
                    * Matrix::new_scaling(1.3);
                let inverse = matrix.try_inverse().expect("invertible");
                let transform = Box::new(crate::geometry::Transform::new(matrix, inverse));
                let mesh = Shape::Mesh {
                    mesh: Arc::clone(&tetrahedron),
                    smooth: false,
                };
                (mesh, Some(transform))
            }
            0 => (Shape::Sphere(Sphere::new(center, 1.0, Vec3::zeros())), None),
            1 => (Shape::Sphere(Sphere::new(center, 0.5, point(2.0))), None),
            2 => {
                let matrix = Matrix::new_translation(&center) * Matrix::new_scaling(0.7);
                let inverse = matrix.try_inverse().expect("invertible");
                let sphere = Sphere::new(Point3::zeros(), 1.0, Vec3::zeros());
                let transform = Box::new(crate::geometry::Transform::new(matrix, inverse));
                (Shape::Sphere(sphere), Some(transform))
            }
            _ => {
                let triangle = Triangle::new([center, center + point(3.0), center + point(3.0)]);
                (Shape::Triangle(triangle), None)
            }
        };
        primitives.push(Primitive {
            shape,
            transform,
            material: i,
            face_materials: None,
        });
    }
    for axis in 0..3 {
        let mut normal = Vec3::zeros();
        normal[axis] = 1.0;
        let plane = Plane::new(normal, 8.0).expect("valid plane");
        primitives.push(Primitive {
            shape: Shape::Plane(plane),
            transform: None,
            material: 100 + axis,
            face_materials: None,
        });
    }
    primitives
}

#[test]
fn small_and_large_worlds_equal_brute_force() {
    let mut rng = crate::rng::Rng::new(11, 12);
    // 6 bounded primitives: tested linearly; 40: through the BVH.
    for count in [6, 40] {
        let world = World::from_primitives(random_primitives(&mut rng, count));
        assert_eq!(world.bounded.is_empty(), count <= LINEAR_LIMIT);
        let mut hits = 0;
        for _ in 0..3000 {
            let origin = Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 12.0
                - Vec3::repeat(6.0);
            let direction =
                Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) - Vec3::repeat(0.5);
            let ray = Ray::new(origin, direction.normalize(), rng.next_f64());
            let t_max = 4.0 + 20.0 * rng.next_f64();
            let brute = world
                .primitives()
                .iter()
                .enumerate()
                .filter_map(|(i, p)| p.intersect(&ray, 0.0, t_max).map(|hit| (i, hit.t)))
                .min_by(|a, b| a.1.total_cmp(&b.1));
            let found = world.intersect(&ray, 0.0, t_max);
            assert_eq!(found.map(|h| h.primitive), brute.map(|b| b.0));
            if let (Some(hit), Some((_, t))) = (found, brute) {
                assert!((hit.t - t).abs() <= 1e-9 * t.max(1.0));
                hits += 1;
            }
            assert_eq!(world.occluded(&ray, 0.0, t_max), brute.is_some());
        }
        assert!(hits > 500, "{hits} hits of 3000");
    }
}

#[test]
fn culled_mesh_instances_keep_every_hit() {
    // Rays aimed at rotated mesh instances of a world without BVH, whose
    // world boxes cull the rays that miss them.
    let mut rng = crate::rng::Rng::new(21, 22);
    let primitives: Vec<Primitive> = random_primitives(&mut rng, 20)
        .into_iter()
        .filter(|p| matches!(p.shape, Shape::Mesh { .. }))
        .collect();
    assert_eq!(primitives.len(), 4);
    let world = World::from_primitives(primitives);
    assert!(world.bounded.is_empty() && world.linear_boxes.iter().all(Option::is_some));
    let mut hits = 0;
    for _ in 0..4000 {
        let target = world.primitive((rng.next_f64() * 4.0) as usize % 4);
        let bounds = target.bounds().unwrap();
        let aim = bounds.min
            + (bounds.max - bounds.min).component_mul(&Vec3::new(
                rng.next_f64(),
                rng.next_f64(),
                rng.next_f64(),
            ));
        let origin =
            Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 30.0 - Vec3::repeat(15.0);
        let ray = Ray::new(origin, aim - origin, 0.0);
        let brute = world
            .primitives()
            .iter()
            .enumerate()
            .filter_map(|(i, p)| p.intersect(&ray, 0.0, 10.0).map(|hit| (i, hit.t)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let found = world.intersect(&ray, 0.0, 10.0);
        assert_eq!(found.map(|h| (h.primitive, h.t)), brute);
        assert_eq!(world.occluded(&ray, 0.0, 10.0), brute.is_some());
        hits += usize::from(brute.is_some());
    }
    assert!(hits > 800, "{hits} hits of 4000");
}

#[test]
fn world_is_send_and_sync() {
    fn check<T: Send + Sync>() {}
    check::<World>();
}

#[test]
fn cav_tessellations_past_their_budget_are_built_exact() {
    use crate::geometry::{CavRevolution, CurveKind, Profile, RevolutionTest};
    let profile = Profile {
        kind: CurveKind::Bezier,
        controls: vec![[1.0, 0.0], [2.0, 1.0], [1.0, 2.0], [1.5, 3.0]],
    };
    let triangles = CavRevolution::triangle_count(&profile);
    let vase = |material| Object::Revolution {
        profile: profile.clone(),
        material,
    };
    let root = Object::Group(vec![vase(0), vase(1), vase(2)]);
    let mut builder = builder::Builder::for_tree(&root);
    builder.rules = ShapeRules {
        revolution_test: RevolutionTest::CavMesh,
        ..ShapeRules::default()
    };
    // Room for two tessellations, not three.
    builder.cav_budget = 3 * triangles - 1;
    builder.visit(&root, None);
    let kinds: Vec<bool> = builder
        .primitives
        .iter()
        .map(|p| matches!(p.shape, Shape::CavRevolution(_)))
        .collect();
    assert_eq!(kinds, [true, true, false]);
    assert!(matches!(builder.primitives[2].shape, Shape::Revolution(_)));
    assert_eq!(builder.cav_exact_instead, 1);
}
