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
}
