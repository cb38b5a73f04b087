//! Adaptive sampling stops where the error target is met, runs to the cap
//! where it is not, keeps the sample sequence of a fixed-spp render, and a
//! time budget stops the render between passes.

mod common;

use pathtracer::color::Color;
use pathtracer::film::Film;
use pathtracer::integrator::Integrator;
use pathtracer::math::Vec3;
use pathtracer::render::adaptive::{MIN_SAMPLES, StoppingRule, progress_for};
use pathtracer::render::{RenderSettings, RenderStats, Renderer, render_into};
use pathtracer::render_scene::RenderScene;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Material, Object, Scene};

/// Left half of the view: a noiseless emissive wall (black albedo ends every
/// path at once). Right half: a diffuse wall lit by a small emitter (noisy).
fn half_and_half() -> Scene {
    let materials = vec![
        Material {
            color: Color::BLACK,
            emission: Color::gray(1.0),
            ..Material::default()
        },
        Material {
            color: Color::gray(0.8),
            ..Material::default()
        },
        Material {
            color: Color::BLACK,
            emission: Color::gray(50.0),
            ..Material::default()
        },
    ];
    let root = Object::Group(vec![
        Object::Rectangle {
            origin: Vec3::new(-10.0, -10.0, -5.0),
            edge_u: Vec3::new(10.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 20.0, 0.0),
            material: 0,
        },
        Object::Rectangle {
            origin: Vec3::new(0.0, -10.0, -5.0),
            edge_u: Vec3::new(10.0, 0.0, 0.0),
            edge_v: Vec3::new(0.0, 20.0, 0.0),
            material: 1,
        },
        Object::Sphere {
            center: Vec3::new(4.0, 0.0, -3.5),
            radius: 1.0,
            motion: Vec3::zeros(),
            material: 2,
        },
    ]);
    let mut scene = common::scene_with(materials, root);
    scene.camera.width = 16;
    scene.camera.height = 8;
    scene
}

fn settings(spp: u32, threads: usize) -> RenderSettings {
    RenderSettings {
        width: 16,
        height: 8,
        spp,
        seed: 3,
        threads: Some(threads),
        integrator: Integrator::Original,
        max_depth: 5,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Default::default(),
        dispersion: None,
    }
}

#[test]
fn noiseless_pixels_stop_early_and_noisy_ones_run_to_the_cap() {
    let scene = common::ready(half_and_half(), &settings(1, 1));
    let rule = StoppingRule {
        target_error: Some(1e-4),
        time_budget: None,
    };
    let mut film = Film::new(16, 8);
    render_adaptively(&scene, &settings(256, 2), rule, &mut film).unwrap();
    for row in film.pixels.chunks(16) {
        for (x, pixel) in row.iter().enumerate() {
            if x < 6 {
                assert_eq!(pixel.samples, MIN_SAMPLES, "constant pixel {x}");
                assert!((pixel.mean().r - 1.0).abs() < 1e-12);
            } else if x > 9 {
                assert_eq!(pixel.samples, 256, "noisy pixel {x}");
            }
        }
    }
}

#[test]
fn adaptive_pixels_equal_fixed_spp_pixels_with_the_same_count() {
    let scene = common::ready(half_and_half(), &settings(1, 1));
    let rule = StoppingRule {
        target_error: Some(0.05),
        time_budget: None,
    };
    let mut adaptive = Film::new(16, 8);
    render_adaptively(&scene, &settings(128, 1), rule, &mut adaptive).unwrap();
    let mut twin = Film::new(16, 8);
    render_adaptively(&scene, &settings(128, 2), rule, &mut twin).unwrap();
    for (a, b) in adaptive.pixels.iter().zip(&twin.pixels) {
        assert_eq!(a.samples, b.samples);
        assert_eq!(a.sum, b.sum, "thread count changed an adaptive image");
    }
    // Each pixel's value is the fixed-spp value of its own sample count.
    for spp in [16, 32, 64, 128] {
        let mut fixed = Film::new(16, 8);
        render_into(&scene, &settings(spp, 2), &mut fixed, 0..spp).unwrap();
        for (a, f) in adaptive.pixels.iter().zip(&fixed.pixels) {
            if a.samples == spp {
                assert_eq!(a.sum, f.sum);
            }
        }
    }
}

#[test]
fn an_exhausted_time_budget_stops_after_the_first_pass() {
    let scene = common::ready(half_and_half(), &settings(1, 1));
    let rule = StoppingRule {
        target_error: None,
        time_budget: Some(0.0),
    };
    let mut film = Film::new(16, 8);
    let stats = render_adaptively(&scene, &settings(1024, 2), rule, &mut film).unwrap();
    assert_eq!(stats.samples, 16 * 8 * MIN_SAMPLES as u64);
}

/// An adaptive render with a renderer of its own.
fn render_adaptively(
    scene: &RenderScene,
    settings: &RenderSettings,
    rule: StoppingRule,
    film: &mut Film,
) -> Result<RenderStats, String> {
    let progress = progress_for(film, settings.spp, rule);
    let renderer = Renderer::new(scene, settings, progress)?;
    pathtracer::render::adaptive::render_adaptive(&renderer, rule, film)
}
