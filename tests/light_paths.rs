//! Light subpaths (light tracing and connections for caustics) do not change
//! the expected image, and they remove most of the noise of caustics.
//!
//! A box with a small sphere light above a glass ball, a mirror ball, a
//! half-mirror ball and a two-sided emissive triangle is rendered many times
//! with independent seeds by the path integrator with and without light
//! subpaths and by the original estimator: per-run image means and a few
//! pixels in the caustics must agree within 4 combined standard errors.

mod common;

use common::statistic;
use pathtracer::color::Color;
use pathtracer::integrator::{Integrator, original::MAX_DEPTH};
use pathtracer::math::{Point3, Vec3};
use pathtracer::render::{RenderSettings, render};
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Material, Object, Scene};

const WIDTH: u32 = 12;
const HEIGHT: u32 = 9;

fn settings(integrator: Integrator, light_paths: bool, spp: u32, seed: u64) -> RenderSettings {
    RenderSettings {
        width: WIDTH,
        height: HEIGHT,
        spp,
        seed,
        threads: None,
        integrator,
        max_depth: MAX_DEPTH,
        sampler: SamplerKind::Independent,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths,
        look: Default::default(),
        dispersion: None,
    }
}

/// Per run: pixel values (channel averages), row-major from the top.
fn runs(
    scene: &Scene,
    integrator: Integrator,
    light_paths: bool,
    spp: u32,
    count: u64,
) -> Vec<Vec<f64>> {
    common::independent_runs(
        scene,
        &settings(integrator, light_paths, spp, 0),
        500,
        count,
    )
}

/// Asserts that two sets of runs agree in the image mean and in the pixels
/// of `pixels`.
fn assert_agree(name: &str, a: &[Vec<f64>], b: &[Vec<f64>], pixels: &[(usize, usize)]) {
    let check = |what: String, f: &dyn Fn(&[f64]) -> f64| {
        let (ma, sa) = statistic(a, f);
        let (mb, sb) = statistic(b, f);
        let combined = (sa * sa + sb * sb).sqrt();
        println!("{name} {what}: {ma:.5} ± {sa:.5} vs {mb:.5} ± {sb:.5}");
        assert!(
            (ma - mb).abs() <= 4.0 * combined + 1e-12,
            "{name} {what}: {ma} ± {sa} vs {mb} ± {sb}"
        );
    };
    check("image mean".into(), &|p: &[f64]| {
        p.iter().sum::<f64>() / p.len() as f64
    });
    for &(x, y) in pixels {
        check(format!("pixel ({x}, {y})"), &move |p: &[f64]| {
            p[y * WIDTH as usize + x]
        });
    }
}

/// Sum over pixels of the variance of the per-run values.
fn total_variance(runs: &[Vec<f64>]) -> f64 {
    (0..runs[0].len())
        .map(|i| {
            let (_, error) = statistic(runs, |p| p[i]);
            error * error * runs.len() as f64
        })
        .sum()
}

fn material(color: f64, diffuse: f64, specular: f64, refract: f64) -> Material {
    Material {
        color: Color::gray(color),
        diffuse,
        specular,
        refract,
        ..Material::default()
    }
}

fn sphere(center: Vec3, radius: f64, motion: Vec3, material: usize) -> Object {
    Object::Sphere {
        center,
        radius,
        motion,
        material,
    }
}

/// The caustic box; `moving` sets the glass ball moving over the shutter
/// and `lens` gives the camera a thin lens.
fn caustic_box(moving: bool, lens: bool) -> Scene {
    let materials = vec![
        material(0.7, 1.0, 0.0, 0.0), // 0 walls
        Material {
            color: Color::BLACK,
            emission: Color::gray(60.0),
            ..Material::default()
        }, // 1 small light
        material(0.95, 0.0, 0.0, 1.0), // 2 glass
        material(0.95, 0.0, 1.0, 0.0), // 3 mirror
        material(0.8, 0.5, 0.5, 0.0), // 4 half mirror
        Material {
            color: Color::BLACK,
            emission: Color::new(3.0, 2.0, 1.0),
            ..Material::default()
        }, // 5 two-sided triangle light
    ];
    let plane = |normal: Vec3, offset: f64| Object::Plane {
        normal,
        offset,
        material: 0,
    };
    let motion = if moving {
        Vec3::new(0.3, 0.0, 0.0)
    } else {
        Vec3::zeros()
    };
    let objects = vec![
        plane(Vec3::y(), -2.0),
        plane(Vec3::y(), 2.0),
        plane(Vec3::x(), -2.0),
        plane(Vec3::x(), 2.0),
        plane(Vec3::z(), -8.0),
        plane(Vec3::z(), 1.0),
        sphere(Vec3::new(0.2, 1.5, -5.0), 0.2, Vec3::zeros(), 1),
        sphere(Vec3::new(0.5, -0.5, -5.0), 0.6, motion, 2),
        sphere(Vec3::new(-0.9, -1.3, -4.5), 0.5, Vec3::zeros(), 3),
        sphere(Vec3::new(0.0, -1.6, -6.5), 0.4, Vec3::zeros(), 4),
        Object::Triangle {
            vertices: [
                Point3::new(-1.5, 0.5, -7.5),
                Point3::new(-0.9, 0.5, -7.9),
                Point3::new(-1.2, 1.2, -7.7),
            ],
            material: 5,
        },
    ];
    let mut scene = common::scene_with(materials, Object::Group(objects));
    scene.camera.direction = Vec3::new(0.0, -0.35, -1.0);
    if lens {
        scene.camera.lens_radius = 0.08;
        scene.camera.focus_distance = 5.0;
    }
    scene
}

/// Pixels on the floor under and beside the glass ball, and on the mirror.
const CAUSTIC_PIXELS: [(usize, usize); 4] = [(7, 7), (6, 8), (3, 6), (8, 5)];

#[test]
fn light_paths_keep_the_expected_image_and_cut_the_noise() {
    let scene = caustic_box(false, false);
    let with = runs(&scene, Integrator::Path, true, 64, 40);
    let without = runs(&scene, Integrator::Path, false, 64, 40);
    let original = runs(&scene, Integrator::Original, true, 256, 40);
    assert_agree(
        "with / without light paths",
        &with,
        &without,
        &CAUSTIC_PIXELS,
    );
    assert_agree(
        "with light paths / original",
        &with,
        &original,
        &CAUSTIC_PIXELS,
    );
    let ratio = total_variance(&without) / total_variance(&with);
    println!("variance without / with light paths: {ratio:.2}");
    assert!(ratio > 1.4, "light paths only cut the variance {ratio:.2}x");
}

#[test]
fn light_paths_agree_with_motion_blur_and_depth_of_field() {
    let scene = caustic_box(true, true);
    let with = runs(&scene, Integrator::Path, true, 64, 40);
    let without = runs(&scene, Integrator::Path, false, 64, 40);
    assert_agree(
        "moving, lens: with / without",
        &with,
        &without,
        &CAUSTIC_PIXELS,
    );
}

#[test]
fn splats_give_the_same_image_for_any_thread_count() {
    let mut one = settings(Integrator::Path, true, 16, 3);
    one.sampler = SamplerKind::Sobol;
    one.threads = Some(1);
    let two = RenderSettings {
        threads: Some(2),
        ..one.clone()
    };
    let scene = common::ready(caustic_box(true, true), &one);
    let (a, _) = render(&scene, &one).expect("renders");
    let (b, _) = render(&scene, &two).expect("renders");
    assert!(a.pixels == b.pixels, "1 and 2 threads differ");
    let (c, _) = common::render_scene(
        &caustic_box(true, true),
        &RenderSettings {
            light_paths: false,
            ..one
        },
    )
    .expect("renders");
    assert!(a.pixels != c.pixels, "light paths changed nothing");
}
