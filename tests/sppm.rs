//! Stochastic progressive photon mapping (`--integrator sppm`), tested by
//! its properties: the same image for any thread count; the path
//! integrator's image on a diffuse scene and on a glass caustic, in the
//! image mean (within 2 standard errors of independent runs) and tile by
//! tile; the white furnace's known radiance; the photons of a pass carrying
//! the emitters' power.

mod common;

use std::f64::consts::PI;

use common::{mean_and_error, ready};
use pathtracer::color::Color;
use pathtracer::image_io::Image;
use pathtracer::integrator::Integrator;
use pathtracer::integrator::sppm::{PhotonSettings, photon};
use pathtracer::look::Look;
use pathtracer::math::{Point3, Vec3};
use pathtracer::photon_render;
use pathtracer::render::{RenderSettings, render};
use pathtracer::sampler::{Sampler, SamplerKind};
use pathtracer::scene::model::{Material, Object, Scene};

fn settings(integrator: Integrator, size: u32, spp: u32, seed: u64) -> RenderSettings {
    RenderSettings {
        width: size,
        height: size,
        spp,
        seed,
        threads: None,
        integrator,
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

fn photon_mapped(scene: &Scene, settings: &RenderSettings, photons: u64, radius: f64) -> Image {
    let ready = ready(scene.clone(), settings);
    let photons = PhotonSettings {
        photons_per_pass: Some(photons),
        initial_radius: Some(radius),
        ..PhotonSettings::default()
    };
    let (image, stats) = photon_render::render(&ready, settings, photons, false).expect("renders");
    assert_eq!(stats.dropped, 0, "NaN or infinite samples");
    image
}

fn path_traced(scene: &Scene, settings: &RenderSettings) -> Image {
    let (image, stats) = render(&ready(scene.clone(), settings), settings).expect("renders");
    assert_eq!(stats.dropped, 0);
    image
}

fn diffuse(grey: f64) -> Material {
    Material {
        color: Color::gray(grey),
        ..Material::default()
    }
}

fn light(radiance: f64) -> Material {
    Material {
        color: Color::BLACK,
        emission: Color::gray(radiance),
        ..Material::default()
    }
}

fn plane(normal: Vec3, offset: f64, material: usize) -> Object {
    Object::Plane {
        normal,
        offset,
        material,
    }
}

fn sphere(center: Point3, radius: f64, material: usize) -> Object {
    Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    }
}

/// A box around the camera at the origin looking down -z (x, y in [-2, 2],
/// z in [-8, 1]); walls grey (0), red (1), green (2); a sphere light (3).
fn diffuse_box() -> Scene {
    let materials = vec![
        diffuse(0.7),
        Material {
            color: Color::new(0.75, 0.25, 0.25),
            ..Material::default()
        },
        Material {
            color: Color::new(0.25, 0.75, 0.25),
            ..Material::default()
        },
        light(20.0),
    ];
    let objects = vec![
        plane(Vec3::y(), -2.0, 0),
        plane(Vec3::y(), 2.0, 0),
        plane(Vec3::x(), -2.0, 1),
        plane(Vec3::x(), 2.0, 2),
        plane(Vec3::z(), -8.0, 0),
        plane(Vec3::z(), 1.0, 0),
        sphere(Point3::new(0.0, 1.4, -5.0), 0.35, 3),
        sphere(Point3::new(-0.6, -1.3, -5.5), 0.7, 0),
    ];
    let mut scene = Scene::new(materials, Object::Group(objects));
    scene.camera.fov = None;
    scene
}

/// The diffuse box with a glass ball under the light: a caustic on the floor.
fn caustic_box() -> Scene {
    let mut scene = diffuse_box();
    scene.materials.push(Material {
        color: Color::gray(0.999),
        diffuse: 0.0,
        refract: 1.0,
        ior: 1.5,
        ..Material::default()
    });
    if let Object::Group(objects) = &mut scene.root {
        objects[7] = sphere(Point3::new(0.3, -1.0, -5.0), 0.8, 4);
    }
    scene
}

/// Image means (channel averages) of `images`, and per tile of `tile`
/// pixels a side.
fn tile_means(image: &Image, tile: usize) -> Vec<f64> {
    let mut means = Vec::new();
    for ty in (0..image.height).step_by(tile) {
        for tx in (0..image.width).step_by(tile) {
            let mut sum = 0.0;
            let mut count = 0.0;
            for y in ty..(ty + tile).min(image.height) {
                for x in tx..(tx + tile).min(image.width) {
                    sum += image.pixels[y * image.width + x].average();
                    count += 1.0;
                }
            }
            means.push(sum / count);
        }
    }
    means
}

fn image_mean(image: &Image) -> f64 {
    image.pixels.iter().map(Color::average).sum::<f64>() / image.pixels.len() as f64
}

/// Runs of SPPM and of the path integrator agree: the image mean within 2
/// combined standard errors, every tile's mean within `tolerance` of the
/// path integrator's (relative, plus a floor for dark tiles).
fn assert_converges_to_path(name: &str, scene: &Scene, tolerance: f64) {
    const RUNS: u64 = 8;
    const SIZE: u32 = 16;
    let sppm_runs: Vec<Image> = (0..RUNS)
        .map(|seed| {
            let settings = settings(Integrator::Sppm, SIZE, 32, 1000 + seed);
            photon_mapped(scene, &settings, 20_000, 0.1)
        })
        .collect();
    let path_runs: Vec<Image> = (0..RUNS)
        .map(|seed| path_traced(scene, &settings(Integrator::Path, SIZE, 64, 2000 + seed)))
        .collect();
    let (a, sa) = mean_and_error(&sppm_runs.iter().map(image_mean).collect::<Vec<_>>());
    let (b, sb) = mean_and_error(&path_runs.iter().map(image_mean).collect::<Vec<_>>());
    println!("{name}: image mean sppm {a:.5} ± {sa:.5}, path {b:.5} ± {sb:.5}");
    assert!(
        (a - b).abs() <= 2.0 * (sa * sa + sb * sb).sqrt(),
        "{name}: image mean sppm {a} ± {sa} vs path {b} ± {sb}"
    );
    let tiles = |runs: &[Image]| {
        let per_run: Vec<Vec<f64>> = runs.iter().map(|i| tile_means(i, 4)).collect();
        (0..per_run[0].len())
            .map(|t| per_run.iter().map(|r| r[t]).sum::<f64>() / runs.len() as f64)
            .collect::<Vec<f64>>()
    };
    let (ours, theirs) = (tiles(&sppm_runs), tiles(&path_runs));
    for (t, (x, y)) in ours.iter().zip(&theirs).enumerate() {
        println!("{name}: tile {t}: sppm {x:.4}, path {y:.4}");
        assert!(
            (x - y).abs() <= tolerance * y + 0.01,
            "{name}: tile {t}: sppm {x} vs path {y}"
        );
    }
}

#[test]
fn sppm_converges_to_the_path_integrator_on_a_diffuse_scene() {
    assert_converges_to_path("diffuse box", &diffuse_box(), 0.08);
}

#[test]
fn sppm_converges_to_the_path_integrator_on_a_glass_caustic() {
    assert_converges_to_path("caustic box", &caustic_box(), 0.12);
}

#[test]
fn sppm_images_do_not_depend_on_the_thread_count() {
    let scene = caustic_box();
    let image = |threads: usize| {
        let mut settings = settings(Integrator::Sppm, 24, 3, 5);
        settings.threads = Some(threads);
        photon_mapped(&scene, &settings, 5_000, 0.3)
    };
    let one = image(1);
    assert!(image_mean(&one) > 0.0);
    for (a, b) in one.pixels.iter().zip(&image(2).pixels) {
        assert_eq!((a.r, a.g, a.b), (b.r, b.g, b.b));
    }
}

/// A closed cube of emissive diffuse rectangles around the camera.
fn furnace(albedo: f64, emission: f64) -> Scene {
    let materials = vec![Material {
        color: Color::gray(albedo),
        emission: Color::gray(emission),
        ..Material::default()
    }];
    let s = 2.0;
    let face = |origin: Point3, edge_u: Vec3, edge_v: Vec3| Object::Rectangle {
        origin,
        edge_u,
        edge_v,
        material: 0,
    };
    let (x, y, z) = (
        Vec3::x() * 2.0 * s,
        Vec3::y() * 2.0 * s,
        Vec3::z() * 2.0 * s,
    );
    let low = Point3::new(-s, -s, -s);
    let high = Point3::new(s, s, s);
    let objects = vec![
        face(low, x, y),
        face(low, y, z),
        face(low, z, x),
        face(high, -x, -y),
        face(high, -y, -z),
        face(high, -z, -x),
    ];
    let mut scene = Scene::new(materials, Object::Group(objects));
    scene.camera.fov = None;
    scene
}

#[test]
fn sppm_furnace_returns_the_geometric_series_of_its_albedo() {
    let (albedo, emission) = (0.6, 1.0);
    let scene = furnace(albedo, emission);
    let settings = settings(Integrator::Sppm, 16, 16, 3);
    let image = photon_mapped(&scene, &settings, 40_000, 0.2);
    // Emission seen through at most five scattering vertices.
    let want: f64 = (0..=5).map(|k| emission * albedo.powi(k)).sum();
    let mean = image_mean(&image);
    println!("furnace: mean {mean:.5}, expected {want:.5}");
    assert!((mean - want).abs() < 0.02 * want, "{mean} vs {want}");
    for pixel in &image.pixels {
        assert!((pixel.average() - want).abs() < 0.1 * want, "{pixel:?}");
    }
}

#[test]
fn the_photons_of_a_pass_carry_the_emitters_power() {
    // A sphere light and a two-sided rectangle light of other colours.
    let materials = vec![
        Material {
            color: Color::BLACK,
            emission: Color::new(4.0, 2.0, 1.0),
            ..Material::default()
        },
        Material {
            color: Color::BLACK,
            emission: Color::new(0.5, 1.0, 3.0),
            ..Material::default()
        },
    ];
    let (radius, edge) = (0.5, 1.5);
    let objects = vec![
        sphere(Point3::new(0.0, 0.0, -5.0), radius, 0),
        Object::Rectangle {
            origin: Point3::new(2.0, -1.0, -6.0),
            edge_u: Vec3::x() * edge,
            edge_v: Vec3::y() * edge,
            material: 1,
        },
    ];
    let scene = Scene::new(materials.clone(), Object::Group(objects));
    let settings = settings(Integrator::Sppm, 8, 1, 0);
    let ready = ready(scene, &settings);
    // Power: pi L A for the sphere, pi L A on each side of the rectangle.
    let power = materials[0].emission * (PI * 4.0 * PI * radius * radius)
        + materials[1].emission * (2.0 * PI * edge * edge);
    let unit = ready.emitters().photon_power_unit();
    let count = 200_000;
    let mut sum = Color::BLACK;
    for i in 0..count {
        let mut sampler = Sampler::new(SamplerKind::Sobol, 0, i, 9);
        let (_, photon_power) = photon::emit(&ready, &mut sampler, 0.0).expect("emits");
        sum += photon_power * unit;
    }
    let mean = sum / count as f64;
    println!("photon power {mean:?}, emitted {power:?}");
    for (got, want) in [(mean.r, power.r), (mean.g, power.g), (mean.b, power.b)] {
        assert!((got - want).abs() < 0.01 * want, "{got} vs {want}");
    }
}

#[test]
fn tschals_look_clamps_an_emitter_seen_directly_to_one_per_sample() {
    // The camera sees only a black sphere light of emission 12.
    let scene = Scene::new(
        vec![light(12.0)],
        Object::Group(vec![sphere(Point3::new(0.0, 0.0, -5.0), 3.0, 0)]),
    );
    for (look, want) in [(Look::TSC, 1.0), (Look::ORIGINAL, 12.0)] {
        let mut settings = settings(Integrator::Sppm, 4, 2, 0);
        settings.look = look;
        let image = photon_mapped(&scene, &settings, 1_000, 0.1);
        for pixel in &image.pixels {
            assert!(
                (pixel.average() - want).abs() < 1e-9,
                "{}: {pixel:?}",
                look.name
            );
        }
    }
}

#[test]
fn the_photon_mapping_looks_are_named_and_tschals_files_detected() {
    for name in ["tsc", "jms", "alz-sppm", "yzc-sppm"] {
        let look = Look::from_name(name).expect("a look of that name");
        assert_eq!(look.integrator, Integrator::Sppm, "{name}");
        assert!(look.photons.is_some(), "{name}");
    }
    let text =
        "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }
Materials { numMaterials 1 Material { color 0.5 0.5 0.5 prop Matte } }
Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } }";
    let dir = common::fresh_dir("sppm_tsc_detection");
    let path = dir.join("prop.txt");
    std::fs::write(&path, text).expect("writes");
    let scene = pathtracer::scene::load_scene(&path, &Default::default()).expect("builds");
    assert_eq!(Look::detect(&scene).0.name, "tsc");
}

#[test]
fn a_photon_looks_direct_light_comes_from_its_photons_alone() {
    // A grey wall at z = -5 facing the camera, lit by a disk light of
    // radius 20 behind the camera, 80 away, facing it: in Tschal-rsa's
    // look a photon of power emission x 1000 lands near the axis with
    // density 1 / (pi (h^2 + R^2)) per unit area, and the wall reflects
    // `colour x power` of each one. A light sample at the visible point
    // would add the physical direct light, 0.353 more (2.3x), as it did
    // before 2026-12-06 (docs/sppm.md, "Tschal-rsa's brightness").
    let (grey, emission, height, disk) = (0.5, 12.0, 80.0, 20.0);
    let scene = Scene::new(
        vec![diffuse(grey), light(emission)],
        Object::Group(vec![
            plane(Vec3::z(), -5.0, 0),
            Object::Disk {
                center: Point3::new(0.0, 0.0, height - 5.0),
                normal: -Vec3::z(),
                radius: disk,
                material: 1,
            },
        ]),
    );
    let mut settings = settings(Integrator::Sppm, 8, 8, 3);
    settings.look = Look::TSC;
    let image = photon_mapped(&scene, &settings, 1_000_000, 1.0);
    let centre: Vec<f64> = [(3, 3), (3, 4), (4, 3), (4, 4)]
        .iter()
        .map(|&(x, y)| image.pixels[y * image.width + x].average())
        .collect();
    let got = centre.iter().sum::<f64>() / centre.len() as f64;
    let want = grey * emission * 1000.0 / (PI * (height * height + disk * disk));
    assert!((got - want).abs() < 0.05 * want, "{got} vs {want}");
}

#[test]
fn tschals_photons_are_gathered_at_their_first_six_hits_only() {
    // In a closed white furnace no photon escapes: with 20 scattering
    // vertices allowed, this renderer's photons reach their 7th hit and
    // beyond, Tschal-rsa's stop adding at their 6th (its roulette then
    // divides their power by thousands).
    let scene = furnace(0.999, 1.0);
    let mut deepest = Vec::new();
    for look in [Look::TSC, Look::ORIGINAL] {
        let mut settings = settings(Integrator::Sppm, 4, 1, 0);
        settings.look = look;
        settings.max_depth = 20;
        let ready = ready(scene.clone(), &settings);
        let mut last = 0;
        for i in 0..2_000 {
            let mut sampler = Sampler::new(SamplerKind::Sobol, 0, i, 5);
            photon::trace(&ready, &mut sampler, 0.0, &mut |hit| {
                last = last.max(hit.bounces);
            });
        }
        deepest.push(last);
    }
    // `bounces` counts the scattering before a hit: 5 before the 6th.
    assert_eq!(deepest[0], 5, "tsc");
    assert!(deepest[1] > 5, "original: {}", deepest[1]);
}

#[test]
fn tschals_look_writes_the_square_root_of_its_average() {
    // Its image writer stores clamp(sqrt(c)): a quarter is written as a half.
    assert_eq!(Look::TSC.output.apply_channel(0.25), 0.5);
    assert_eq!(Look::TSC.output.apply_channel(4.0), 1.0);
    assert_eq!(Look::ORIGINAL.output.apply_channel(0.25), 0.25);
}
