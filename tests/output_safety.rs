//! Outputs under hostile or careless use: refused before any work when they
//! cannot be written, never an input of the run, written through symlinks,
//! image and sidecar replaced together, and no temporary left by a signal.

use std::fs;
use std::path::{Path, PathBuf};
use std::process::{Command, Output, Stdio};

use pathtracer::image_io::{PendingFile, TEMPORARY_MARK, commit_together};

/// What `render` prints once an image is written.
const SUMMARY: &str = "spp spent";

fn pathtracer_in(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the binary runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-output-{name}-{}", std::process::id()));
    let _ = fs::remove_dir_all(&dir);
    fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn project(path: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(path)
}

/// A render of smallpt, tiny, into `output` (relative to `dir`).
fn render(dir: &Path, scene: &Path, output: &str) -> Output {
    let scene = scene.to_str().expect("utf-8 path");
    pathtracer_in(
        dir,
        &[
            "render", scene, "-o", output, "--width", "8", "--height", "6", "--spp", "1", "--quiet",
        ],
    )
}

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The names in `dir` that are temporaries of this program.
fn temporaries(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|name| name.contains(TEMPORARY_MARK))
                .collect()
        })
        .unwrap_or_default()
}

/// The run failed with `message`, before the scene was read: the scene
/// does not exist, so an output check after loading would report that.
fn assert_refused_before_the_scene(out: &Output, message: &str) {
    let text = stderr(out);
    assert!(!out.status.success(), "exit 0; stderr: {text}");
    assert!(text.contains(message), "expected '{message}' in: {text}");
    assert!(
        !text.contains("no-such-scene.txt"),
        "the scene was read first: {text}"
    );
}

#[test]
fn output_in_a_folder_that_takes_no_files_is_refused_before_the_scene_is_read() {
    let dir = temp_dir("proc");
    let missing = dir.join("no-such-scene.txt");
    let out = render(&dir, &missing, "/proc/pathtracer-output.png");
    assert_refused_before_the_scene(&out, "/proc/pathtracer-output.png: cannot create a file in");
    // A read-only folder, where permissions hold (not for root).
    let locked = dir.join("locked");
    fs::create_dir(&locked).unwrap();
    set_mode(&locked, 0o555);
    if fs::write(locked.join("probe"), b"").is_err() {
        let out = render(&dir, &missing, "locked/x.bmp");
        assert_refused_before_the_scene(&out, "locked/x.bmp: cannot create a file in locked");
    }
    set_mode(&locked, 0o755);
}

fn set_mode(path: &Path, mode: u32) {
    use std::os::unix::fs::PermissionsExt;
    fs::set_permissions(path, fs::Permissions::from_mode(mode)).unwrap();
}

#[test]
fn output_that_is_a_directory_is_refused_before_the_scene_is_read() {
    let dir = temp_dir("directory");
    fs::create_dir(dir.join("image.bmp")).unwrap();
    let out = render(&dir, &dir.join("no-such-scene.txt"), "image.bmp");
    assert_refused_before_the_scene(&out, "image.bmp: is a directory");
}

#[test]
fn default_output_folder_blocked_by_a_file_is_refused_before_the_scene_is_read() {
    let dir = temp_dir("blocked");
    fs::write(dir.join("output"), b"not a folder").unwrap();
    let missing = dir.join("no-such-scene.txt");
    let out = pathtracer_in(&dir, &["render", missing.to_str().unwrap(), "--quiet"]);
    assert_refused_before_the_scene(&out, "cannot create folder output");
    assert_eq!(fs::read(dir.join("output")).unwrap(), b"not a folder");
}

#[test]
fn output_name_longer_than_the_file_system_allows_is_refused_before_the_scene_is_read() {
    let dir = temp_dir("too-long");
    let name = format!("{}.bmp", "n".repeat(252));
    let out = render(&dir, &dir.join("no-such-scene.txt"), &name);
    assert_refused_before_the_scene(&out, "more than the file system allows");
    assert!(temporaries(&dir).is_empty());
}

#[test]
fn output_name_of_255_bytes_is_written_though_its_temporary_would_be_longer() {
    let dir = temp_dir("255");
    let name = format!("{}.bmp", "l".repeat(251));
    assert_eq!(name.len(), 255);
    let out = render(&dir, &project("testcases/smallpt.txt"), &name);
    assert!(out.status.success(), "{}", stderr(&out));
    assert_eq!(fs::read(dir.join(&name)).unwrap().len(), 54 + 8 * 6 * 3);
    assert!(temporaries(&dir).is_empty());
}

#[test]
fn output_onto_the_scene_file_is_refused_and_the_scene_kept() {
    let dir = temp_dir("scene");
    let scene = dir.join("scene.bmp");
    fs::copy(project("testcases/smallpt.txt"), &scene).unwrap();
    fs::hard_link(&scene, dir.join("hard-link.bmp")).unwrap();
    let original = fs::read(&scene).unwrap();
    for output in ["scene.bmp", "./scene.bmp", "hard-link.bmp"] {
        let out = render(&dir, Path::new("scene.bmp"), output);
        assert!(!out.status.success(), "-o {output}: exit 0");
        assert!(
            stderr(&out).contains("is the scene file"),
            "{}",
            stderr(&out)
        );
        assert!(!stdout(&out).contains(SUMMARY), "-o {output} rendered");
        assert_eq!(fs::read(&scene).unwrap(), original, "-o {output}");
    }
    assert!(temporaries(&dir).is_empty());
}

#[test]
fn output_onto_a_texture_of_the_scene_is_refused_and_the_texture_kept() {
    let dir = temp_dir("asset");
    for folder in ["testcases", "texture", "mesh"] {
        fs::create_dir(dir.join(folder)).unwrap();
    }
    for file in [
        "testcases/showcase.txt",
        "texture/checker.bmp",
        "mesh/torus.obj",
    ] {
        fs::copy(project(file), dir.join(file)).unwrap();
    }
    let texture = fs::read(dir.join("texture/checker.bmp")).unwrap();
    let out = render(
        &dir,
        Path::new("testcases/showcase.txt"),
        "texture/checker.bmp",
    );
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("is a file the scene reads"),
        "{}",
        stderr(&out)
    );
    assert!(!stdout(&out).contains(SUMMARY));
    assert_eq!(fs::read(dir.join("texture/checker.bmp")).unwrap(), texture);
    assert!(temporaries(&dir.join("texture")).is_empty());
}

#[test]
fn convert_onto_its_input_is_refused() {
    let dir = temp_dir("convert");
    let out = render(&dir, &project("testcases/smallpt.txt"), "a.bmp");
    assert!(out.status.success(), "{}", stderr(&out));
    let before = fs::read(dir.join("a.bmp")).unwrap();
    let out = pathtracer_in(&dir, &["convert", "a.bmp", "./a.bmp", "--gamma", "2.2"]);
    assert!(!out.status.success());
    assert!(stderr(&out).contains("is the input"), "{}", stderr(&out));
    assert_eq!(fs::read(dir.join("a.bmp")).unwrap(), before);
}

#[test]
fn output_through_a_symlink_updates_its_target_and_keeps_the_link() {
    let dir = temp_dir("symlink");
    fs::write(dir.join("real.bmp"), b"old").unwrap();
    std::os::unix::fs::symlink("real.bmp", dir.join("link.bmp")).unwrap();
    std::os::unix::fs::symlink("new.bmp", dir.join("dangling.bmp")).unwrap();
    for (link, target) in [("link.bmp", "real.bmp"), ("dangling.bmp", "new.bmp")] {
        let out = render(&dir, &project("testcases/smallpt.txt"), link);
        assert!(out.status.success(), "{}", stderr(&out));
        let kind = fs::symlink_metadata(dir.join(link)).unwrap().file_type();
        assert!(kind.is_symlink(), "{link} was replaced by a file");
        assert_eq!(fs::read(dir.join(target)).unwrap().len(), 54 + 8 * 6 * 3);
    }
    assert!(temporaries(&dir).is_empty());
}

#[test]
fn unwritable_sidecar_is_refused_before_rendering_and_the_image_kept() {
    let dir = temp_dir("sidecar");
    fs::write(dir.join("x.pfm"), b"old image").unwrap();
    fs::create_dir(dir.join("x.pfm.json")).unwrap();
    let out = render(&dir, &project("testcases/smallpt.txt"), "x.pfm");
    assert!(!out.status.success());
    assert!(
        stderr(&out).contains("x.pfm.json: is a directory"),
        "{}",
        stderr(&out)
    );
    assert!(!stdout(&out).contains(SUMMARY));
    assert_eq!(fs::read(dir.join("x.pfm")).unwrap(), b"old image");
    assert!(temporaries(&dir).is_empty());
}

#[test]
fn failed_rename_of_the_second_output_puts_the_first_back() {
    let dir = temp_dir("together");
    let (old, new, blocked) = (dir.join("old.pfm"), dir.join("new.pfm"), dir.join("b.json"));
    fs::write(&old, b"old image").unwrap();
    let mut files = Vec::new();
    for path in [&old, &new, &blocked] {
        let mut file = PendingFile::reserve(path).unwrap();
        file.write(b"new content").unwrap();
        files.push(file);
    }
    // The last temporary vanishes (as if removed by hand): its rename fails.
    fs::write(&blocked, b"old sidecar").unwrap();
    let last = temporaries(&dir)
        .into_iter()
        .find(|t| t.starts_with(".b.json"));
    fs::remove_file(dir.join(last.expect("the temporary of b.json"))).unwrap();
    let error = commit_together(files).expect_err("renaming a vanished temporary fails");
    assert!(error.contains("put back as they were"), "{error}");
    assert_eq!(fs::read(&old).unwrap(), b"old image");
    assert!(!new.exists(), "a new first output stays after the failure");
    assert_eq!(fs::read(&blocked).unwrap(), b"old sidecar");
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
}

/// Renders far more samples than the test waits for, sends `signal` once its
/// temporaries exist, and returns the exit code.
fn interrupted_render(name: &str, signal: &str) -> (PathBuf, Option<i32>) {
    let dir = temp_dir(name);
    let mut child = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(["render", project("testcases/smallpt.txt").to_str().unwrap()])
        .args(["-o", "out.pfm", "--width", "64", "--height", "48"])
        .args(["--spp", "10000000", "--threads", "1", "--quiet"])
        .current_dir(&dir)
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .expect("the binary runs");
    // Temporaries are created before the scene is read; seconds of waiting
    // for them is a broken build, not a slow machine.
    for _ in 0..1000 {
        if temporaries(&dir).len() == 2 {
            break;
        }
        assert!(
            child.try_wait().unwrap().is_none(),
            "the render ended early"
        );
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    if temporaries(&dir).len() < 2 {
        let _ = child.kill();
        panic!("no temporary files appeared before the render");
    }
    let pid = child.id().to_string();
    let sent = Command::new("kill").args([signal, &pid]).status().unwrap();
    assert!(sent.success());
    (dir, child.wait().unwrap().code())
}

#[test]
fn sigint_during_a_render_removes_its_temporaries_and_exits_130() {
    let (dir, code) = interrupted_render("sigint", "-INT");
    assert_eq!(code, Some(130));
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
    assert_no_image_or_a_partial_one(&dir);
}

/// Stopped before rendering, a render writes nothing; stopped while
/// rendering, a partial image that says so, with its checkpoint.
fn assert_no_image_or_a_partial_one(dir: &Path) {
    if dir.join("out.pfm").exists() {
        let sidecar = std::fs::read_to_string(dir.join("out.pfm.json")).expect("its sidecar");
        assert!(sidecar.contains("\"complete\": false"), "{sidecar}");
        assert!(dir.join("out.pfm.checkpoint.exr").exists());
    }
}

#[test]
fn sigterm_during_a_render_removes_its_temporaries_and_exits_143() {
    let (dir, code) = interrupted_render("sigterm", "-TERM");
    assert_eq!(code, Some(143));
    assert!(temporaries(&dir).is_empty(), "{:?}", temporaries(&dir));
    assert_no_image_or_a_partial_one(&dir);
}
