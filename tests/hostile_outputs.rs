//! Hostile output names (issue 30, cases 8 and 9): an output name so long
//! that its checkpoint's or sidecar's name did not fit, and two outputs of
//! one command on the same file.
//!
//! `HOSTILE_BIN` runs them against another build.

#![cfg(unix)]

mod common;

use common::{fresh_dir, interrupt_long_render, leftovers, render_small, run_in, smallpt};
use pathtracer::limits::MAX_FILE_NAME_BYTES;
use std::path::Path;

/// The names in `dir` that end with `suffix`.
fn named(dir: &Path, suffix: &str) -> Vec<String> {
    std::fs::read_dir(dir)
        .expect("folder")
        .filter_map(|e| e.ok())
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .filter(|name| name.ends_with(suffix))
        .collect()
}

#[test]
fn an_output_name_of_255_bytes_had_no_room_for_its_sidecar() {
    let dir = fresh_dir("long-sidecar");
    let name = format!("{}.pfm", "s".repeat(MAX_FILE_NAME_BYTES - 4));
    let ran = render_small(&dir, &name, &[]);
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    assert!(dir.join(&name).is_file());
    let sidecars = named(&dir, ".json");
    assert_eq!(sidecars.len(), 1, "{sidecars:?}");
    assert!(sidecars[0].len() <= MAX_FILE_NAME_BYTES);
    // The same output gets the same sidecar name (a second render replaces it).
    let again = render_small(&dir, &name, &[]);
    assert_eq!(again.code, Some(0), "{}", again.stderr);
    assert_eq!(named(&dir, ".json"), sidecars);
}

#[test]
fn sigint_with_a_246_byte_output_name_saved_nothing() {
    let dir = fresh_dir("long-checkpoint");
    let name = format!("{}.png", "c".repeat(246 - 4));
    let ran = interrupt_long_render(&dir, &name, "INT");
    assert_eq!(ran.code, Some(130), "{}", ran.stderr);
    let checkpoints = named(&dir, ".checkpoint.exr");
    assert_eq!(checkpoints.len(), 1, "{}", ran.stderr);
    assert!(checkpoints[0].len() <= MAX_FILE_NAME_BYTES);
    assert!(ran.stdout.contains("--resume"), "{}", ran.stdout);
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

#[test]
fn merge_with_film_and_image_on_one_path_overwrote_the_film() {
    let dir = fresh_dir("same-outputs");
    let scene = smallpt();
    let scene = scene.to_str().expect("utf-8 path");
    let part = run_in(
        &dir,
        &[
            "render", scene, "--film", "part.exr", "--width", "8", "--height", "6", "--spp", "2",
            "--quiet",
        ],
    );
    assert_eq!(part.code, Some(0), "{}", part.stderr);
    for output in ["m.exr", "./m.exr"] {
        let ran = run_in(
            &dir,
            &["merge", "part.exr", "--film", "m.exr", "-o", output],
        );
        let error = ran.refused();
        assert!(error.contains("the same file"), "{error}");
    }
    assert!(!dir.join("m.exr").exists());
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

#[test]
fn converge_with_csv_and_plot_on_one_path_lost_the_csv() {
    let dir = fresh_dir("same-curves");
    let scene = smallpt();
    let ran = run_in(
        &dir,
        &[
            "converge",
            scene.to_str().expect("utf-8 path"),
            "--csv",
            "c.svg",
            "--plot",
            "c.svg",
            "--width",
            "8",
            "--height",
            "6",
            "--max-spp",
            "2",
            "--reference-spp",
            "4",
        ],
    );
    let error = ran.refused();
    assert!(error.contains("the same file"), "{error}");
    assert!(!dir.join("c.svg").exists());
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}
