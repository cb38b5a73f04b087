//! Scene text to a 4x4 image at 1 sample per pixel: every stage a scene goes
//! through (parse, build, the look's adaptations, the world, each integrator)
//! at a size that costs almost nothing.

use std::path::Path;

use pathtracer::integrator::Integrator;
use pathtracer::look::Look;
use pathtracer::math::Aabb;
use pathtracer::render::{RenderSettings, render};
use pathtracer::render_scene::RenderScene;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::Scene;
use pathtracer::look::summary;
use pathtracer::scene::{LoadOptions, build, parse};

/// Pixels on each side of the tiny image.
pub const SIDE: u32 = 4;

/// Parses and builds `text` as the file `file` (its relative names resolve
/// against `options.base`, `file`'s folder and the working directory), and
/// formats what `check` would print: the error, or the warnings and summary.
pub fn build_text(text: &str, file: &Path, options: &LoadOptions) -> Option<Scene> {
    let built = parse(text, file).and_then(|document| build(&document, file, options));
    match built {
        Ok(scene) => {
            let printed: usize = scene.warnings.iter().map(|w| w.to_string().len()).sum();
            std::hint::black_box((printed, summary(&scene)));
            Some(scene)
        }
        Err(error) => {
            std::hint::black_box(error.to_string());
            None
        }
    }
}

/// The settings of a [`SIDE`]x[`SIDE`], 1-spp render with `integrator`
/// under `look`.
fn settings(look: Look, integrator: Integrator) -> RenderSettings {
    RenderSettings {
        width: SIDE,
        height: SIDE,
        spp: 1,
        seed: 1,
        threads: Some(1),
        integrator,
        max_depth: look.max_depth,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    }
}

/// The bounds of the scene's shapes as its own look builds them.
pub fn bounds(scene: &Scene) -> Aabb {
    let (look, _) = Look::detect(scene);
    let settings = settings(look, Integrator::Path);
    RenderScene::build(scene.clone(), &settings.scene()).bounds()
}

/// Renders `scene` at [`SIDE`]x[`SIDE`], 1 spp, with each integrator under
/// the scene's look (its render-time scene built once, as a render builds
/// it). A render error is fine (hostile input may be refused); the image
/// must have its size and no pixel may be NaN or infinite.
pub fn render_every_integrator(scene: Scene) {
    let (look, _) = Look::detect(&scene);
    let scene = RenderScene::build(scene, &settings(look, Integrator::Path).scene());
    for integrator in Integrator::ALL {
        let settings = settings(look, integrator);
        if let Ok((image, _)) = render(&scene, &settings) {
            assert_eq!(image.pixels.len(), (SIDE * SIDE) as usize);
            assert!(
                image.pixels.iter().all(|p| p.is_finite()),
                "a non-finite pixel under the {} integrator",
                integrator.name()
            );
        }
    }
}
