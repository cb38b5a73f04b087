//! Hostile scene and descriptor files (issue 12): a scene file or a rub
//! texture descriptor that is larger than `limits::MAX_SCENE_BYTES`, a
//! device such as `/dev/zero` is refused before it is read,
//! with a message naming the file, and a non-zero exit; a path of
//! thousands of bytes is cut in the middle in messages.
//!
//! Each test spawns the binary (`HOSTILE_BIN` runs them against another
//! build) and kills it if it has not ended after [`DEADLINE`]: the old build
//! read `/dev/zero` forever. Big files are sparse (`File::set_len`).

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use pathtracer::limits::MAX_SCENE_BYTES;

/// Far longer than a refusal takes (milliseconds); a run still going after
/// it is reading what it should have refused.
const DEADLINE: Duration = Duration::from_secs(20);

/// Runs `check FILE`; returns the exit code and stderr, or fails the test
/// if the run does not end by the deadline.
fn check(file: &Path) -> (Option<i32>, String) {
    let binary =
        std::env::var("HOSTILE_BIN").unwrap_or_else(|_| env!("CARGO_BIN_EXE_pathtracer").into());
    let mut child = Command::new(binary)
        .arg("check")
        .arg(file)
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    let started = Instant::now();
    loop {
        if child.try_wait().expect("wait").is_some() {
            break;
        }
        if started.elapsed() > DEADLINE {
            let _ = child.kill();
            let _ = child.wait();
            panic!("check {} still running after {DEADLINE:?}", file.display());
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let output = child.wait_with_output().expect("output");
    (
        output.status.code(),
        String::from_utf8_lossy(&output.stderr).into_owned(),
    )
}

/// `check FILE` fails cleanly (exit 1, no panic); returns its message.
fn check_fails(file: &Path) -> String {
    let (code, error) = check(file);
    assert_eq!(code, Some(1), "{error}");
    assert!(!error.contains("panicked"), "{error}");
    error
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-files-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// A sparse file of `bytes` zeros: nothing is written.
fn sparse(file: &Path, bytes: u64) {
    std::fs::File::create(file)
        .and_then(|f| f.set_len(bytes))
        .expect("sparse file");
}

/// A rub scene whose one material's texture is the descriptor `descriptor`.
fn descriptor_scene(dir: &Path, descriptor: &Path) -> PathBuf {
    let file = dir.join("scene.txt");
    std::fs::write(
        &file,
        format!(
            "PerspectiveCamera {{ center 0 0 6 direction 0 0 -1 up 0 1 0 angle 30 width 8 height 8 \
             defocusAngle 0 focusDist 1 }}\n\
             Materials {{ numMaterials 1\n Material {{ diffuseColor 1 1 1 perDiffuse 1 texture {} \
             cookTorrence 1.3 0.04 0 }}\n}}\n\
             Group {{ numObjects 1 MaterialIndex 0 Quad {{ origin -2 -2 0 u 4 0 0 v 0 4 0 }} }}\n",
            descriptor.display()
        ),
    )
    .expect("write scene");
    file
}

#[test]
fn a_scene_file_over_the_limit_was_read_whole() {
    let dir = temp_dir("big-scene");
    let file = dir.join("huge.txt");
    sparse(&file, MAX_SCENE_BYTES + 1);
    let error = check_fails(&file);
    assert!(error.contains("huge.txt"), "{error}");
    assert!(error.contains("MAX_SCENE_BYTES"), "{error}");
    // A file at the limit is read (and then found to hold no camera).
    sparse(&file, 1 << 10);
    let error = check_fails(&file);
    assert!(error.contains("no camera"), "{error}");
}

#[test]
fn check_dev_zero_read_forever() {
    let zero = Path::new("/dev/zero");
    if !zero.exists() {
        return;
    }
    let error = check_fails(zero);
    assert!(
        error.contains("'/dev/zero' is not a regular file"),
        "{error}"
    );
}

#[test]
fn a_descriptor_over_the_limit_was_read_whole() {
    let dir = temp_dir("big-descriptor");
    let descriptor = dir.join("huge.txt");
    sparse(&descriptor, MAX_SCENE_BYTES + 1);
    let error = check_fails(&descriptor_scene(&dir, &descriptor));
    assert!(error.contains("scene.txt:3:"), "{error}");
    assert!(error.contains("huge.txt"), "{error}");
    assert!(error.contains("MAX_SCENE_BYTES"), "{error}");
}

#[cfg(unix)]
#[test]
fn a_descriptor_linked_to_dev_zero_was_read_forever() {
    let zero = Path::new("/dev/zero");
    if !zero.exists() {
        return;
    }
    let dir = temp_dir("zero-descriptor");
    // A descriptor is named by its `.txt` ending: a link gives it one.
    let descriptor = dir.join("zero.txt");
    std::os::unix::fs::symlink(zero, &descriptor).expect("symlink");
    let error = check_fails(&descriptor_scene(&dir, &descriptor));
    assert!(error.contains("scene.txt:3:"), "{error}");
    assert!(error.contains("is not a regular file"), "{error}");
}

#[test]
fn a_path_of_thousands_of_bytes_was_shown_whole_in_messages() {
    // 15 folders of 200 bytes: 3 kB, within Linux's 4096-byte paths.
    let mut deep = temp_dir("long-path");
    for _ in 0..15 {
        deep.push("d".repeat(200));
    }
    std::fs::create_dir_all(&deep).expect("deep folders");
    let mesh = deep.join("bad.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 nan\nf 1 2 3\n").expect("write mesh");
    let scene = deep.join("scene.txt");
    std::fs::write(
        &scene,
        format!(
            "PerspectiveCamera {{ center 0 0 10 direction 0 0 -1 up 0 1 0 angle 40 width 8 \
             height 8 }}\nMaterials {{ Material {{ color 1 1 1 }} }}\n\
             Group {{ TriangleMesh {{ obj_file {} }} }}\n",
            mesh.display()
        ),
    )
    .expect("write scene");
    let error = check_fails(&scene);
    let first = error.lines().next().unwrap_or_default();
    // Both paths (the scene's and the mesh's) are cut to their bound.
    let bound = 2 * pathtracer::limits::MAX_SHOWN_PATH + 100;
    assert!(first.chars().count() < bound, "{} chars", first.len());
    assert_eq!(first.matches('…').count(), 2, "{first}");
    let start = std::env::temp_dir().display().to_string();
    assert!(first.starts_with(&format!("error: {start}")), "{first}");
    assert!(first.contains("/scene.txt:3:"), "{first}");
    assert!(first.contains("/bad.obj:3: "), "{first}");
    assert!(first.contains("not a finite number"), "{first}");
}
