//! cyy's lights (Chenyu-Yang-2000/PathTracing): an `AreaLight` is a
//! parallelogram from its `position` corner along `deltax` and `deltay`
//! whose `color` is the radiance it shows; a `SpotLight` is a point light
//! that falls off as `max(0, cos)^shininess` about its `direction`, added
//! by shadow rays like the PA1 lights, next to the area lights.

mod common;

use pathtracer::color::Color;
use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Dialect, Scene};
use pathtracer::scene::{LoadOptions, load_scene};

fn load(name: &str, text: &str, dialect: Option<Dialect>) -> Scene {
    let dir = std::env::temp_dir().join(format!("pt-cyy-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("write");
    let options = LoadOptions {
        dialect,
        ..LoadOptions::default()
    };
    load_scene(&file, &options).expect("loads")
}

fn settings(size: u32, spp: u32, integrator: Integrator) -> RenderSettings {
    RenderSettings {
        width: size,
        height: size,
        spp,
        seed: 7,
        threads: None,
        integrator,
        max_depth: pathtracer::integrator::original::MAX_DEPTH,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Default::default(),
        dispersion: None,
    }
}

/// The scene rendered in the look detected for it, as `render` does.
fn pixels(scene: &Scene, settings: &RenderSettings) -> Vec<Color> {
    let settings = RenderSettings {
        look: Look::detect(scene).0,
        ..settings.clone()
    };
    pixels_in_its_look(scene, &settings)
}

fn pixels_in_its_look(scene: &Scene, settings: &RenderSettings) -> Vec<Color> {
    let (image, stats) = common::render_scene(scene, settings).expect("renders");
    assert_eq!(stats.dropped, 0);
    image.pixels
}

#[test]
fn an_area_light_seen_directly_shows_its_colour_at_any_size() {
    // The camera looks down at a light whose corner is at (-1, 0, -1):
    // every pixel of a narrow view of its middle sees it.
    for (size, corner) in [(2.0, -1.0), (20.0, -10.0)] {
        let text = format!(
            "PerspectiveCamera {{ center 0 5 0 direction 0 -1 0 up 0 0 -1 angle 5 width 8 height 8 }}\n\
             Lights {{ numLights 1 AreaLight {{ position {corner} 0 {corner} deltax {size} 0 0 deltay 0 0 {size} color 0.25 0.5 4 resolution 3 }} }}\n\
             Materials {{ numMaterials 1 Material {{ color 1 1 1 BRDF 1 0 0 1 0 0 1 }} }}\n\
             Group {{ numObjects 0 }}\n"
        );
        let scene = load("direct", &text, None);
        assert_eq!(scene.dialect, Dialect::Cyy);
        // rub's estimator returns black for a fifth of its camera rays (its
        // own rule, tests/rub_look.rs): every other estimator.
        for integrator in Integrator::ALL
            .into_iter()
            .filter(|&i| i != Integrator::Rub)
        {
            for p in pixels(&scene, &settings(8, 4, integrator)) {
                assert!(
                    (p.r - 0.25).abs() < 1e-12
                        && (p.g - 0.5).abs() < 1e-12
                        && (p.b - 4.0).abs() < 1e-12,
                    "{p:?}"
                );
            }
        }
    }
}

const FLOOR_LIT_BY_BOTH: &str =
    "PerspectiveCamera { center 0 6 0 direction 0 -1 0 up 0 0 -1 angle 60 width 16 height 16 }
Lights { numLights 2
  AreaLight { position 20 3 -1 deltax 1 0 0 deltay 0 0 1 color 1 1 1 resolution 2 }
  SpotLight { position 0 4 0 color 1 1 1 direction 0 -1 0 shininess 30 }
}
Materials { numMaterials 1 Material { color 0.5 0.5 0.5 BRDF 1 0 0 1 0 0 1 } }
Group { numObjects 1 MaterialIndex 0 Plane { normal 0 1 0 offset 0 } }
";

#[test]
fn a_spot_light_lights_its_cone_next_to_cyys_area_lights() {
    let with_spot = load("spot", FLOOR_LIT_BY_BOTH, None);
    let without = load(
        "no-spot",
        &FLOOR_LIT_BY_BOTH
            .replace("numLights 2", "numLights 1")
            .replace(
                "  SpotLight { position 0 4 0 color 1 1 1 direction 0 -1 0 shininess 30 }\n",
                "",
            ),
        None,
    );
    let settings = settings(16, 8, Integrator::Path);
    let lit = pixels(&with_spot, &settings);
    let unlit = pixels(&without, &settings);
    // The floor near the spot's axis: albedo 0.5 times colour 1 times
    // cos^30 of about 4 degrees (0.92) times the floor's cosine, with no
    // distance falloff.
    let centre = |p: &[Color]| p[8 * 16 + 8].r;
    let added = centre(&lit) - centre(&unlit);
    assert!(added > 0.42 && added < 0.5, "the spot adds {added}");
    // Its cone: the corner of the view (48 degrees off the axis, cos^30 =
    // 6e-6) gets almost nothing from it.
    let corner = |p: &[Color]| p[0].r;
    assert!(corner(&lit) - corner(&unlit) < 0.01);
    // In the original look, the area light's emitting rectangle makes the
    // scene one with emitters, whose point lights are not added.
    let original = RenderSettings {
        look: Look::ORIGINAL,
        ..settings.clone()
    };
    let in_original = pixels_in_its_look(&with_spot, &original);
    assert!((centre(&in_original) - centre(&unlit)).abs() < 1e-12);
}
