//! Every scene of the shared corpus loads without error (and some facts about them hold).

mod common;

use std::path::Path;

use common::{corpus, shared};

use pathtracer::scene::model::{Object, Scene};
use pathtracer::scene::{LoadOptions, load_scene};

fn counts(scene: &Scene) -> (usize, usize) {
    let (mut objects, mut triangles) = (0, 0);
    scene.root.for_each_leaf(&mut |leaf| {
        objects += 1;
        if let Object::Mesh { mesh, .. } = leaf {
            triangles += mesh.triangles.len();
        }
    });
    (objects, triangles)
}

fn load(file: &Path, base: &Path) -> Scene {
    let options = LoadOptions {
        base: Some(base.to_path_buf()),
        ..LoadOptions::default()
    };
    match load_scene(file, &options) {
        Ok(scene) => scene,
        Err(e) => panic!("{e}"),
    }
}

#[test]
fn every_corpus_scene_loads() {
    let Some(shared) = shared() else { return };
    let scenes = corpus(&shared);
    assert_eq!(scenes.len(), 146, "corpus size");
    let mut failures = Vec::new();
    let mut warnings = 0;
    for (file, base) in &scenes {
        let options = LoadOptions {
            base: Some(base.clone()),
            ..LoadOptions::default()
        };
        match load_scene(file, &options) {
            Ok(scene) => {
                let (objects, triangles) = counts(&scene);
                warnings += scene.warnings.len();
                println!(
                    "{}: {} materials, {objects} objects, {triangles} triangles, {} textures, {} lights, {} warnings [{}]",
                    file.strip_prefix(&shared).unwrap_or(file).display(),
                    scene.materials.len(),
                    scene.textures.len(),
                    scene.lights.len(),
                    scene.warnings.len(),
                    scene.dialect.name(),
                );
                for w in &scene.warnings {
                    println!("    warning: {w}");
                }
            }
            Err(e) => failures.push(e.to_string()),
        }
    }
    println!(
        "{} scenes, {} failures, {warnings} warnings",
        scenes.len(),
        failures.len()
    );
    assert!(failures.is_empty(), "failures:\n{}", failures.join("\n"));
}

#[test]
fn content_facts() {
    let Some(shared) = shared() else { return };
    let spheres = load(&shared.join("scenes/report_scene15_spheres.txt"), &shared);
    assert_eq!(counts(&spheres).0, 10);
    assert_eq!(spheres.materials.len(), 8);
    assert_eq!(spheres.camera.canvas_distance, 140.0);
    let dragons = load(&shared.join("scenes/report_scene11_dragons.txt"), &shared);
    let mut largest = 0;
    dragons.root.for_each_leaf(&mut |leaf| {
        if let Object::Mesh { mesh, .. } = leaf {
            largest = largest.max(mesh.triangles.len());
        }
    });
    assert_eq!(largest, 100_000);
    // Cambrian's glass bunny disperses (its camera's flag and `cauchy`).
    let cambrian = shared.join("reference/cambrian-pathtracer");
    let bunny = load(&cambrian.join("testcases/bunny_only.txt"), &cambrian);
    assert!(bunny.has_dispersion());
}

/// Fields that are read and not rendered: each must warn at its own line
/// (the rule that nothing a scene says is dropped silently).
const NOT_RENDERED: &[&str] = &[
    "textureLuminance",
    "opacity",
    "transparency",
    "transparent",
    "refractiveColor",
    "transparentColor",
    "ambientColor",
    "enableReflect",
    "enableRefract",
    "tStart",
    "tEnd",
    "time0",
    "time1",
    "falloff",
    "lookat",
    "Textures",
    "Global",
    "Objects",
    "cubeMap",
    "metallic",
];

#[test]
fn fields_that_are_not_rendered_warn_at_their_line_in_every_corpus_scene() {
    let Some(shared) = shared() else { return };
    let mut checked = 0;
    for (file, base) in corpus(&shared) {
        let scene = load(&file, &base);
        let text = std::fs::read_to_string(&file).expect("readable");
        for (index, line) in text.lines().enumerate() {
            let line_number = index as u32 + 1;
            for token in line.split(|c: char| c.is_whitespace() || "{}[]".contains(c)) {
                if !NOT_RENDERED.contains(&token) {
                    continue;
                }
                checked += 1;
                let warned = scene
                    .warnings
                    .iter()
                    .any(|w| w.location.line == line_number && w.message.contains(token));
                assert!(
                    warned,
                    "{}:{line_number}: '{token}' is not rendered and does not warn",
                    file.display()
                );
            }
        }
    }
    println!("{checked} fields that are not rendered, each warned at its line");
    assert!(
        checked > 0,
        "the corpus has such fields (textureScale, metallic, ...)"
    );
}
