//! Checkpoints and resume through the command line: a render stopped by
//! SIGINT or SIGTERM at any moment, or killed, and then resumed, gives the
//! bytes of an uninterrupted render; checkpoints that belong to another
//! render, or to none, are refused.

#![cfg(unix)]

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant, SystemTime};

use pathtracer::render::film_file::read_film;

fn command(args: &[&str]) -> Command {
    let mut command = Command::new(env!("CARGO_BIN_EXE_pathtracer"));
    command.args(args).current_dir(env!("CARGO_MANIFEST_DIR"));
    command
}

fn run(args: &[&str]) -> Output {
    command(args).output().expect("the binary runs")
}

fn start(args: &[&str]) -> Child {
    command(args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts")
}

fn signal(child: &Child, name: &str) {
    let status = Command::new("kill")
        .args([format!("-{name}"), child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(status.success(), "kill -{name}");
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "pathtracer-checkpoints-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn path(dir: &Path, name: &str) -> String {
    dir.join(name).to_string_lossy().into_owned()
}

/// The arguments of a render of smallpt's box (a mirror and a glass ball,
/// light subpaths on) into `output`, long enough to be stopped part way.
fn render_args<'a>(output: &'a str, spp: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        "render",
        "testcases/smallpt.txt",
        "--width",
        "32",
        "--height",
        "24",
        "--threads",
        "2",
        "--quiet",
        "--spp",
        spp,
        "-o",
        output,
    ];
    args.extend(extra);
    args
}

fn assert_success(out: &Output, what: &str) {
    assert!(
        out.status.success(),
        "{what}: {:?} {}",
        out.status,
        String::from_utf8_lossy(&out.stderr)
    );
}

/// A number in `0..1` that differs from run to run (the moment to stop a
/// render at), printed so that a failure can be repeated.
fn random_fraction() -> f64 {
    let nanos = SystemTime::now()
        .duration_since(SystemTime::UNIX_EPOCH)
        .map_or(0, |d| d.subsec_nanos());
    let fraction = (nanos % 1000) as f64 / 1000.0;
    eprintln!("stopping at fraction {fraction:.3} of the render");
    fraction
}

/// Starts the render, stops it with `name` after `delay`, and waits:
/// `Some(output)` if the signal stopped it, `None` if it had finished.
fn interrupted_at(args: &[&str], name: &str, delay: Duration) -> Option<Output> {
    let child = start(args);
    std::thread::sleep(delay);
    signal(&child, name);
    let out = child.wait_with_output().expect("the render ends");
    if out.status.success() {
        return None;
    }
    Some(out)
}

/// Renders `output` uninterrupted; then renders `resumed` stopped by
/// `name` at a random moment and resumed, and checks the two files are
/// the same bytes.
fn stop_and_resume_gives_the_same_bytes(name: &str, code: i32, extension: &str) {
    let dir = temp_dir(&format!("{name}-{extension}"));
    let whole = path(&dir, &format!("whole.{extension}"));
    let resumed = path(&dir, &format!("resumed.{extension}"));
    let spp = "1024";
    let started = Instant::now();
    assert_success(&run(&render_args(&whole, spp, &[])), "uninterrupted render");
    let duration = started.elapsed();
    let mut out = None;
    let mut fraction = 0.1 + 0.7 * random_fraction();
    for _ in 0..4 {
        out = interrupted_at(
            &render_args(&resumed, spp, &[]),
            name,
            duration.mul_f64(fraction),
        );
        if out.is_some() {
            break;
        }
        // The render was quicker this time: stop it sooner.
        std::fs::remove_file(&resumed).expect("remove the finished render");
        fraction /= 2.0;
    }
    let out = out.expect("a signal stopped the render part way");
    assert_eq!(out.status.code(), Some(code), "exit code after SIG{name}");
    let checkpoint = format!("{resumed}.checkpoint.exr");
    let (partial, header) = read_film(Path::new(&checkpoint)).expect("a checkpoint was written");
    assert!(header.checkpoint);
    let taken = partial.samples() + partial.dropped();
    assert!(
        taken < 32 * 24 * 1024,
        "the checkpoint holds part of the render: {taken} samples"
    );
    assert!(
        Path::new(&resumed).exists(),
        "the partial image was written"
    );
    let again = run(&render_args(&resumed, spp, &["--resume"]));
    assert_success(&again, "resumed render");
    assert!(
        !Path::new(&checkpoint).exists(),
        "a finished render removes its checkpoint"
    );
    let a = std::fs::read(&whole).unwrap();
    let b = std::fs::read(&resumed).unwrap();
    assert!(
        a == b,
        "an interrupted and resumed render differs from an uninterrupted one"
    );
}

#[test]
fn sigint_at_a_random_moment_then_resume_gives_the_bytes_of_one_render() {
    stop_and_resume_gives_the_same_bytes("INT", 130, "pfm");
    stop_and_resume_gives_the_same_bytes("INT", 130, "bmp");
}

#[test]
fn sigterm_stops_a_render_the_same_way() {
    stop_and_resume_gives_the_same_bytes("TERM", 143, "pfm");
}

#[test]
fn after_sigkill_resuming_loses_at_most_one_checkpoint_interval() {
    let dir = temp_dir("kill");
    let whole = path(&dir, "whole.pfm");
    let killed = path(&dir, "killed.pfm");
    let spp = "4096";
    let interval = 0.5;
    assert_success(&run(&render_args(&whole, spp, &[])), "uninterrupted render");
    let child = start(&render_args(&killed, spp, &["--checkpoint", "0.5"]));
    std::thread::sleep(Duration::from_millis(2200));
    signal(&child, "KILL");
    let killed_at = SystemTime::now();
    let out = child.wait_with_output().expect("the render ends");
    assert!(!out.status.success(), "SIGKILL ended the render part way");
    let checkpoint = format!("{killed}.checkpoint.exr");
    let written = std::fs::metadata(&checkpoint)
        .and_then(|m| m.modified())
        .expect("a checkpoint was written before the kill");
    let age = killed_at.duration_since(written).unwrap_or_default();
    // One interval, and the time one write takes (well under a second at
    // this size, even on a loaded machine).
    assert!(
        age.as_secs_f64() <= interval + 1.0,
        "the checkpoint was {age:?} old when the render was killed"
    );
    // The temporaries a kill leaves behind are the only other files.
    let again = run(&render_args(&killed, spp, &["--resume"]));
    assert_success(&again, "resumed render");
    let a = std::fs::read(&whole).unwrap();
    let b = std::fs::read(&killed).unwrap();
    assert!(
        a == b,
        "a killed and resumed render differs from one render"
    );
}

#[test]
fn checkpoints_are_refused_where_they_do_not_belong() {
    let dir = temp_dir("refused");
    let image = path(&dir, "image.pfm");
    let checkpoint = format!("{image}.checkpoint.exr");
    let spp = "4096";
    let out = interrupted_at(
        &render_args(&image, spp, &[]),
        "INT",
        Duration::from_millis(600),
    )
    .expect("the render was stopped");
    assert_eq!(out.status.code(), Some(130));
    let saved = std::fs::read(&checkpoint).expect("a checkpoint");
    let partial_image = std::fs::read(&image).expect("a partial image");

    // A new render of the same output without --resume would lose it.
    let out = run(&render_args(&image, spp, &[]));
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("--resume continues it"), "{stderr}");
    // Another seed is another render.
    let out = run(&render_args(&image, spp, &["--resume", "--seed", "9"]));
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("a checkpoint of another render (seed is"),
        "{stderr}"
    );
    // Fewer samples than some pixels already have.
    let out = run(&render_args(&image, "1", &["--resume"]));
    assert!(!out.status.success());
    // Merge takes parts of a render, not a checkpoint.
    let merged = path(&dir, "merged.pfm");
    let out = run(&["merge", &checkpoint, "-o", &merged]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("checkpoint of an unfinished render"),
        "{stderr}"
    );
    assert!(!Path::new(&merged).exists());
    // Nothing was lost on the way.
    assert_eq!(std::fs::read(&checkpoint).unwrap(), saved);
    assert_eq!(std::fs::read(&image).unwrap(), partial_image);

    // --resume without a checkpoint says so and renders from the start.
    let fresh = path(&dir, "fresh.pfm");
    let out = run(&render_args(&fresh, "4", &["--resume"]));
    assert_success(&out, "--resume without a checkpoint");
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("no checkpoint to resume"), "{stderr}");
    // An adaptive render has no checkpoints to resume.
    let out = run(&render_args(
        &fresh,
        "4",
        &["--resume", "--target-error", "0.1"],
    ));
    assert!(!out.status.success());
}

#[test]
fn two_signals_end_the_render_with_130_and_leave_no_temporaries() {
    let dir = temp_dir("twice");
    let image = path(&dir, "image.bmp");
    // A render that takes minutes: only the signals end it.
    let child = start(&render_args(&image, "1000000", &["--checkpoint", "0"]));
    std::thread::sleep(Duration::from_millis(500));
    signal(&child, "INT");
    signal(&child, "INT");
    let started = Instant::now();
    let out = child.wait_with_output().expect("the render ends");
    assert!(started.elapsed() < Duration::from_secs(10));
    assert_eq!(out.status.code(), Some(130));
    let left: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|name| name.contains(".pathtracer-tmp-"))
        .collect();
    assert!(left.is_empty(), "temporaries left behind: {left:?}");
}
