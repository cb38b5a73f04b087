//! The facts of the looks of yangjunx21's (`yjx`) and chen-yingfa's (`cyf`)
//! path tracers, one test per fact that changes pixels, on scenes whose
//! pixels are known in closed form (../shared/docs/looks.md has the facts).

mod common;

use pathtracer::image_io::{Image, read_image_encoded};
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

fn write_scene(name: &str, text: &str) -> std::path::PathBuf {
    let dir = common::fresh_dir(&format!("smallpt-looks-{name}"));
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("writes");
    file
}

/// The linear image of `text` in `look` (no output curve), at `spp`.
fn render_text(name: &str, text: &str, look: Look, spp: u32) -> Image {
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
    let (image, _) = common::render_scene(&scene, &settings).expect("renders");
    std::fs::remove_dir_all(file.parent().expect("a folder")).ok();
    image
}

fn mean(image: &Image) -> f64 {
    let sum: f64 = image.pixels.iter().map(|p| p.r + p.g + p.b).sum();
    sum / (3 * image.pixels.len()) as f64
}

/// A camera at z = 5 looking down -z, 4x4 pixels.
const CAMERA: &str =
    "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }\n";

/// In view, a plane at z = 0 of `material`; behind the camera, a plane at
/// z = 10 facing it that emits 1 and reflects nothing: a white diffuse
/// plane in view reflects 1, a mirror shows 1.
fn plane_under_a_sky(material: &str) -> String {
    format!(
        "{CAMERA}Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 2 Material {{ {material} }} \
         Material {{ color 0 0 0 emission 1 1 1 type 1 0 0 }} }}\n\
         Group {{ numObjects 2 MaterialIndex 0 Plane {{ normal 0 0 1 offset 0 }} \
         MaterialIndex 1 Plane {{ normal 0 0 -1 offset -10 }} }}"
    )
}

/// Nothing but a white background.
const EMPTY_UNDER_WHITE: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 4 height 4 }\nBackground { color 1 1 1 }\n\
     Materials { numMaterials 1 Material { color 1 1 1 type 1 0 0 } }\n\
     Group { numObjects 1 MaterialIndex 0 Sphere { center 100 0 0 radius 1 } }";

/// A plane in view that emits 0.2 and reflects nothing: every pixel 0.2.
const DIM_EMITTER: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 4 height 4 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 1 Material { color 0 0 0 emission 0.2 0.2 0.2 type 1 0 0 } }\n\
     Group { numObjects 1 MaterialIndex 0 Plane { normal 0 0 1 offset 0 } }";

/// The bytes `render --look NAME` writes for [`DIM_EMITTER`] (every pixel
/// the same).
fn written_byte(look: &str) -> u8 {
    let file = write_scene(&format!("written-{look}"), DIM_EMITTER);
    let dir = file.parent().expect("a folder").to_path_buf();
    let ran = common::run_in(
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

#[test]
fn yjx_writes_the_gamma_of_2_2_rounded_to_the_nearest_byte() {
    // 0.2^(1/2.2) * 255 = 122.69: rounded 123 (truncated it would be 122);
    // the framework writer alone stores int(0.2 * 255) = 50 (0.2 * 255 is
    // 50.99... in binary floating point).
    assert_eq!(written_byte("yjx"), 123);
    assert_eq!(written_byte("original"), 50);
}

#[test]
fn cyf_writes_the_square_root() {
    // sqrt(0.2) * 255 = 114.04.
    assert_eq!(written_byte("cyf"), 114);
}

#[test]
fn yjx_and_cyf_misses_are_black_whatever_the_background() {
    for look in [Look::YJX, Look::CYF] {
        let image = render_text("miss", EMPTY_UNDER_WHITE, look, 1);
        assert_eq!(mean(&image), 0.0, "{}", look.name);
    }
    assert_eq!(
        mean(&render_text("miss", EMPTY_UNDER_WHITE, Look::ORIGINAL, 1)),
        1.0
    );
}

#[test]
fn yjx_and_cyf_emitters_end_the_path() {
    // A white diffuse plane that emits 0.1 under the sky: 0.1 + 1 when it
    // also reflects, 0.1 when a hit on it returns its emission only.
    let emitting = plane_under_a_sky("color 1 1 1 emission 0.1 0.1 0.1 type 1 0 0");
    for look in [Look::YJX, Look::CYF] {
        let m = mean(&render_text("emitter", &emitting, look, 4));
        assert!((m - 0.1).abs() < 1e-9, "{}: {m}", look.name);
    }
    let m = mean(&render_text("emitter", &emitting, Look::ORIGINAL, 64));
    assert!((m - 1.1).abs() < 0.05, "original: {m}");
}

#[test]
fn yjx_renders_a_material_neither_wholly_diffuse_nor_wholly_mirror_as_glass() {
    // Half diffuse, half mirror: 0.5 reflected + 0.5 mirrored = 1 in ours;
    // glass of index 1.5 in yangjunx21's, which reflects about 4% of the
    // sky and lets the rest through into the dark half-space behind.
    let mixed = plane_under_a_sky("color 1 1 1 type 0.5 0.5 0");
    let yjx = mean(&render_text("mixed", &mixed, Look::YJX, 256));
    assert!(yjx > 0.02 && yjx < 0.07, "yjx: {yjx}");
    let ours = mean(&render_text("mixed", &mixed, Look::ORIGINAL, 64));
    assert!((ours - 1.0).abs() < 0.05, "original: {ours}");
    // A wholly diffuse material stays diffuse.
    let diffuse = plane_under_a_sky("color 1 1 1 type 1 0 0");
    let m = mean(&render_text("diffuse", &diffuse, Look::YJX, 64));
    assert!((m - 1.0).abs() < 0.05, "yjx diffuse: {m}");
}
