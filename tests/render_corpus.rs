//! Every scene of the shared corpus renders without a single NaN or infinite
//! sample, with either integrator: the 15 Cambrian files and the 3 report scenes at 64x48 and 16 spp
//! (the faithful renderer's acceptance size), the 128 complete coursework
//! scenes at 32x24 and 4 spp.

mod common;

use pathtracer::integrator::Integrator;
use pathtracer::render::RenderSettings;
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::{LoadOptions, load_scene};

#[test]
fn every_shared_scene_renders_without_nan_or_inf_samples() {
    let Some(shared) = common::shared() else {
        return;
    };
    let mut failures = Vec::new();
    let mut rendered = 0;
    for (file, base) in common::corpus(&shared) {
        let options = LoadOptions {
            base: Some(base),
            ..LoadOptions::default()
        };
        let scene = match load_scene(&file, &options) {
            Ok(scene) => scene,
            Err(error) => {
                failures.push(format!("{}: does not load: {error}", file.display()));
                continue;
            }
        };
        let acceptance = !file.to_string_lossy().contains("coursework");
        let (width, height, spp) = if acceptance {
            (64, 48, 16)
        } else {
            (32, 24, 4)
        };
        let look = Default::default();
        let mut scene_settings = SceneSettings::defaults(&scene, look);
        (scene_settings.width, scene_settings.height) = (width, height);
        let scene = RenderScene::build(scene, &scene_settings);
        for integrator in Integrator::ALL {
            let settings = RenderSettings {
                width,
                height,
                spp,
                seed: 1,
                threads: None,
                integrator,
                max_depth: pathtracer::integrator::original::MAX_DEPTH,
                sampler: SamplerKind::Sobol,
                progress: false,
                progress_every: None,
                clamp: None,
                light_paths: true,
                look,
                dispersion: None,
            };
            let name = format!("{} ({})", file.display(), integrator.name());
            let (image, stats) = match common::render_ready(&scene, &settings) {
                Ok(result) => result,
                Err(error) => {
                    failures.push(format!("{name}: {error}"));
                    continue;
                }
            };
            if integrator == Integrator::Path {
                rendered += 1;
            }
            if stats.dropped > 0 {
                failures.push(format!("{name}: {} NaN/Inf samples", stats.dropped));
            }
            if image.pixels.iter().any(|p| !p.is_finite()) {
                failures.push(format!("{name}: non-finite pixel"));
            }
        }
    }
    println!("rendered {rendered} scenes");
    assert!(rendered >= 146, "only {rendered} scenes rendered");
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}
