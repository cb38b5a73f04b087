//! `--missing-assets`: a texture or mesh file that is not found is an error
//! at the place that names it (the default), or with `placeholder` a
//! warning there and a magenta and grey checker (colour textures) or
//! nothing (meshes, normal and height maps). Every coursework scene whose
//! MANIFEST.md says a file is missing loads that way and renders.

mod common;

use std::path::{Path, PathBuf};

use pathtracer::color::Color;
use pathtracer::integrator::Integrator;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::error::SceneError;
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, MissingAssets, load_scene};
use pathtracer::texture::Texture;

fn placeholder() -> LoadOptions {
    LoadOptions {
        missing_assets: MissingAssets::Placeholder,
        ..LoadOptions::default()
    }
}

/// A scene file in a fresh folder (no textures, no meshes next to it).
fn scene_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pt-missing-{}-{name}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("write scene");
    file
}

const SCENE: &str = "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 width 4 height 4 }
Materials { numMaterials 2
  Material { color 1 1 1 texture texture/gone.png }
  Material { color 1 1 1 bump texture/gone_bump.png }
}
Group { numObjects 3
  MaterialIndex 0
  Sphere { center 0 0 0 radius 1 }
  MaterialIndex 1
  Sphere { center 2 0 0 radius 1 }
  TriangleMesh { obj_file mesh/gone.obj }
}
";

fn leaves(scene: &Scene) -> usize {
    let mut n = 0;
    scene.root.for_each_leaf(&mut |_| n += 1);
    n
}

#[test]
fn by_default_a_missing_texture_is_an_error_at_its_place() {
    let file = scene_file(
        "default",
        &SCENE.replace("TriangleMesh { obj_file mesh/gone.obj }", ""),
    );
    let error = load_scene(&file, &LoadOptions::default())
        .expect_err("missing texture")
        .to_string();
    // Line 3, the column of the path after `texture`.
    let place = format!("{}:3:34:", file.display());
    assert!(error.starts_with(&place), "{error}");
    assert!(error.contains("texture/gone.png"), "{error}");
}

#[test]
fn placeholder_replaces_textures_and_leaves_out_meshes_and_maps_with_located_warnings() {
    let file = scene_file("placeholder", SCENE);
    let scene = load_scene(&file, &placeholder()).expect("loads with placeholders");
    let texture = scene.materials[0].texture.expect("a placeholder texture");
    assert_eq!(*scene.textures[texture], Texture::placeholder());
    assert_eq!(
        scene.materials[1].bump, None,
        "a missing height map is left out"
    );
    assert_eq!(scene.textures.len(), 1);
    assert_eq!(leaves(&scene), 2, "the missing mesh is left out");
    let warned = |line: u32, name: &str| {
        scene
            .warnings
            .iter()
            .any(|w| w.location.line == line && w.message.contains(name) && w.file == file)
    };
    assert!(warned(3, "texture/gone.png"), "{:?}", scene.warnings);
    assert!(warned(4, "texture/gone_bump.png"), "{:?}", scene.warnings);
    assert!(warned(11, "mesh/gone.obj"), "{:?}", scene.warnings);
    // Strict mode keeps every such warning an error.
    let strict = LoadOptions {
        strict: true,
        ..placeholder()
    };
    assert!(load_scene(&file, &strict).is_err());
}

#[test]
fn the_placeholder_shows_magenta_and_grey() {
    // A textured plane facing the camera, lit head-on by a directional
    // light of colour 1: a Lambert pixel is its texel (albedo * colour *
    // cos), and the plane's 10 texels per unit make squares of about 9
    // pixels in this narrow view.
    let text =
        "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 width 32 height 32 angle 2 }
Lights { numLights 1 DirectionalLight { direction 0 0 -1 color 1 1 1 } }
Materials { numMaterials 1 Material { color 1 1 1 texture texture/gone.png } }
Group { numObjects 1 MaterialIndex 0 Plane { normal 0 0 1 offset 0 } }
";
    let file = scene_file("colours", text);
    let scene = load_scene(&file, &placeholder()).expect("loads");
    let (image, stats) = common::render_scene(&scene, &settings(32, 32, 4)).expect("renders");
    assert_eq!(stats.dropped, 0);
    let near =
        |a: Color, b: Color| (a.r - b.r).abs() + (a.g - b.g).abs() + (a.b - b.b).abs() < 1e-6;
    let magenta = image
        .pixels
        .iter()
        .filter(|&&p| near(p, Color::new(1.0, 0.0, 1.0)))
        .count();
    let grey = image
        .pixels
        .iter()
        .filter(|&&p| near(p, Color::gray(0.5)))
        .count();
    // Pixels on the squares' edges mix the two; most are one or the other.
    assert!(
        magenta > 200 && grey > 200,
        "{magenta} magenta, {grey} grey"
    );
}

fn settings(width: u32, height: u32, spp: u32) -> RenderSettings {
    RenderSettings {
        width,
        height,
        spp,
        seed: 3,
        threads: None,
        integrator: Integrator::Path,
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

#[test]
fn every_coursework_scene_with_a_missing_file_loads_with_placeholders_and_renders() {
    let Some(shared) = common::shared() else {
        return;
    };
    let scenes = common::coursework(&shared, "missing");
    assert!(
        scenes.len() >= 38,
        "{} scenes with missing files",
        scenes.len()
    );
    let mut failures = Vec::new();
    let mut errors_by_default = 0;
    for (file, base) in &scenes {
        let name = file
            .strip_prefix(&shared)
            .unwrap_or(file)
            .display()
            .to_string();
        let by_default = load_scene(file, &LoadOptions::default().with_base(base));
        let scene = match load_scene(file, &placeholder().with_base(base)) {
            Ok(scene) => scene,
            Err(error) => {
                failures.push(format!("{name}: does not load: {error}"));
                continue;
            }
        };
        // The file that stops the default load is named by a warning at
        // the same place.
        if let Err(SceneError::At(error)) = by_default {
            errors_by_default += 1;
            let named = scene.warnings.iter().any(|w| {
                w.file == error.file
                    && w.location == error.location
                    && w.message.starts_with(&error.message)
            });
            if !named {
                failures.push(format!("{name}: no warning in place of '{error}'"));
            }
        }
        match common::render_scene(&scene, &settings(8, 6, 2)) {
            Ok((image, stats)) => {
                if stats.dropped > 0 || image.pixels.iter().any(|p| !p.is_finite()) {
                    failures.push(format!("{name}: NaN or infinite samples"));
                }
            }
            Err(error) => failures.push(format!("{name}: {error}")),
        }
    }
    println!(
        "{} scenes with missing files load with placeholders and render; {errors_by_default} of them fail to load by default",
        scenes.len()
    );
    assert!(
        errors_by_default >= 38,
        "{errors_by_default} fail by default"
    );
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

trait WithBase {
    fn with_base(self, base: &Path) -> Self;
}

impl WithBase for LoadOptions {
    fn with_base(self, base: &Path) -> Self {
        LoadOptions {
            base: Some(base.to_path_buf()),
            ..self
        }
    }
}
