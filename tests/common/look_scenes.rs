//! Helpers for the tests of the looks' facts: a scene's text rendered in
//! a look (linear, no output curve), and the byte `render --look` writes.

use pathtracer::image_io::{Image, read_image_encoded};
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

use super::{fresh_dir, render_scene, run_in};

pub fn write_scene(name: &str, text: &str) -> std::path::PathBuf {
    let dir = fresh_dir(&format!("smallpt-looks-{name}"));
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("writes");
    file
}

/// The linear image of `text` in `look` (no output curve), at `spp`.
pub fn render_text(name: &str, text: &str, look: Look, spp: u32) -> Image {
    let file = write_scene(&format!("{name}-{}", look.name), text);
    let scene = load_scene(&file, &LoadOptions::default()).expect("loads");
    let settings = RenderSettings {
        width: scene.camera.width,
        height: scene.camera.height,
        spp,
        seed: 1,
        threads: Some(1),
        integrator: look.integrator,
        max_depth: look.max_depth,
        sampler: SamplerKind::Independent,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    };
    let (image, _) = render_scene(&scene, &settings).expect("renders");
    std::fs::remove_dir_all(file.parent().expect("a folder")).ok();
    image
}

pub fn mean(image: &Image) -> f64 {
    let sum: f64 = image.pixels.iter().map(|p| p.r + p.g + p.b).sum();
    sum / (3 * image.pixels.len()) as f64
}

/// A camera at z = 5 looking down -z, 4x4 pixels.
pub const CAMERA: &str =
    "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }\n";

/// A plane in view that emits 0.2 and reflects nothing: every pixel 0.2.
pub const DIM_EMITTER: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 4 height 4 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 1 Material { color 0 0 0 emission 0.2 0.2 0.2 type 1 0 0 } }\n\
     Group { numObjects 1 MaterialIndex 0 Plane { normal 0 0 1 offset 0 } }";

/// The bytes `render --look NAME` writes for [`DIM_EMITTER`] (every pixel
/// the same).
pub fn written_byte(look: &str) -> u8 {
    let file = write_scene(&format!("written-{look}"), DIM_EMITTER);
    let dir = file.parent().expect("a folder").to_path_buf();
    let ran = run_in(
        &dir,
        &[
            "render",
            "scene.txt",
            "-o",
            "out.png",
            "--look",
            look,
            "--spp",
            "1",
        ],
    );
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let (image, _) = read_image_encoded(&dir.join("out.png")).expect("reads");
    let bytes: Vec<u8> = image
        .pixels
        .iter()
        .map(|p| (p.g * 255.0).round() as u8)
        .collect();
    std::fs::remove_dir_all(&dir).ok();
    assert!(bytes.iter().all(|&b| b == bytes[0]), "{bytes:?}");
    bytes[0]
}

/// In view, a plane at z = 0 of `material`; behind the camera, a plane at
/// z = 10 facing it that emits 1 and reflects nothing: a white diffuse
/// plane in view reflects 1, a mirror shows 1.
pub fn plane_under_a_sky(material: &str) -> String {
    format!(
        "{CAMERA}Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 2 Material {{ {material} }} \
         Material {{ color 0 0 0 emission 1 1 1 type 1 0 0 }} }}\n\
         Group {{ numObjects 2 MaterialIndex 0 Plane {{ normal 0 0 1 offset 0 }} \
         MaterialIndex 1 Plane {{ normal 0 0 -1 offset -10 }} }}"
    )
}

/// Nothing but a white background.
pub const EMPTY_UNDER_WHITE: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 4 height 4 }\nBackground { color 1 1 1 }\n\
     Materials { numMaterials 1 Material { color 1 1 1 type 1 0 0 } }\n\
     Group { numObjects 1 MaterialIndex 0 Sphere { center 100 0 0 radius 1 } }";

/// The camera inside a closed sphere whose wall reflects `albedo` (white,
/// diffuse) and emits `emission`: every ray hits the wall, and a path of
/// `n` hits gathers `emission (1 + albedo + ... + albedo^(n-1))`, which is
/// `emission / (1 - albedo)` without a depth limit.
pub fn inside_a_glowing_sphere(albedo: f64, emission: f64) -> String {
    format!(
        "{CAMERA}Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 1 Material {{ color {albedo} {albedo} {albedo} \
         emission {emission} {emission} {emission} type 1 0 0 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 0 radius 20 }} }}"
    )
}

/// The camera 5 above a white diffuse floor of `albedo` under a white
/// background, looking straight down: 0 when a miss after a bounce is
/// black, `albedo` when the background is weighted by the path, 1 when it
/// is added unweighted.
pub fn floor_under_white(albedo: f64) -> String {
    format!(
        "PerspectiveCamera {{ center 0 5 0 direction 0 -1 0 up 0 0 -1 angle 30 width 4 height 4 }}\n\
         Background {{ color 1 1 1 }}\n\
         Materials {{ numMaterials 1 Material {{ color {albedo} {albedo} {albedo} type 1 0 0 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 1 0 offset 0 }} }}"
    )
}
