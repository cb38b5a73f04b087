//! Progress in a batch log: when standard error is not a terminal (here a
//! pipe), a render reports one whole line at a time, with percent, samples
//! per second, elapsed and remaining time, and no carriage returns.

use std::path::Path;
use std::process::Command;

/// Renders smallpt at 80x60 and 256 spp (about a second on 2 cores) into
/// `output`, reporting progress every 0.1 s; its standard error.
fn render_log(output: &Path, extra: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args([
            "render",
            "testcases/smallpt.txt",
            "--width",
            "80",
            "--height",
            "60",
        ])
        .args(["--spp", "256", "--progress-every", "0.1"])
        .args(extra)
        .arg("-o")
        .arg(output)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let log = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(out.status.success(), "{log}");
    log
}

#[test]
fn progress_goes_to_a_batch_log_as_whole_lines() {
    let dir = std::env::temp_dir().join(format!("pathtracer-progress-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let log = render_log(&dir.join("smallpt.pfm"), &[]);
    // --quiet still prints no progress.
    let quiet_log = render_log(&dir.join("quiet.pfm"), &["--quiet"]);
    let _ = std::fs::remove_dir_all(&dir);
    assert!(!quiet_log.contains("rendering"), "{quiet_log}");
    assert!(
        !log.contains('\r'),
        "carriage returns in a batch log: {log:?}"
    );
    let lines: Vec<&str> = log.lines().filter(|l| l.starts_with("rendering")).collect();
    assert!(!lines.is_empty(), "no progress line in {log:?}");
    for line in &lines {
        for part in ["%", "M samples/s", "s elapsed"] {
            assert!(line.contains(part), "'{part}' missing from {line:?}");
        }
        assert!(
            line.contains("s left") || line.contains("estimating"),
            "{line:?}"
        );
    }
    let percents: Vec<f64> = lines
        .iter()
        .map(|l| {
            let after = l["rendering".len()..].trim_start();
            after.split('%').next().unwrap().trim().parse().unwrap()
        })
        .collect();
    assert!(
        percents.windows(2).all(|w| w[0] <= w[1]),
        "progress went backwards: {percents:?}"
    );
}
