//! The facts of the looks of yangjunx21's (`yjx`) and chen-yingfa's (`cyf`)
//! path tracers, one test per fact that changes pixels, on scenes whose
//! pixels are known in closed form (../shared/docs/looks.md has the facts).

mod common;

use common::{EMPTY_UNDER_WHITE, mean, plane_under_a_sky, render_text, written_byte};
use pathtracer::look::Look;

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

/// The camera 61.6 under a diffuse ceiling at y = 81.6 (yangjunx21's)
/// that reflects 0.5, looking straight up; above the ceiling, out of
/// sight, a plane that emits 1. Everything else is black.
const CEILING_UNDER_A_HIDDEN_LIGHT: &str = "PerspectiveCamera { center 0 20 0 direction 0 1 0 \
     up 0 0 -1 angle 30 width 4 height 4 }\nBackground { color 0 0 0 }\n\
     Materials { numMaterials 2 Material { color 0.5 0.5 0.5 type 1 0 0 } \
     Material { color 0 0 0 emission 1 1 1 type 1 0 0 } }\n\
     Group { numObjects 2 MaterialIndex 0 Plane { normal 0 -1 0 offset -81.6 } \
     MaterialIndex 1 Plane { normal 0 -1 0 offset -90 } }";

#[test]
fn yjx_planes_in_single_precision_let_light_through_from_behind() {
    // A bounce leaves from the hit itself, computed in float: when it
    // rounded to above the ceiling (for a few % of these camera rays), the
    // ceiling is met again from behind and the path scatters up to the
    // light (0.5 x 0.5 = 0.25 of it). In double precision with rays
    // leaving off the surface nothing passes.
    let yjx = mean(&render_text(
        "leak",
        CEILING_UNDER_A_HIDDEN_LIGHT,
        Look::YJX,
        64,
    ));
    assert!(yjx > 0.0005 && yjx < 0.05, "yjx: {yjx}");
    let original = mean(&render_text(
        "leak",
        CEILING_UNDER_A_HIDDEN_LIGHT,
        Look::ORIGINAL,
        64,
    ));
    assert_eq!(original, 0.0);
}

#[test]
fn yjx_draws_independent_samples_unless_told() {
    // Its pixels are clamped averages of few samples, whose noise is that
    // of its single random generator: the default sampler is its own.
    let file = common::write_scene("yjx-sampler", CEILING_UNDER_A_HIDDEN_LIGHT);
    let dir = file.parent().expect("a folder").to_path_buf();
    let render = |extra: &[&str]| {
        let mut args = vec!["render", "scene.txt", "-o", "out.pfm", "--look", "yjx"];
        args.extend_from_slice(extra);
        let ran = common::run_in(&dir, &args);
        assert_eq!(ran.code, Some(0), "{}", ran.stderr);
        std::fs::read(dir.join("out.pfm")).expect("reads the image")
    };
    let default = render(&[]);
    assert_eq!(default, render(&["--sampler", "independent"]));
    assert_ne!(default, render(&["--sampler", "sobol"]));
    std::fs::remove_dir_all(&dir).ok();
}
