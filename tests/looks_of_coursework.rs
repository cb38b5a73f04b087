//! `check` names a look of its own for every scene of every coursework
//! folder of ../shared/reference/ (the renderer's, found by its
//! fingerprint); the photon mappers' folders, whose framework files carry
//! no word of their own, their renderer's look by folder ([`OWN`]).

mod common;

use std::path::{Path, PathBuf};

use pathtracer::look::Look;
use pathtracer::scene::{LoadOptions, MissingAssets, load_scene};

/// Folders every scene of which must have this look (issue 32).
const OWN: [(&str, &str); 2] = [
    ("Tschal-rsa+rang-kardan", "tsc"),
    ("yao-jz+Computer-Graphics-THU", "yao"),
];

/// The scene files of a folder (in `testcases/`, or `code/testcases/` for
/// chen-yingfa's) with the folder their paths resolve against.
fn scenes_of(folder: &Path) -> Vec<(PathBuf, PathBuf)> {
    let mut files = Vec::new();
    for base in [folder.to_path_buf(), folder.join("code")] {
        let mut found: Vec<PathBuf> = std::fs::read_dir(base.join("testcases"))
            .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
            .unwrap_or_default();
        found.retain(|p| p.extension().is_some_and(|e| e == "txt"));
        found.sort();
        files.extend(found.into_iter().map(|file| (file, base.clone())));
    }
    files
}

#[test]
fn every_coursework_scene_gets_a_look_of_its_own() {
    let Some(shared) = common::shared() else {
        return;
    };
    let reference = shared.join("reference");
    let mut folders = vec![reference.join("cambrian-pathtracer")];
    let mut coursework: Vec<PathBuf> = std::fs::read_dir(reference.join("coursework"))
        .map(|d| d.filter_map(|e| e.ok().map(|e| e.path())).collect())
        .unwrap_or_default();
    coursework.retain(|p| p.is_dir());
    coursework.sort();
    folders.extend(coursework);
    let options = LoadOptions {
        missing_assets: MissingAssets::Placeholder,
        ..LoadOptions::default()
    };
    let mut checked = 0;
    let mut without = Vec::new();
    for folder in &folders {
        let name = folder.file_name().and_then(|n| n.to_str()).unwrap_or("");
        let own = OWN.iter().find(|(f, _)| *f == name).map(|(_, look)| *look);
        for (file, base) in scenes_of(folder) {
            let options = LoadOptions {
                base: Some(base),
                ..options.clone()
            };
            let Ok(scene) = load_scene(&file, &options) else {
                continue;
            };
            let (look, why) = Look::detect(&scene);
            println!("{name}/{}: {} ({why})", file.display(), look.name);
            checked += 1;
            if why.contains("no look of its own")
                || look.name == "original"
                || own.is_some_and(|own| own != look.name)
            {
                without.push(format!("{name}: {} ({why})", file.display()));
            }
        }
    }
    assert!(checked > 100, "only {checked} scenes checked");
    assert!(
        without.is_empty(),
        "without a look of their own:\n{}",
        without.join("\n")
    );
}
