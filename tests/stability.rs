//! Numerical stability: the same scene translated by 1e5 or scaled by 1e-3
//! and 1e3 renders the same image (no acne, no lost hits); the full dragon
//! with its 108 zero-area triangles and a cusped revolution profile give no
//! NaN.

mod common;

use std::sync::Arc;

use pathtracer::color::Color;
use pathtracer::geometry::{CurveKind, MeshData, Profile};
use pathtracer::image_io::Image;
use pathtracer::integrator::Integrator;
use pathtracer::math::{Matrix, Ray, Vec3};
use pathtracer::metrics::compare;
use pathtracer::render::RenderSettings;
use pathtracer::rng::Rng;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Material, Object, Scene};

fn materials() -> Vec<Material> {
    vec![
        Material {
            color: Color::new(0.7, 0.6, 0.5),
            ..Material::default()
        },
        Material {
            color: Color::gray(0.9),
            diffuse: 0.0,
            specular: 1.0,
            ..Material::default()
        },
        Material {
            color: Color::gray(0.95),
            diffuse: 0.0,
            refract: 1.0,
            ..Material::default()
        },
        Material {
            color: Color::BLACK,
            emission: Color::gray(8.0),
            ..Material::default()
        },
    ]
}

fn octahedron() -> Arc<MeshData> {
    let p = |x: f64, y: f64, z: f64| Vec3::new(x, y, z);
    Arc::new(MeshData {
        framework_reading: None,
        positions: vec![
            p(1.0, 0.0, 0.0),
            p(-1.0, 0.0, 0.0),
            p(0.0, 1.0, 0.0),
            p(0.0, -1.0, 0.0),
            p(0.0, 0.0, 1.0),
            p(0.0, 0.0, -1.0),
        ],
        normals: None,
        uvs: None,
        triangles: vec![
            [0, 2, 4],
            [2, 1, 4],
            [1, 3, 4],
            [3, 0, 4],
            [2, 0, 5],
            [1, 2, 5],
            [3, 1, 5],
            [0, 3, 5],
        ],
    })
}

/// A floor, back wall, spheres of each material, a mesh, a vase and a light,
/// seen from (0, 2, 10), with world-space coordinates `p * scale + offset`
/// written into the shapes (not applied as a transform).
fn objects(scale: f64, offset: Vec3) -> Object {
    let place = Matrix::new_translation(&offset) * Matrix::new_scaling(scale);
    let unplace = Matrix::new_scaling(1.0 / scale) * Matrix::new_translation(&-offset);
    let rect = |origin: Vec3, u: Vec3, v: Vec3, material| Object::Rectangle {
        origin: origin * scale + offset,
        edge_u: u * scale,
        edge_v: v * scale,
        material,
    };
    let sphere = |c: Vec3, r: f64, material| Object::Sphere {
        center: c * scale + offset,
        radius: r * scale,
        motion: Vec3::zeros(),
        material,
    };
    Object::Group(vec![
        rect(
            Vec3::new(-6.0, 0.0, -6.0),
            Vec3::new(0.0, 0.0, 14.0),
            Vec3::new(12.0, 0.0, 0.0),
            0,
        ),
        rect(
            Vec3::new(-6.0, 0.0, -6.0),
            Vec3::new(12.0, 0.0, 0.0),
            Vec3::new(0.0, 8.0, 0.0),
            0,
        ),
        sphere(Vec3::new(-2.5, 1.0, 0.0), 1.0, 1),
        sphere(Vec3::new(0.0, 1.0, 1.5), 1.0, 2),
        sphere(Vec3::new(2.5, 1.0, 0.0), 1.0, 0),
        sphere(Vec3::new(0.0, 7.0, 2.0), 1.0, 3),
        Object::Transform {
            matrix: place
                * Matrix::new_translation(&Vec3::new(-1.0, 0.7, -3.0))
                * Matrix::new_scaling(0.7),
            inverse: Matrix::new_scaling(1.0 / 0.7)
                * Matrix::new_translation(&Vec3::new(1.0, -0.7, 3.0))
                * unplace,
            child: Box::new(Object::Mesh {
                mesh: octahedron(),
                smooth: false,
                material: 0,
                face_materials: None,
            }),
        },
        Object::Transform {
            matrix: place
                * Matrix::new_translation(&Vec3::new(2.0, 0.0, -3.0))
                * Matrix::new_scaling(0.4),
            inverse: Matrix::new_scaling(1.0 / 0.4)
                * Matrix::new_translation(&Vec3::new(-2.0, 0.0, 3.0))
                * unplace,
            child: Box::new(Object::Revolution {
                profile: common::vase(),
                material: 0,
            }),
        },
    ])
}

/// The scene moved by `offset` and scaled by `scale` about the origin, camera
/// included.
fn scene(scale: f64, offset: Vec3) -> Scene {
    let mut scene = common::scene_with(materials(), objects(scale, offset));
    scene.camera.center = Vec3::new(0.0, 2.0, 10.0) * scale + offset;
    scene.camera.direction = Vec3::new(0.0, -0.1, -1.0);
    scene.camera.width = 48;
    scene.camera.height = 36;
    scene
}

fn render_scene(scene: &Scene) -> (Image, u64) {
    let settings = RenderSettings {
        width: 48,
        height: 36,
        spp: 64,
        seed: 9,
        threads: None,
        integrator: Integrator::Original,
        max_depth: 5,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Default::default(),
        dispersion: None,
    };
    let (image, stats) = common::render_scene(scene, &settings).expect("renders");
    (image, stats.dropped)
}

#[test]
fn translated_and_scaled_scenes_render_the_same_image() {
    let (reference, dropped) = render_scene(&scene(1.0, Vec3::zeros()));
    assert_eq!(dropped, 0);
    let mean: f64 =
        reference.pixels.iter().map(|p| p.average()).sum::<f64>() / reference.pixels.len() as f64;
    assert!(mean > 0.05, "the reference is lit: {mean}");
    for (scale, offset) in [
        (1.0, Vec3::new(1e5, -1e5, 1e5)),
        (1e-3, Vec3::zeros()),
        (1e3, Vec3::zeros()),
        (1e-3, Vec3::new(1e2, 0.0, -1e2)),
    ] {
        let (image, dropped) = render_scene(&scene(scale, offset));
        assert_eq!(dropped, 0);
        let difference = compare(&image, &reference).expect("same size");
        let image_mean: f64 =
            image.pixels.iter().map(|p| p.average()).sum::<f64>() / image.pixels.len() as f64;
        println!(
            "scale {scale:e} offset {offset:?}: {difference}, mean {image_mean:.4} vs {mean:.4}"
        );
        // Acne darkens, lost hits change whole regions: both show in the mean
        // and in the per-pixel error. Paths that diverge by rounding add noise.
        assert!(
            (image_mean - mean).abs() < 0.01 * mean,
            "mean {image_mean} vs {mean}"
        );
        assert!(difference.rel_mse < 0.01, "{difference}");
    }
}

#[test]
fn the_full_dragon_with_degenerate_triangles_gives_finite_hits() {
    let Some(mesh) = common::load_mesh(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../shared/reference/meshes/dragon_vrip.obj"
    )) else {
        return;
    };
    let degenerate = mesh
        .triangles
        .iter()
        .filter(|t| {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            (b - a).cross(&(c - a)).norm() == 0.0
        })
        .count();
    assert_eq!(degenerate, 108, "the dragon's known zero-area triangles");
    let root = Object::Mesh {
        mesh,
        smooth: false,
        material: 0,
        face_materials: None,
    };
    let scene = common::built(common::scene_with(materials(), root));
    let world = scene.world();
    let bounds = world.bounds();
    let mut rng = Rng::new(4, 4);
    let mut hits = 0;
    for _ in 0..20_000 {
        let ray = common::ray_at_box(&mut rng, &bounds);
        if let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) {
            hits += 1;
            assert!(hit.t.is_finite() && hit.point.iter().all(|c| c.is_finite()));
            assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-9);
        }
    }
    assert!(hits > 5_000, "{hits} hits");
}

#[test]
fn a_cusped_profile_and_near_tangent_rays_give_no_nan() {
    // The control polygon folds back on itself: the curve has a cusp.
    let profile = Profile {
        kind: CurveKind::Bezier,
        controls: vec![[0.0, 0.0], [2.0, 1.0], [0.0, 1.0], [2.0, 0.0], [1.0, 2.0]],
    };
    let root = Object::Revolution {
        profile,
        material: 0,
    };
    let scene = common::built(common::scene_with(materials(), root));
    let world = scene.world();
    let bounds = world.bounds();
    let mut rng = Rng::new(6, 6);
    let mut hits = 0;
    for i in 0..20_000 {
        let mut ray = common::ray_at_box(&mut rng, &bounds);
        if i % 2 == 0 {
            // Skim the bounding cylinder: nearly tangent to the widest part.
            let r = bounds.max.x * (1.0 - 1e-6 * rng.next_f64());
            let y = bounds.min.y + (bounds.max.y - bounds.min.y) * rng.next_f64();
            ray = Ray::new(Vec3::new(r, y, 10.0), Vec3::new(0.0, 0.0, -1.0), 0.0);
        }
        if let Some(hit) = world.intersect(&ray, 0.0, f64::INFINITY) {
            hits += 1;
            assert!(hit.point.iter().all(|c| c.is_finite()));
            assert!(hit.geometric_normal.iter().all(|c| c.is_finite()));
            assert!((hit.geometric_normal.norm() - 1.0).abs() < 1e-6);
        }
    }
    assert!(hits > 1_000, "{hits} hits");
}
