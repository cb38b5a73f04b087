//! Look detection a user can trust: a file in the canonical grammar
//! (docs/guide/scene-format.md, "The canonical grammar") renders in
//! `original` with any of its fields, and a coursework look is chosen only
//! on its renderer's own fingerprint, which the reason names.

use std::path::{Path, PathBuf};

use pathtracer::look::Look;
use pathtracer::look::detect::{Evidence, FINGERPRINTS};
use pathtracer::scene::model::Dialect;
use pathtracer::scene::{LoadOptions, load_scene};

const GUIDE: &str = include_str!("../docs/guide/scene-format.md");

/// The guide's file of every canonical field.
fn canonical_grammar() -> Vec<&'static str> {
    let section = GUIDE
        .split("## The canonical grammar")
        .nth(1)
        .expect("the guide has a section 'The canonical grammar'");
    let block = section
        .split("```")
        .nth(1)
        .expect("the section holds the grammar as a code block");
    block.lines().filter(|l| !l.trim().is_empty()).collect()
}

fn opens_or_closes(line: &str) -> bool {
    let line = line.trim();
    line.ends_with('{') || line == "}"
}

/// The grammar's skeleton (block openings and closings) with the colours of
/// its materials: the smallest hand-written canonical scene, and each
/// other line of the grammar added to it alone.
fn variants() -> (Vec<String>, Vec<(String, String)>) {
    let lines = canonical_grammar();
    let mut blocks: Vec<&str> = Vec::new();
    let mut keep = Vec::new();
    for line in &lines {
        let word = line.split_whitespace().next().unwrap_or("");
        if opens_or_closes(line) {
            if line.trim() == "}" {
                blocks.pop();
            } else {
                blocks.push(word);
            }
            keep.push(true);
        } else {
            keep.push(word == "color" && blocks.last() == Some(&"Material"));
        }
    }
    let base: Vec<String> = lines
        .iter()
        .zip(&keep)
        .filter(|(_, k)| **k)
        .map(|(l, _)| l.to_string())
        .collect();
    let mut added = Vec::new();
    for (index, line) in lines.iter().enumerate() {
        if keep[index] {
            continue;
        }
        let text: Vec<&str> = lines
            .iter()
            .enumerate()
            .filter(|(i, _)| keep[*i] || *i == index)
            .map(|(_, l)| *l)
            .collect();
        added.push((line.trim().to_string(), text.join("\n")));
    }
    (base, added)
}

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn look_of_text(dir: &Path, name: &str, text: &str) -> (Look, String) {
    let file = dir.join(name);
    std::fs::write(&file, text).expect("writes the scene");
    let options = LoadOptions {
        base: Some(root()),
        ..LoadOptions::default()
    };
    let scene = load_scene(&file, &options).unwrap_or_else(|e| panic!("{name}: {e}\n{text}"));
    Look::detect(&scene)
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pt-look-detection-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

#[test]
fn a_canonical_scene_stays_original_whatever_canonical_field_is_added() {
    let dir = temp_dir("canonical");
    let (base, added) = variants();
    assert!(
        added.len() >= 40,
        "the grammar lists {} fields",
        added.len()
    );
    let (look, why) = look_of_text(&dir, "base.txt", &base.join("\n"));
    assert_eq!(look.name, "original", "the base scene: {why}");
    for (index, (line, text)) in added.iter().enumerate() {
        let (look, why) = look_of_text(&dir, &format!("added{index}.txt"), text);
        assert_eq!(look.name, "original", "with '{line}' added: {why}");
    }
    let everything = canonical_grammar().join("\n");
    let (look, why) = look_of_text(&dir, "all.txt", &everything);
    assert_eq!(look.name, "original", "the whole grammar: {why}");
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn no_fingerprint_is_of_the_canonical_dialect() {
    // Together with the test above (canonical fields keep a file in the
    // canonical dialect), no canonical file can carry a fingerprint of its
    // words: only a file inside a clone of the renderer's repository, named
    // owner+repository in full, can (W-Solaris's scene05).
    for row in FINGERPRINTS {
        let in_a_clone = matches!(
            row.evidence,
            Evidence::Folder {
                repository_alone: false,
                ..
            }
        );
        assert!(
            in_a_clone || !row.dialects.contains(&Dialect::Canonical),
            "{}",
            row.look.name
        );
        if let Evidence::AnyWord(words) = row.evidence {
            assert!(!words.is_empty(), "{}: a row of no words", row.look.name);
        }
    }
}

const CAMERA: &str =
    "PerspectiveCamera { center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }\n";

#[test]
fn the_reason_names_the_fingerprint_found() {
    let dir = temp_dir("reasons");
    let cases = [
        (
            "Material { color 1 1 1 type 1 0 0 glossy 1 }",
            "osb",
            "'glossy'",
        ),
        (
            "Material { color 1 1 1 type 1 0 0 } } DiskLights { numDiskLights 0 } Materials {",
            "ylc",
            "'DiskLights'",
        ),
        (
            "Material { color 1 1 1 type 1 0 0 bump texture/checker.bmp }",
            "wso",
            "'bump'",
        ),
        (
            "Material { diffuseColor 1 0 0 specularColor 1 1 1 shininess 20 }",
            "pa1",
            "pa1 dialect",
        ),
    ];
    for (index, (material, look, found)) in cases.iter().enumerate() {
        let text = format!("{CAMERA}Materials {{ {material} }}");
        let (detected, why) = look_of_text(&dir, &format!("case{index}.txt"), &text);
        assert_eq!(detected.name, *look, "{material}: {why}");
        assert!(
            why.contains(found),
            "{material}: '{why}' does not name {found}"
        );
    }
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn the_shared_dialect_of_w_solaris_and_yuzc19_is_said_with_the_look_that_tells_them_apart() {
    let dir = temp_dir("shared-dialect");
    let text = format!("{CAMERA}Materials {{ Material {{ color 1 1 1 type 1 0 0 refr 1.5 }} }}");
    let (look, why) = look_of_text(&dir, "d3.txt", &text);
    assert_eq!(look.name, "yzc");
    assert!(
        why.contains("W-Solaris") && why.contains("--look wso"),
        "{why}"
    );
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn a_canonical_file_takes_w_solaris_look_only_inside_a_clone_named_in_full() {
    let dir = temp_dir("clone");
    let text = format!("{CAMERA}Materials {{ Material {{ color 1 1 1 }} }}");
    let clone = dir.join("W-Solaris+computer-graphics").join("testcases");
    let anybody = dir.join("computer-graphics").join("testcases");
    for folder in [&clone, &anybody] {
        std::fs::create_dir_all(folder).expect("folder");
    }
    let (look, why) = look_of_text(&clone, "scene05.txt", &text);
    assert_eq!(look.name, "wso", "{why}");
    assert!(why.contains("W-Solaris/computer-graphics"), "{why}");
    let (look, why) = look_of_text(&anybody, "scene05.txt", &text);
    assert_eq!(look.name, "original", "{why}");
    let (look, why) = look_of_text(&dir, "scene05.txt", &text);
    assert_eq!(look.name, "original", "{why}");
    std::fs::remove_dir_all(&dir).ok();
}
