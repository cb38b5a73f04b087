//! The facts of the looks of AfireBao's (`afb`), Bowen-Xu04's (`bow`),
//! ShuoAndy's (`shu`) and re2ikotr's (`re2`) path tracers and aliezlo's
//! `pt` mode (`alz-pt`), one test per
//! fact that changes pixels, on scenes whose pixels are known in closed
//! form (../shared/docs/looks.md has the facts).

mod common;

use common::{
    EMPTY_UNDER_WHITE, floor_under_white, inside_a_glowing_sphere, mean, plane_under_a_sky,
    render_text, written_byte,
};
use pathtracer::look::Look;

/// `emission (1 + albedo + ... + albedo^(hits - 1))`.
fn gathered(albedo: f64, emission: f64, hits: i32) -> f64 {
    emission * (1.0 - albedo.powi(hits)) / (1.0 - albedo)
}

#[test]
fn afb_and_bow_paths_have_no_depth_cap() {
    // Inside a glowing white sphere of albedo 0.8: 0.1 / 0.2 = 0.5 with no
    // cap; the original's 5 scatterings gather 0.369.
    let scene = inside_a_glowing_sphere(0.8, 0.1);
    for look in [Look::AFB, Look::BOW] {
        let m = mean(&render_text("unbounded", &scene, look, 256));
        assert!((m - 0.5).abs() < 0.03, "{}: {m}", look.name);
    }
    let original = mean(&render_text("unbounded", &scene, Look::ORIGINAL, 64));
    assert!(
        (original - gathered(0.8, 0.1, 6)).abs() < 0.01,
        "{original}"
    );
}

#[test]
fn shu_paths_end_at_the_50th_hit_and_re2_at_the_10th() {
    // With emitters that reflect (to see the depth alone): albedo 0.9
    // gathers 0.1 (1 - 0.9^n) / 0.1 over n hits.
    let scene = inside_a_glowing_sphere(0.9, 0.1);
    for (look, hits) in [(Look::SHU, 50), (Look::RE2, 10)] {
        let look = Look {
            emitters_reflect: true,
            ..look
        };
        // Roulette (unbiased) ends some paths early: a tolerance.
        let m = mean(&render_text("depth", &scene, look, 256));
        let expected = gathered(0.9, 0.1, hits);
        assert!(
            (m - expected).abs() < 0.03,
            "{}: {m} for {expected}",
            look.name
        );
    }
}

#[test]
fn alz_pt_paths_end_at_the_20th_hit_where_wso_ends_at_the_15th() {
    // Rays leaving from an offset point of f64 shapes, diffuse bounces
    // about the normal turned towards the ray (to see the depth alone).
    let scene = inside_a_glowing_sphere(0.9, 0.1);
    for (look, hits) in [(Look::ALZ_PT, 20), (Look::WSO, 15)] {
        let look = Look {
            ray_origins: pathtracer::look::RayOrigins::Offset,
            single_precision_hits: false,
            diffuse_about_modelled_normal: false,
            ..look
        };
        let m = mean(&render_text("alz-depth", &scene, look, 64));
        let expected = gathered(0.9, 0.1, hits);
        assert!(
            (m - expected).abs() < 0.02,
            "{}: {m} for {expected}",
            look.name
        );
    }
}

#[test]
fn afb_misses_are_black_whatever_the_background() {
    assert_eq!(
        mean(&render_text("miss", EMPTY_UNDER_WHITE, Look::AFB, 1)),
        0.0
    );
}

#[test]
fn bow_adds_the_background_unweighted_after_a_bounce() {
    // A floor of albedo 0.25 under a white sky: 1 when the sky is added
    // raw after the bounce, 0.25 when it is weighted by the path.
    let scene = floor_under_white(0.25);
    let bow = mean(&render_text("unweighted", &scene, Look::BOW, 16));
    assert!((bow - 1.0).abs() < 1e-9, "bow: {bow}");
    let physical = mean(&render_text("unweighted", &scene, Look::PHYSICAL, 64));
    assert!((physical - 0.25).abs() < 0.02, "physical: {physical}");
}

#[test]
fn shu_and_re2_weight_the_background_by_the_path() {
    let scene = floor_under_white(0.25);
    for look in [Look::SHU, Look::RE2] {
        let m = mean(&render_text("weighted", &scene, look, 64));
        assert!((m - 0.25).abs() < 0.02, "{}: {m}", look.name);
    }
}

#[test]
fn bow_writes_the_power_0_6() {
    // 0.2^0.6 * 255 = 97.0...: int 97.
    assert_eq!(written_byte("bow"), 97);
}

#[test]
fn bow_traces_one_fixed_ray_through_each_pixel_centre() {
    // A pixel cut by the edge of a sphere is wholly in or out: its camera
    // rays do not spread over the pixel.
    let scene = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 \
                 width 7 height 7 }\nBackground { color 1 1 1 }\n\
                 Materials { numMaterials 1 Material { color 0 0 0 type 1 0 0 } }\n\
                 Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 0.8 } }";
    let bow = render_text("centre", scene, Look::BOW, 16);
    assert!(bow.pixels.iter().all(|p| p.g == 0.0 || p.g == 1.0));
    let original = render_text("centre", scene, Look::ORIGINAL, 16);
    assert!(original.pixels.iter().any(|p| p.g > 0.0 && p.g < 1.0));
}

#[test]
fn bow_glass_has_no_fresnel_reflection() {
    // A glass plane under the sky, seen from the sky's side: Schlick's
    // glass reflects about 4% of it, bow's nothing (the rest passes into
    // the dark half-space behind).
    let scene = plane_under_a_sky("color 1 1 1 type 0 0 1 refr 1.5");
    let bow = mean(&render_text("glass", &scene, Look::BOW, 16));
    assert_eq!(bow, 0.0);
    let original = mean(&render_text("glass", &scene, Look::ORIGINAL, 64));
    assert!(original > 0.02, "{original}");
}

#[test]
fn shu_and_re2_lights_do_not_scatter() {
    let emitting = plane_under_a_sky("color 1 1 1 emission 0.1 0.1 0.1 type 1 0 0");
    for look in [Look::SHU, Look::RE2] {
        let m = mean(&render_text("light", &emitting, look, 4));
        assert!((m - 0.1).abs() < 1e-9, "{}: {m}", look.name);
    }
}
