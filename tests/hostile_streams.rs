//! Hostile streams (issue 30, cases 2, 3, 4, 10 and 12): a standard error
//! that cannot be written, named pipes and devices where a command reads a
//! file or writes its output, and the signals of a closed terminal.
//!
//! Every run has a deadline (`common::DEADLINE`): the old build waited on a
//! pipe forever. `HOSTILE_BIN=old-binary` runs the tests against another
//! build. An `-o` onto a device is tried on a node made in the test's own
//! folder (`mknod`, as root), never on `/dev/null` itself: an old build
//! replaced the node it was given with a regular file.

#![cfg(unix)]

mod common;

use std::path::Path;

use common::{
    command_in, finish, fresh_dir, interrupt_long_render, leftovers, make_fifo, render_small,
    run_in, smallpt,
};
use pathtracer::limits::MAX_TABLE_BYTES;

/// A small scene with a field the parser does not know (one warning).
const SCENE_WITH_A_WARNING: &str = "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 \
    angle 30 width 8 height 8 }\nLights { numLights 0 }\n\
    Background { color 0.1 0.1 0.1 sparkle 3 }\n\
    Materials { numMaterials 1 Material { diffuseColor 1 0 0 } }\n\
    Group { numObjects 1 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } }\n";

#[test]
fn a_warning_with_stderr_on_dev_full_exited_101() {
    let full = Path::new("/dev/full");
    if !full.exists() {
        println!("skipped: no /dev/full");
        return;
    }
    let dir = fresh_dir("stderr-full");
    std::fs::write(dir.join("scene.txt"), SCENE_WITH_A_WARNING).expect("scene");
    for args in [
        &["check", "scene.txt"][..],
        &["render", "scene.txt", "-o", "out.png", "--spp", "1"][..],
    ] {
        let mut command = command_in(&dir, args);
        command.stderr(std::fs::File::create(full).expect("open /dev/full"));
        let ran = finish(command);
        assert_eq!(ran.code, Some(0), "{args:?}: {}", ran.stdout);
    }
    assert!(dir.join("out.png").is_file());
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

/// Sets up `dir` with the named pipes the commands below are given.
fn pipes(dir: &Path) -> bool {
    std::fs::create_dir_all(dir.join("r")).expect("folder");
    ["f.exr", "f.csv", "f.tsv", "r/out.png.checkpoint.exr"]
        .iter()
        .all(|name| make_fifo(&dir.join(name)))
}

#[test]
fn resume_merge_plot_and_lookalike_hung_on_a_named_pipe() {
    let dir = fresh_dir("fifo-inputs");
    if !pipes(&dir) {
        println!("skipped: no mkfifo");
        return;
    }
    let scene = smallpt();
    let scene = scene.to_str().expect("utf-8 path");
    let runs: [&[&str]; 4] = [
        &[
            "render",
            scene,
            "-o",
            "r/out.png",
            "--resume",
            "--width",
            "8",
            "--height",
            "6",
            "--spp",
            "1",
        ],
        &["merge", "f.exr", "-o", "m.png"],
        &["plot", "a=f.csv", "-o", "p.svg"],
        &["lookalike", "f.tsv", "--out", "lk"],
    ];
    for args in runs {
        let ran = run_in(&dir, args);
        let error = ran.refused();
        assert!(error.contains("not a regular file"), "{args:?}: {error}");
    }
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
    assert!(leftovers(&dir.join("r")).is_empty());
}

#[test]
fn plot_and_lookalike_of_dev_zero_grew_past_8_gb() {
    let dir = fresh_dir("dev-zero-tables");
    if !Path::new("/dev/zero").exists() {
        println!("skipped: no /dev/zero");
        return;
    }
    for args in [
        &["plot", "a=/dev/zero", "-o", "p.svg"][..],
        &["lookalike", "/dev/zero", "--out", "lk"][..],
    ] {
        let ran = run_in(&dir, args);
        let error = ran.refused();
        assert!(
            error.contains("'/dev/zero' is not a regular file"),
            "{error}"
        );
    }
}

#[test]
fn plot_read_a_4_gib_csv_whole() {
    let dir = fresh_dir("big-csv");
    // Sparse: nothing is written.
    std::fs::File::create(dir.join("big.csv"))
        .and_then(|f| f.set_len(MAX_TABLE_BYTES + 1))
        .expect("sparse file");
    std::fs::write(dir.join("pairs.tsv"), "").expect("pairs");
    std::fs::File::options()
        .append(true)
        .open(dir.join("pairs.tsv"))
        .and_then(|f| f.set_len(MAX_TABLE_BYTES + 1))
        .expect("sparse pairs");
    for args in [
        &["plot", "a=big.csv", "-o", "p.svg"][..],
        &["lookalike", "pairs.tsv", "--out", "lk"][..],
    ] {
        let ran = run_in(&dir, args);
        let error = ran.refused();
        assert!(error.contains("MAX_TABLE_BYTES"), "{error}");
    }
}

#[test]
fn an_output_onto_a_named_pipe_replaced_it_with_a_file() {
    let dir = fresh_dir("fifo-output");
    if !make_fifo(&dir.join("o.bmp")) {
        println!("skipped: no mkfifo");
        return;
    }
    let ran = render_small(&dir, "o.bmp", &[]);
    let error = ran.refused();
    assert!(error.contains("not a regular file"), "{error}");
    use std::os::unix::fs::FileTypeExt;
    let kind = std::fs::symlink_metadata(dir.join("o.bmp")).expect("still there");
    assert!(kind.file_type().is_fifo(), "the pipe was replaced");
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

/// Makes a character device at `path` like `/dev/null` (1, 3) with
/// `mknod`; false where that is not allowed (not root, no `mknod`).
fn make_null_device(path: &Path) -> bool {
    std::process::Command::new("mknod")
        .arg(path)
        .args(["c", "1", "3"])
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok_and(|s| s.success())
}

#[test]
fn an_output_onto_a_device_replaced_it_with_a_file() {
    let dir = fresh_dir("device-output");
    if !make_null_device(&dir.join("null.png")) {
        println!("skipped: cannot mknod (not root?)");
        return;
    }
    // The device itself, and a symlink to it (outputs' links are followed).
    std::os::unix::fs::symlink(dir.join("null.png"), dir.join("link.png")).expect("symlink");
    for output in ["null.png", "link.png"] {
        let ran = render_small(&dir, output, &[]);
        let error = ran.refused();
        assert!(error.contains("not a regular file"), "{output}: {error}");
    }
    use std::os::unix::fs::FileTypeExt;
    let kind = std::fs::symlink_metadata(dir.join("null.png")).expect("still there");
    assert!(kind.file_type().is_char_device(), "the device was replaced");
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

/// A render that would take minutes, stopped by `signal` once it has
/// started: ends as SIGTERM does (128 + signal), with its checkpoint
/// written and no temporary left.
fn stopped_by(signal: &str, code: i32) {
    let dir = fresh_dir(&format!("signal-{signal}"));
    let ran = interrupt_long_render(&dir, "out.png", signal);
    assert_eq!(ran.code, Some(code), "{}", ran.stderr);
    assert!(
        dir.join("out.png.checkpoint.exr").is_file(),
        "no checkpoint: {}",
        ran.stderr
    );
    assert!(dir.join("out.png").is_file(), "no partial image");
    assert!(leftovers(&dir).is_empty(), "{:?}", leftovers(&dir));
}

#[test]
fn sighup_killed_the_render_and_left_its_temporaries() {
    stopped_by("HUP", 129);
}

#[test]
fn sigquit_killed_the_render_and_left_its_temporaries() {
    stopped_by("QUIT", 131);
}
