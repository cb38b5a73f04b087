//! Shared test helpers: the scene corpus in ../shared (where it is and which
//! of its scenes are complete), and scenes built in code.

#![allow(dead_code)]

mod look_scenes;
mod run;
mod shapes;
mod view_client;
#[allow(unused_imports)]
pub use look_scenes::*;
#[allow(unused_imports)]
pub use run::*;
#[allow(unused_imports)]
pub use shapes::*;
#[allow(unused_imports)]
pub use view_client::*;

use std::path::{Path, PathBuf};

use pathtracer::color::Color;
use pathtracer::image_io::Image;
use pathtracer::integrator::Integrator;
use pathtracer::integrator::sppm::PhotonSettings;
use pathtracer::look::Look;
use pathtracer::render::photon_passes;
use pathtracer::render::{RenderSettings, RenderStats, render};
use pathtracer::render_scene::{RenderScene, SceneSettings};
use pathtracer::scene::model::{Material, Object, Scene};

pub fn shared() -> Option<PathBuf> {
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared"));
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("skipped: ../shared not found");
        None
    }
}

/// (scene file, base folder) of every corpus scene whose assets are all present.
pub fn corpus(shared: &Path) -> Vec<(PathBuf, PathBuf)> {
    let mut scenes = Vec::new();
    let cambrian = shared.join("reference/cambrian-pathtracer/testcases");
    let mut names: Vec<_> = std::fs::read_dir(&cambrian)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    names.sort();
    for path in names
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
    {
        scenes.push((path, shared.join("reference/cambrian-pathtracer")));
    }
    let mut own: Vec<_> = std::fs::read_dir(shared.join("scenes"))
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    own.sort();
    for path in own
        .into_iter()
        .filter(|p| p.extension().is_some_and(|e| e == "txt"))
    {
        scenes.push((path, shared.to_path_buf()));
    }
    scenes.extend(coursework(shared, "complete"));
    scenes
}

/// (scene file, base folder) of every coursework scene whose MANIFEST.md
/// status starts with `status` ("complete", or "missing" for the scenes
/// that name a file the folder does not have).
pub fn coursework(shared: &Path, status: &str) -> Vec<(PathBuf, PathBuf)> {
    let mut scenes = Vec::new();
    let coursework = shared.join("reference/coursework");
    let mut repos: Vec<_> = std::fs::read_dir(&coursework)
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    repos.sort();
    for repo in repos {
        let Ok(manifest) = std::fs::read_to_string(repo.join("MANIFEST.md")) else {
            continue;
        };
        let mut base = repo.clone();
        for line in manifest.lines() {
            if line.starts_with("- Base folder")
                && let Some(folder) = line.split('`').nth(1)
            {
                base = repo.join(folder);
            }
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            if let [_, file, found, ..] = cells.as_slice()
                && found.starts_with(status)
                && file.starts_with('`')
            {
                scenes.push((repo.join(file.trim_matches('`')), base.clone()));
            }
        }
    }
    scenes
}

/// A scene with the camera at the origin looking down -z, built in code.
/// Mean and standard error of a set of independent estimates.
pub fn mean_and_error(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let variance = values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0);
    (mean, (variance / n).sqrt())
}

/// `count` renders of `scene` with `settings` and seeds `first_seed`,
/// `first_seed + 1`, ...: per run, the pixel values (channel averages),
/// row-major from the top. No sample may be NaN or infinite.
pub fn independent_runs(
    scene: &Scene,
    settings: &RenderSettings,
    first_seed: u64,
    count: u64,
) -> Vec<Vec<f64>> {
    let ready = ready(scene.clone(), settings);
    (0..count)
        .map(|run| {
            let settings = RenderSettings {
                seed: first_seed + run,
                ..settings.clone()
            };
            let (image, stats) = render(&ready, &settings).expect("renders");
            assert_eq!(stats.dropped, 0, "NaN or infinite samples");
            image.pixels.iter().map(Color::average).collect()
        })
        .collect()
}

/// The render-time scene of `scene` for `settings` (through the one
/// function that makes one, as the command line does).
pub fn ready(scene: Scene, settings: &RenderSettings) -> RenderScene {
    RenderScene::build(scene, &settings.scene())
}

/// The render-time scene of `scene` in the original look with its own
/// camera (for tests of its geometry: `built(scene).world()`).
pub fn built(scene: Scene) -> RenderScene {
    let settings = SceneSettings::defaults(&scene, Look::ORIGINAL);
    RenderScene::build(scene, &settings)
}

/// The render-time scene of `objects` alone, without materials (so that
/// every hit has its uv and surface derivatives): for tests of geometry.
pub fn world_of(objects: Vec<Object>) -> RenderScene {
    built(Scene::new(Vec::new(), Object::Group(objects)))
}

/// `scene` rendered with `settings`.
pub fn render_scene(
    scene: &Scene,
    settings: &RenderSettings,
) -> Result<(Image, RenderStats), String> {
    render_ready(&ready(scene.clone(), settings), settings)
}

/// A render-time scene rendered with `settings`, by any integrator
/// (photon mapping through its own driver, with its default parameters).
pub fn render_ready(
    scene: &RenderScene,
    settings: &RenderSettings,
) -> Result<(Image, RenderStats), String> {
    if settings.integrator == Integrator::Sppm {
        photon_passes::render(scene, settings, PhotonSettings::default(), false)
    } else {
        render(scene, settings)
    }
}

/// Statistic `f` of independent runs (image mean or one pixel): its mean
/// and standard error.
pub fn statistic(runs: &[Vec<f64>], f: impl Fn(&[f64]) -> f64) -> (f64, f64) {
    let values: Vec<f64> = runs.iter().map(|r| f(r)).collect();
    mean_and_error(&values)
}

pub fn scene_with(materials: Vec<Material>, root: Object) -> Scene {
    Scene::new(materials, root)
}

/// A file below `../shared`, or `None` (with a note) when it is absent.
pub fn shared_file(relative: &str) -> Option<PathBuf> {
    let path = shared()?.join(relative);
    if path.exists() {
        Some(path)
    } else {
        println!("skipped: {} not found", path.display());
        None
    }
}
