//! Progress in a batch log: when standard error is not a terminal (here a
//! pipe), a render reports one whole line at a time, with percent, samples
//! per second, elapsed and remaining time, and no carriage returns.

use std::process::Command;

#[test]
fn progress_goes_to_a_batch_log_as_whole_lines() {
    let dir = std::env::temp_dir().join(format!("pathtracer-progress-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let output = dir.join("smallpt.pfm");
    // About a second of rendering on 2 cores, reported every 0.1 s.
    let out = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args([
            "render",
            "testcases/smallpt.txt",
            "--width",
            "80",
            "--height",
            "60",
        ])
        .args(["--spp", "256", "--progress-every", "0.1", "-o"])
        .arg(&output)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let log = String::from_utf8_lossy(&out.stderr);
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
            l["rendering".len()..]
                .trim_start()
                .split('%')
                .next()
                .unwrap()
                .trim()
                .parse()
                .unwrap()
        })
        .collect();
    assert!(
        percents.windows(2).all(|w| w[0] <= w[1]),
        "progress went backwards: {percents:?}"
    );
    // --quiet still prints no progress.
    let quiet = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args([
            "render",
            "testcases/smallpt.txt",
            "--width",
            "80",
            "--height",
            "60",
        ])
        .args(["--spp", "256", "--progress-every", "0.1", "--quiet", "-o"])
        .arg(dir.join("quiet.pfm"))
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let _ = std::fs::remove_dir_all(&dir);
    assert!(
        quiet.status.success(),
        "{}",
        String::from_utf8_lossy(&quiet.stderr)
    );
    let quiet_log = String::from_utf8_lossy(&quiet.stderr);
    assert!(!quiet_log.contains("rendering"), "{quiet_log}");
}
