//! The facts of the looks of the Whitted ray tracers (jefflyy's `jef`,
//! emily-jia's `emj`) and of hanna0911's ray caster (`han`), one test per
//! fact that changes pixels, on scenes whose pixels are known in closed
//! form (../shared/docs/looks.md has the facts).

mod common;

use pathtracer::image_io::Image;
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

fn render_text(name: &str, text: &str, look: Look) -> Image {
    let dir = std::env::temp_dir().join(format!("pt-whitted-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join(format!("{name}-{}.txt", look.name));
    std::fs::write(&file, text).expect("writes");
    let scene = load_scene(&file, &LoadOptions::default()).expect("loads");
    let settings = RenderSettings {
        width: scene.camera.width,
        height: scene.camera.height,
        spp: 1,
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
    std::fs::remove_file(&file).ok();
    image
}

/// A camera 5 above a floor, looking straight down, 4x4 pixels.
const CAMERA: &str =
    "PerspectiveCamera { center 0 5 0 direction 0 -1 0 up 0 0 -1 angle 30 width 4 height 4 }\n";

/// A floor of `floor`'s material lit from the upper left (45 degrees) by a
/// white directional light, with (or without) a black roof far to the left
/// at height 10 that shadows the floor in view but is not seen in it, nor
/// in its mirror.
fn shadowed_floor(floor: &str, background: f64, roof: bool) -> String {
    let roof = if roof {
        "Triangle { vertex0 -30 10 -40 vertex1 -5 10 -40 vertex2 -5 10 40 }\n\
         Triangle { vertex0 -30 10 -40 vertex1 -5 10 40 vertex2 -30 10 40 }"
    } else {
        ""
    };
    format!(
        "{CAMERA}Lights {{ numLights 1 DirectionalLight {{ direction 1 -1 0 color 1 1 1 }} }}\n\
         Background {{ color {background} {background} {background} }}\n\
         Materials {{ numMaterials 2 PhongMaterial {{ {floor} }} PhongMaterial {{ diffuseColor 0 0 0 }} }}\n\
         Group {{ MaterialIndex 0 Plane {{ normal 0 1 0 offset 0 }} MaterialIndex 1 {roof} }}"
    )
}

fn every_pixel(image: &Image, expected: f64, tolerance: f64, what: &str) {
    for (i, p) in image.pixels.iter().enumerate() {
        for c in [p.r, p.g, p.b] {
            assert!(
                (c - expected).abs() <= tolerance,
                "{what}: pixel {i} is {c}, expected {expected}"
            );
        }
    }
}

const LIT: f64 = 0.5 * std::f64::consts::FRAC_1_SQRT_2;

#[test]
fn jef_a_point_no_light_reaches_takes_the_background_colour() {
    let floor = "diffuseColor 0.5 0.5 0.5";
    let lit = render_text("lit", &shadowed_floor(floor, 0.2, false), Look::JEF);
    every_pixel(&lit, LIT, 1e-9, "lit floor: kd cos");
    let shadowed = render_text("shadowed", &shadowed_floor(floor, 0.2, true), Look::JEF);
    every_pixel(&shadowed, 0.2, 1e-9, "shadowed floor: the background");
}

#[test]
fn jef_mirrors_by_the_fixed_untinted_weight() {
    // No lights: the local colour is the background (0.2); the mirror ray
    // brings the background back, times `reflective` 0.5, untinted.
    let text = format!(
        "{CAMERA}Background {{ color 0.2 0.2 0.2 }}\n\
         Materials {{ PhongMaterial {{ diffuseColor 0.1 0.9 0.1 reflective 0.5 }} }}\n\
         Group {{ MaterialIndex 0 Plane {{ normal 0 1 0 offset 0 }} }}"
    );
    every_pixel(
        &render_text("mirror", &text, Look::JEF),
        0.3,
        1e-9,
        "0.2 + 0.5 x 0.2",
    );
}

#[test]
fn jef_follows_five_hits() {
    // Two facing perfect mirrors and no light: each hit adds the
    // background as its local colour, five hits along the camera ray.
    let text = format!(
        "{CAMERA}Background {{ color 0.1 0.1 0.1 }}\n\
         Materials {{ PhongMaterial {{ diffuseColor 1 1 1 reflective 1 }} }}\n\
         Group {{ MaterialIndex 0 Plane {{ normal 0 1 0 offset 0 }} Plane {{ normal 0 1 0 offset 6 }} }}"
    );
    every_pixel(
        &render_text("depth", &text, Look::JEF),
        0.5,
        1e-9,
        "5 x 0.1",
    );
}

#[test]
fn emj_casts_no_shadow_rays() {
    let floor = "diffuseColor 0.5 0.5 0.5";
    let image = render_text("unshadowed", &shadowed_floor(floor, 0.0, true), Look::EMJ);
    every_pixel(&image, LIT, 1e-9, "the roof casts no shadow");
}

#[test]
fn emj_every_surface_mirrors_the_scene_by_one_minus_schlick_at_index_one() {
    // A black floor, no lights, a grey sky: what is seen is the sky in the
    // "refracted" (mirror) ray, weighted 1 - (1 - cos)^5, untinted.
    let text = format!(
        "{CAMERA}Background {{ color 0.8 0.8 0.8 }}\n\
         Materials {{ PhongMaterial {{ diffuseColor 0 0 0 }} }}\n\
         Group {{ MaterialIndex 0 Plane {{ normal 0 1 0 offset 0 }} }}"
    );
    let image = render_text("sky", &text, Look::EMJ);
    // Rays leave at most 15 degrees (times the diagonal) off the normal:
    // (1 - cos)^5 stays below 2.5e-6.
    every_pixel(&image, 0.8, 2e-6, "the sky in every surface");
    let pa1 = render_text("sky", &text, Look::PA1);
    every_pixel(&pa1, 0.0, 0.0, "the ray caster sees a black floor");
}

#[test]
fn han_traces_through_pixel_corners() {
    // A 2x1 image, 90 degrees vertical: a pixel spans 2 units of the plane
    // z = -1, film x in [0, 2] meets it at world x = 2 film x - 2. A white
    // strip over world x in [-1.5, -0.5] holds the left pixel's centre
    // (film 0.5: world -1) but neither corner ray (film 0 and 1: world -2
    // and 0).
    let text = "PerspectiveCamera { center 0 0 0 direction 0 0 -1 up 0 1 0 angle 90 width 2 height 1 }\n\
         Lights { DirectionalLight { direction 0 0 -1 color 1 1 1 } }\n\
         Background { color 0.25 0.25 0.25 }\n\
         Materials { PhongMaterial { diffuseColor 1 1 1 } }\n\
         Group { MaterialIndex 0\n\
         Triangle { vertex0 -1.5 -9 -1 vertex1 -0.5 -9 -1 vertex2 -0.5 9 -1 }\n\
         Triangle { vertex0 -1.5 -9 -1 vertex1 -0.5 9 -1 vertex2 -1.5 9 -1 } }";
    let centres = render_text("corner", text, Look::PA1);
    assert_eq!(
        centres.pixels[0].r, 1.0,
        "pa1: the left centre sees the strip"
    );
    let corners = render_text("corner", text, Look::HAN);
    assert_eq!(corners.pixels[0].r, 0.25, "han: the left corner misses it");
    assert_eq!(corners.pixels[1].r, 0.25);
}

#[test]
fn jef_turns_surfaces_of_revolution_about_z() {
    // A tube of radius 1 from y = -1 to 1 in the profile, seen from z = 5
    // down -z under a light along -z: turned about y (the framework's) its
    // side faces the camera and the middle pixel is lit; turned about z
    // (jefflyy's: the profile's y becomes z) the camera looks down the tube
    // and the middle pixel sees the black background through it.
    let text = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 9 height 9 }\n\
         Lights { numLights 1 DirectionalLight { direction 0 0 -1 color 1 1 1 } }\n\
         Background { color 0 0 0 }\n\
         Materials { numMaterials 1 Material { diffuseColor 0.5 0.5 0.5 } }\n\
         Group { numObjects 1 MaterialIndex 0 RevSurface { profile BezierCurve { controls \
         [ 1 -1 0 ] [ 1 -0.3 0 ] [ 1 0.3 0 ] [ 1 1 0 ] } } }";
    let middle = |look: Look| {
        let image = render_text("revolution-axis", text, look);
        image.pixels[4 * 9 + 4].g
    };
    assert_eq!(middle(Look::JEF), 0.0);
    let about_y = Look {
        revolutions_about_z: false,
        ..Look::JEF
    };
    assert!(middle(about_y) > 0.4, "{}", middle(about_y));
}

#[test]
fn emj_hits_a_transformed_sphere_at_its_distance_used_as_parameter() {
    // A unit sphere scaled by 2, seen from z = 10 under a light along -x
    // (lighting the +x side). In object space the ray's direction has
    // length 1/2: emily-jia's sphere finds the hit's distance along it and
    // uses that as the parameter, so the point lies halfway between the
    // eye and the sphere, where the normal (from the centre) points more
    // towards the eye than at the true hit: a pixel right of the middle is
    // darker than the exact hit's. One hit only (no mirror ray).
    let text = |object: &str| {
        format!(
            "PerspectiveCamera {{ center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 width 9 height 9 }}\n\
             Lights {{ numLights 1 DirectionalLight {{ direction -1 0 0 color 1 1 1 }} }}\n\
             Background {{ color 0 0 0 }}\n\
             Materials {{ numMaterials 1 Material {{ diffuseColor 0.5 0.5 0.5 }} }}\n\
             Group {{ numObjects 1 MaterialIndex 0 {object} }}"
        )
    };
    let scaled = "Transform { Scale 2 2 2 Sphere { center 0 0 0 radius 1 } }";
    let plain = "Sphere { center 0 0 0 radius 2 }";
    let right = |object: &str, look: Look| {
        let look = Look {
            max_depth: 1,
            ..look
        };
        let image = render_text("scaled-sphere", &text(object), look);
        image.pixels[4 * 9 + 6].g
    };
    let exact = Look {
        sphere_test: pathtracer::geometry::SphereTest::Robust,
        ..Look::EMJ
    };
    let (theirs, ours) = (right(scaled, Look::EMJ), right(scaled, exact));
    assert!(ours > 0.15 && theirs < ours - 0.05, "{theirs} {ours}");
    // Untransformed, distance and parameter agree: the exact hit.
    let untransformed = right(plain, Look::EMJ);
    assert!(
        (untransformed - ours).abs() < 1e-9,
        "{untransformed} {ours}"
    );
}

#[test]
fn jef_misses_the_roots_near_the_start_of_a_profile() {
    // A flat washer at z = 1 (the profile runs in from radius 2 to 0.5,
    // x(s) = 0.5 + 1.5 (1 - s)^3) seen down its axis from z = 5 under a
    // light along -z. jefflyy's Newton steps are scaled by the profile
    // parameter s, so near s = 0 they crawl and stop short of the root:
    // the washer's outer rim (s < 0.05: radius above 1.79) is missed and
    // shows the black background, where the exact test sees it lit; its
    // middle (s > 0.1) is lit the same under both.
    const SIZE: usize = 21;
    let text = format!(
        "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 60 width {SIZE} height {SIZE} }}\n\
         Lights {{ numLights 1 DirectionalLight {{ direction 0 0 -1 color 1 1 1 }} }}\n\
         Background {{ color 0 0 0 }}\n\
         Materials {{ numMaterials 1 Material {{ diffuseColor 0.5 0.5 0.5 }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 RevSurface {{ profile BezierCurve {{ controls \
         [ 2 1 0 ] [ 0.5 1 0 ] [ 0.5 1 0 ] [ 0.5 1 0 ] }} }} }}"
    );
    let exact = Look {
        revolution_test: pathtracer::geometry::RevolutionTest::Robust,
        ..Look::JEF
    };
    let theirs = render_text("washer", &text, Look::JEF);
    let ours = render_text("washer", &text, exact);
    // The radius at which pixel (column, row)'s ray (through the pixel's
    // corner, rows from the top) meets the plane z = 1, 4 below the eye.
    let span = 2.0 * 30f64.to_radians().tan();
    let radius = |column: usize, row: usize| {
        let x = (column as f64 / SIZE as f64 - 0.5) * span;
        let y = ((SIZE - 1 - row) as f64 / SIZE as f64 - 0.5) * span;
        4.0 * x.hypot(y)
    };
    let (mut rim, mut middle) = (0, 0);
    for row in 0..SIZE {
        for column in 0..SIZE {
            let r = radius(column, row);
            let (theirs, ours) = (
                theirs.pixels[row * SIZE + column].g,
                ours.pixels[row * SIZE + column].g,
            );
            if (1.8..1.98).contains(&r) {
                rim += 1;
                assert_eq!(theirs, 0.0, "rim pixel ({column}, {row}) at radius {r}");
                assert!(ours > 0.4, "rim pixel ({column}, {row}): {ours}");
            } else if (0.6..1.6).contains(&r) {
                middle += 1;
                assert!(ours > 0.4, "middle pixel ({column}, {row}): {ours}");
                assert!(
                    (theirs - ours).abs() < 1e-4,
                    "{theirs} {ours} at radius {r}"
                );
            }
        }
    }
    assert!(rim > 10 && middle > 50, "{rim} {middle}");
}
