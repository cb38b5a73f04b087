//! Running the binary for the hostile-input tests: in a folder, with a
//! deadline (a run still going after it is waiting on what it should have
//! refused), and against another build when `HOSTILE_BIN` names one (to
//! check that a test fails on an older binary).

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// Far longer than a refusal takes (milliseconds).
pub const DEADLINE: Duration = Duration::from_secs(30);

/// How one run ended.
pub struct Ran {
    /// The exit code (`None`: ended by a signal).
    pub code: Option<i32>,
    pub stdout: String,
    pub stderr: String,
}

impl Ran {
    /// Asserts a clean refusal: exit 1, no panic, no abort; returns stderr.
    pub fn refused(&self) -> &str {
        assert_eq!(self.code, Some(1), "{}", self.stderr);
        assert!(!self.stderr.contains("panicked"), "{}", self.stderr);
        &self.stderr
    }
}

pub fn binary() -> PathBuf {
    std::env::var_os("HOSTILE_BIN")
        .map(PathBuf::from)
        .unwrap_or_else(|| env!("CARGO_BIN_EXE_pathtracer").into())
}

/// A fresh folder for one test.
pub fn fresh_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// The binary with `args`, in `dir`, its outputs captured.
pub fn command_in(dir: &Path, args: &[&str]) -> Command {
    let mut command = Command::new(binary());
    command
        .args(args)
        .current_dir(dir)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    command
}

/// Runs `command`, killing it (and failing the test) after [`DEADLINE`].
pub fn finish(mut command: Command) -> Ran {
    let child = command.spawn().expect("the binary runs");
    wait_within(child, DEADLINE)
}

/// Waits for `child`, killing it (and failing the test) after `deadline`.
pub fn wait_within(mut child: Child, deadline: Duration) -> Ran {
    let started = Instant::now();
    while child.try_wait().expect("wait").is_none() {
        if started.elapsed() > deadline {
            let _ = child.kill();
            let _ = child.wait();
            panic!("still running after {deadline:?}");
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    let output = child.wait_with_output().expect("output");
    Ran {
        code: output.status.code(),
        stdout: String::from_utf8_lossy(&output.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&output.stderr).into_owned(),
    }
}

/// Runs the binary with `args` in `dir` (see [`finish`]).
pub fn run_in(dir: &Path, args: &[&str]) -> Ran {
    finish(command_in(dir, args))
}

/// The temporaries left in `dir` (the README's `.pathtracer-tmp-` pattern).
pub fn leftovers(dir: &Path) -> Vec<String> {
    std::fs::read_dir(dir)
        .map(|entries| {
            entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|name| name.contains(".pathtracer-tmp-"))
                .collect()
        })
        .unwrap_or_default()
}

/// Makes a named pipe at `path` (with `mkfifo`); false where there is none.
pub fn make_fifo(path: &Path) -> bool {
    Command::new("mkfifo")
        .arg(path)
        .status()
        .is_ok_and(|s| s.success())
}

/// The scene of the project's smallpt box (a mirror and a glass ball).
pub fn smallpt() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/smallpt.txt")
}

/// Renders smallpt's box in `dir` into `output` at 8x6 and 1 spp, with
/// `extra` arguments after those.
pub fn render_small(dir: &Path, output: &str, extra: &[&str]) -> Ran {
    let scene = smallpt();
    let scene = scene.to_str().expect("a UTF-8 path");
    let mut args = vec![
        "render", scene, "-o", output, "--width", "8", "--height", "6", "--spp", "1",
    ];
    args.extend_from_slice(extra);
    run_in(dir, &args)
}

/// Starts a render of smallpt's box in `dir` into `output` that would take
/// minutes (32x24 at a million spp, checkpoints only when stopped), sends
/// it `signal` (a name for `kill`: `INT`, `HUP`, ...) once it renders (its
/// temporaries exist, and half a second later), and waits for it to end.
pub fn interrupt_long_render(dir: &Path, output: &str, signal: &str) -> Ran {
    let scene = smallpt();
    let args = [
        "render",
        scene.to_str().expect("a UTF-8 path"),
        "-o",
        output,
        "--width",
        "32",
        "--height",
        "24",
        "--spp",
        "1000000",
        "--checkpoint",
        "0",
        "--quiet",
    ];
    let child = command_in(dir, &args).spawn().expect("the binary runs");
    let started = Instant::now();
    while leftovers(dir).is_empty() && started.elapsed() < Duration::from_secs(20) {
        std::thread::sleep(Duration::from_millis(20));
    }
    std::thread::sleep(Duration::from_millis(500));
    let status = Command::new("kill")
        .args([format!("-{signal}"), child.id().to_string()])
        .status()
        .expect("kill runs");
    assert!(status.success(), "kill -{signal}");
    wait_within(child, Duration::from_secs(60))
}
