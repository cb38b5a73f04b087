//! The facts of 1rubbishyuan's look (`rub`, its recursive estimator), one
//! test per fact that changes pixels, on scenes whose pixels are known in
//! closed form (../shared/docs/looks.md, "1rubbishyuan+path_tracing").

mod common;

use common::{EMPTY_UNDER_WHITE, floor_under_white, mean, render_text, run_in, write_scene};
use pathtracer::image_io::read_image_encoded;
use pathtracer::look::{Integrator, Look, OutputCurve};
use pathtracer::scene::{LoadOptions, load_scene};

/// rub's camera (its `defocusAngle` and `focusDist` are required), 4x4.
const RUB_CAMERA: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 \
     angle 30 width 4 height 4 defocusAngle 0 focusDist 1 }\n";

/// A quad at z = `z` facing the camera (normal +z) or away from it.
fn quad(z: f64, toward_camera: bool) -> String {
    if toward_camera {
        format!("Quad {{ origin -50 -50 {z} u 100 0 0 v 0 100 0 }}")
    } else {
        format!("Quad {{ origin -50 -50 {z} u 0 100 0 v 100 0 0 }}")
    }
}

#[test]
fn rub_files_render_in_rub_with_its_estimator() {
    let text = format!(
        "{RUB_CAMERA}Materials {{ numMaterials 1 Material {{ lightColor 1 1 1 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 {} }}",
        quad(0.0, true)
    );
    let file = write_scene("rub-detect", &text);
    let scene = load_scene(&file, &LoadOptions::default()).expect("loads");
    let (look, why) = Look::detect(&scene);
    assert_eq!(look.name, "rub", "{why}");
    assert_eq!(look.integrator, Integrator::Rub);
    assert_eq!(look.output, OutputCurve::SquareRoot);
}

#[test]
fn rub_writes_the_square_root_of_its_average() {
    // Only a background of 0.25: 0.8 of the camera rays survive, 0.2 on
    // average, written as sqrt(0.2) * 255 = 114 (linear: 51).
    let text = format!(
        "{RUB_CAMERA}Background {{ color 0.25 0.25 0.25 }}\n\
         Materials {{ numMaterials 1 Material {{ diffuseColor 1 1 1 perDiffuse 1 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 100 0 0 radius 1 }} }}"
    );
    let file = write_scene("rub-sqrt", &text);
    let dir = file.parent().expect("a folder").to_path_buf();
    let ran = run_in(
        &dir,
        &["render", "scene.txt", "-o", "out.png", "--spp", "4000"],
    );
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let (image, _) = read_image_encoded(&dir.join("out.png")).expect("reads");
    std::fs::remove_dir_all(&dir).ok();
    for p in &image.pixels {
        let byte = (p.g * 255.0).round();
        assert!((111.0..=117.0).contains(&byte), "{byte}");
    }
}

#[test]
fn rub_kills_every_call_with_probability_0_2_and_never_reweights() {
    // The camera rays of an empty scene under a white background: 0.8 of
    // them bring 1 back, unweighted (the original's image is 1).
    let m = mean(&render_text(
        "rub-death",
        EMPTY_UNDER_WHITE,
        Look::RUB,
        1024,
    ));
    assert!((m - 0.8).abs() < 0.02, "{m}");
    let original = mean(&render_text(
        "rub-death",
        EMPTY_UNDER_WHITE,
        Look::ORIGINAL,
        1,
    ));
    assert_eq!(original, 1.0);
}

#[test]
fn rub_misses_bring_the_background_back_at_every_depth() {
    // A floor of albedo 0.5 under a white background, seen from above: the
    // bounce's 1000 brdf cos L clamps to 1 when its call survives, so the
    // pixel is 0.5 x 0.8 (camera call) x 0.8 (bounce call) = 0.32.
    let m = mean(&render_text(
        "rub-miss",
        &floor_under_white(0.5),
        Look::RUB,
        2048,
    ));
    assert!((m - 0.32).abs() < 0.015, "{m}");
}

#[test]
fn rub_boosts_emitters_only_when_seen_after_a_bounce() {
    let light = "Material { lightColor 0.2 0.2 0.2 boost 4 }";
    // Seen directly: 0.2 (no boost) on the 0.8 of the camera rays that live.
    let direct = format!(
        "{RUB_CAMERA}Materials {{ numMaterials 1 {light} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 {} }}",
        quad(0.0, true)
    );
    let m = mean(&render_text("rub-boost-direct", &direct, Look::RUB, 2048));
    assert!((m - 0.16).abs() < 0.01, "{m}");
    // In a mirror facing the camera, the light behind the camera is seen
    // after a bounce: 0.2 x 4, so the mirror pixel is 0.8 (camera call) x
    // 0.8 (reflected call) x min(1, cos 0.8); cos is about 0.98 over the
    // view. Without the boost it would be about 0.13.
    let mirrored = format!(
        "{RUB_CAMERA}Materials {{ numMaterials 2 Material {{ diffuseColor 1 1 1 perReflect 1 }} {light} }}\n\
         Group {{ numObjects 2 MaterialIndex 0 {} MaterialIndex 1 {} }}",
        quad(0.0, true),
        quad(10.0, false)
    );
    let m = mean(&render_text("rub-boost-mirror", &mirrored, Look::RUB, 2048));
    assert!((m - 0.8 * 0.8 * 0.8 * 0.98).abs() < 0.03, "{m}");
}

#[test]
fn rub_normals_are_not_turned_toward_the_ray() {
    // The camera inside a white diffuse sphere with a light beside it: the
    // wall's outward normal faces away from the camera and from the light,
    // so max(0, N.V) and max(0, N.L) are 0 and the wall is black.
    let text = format!(
        "{RUB_CAMERA}Background {{ color 1 1 1 }}\n\
         Materials {{ numMaterials 2 Material {{ diffuseColor 1 1 1 perDiffuse 1 }} \
         Material {{ lightColor 1 1 1 }} }}\n\
         Group {{ numObjects 2 MaterialIndex 0 Sphere {{ center 0 0 0 radius 20 }} \
         MaterialIndex 1 Sphere {{ center 0 0 10 radius 1 }} }}"
    );
    assert_eq!(mean(&render_text("rub-inside", &text, Look::RUB, 64)), 0.0);
    // The same wall in the original's look is lit.
    assert!(mean(&render_text("rub-inside", &text, Look::ORIGINAL, 16)) > 0.001);
}
