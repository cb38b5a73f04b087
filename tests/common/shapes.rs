//! Helpers for the geometry tests: reference meshes, random rays, profiles.

use std::path::Path;
use std::sync::Arc;

use pathtracer::geometry::{CurveKind, MeshData, Profile};
use pathtracer::math::{Aabb, Matrix, Point3, Ray, Vec3};
use pathtracer::rng::Rng;
use pathtracer::scene::model::Object;

pub const BUNNY: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/reference/meshes/bunny.obj"
);
pub const BUNNY_1K: &str = concat!(
    env!("CARGO_MANIFEST_DIR"),
    "/../shared/reference/cambrian-pathtracer/mesh/bunny_1k.obj"
);

pub fn load_mesh(path: &str) -> Option<Arc<MeshData>> {
    if !Path::new(path).exists() {
        println!("skipped: ../shared not found ({path})");
        return None;
    }
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ..Default::default()
    };
    let (models, _) = tobj::load_obj(path, &options).expect("reference OBJ loads");
    let mut data = MeshData::default();
    for model in models {
        let mesh = model.mesh;
        let base = data.positions.len() as u32;
        data.positions.extend(
            mesh.positions
                .chunks(3)
                .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64)),
        );
        data.triangles.extend(
            mesh.indices
                .chunks(3)
                .map(|t| [base + t[0], base + t[1], base + t[2]]),
        );
    }
    Some(Arc::new(data))
}

pub fn random_unit(rng: &mut Rng) -> Vec3 {
    let z = 2.0 * rng.next_f64() - 1.0;
    let phi = 2.0 * std::f64::consts::PI * rng.next_f64();
    let r = (1.0 - z * z).max(0.0).sqrt();
    Vec3::new(r * phi.cos(), r * phi.sin(), z)
}

pub fn random_in_box(rng: &mut Rng, b: &Aabb) -> Point3 {
    let e = b.extent();
    b.min
        + Vec3::new(
            e.x * rng.next_f64(),
            e.y * rng.next_f64(),
            e.z * rng.next_f64(),
        )
}

/// A ray from outside the box towards a random point inside it.
pub fn ray_at_box(rng: &mut Rng, b: &Aabb) -> Ray {
    let size = b.extent().norm();
    let origin = b.centroid() + random_unit(rng) * size * 1.5;
    let target = random_in_box(rng, b);
    Ray::new(origin, target - origin, rng.next_f64())
}

/// `child` under the object-to-world transform `matrix`.
pub fn transformed(matrix: Matrix, child: Object) -> Object {
    let inverse = matrix.try_inverse().expect("invertible");
    Object::Transform {
        matrix,
        inverse,
        child: Box::new(child),
    }
}

/// A sphere that does not move.
pub fn ball(center: Point3, radius: f64, material: usize) -> Object {
    Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    }
}

pub fn vase() -> Profile {
    Profile {
        kind: CurveKind::Bezier,
        controls: vec![
            [0.0, 0.0],
            [2.2, 0.0],
            [3.0, 1.5],
            [1.2, 3.0],
            [0.8, 4.0],
            [1.6, 5.0],
            [2.0, 5.6],
        ],
    }
}

/// The B-spline wine glass of cambrian-pathtracer/testcases/bspline.txt.
pub fn wine_glass() -> Profile {
    let controls = [
        [0.0, -0.459543],
        [0.0, -0.459544],
        [0.0, -0.459545],
        [-0.351882, -0.426747],
        [-0.848656, -0.278898],
        [-1.112097, 0.084005],
        [-1.164785, 1.105511],
        [-0.991667, 2.328629],
        [-1.029301, 2.503360],
        [-1.088800, 2.345600],
        [-1.278000, 1.162800],
        [-1.214800, 0.055200],
        [-0.915600, -0.381200],
        [-0.380400, -0.622000],
        [-0.144000, -0.968400],
        [-0.096800, -1.480000],
        [-0.128400, -2.112400],
        [-0.317200, -2.202800],
        [-0.994400, -2.262800],
        [-1.214800, -2.323200],
        [-1.199200, -2.398400],
        [-1.057600, -2.458800],
        [-0.711200, -2.458800],
        [0.000000, -2.458800],
        [0.000000, -2.458801],
        [0.000000, -2.458802],
    ];
    Profile {
        kind: CurveKind::Bspline,
        controls: controls.to_vec(),
    }
}
