//! Every scene of the shared corpus loads without error (and some facts about them hold).

use std::path::{Path, PathBuf};

use pathtracer::scene::model::{Object, Scene};
use pathtracer::scene::{LoadOptions, load_scene};

fn shared() -> Option<PathBuf> {
    let dir = PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/../shared"));
    if dir.is_dir() {
        Some(dir)
    } else {
        println!("skipped: ../shared not found");
        None
    }
}

/// (scene file, base folder) of every corpus scene whose assets are all present.
fn corpus(shared: &Path) -> Vec<(PathBuf, PathBuf)> {
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
            if let [_, file, status, ..] = cells.as_slice()
                && status.starts_with("complete")
                && file.starts_with('`')
            {
                scenes.push((repo.join(file.trim_matches('`')), base.clone()));
            }
        }
    }
    scenes
}

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
