//! The `yao` look (yao-jz's progressive photon mapping,
//! `../shared/docs/looks.md`), one test per fact that changes pixels: its
//! files detected; the light of point lights by photons, cone-weighted,
//! with its brightness, radius and energy schedules and the division by
//! the camera rays so far; emitters seen times the round's energy; every
//! branch of a material followed at once; a black background; view points
//! lit from the front only; diffuse photons leaving from just off the
//! surface on its normal's side, whichever way they go.

mod common;

use std::path::Path;

use pathtracer::image_io::Image;
use pathtracer::integrator::Integrator;
use pathtracer::integrator::sppm::PhotonSettings;
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::render::photon_passes;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

/// A camera at the origin looking down -z at an 8x8 image, 10 degrees.
const CAMERA: &str =
    "PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 10 width 8 height 8 }\n";

/// Renders yao's `text` (`--spp 40`: 5 rounds) as `render` does.
fn render(name: &str, text: &str) -> Image {
    let dir = common::fresh_dir(&format!("yao_{name}"));
    let path = dir.join("scene.txt");
    std::fs::write(&path, text).expect("writes");
    let scene = load_scene(&path, &LoadOptions::default()).expect("builds");
    let (look, why) = Look::detect(&scene);
    assert_eq!(look.name, "yao", "{why}");
    let settings = RenderSettings {
        width: 8,
        height: 8,
        spp: 40,
        seed: 1,
        threads: None,
        integrator: look.integrator,
        max_depth: look.max_depth,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    };
    let ready = common::ready(scene, &settings);
    let (image, stats) = photon_passes::render(&ready, &settings, PhotonSettings::default(), false)
        .expect("renders");
    assert_eq!(stats.samples, 5 * 8 * 64, "5 rounds of 8 rays per pixel");
    image
}

/// The camera's energy summed over 5 rounds, each over the rays so far:
/// `sum_k (1 / ln 5) 0.95^-(k-1) / k`.
fn seen_sum() -> f64 {
    (1..=5)
        .map(|k| 1.0 / 5f64.ln() / 0.95f64.powi(k - 1) / k as f64)
        .sum()
}

fn assert_every_pixel(image: &Image, want: f64) {
    for pixel in &image.pixels {
        assert!((pixel.average() - want).abs() < 1e-9, "{pixel:?} vs {want}");
    }
}

#[test]
fn yao_files_are_detected_by_dialect_and_its_framework_files_by_folder() {
    let text = format!(
        "{CAMERA}Materials {{ numMaterials 1 Material {{ color 1 1 1 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 -5 radius 1 }} }}"
    );
    render("dialect", &text);
    for (folder, look) in [
        ("yao-jz+Computer-Graphics-THU", "yao"),
        ("Tschal-rsa+rang-kardan", "tsc"),
    ] {
        let dir = common::fresh_dir("yao_folders")
            .join(folder)
            .join("testcases");
        std::fs::create_dir_all(&dir).expect("makes the folder");
        let path = dir.join("pa1.txt");
        let pa1 = format!(
            "{CAMERA}Materials {{ numMaterials 1 Material {{ diffuseColor 1 0 0 specularColor 1 1 1 shininess 20 }} }}
Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 -5 radius 1 }} }}"
        );
        std::fs::write(&path, pa1).expect("writes");
        let scene = load_scene(Path::new(&path), &LoadOptions::default()).expect("builds");
        assert_eq!(Look::detect(&scene).0.name, look, "{folder}");
        assert_eq!(Look::detect(&scene).0.integrator, Integrator::Sppm);
    }
}

/// A grey wall 5 ahead and a white point light at `light_z` (35 behind
/// the camera, or 45 behind the wall), rendered by yao's look; the mean
/// of its pixels.
fn lit_wall(name: &str, light_z: f64) -> f64 {
    let text = format!(
        "{CAMERA}Lights {{ numLights 1 PointLight {{ position 0 0 {light_z} color 1 1 1 brightness 1 }} }}
Background {{ color 0 0 0 }}
Materials {{ numMaterials 1 Material {{ color 0.5 0.5 0.5 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 0 1 offset -5 }} }}"
    );
    let image = render(name, &text);
    image.pixels.iter().map(|p| p.average()).sum::<f64>() / image.pixels.len() as f64
}

/// What the photons that land on the wall's front give a view point on
/// the axis, summed over the rounds: per round k, from photons of energy
/// 1800 / P landing with density P / (4 pi 40^2) near the axis, `1800
/// (r^2 pi / 6) / (4 pi 40^2) x 0.5 x e_k` (the cone ((r - d) / r)^2
/// integrates to pi r^2 / 6), with r_k = 5 x 0.95^(k-1) and e_k =
/// 0.95^-(k-1) / ln 5; each round's 8 view points are summed and divided
/// by the 8 k rays so far.
fn front_landings() -> f64 {
    let distance: f64 = 40.0;
    (1..=5)
        .map(|k| {
            let r = 5.0 * 0.95f64.powi(k - 1);
            let energy = 1.0 / 5f64.ln() / 0.95f64.powi(k - 1);
            1800.0 * (r * r / 6.0) / (4.0 * distance * distance) * 0.5 * energy / k as f64
        })
        .sum()
}

/// A photon leaves a diffuse hit from 1e-4 along the wall's normal, in
/// the direction `normalize(n * u) sin(phi) + n cos(phi)`: for a wall
/// facing +z that is along +z or -z, and through the wall (-z) when `u`
/// points back (half the time) and `phi` passes 45 degrees (cos phi is
/// uniform: 1 / sqrt 2 of the time), so with probability 0.5 / sqrt 2.
/// Going through, it meets the wall again from the front a hair away and
/// lands there once more, its colour times 0.5 and its share divided by
/// its landings so far + 1, up to its 6th hit. The factor of landing `k`
/// over the first.
fn relanding(k: i32) -> f64 {
    let through = 0.5 / 2f64.sqrt();
    (through * 0.5).powi(k) / (k + 1) as f64
}

#[test]
fn a_point_lights_photons_light_a_wall_by_the_cone_weighted_sums() {
    // Lit from the front: the first landing and the photons that go
    // through the wall and land again.
    let got = lit_wall("wall", 35.0);
    let want = front_landings() * (0..=5).map(relanding).sum::<f64>();
    // Off the axis the density falls by at most 2% within the cone.
    assert!((got - want).abs() < 0.06 * want, "{got} vs {want}");
}

#[test]
fn view_points_take_photons_from_the_front_only() {
    // Lit from behind: photons reach the wall's back, where the view
    // points (facing the camera) do not take them; those that leave from
    // the front side (the wall's normal) through the wall land on its
    // front. Were the first landing taken, the wall would be 11 times as
    // bright.
    let got = lit_wall("behind", -45.0);
    let want = front_landings() * (1..=5).map(relanding).sum::<f64>();
    assert!((got - want).abs() < 0.06 * want, "{got} vs {want}");
}

#[test]
fn an_emitter_seen_adds_its_emission_times_the_rounds_energy() {
    let text = format!(
        "{CAMERA}Materials {{ numMaterials 1 Material {{ color 0 0 0 emissionColor 0.5 0.5 0.5 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 0 1 offset -5 }} }}"
    );
    assert_every_pixel(&render("emitter", &text), 0.5 * seen_sum());
}

#[test]
fn every_branch_of_a_material_is_followed_at_once() {
    // Half mirror, half diffuse: the mirror half of every camera ray sees
    // the emitter behind the camera; the diffuse half gets no photons (no
    // point light). Choosing one branch at random would give each ray all
    // or nothing.
    let text = format!(
        "{CAMERA}Materials {{ numMaterials 2
  Material {{ color 1 1 1 diff 0.5 refl 0.5 refr 0 }}
  Material {{ color 0 0 0 emissionColor 0.5 0.5 0.5 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 2 MaterialIndex 0 Plane {{ normal 0 0 1 offset -5 }}
  MaterialIndex 1 Plane {{ normal 0 0 -1 offset -5 }} }}"
    );
    assert_every_pixel(&render("branches", &text), 0.5 * 0.5 * seen_sum());
}

#[test]
fn a_miss_is_black_whatever_the_background() {
    let text = format!(
        "{CAMERA}Background {{ color 1 1 1 }}
Materials {{ numMaterials 1 Material {{ color 1 1 1 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 5 radius 1 }} }}"
    );
    assert_every_pixel(&render("miss", &text), 0.0);
}

#[test]
fn its_five_rounds_are_rendered_whatever_spp_asks() {
    // yao-jz's rounds are fixed in its code (5 of 8 camera rays): `render
    // --spp 64` renders 40 per pixel and says so, `--spp 40` says nothing.
    let dir = common::fresh_dir("yao_rounds");
    let text = format!(
        "{CAMERA}Lights {{ numLights 1 PointLight {{ position 0 0 35 color 1 1 1 brightness 1 }} }}
Materials {{ numMaterials 1 Material {{ color 0.5 0.5 0.5 diff 1 refl 0 refr 0 }} }}
Group {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 0 1 offset -5 }} }}"
    );
    std::fs::write(dir.join("scene.txt"), text).expect("writes");
    let run = |spp: &str, output: &str| {
        let args = ["render", "scene.txt", "--spp", spp, "--quiet", "-o", output];
        let ran = common::finish(common::command_in(&dir, &args));
        assert_eq!(ran.code, Some(0), "{}", ran.stderr);
        (
            ran.stderr,
            std::fs::read(dir.join(output)).expect("written"),
        )
    };
    let (asked_64, image_64) = run("64", "a.pfm");
    assert!(
        asked_64.contains("traces 40 camera rays per pixel") && asked_64.contains("64 asked"),
        "{asked_64}"
    );
    let (asked_40, image_40) = run("40", "b.pfm");
    assert!(!asked_40.contains("camera rays per pixel"), "{asked_40}");
    assert_eq!(image_64, image_40, "the same 5 rounds");
}
