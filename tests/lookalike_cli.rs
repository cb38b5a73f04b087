//! `pathtracer compare` with FLIP, the look-alike criterion and `--diff`, and
//! `pathtracer lookalike` over a small pairs file, as a user runs them.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use pathtracer::image_io::{DisplayImage, read_image};

fn pathtracer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn succeeds(args: &[&str]) -> String {
    let out = pathtracer(args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!(
        "pathtracer-lookalike-{name}-{}",
        std::process::id()
    ));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Renders smallpt's Cornell box small and fast; `extra` adds options.
fn render(out: &Path, size: (u32, u32), extra: &[&str]) {
    let (width, height) = (size.0.to_string(), size.1.to_string());
    let mut args = vec![
        "render",
        "testcases/smallpt.txt",
        "-o",
        out.to_str().unwrap(),
        "--width",
        &width,
        "--height",
        &height,
        "--spp",
        "4",
        "--quiet",
    ];
    args.extend_from_slice(extra);
    succeeds(&args);
}

#[test]
fn compare_prints_flip_and_the_lookalike_figures_and_writes_the_error_map() {
    let dir = temp_dir("compare");
    let (a, b, heat) = (dir.join("a.png"), dir.join("b.png"), dir.join("heat.png"));
    render(&a, (40, 30), &["--seed", "1"]);
    render(&b, (40, 30), &["--seed", "2"]);
    let text = succeeds(&["compare", a.to_str().unwrap(), b.to_str().unwrap()]);
    assert!(text.contains("ssim") && text.contains("flip 0."), "{text}");
    assert!(text.contains("\nlookalike: mean "), "{text}");
    let json = succeeds(&[
        "compare",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--json",
        "--diff",
        heat.to_str().unwrap(),
        "--ppd",
        "30",
    ]);
    for key in [
        "\"ssim\": 0.",
        "\"flip\": 0.",
        "\"ppd\": 30.0",
        "\"lookalike\": {\"mean\": ",
    ] {
        assert!(json.contains(key), "{key} missing from {json}");
    }
    let map = read_image(&heat).unwrap();
    assert_eq!((map.width, map.height), (40, 30));
    // An image against itself: FLIP 0, the same with 0 and 0, a black map.
    let same = succeeds(&[
        "compare",
        a.to_str().unwrap(),
        a.to_str().unwrap(),
        "--diff",
        heat.to_str().unwrap(),
    ]);
    assert!(same.contains("flip 0.00000"), "{same}");
    assert!(
        same.contains("lookalike: mean 0.0, p95 0.0, same"),
        "{same}"
    );
    let black = DisplayImage::from_image(&read_image(&heat).unwrap());
    let darkest = black.pixels[0];
    assert!(black.pixels.iter().all(|&p| p == darkest) && darkest.iter().all(|&c| c < 10));
}

#[test]
fn compare_of_different_sizes_gives_the_lookalike_only_and_refuses_a_diff() {
    let dir = temp_dir("sizes");
    let (small, large, square) = (dir.join("s.png"), dir.join("l.png"), dir.join("q.png"));
    render(&small, (40, 30), &[]);
    render(&large, (80, 60), &[]);
    render(&square, (40, 40), &[]);
    let text = succeeds(&["compare", small.to_str().unwrap(), large.to_str().unwrap()]);
    assert!(
        text.starts_with("image sizes differ: 40x30 against a 80x60 reference"),
        "{text}"
    );
    assert!(text.contains("lookalike: mean"), "{text}");
    assert!(!text.contains("aspect ratios differ"), "{text}");
    let text = succeeds(&["compare", square.to_str().unwrap(), large.to_str().unwrap()]);
    assert!(
        text.contains("aspect ratios differ (40x40 against a 80x60 reference): compared at 32x24"),
        "{text}"
    );
    let json = succeeds(&[
        "compare",
        small.to_str().unwrap(),
        large.to_str().unwrap(),
        "--json",
    ]);
    assert!(
        json.starts_with("{\"rmse\": null,") && json.contains("\"flip\": null"),
        "{json}"
    );
    let heat = dir.join("heat.png");
    let out = pathtracer(&[
        "compare",
        small.to_str().unwrap(),
        large.to_str().unwrap(),
        "--diff",
        heat.to_str().unwrap(),
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--diff needs images of the same size"));
    assert!(!heat.exists());
}

#[test]
fn compare_of_linear_images_has_no_flip_and_maps_the_largest_channel_difference() {
    let dir = temp_dir("linear");
    let (a, b, heat) = (dir.join("a.pfm"), dir.join("b.pfm"), dir.join("heat.png"));
    render(&a, (20, 15), &["--seed", "1"]);
    render(&b, (20, 15), &["--seed", "2"]);
    let text = succeeds(&[
        "compare",
        a.to_str().unwrap(),
        b.to_str().unwrap(),
        "--diff",
        heat.to_str().unwrap(),
    ]);
    assert!(text.contains("flip n/a (linear image"), "{text}");
    assert!(text.contains("lookalike: mean"), "{text}");
    assert_eq!(read_image(&heat).unwrap().width, 20);
}

#[test]
fn lookalike_renders_each_pair_as_render_would_and_reports_failures_as_rows() {
    let dir = temp_dir("pairs");
    let folder = dir.join("repo+one");
    std::fs::create_dir_all(folder.join("testcases")).unwrap();
    let scene = folder.join("testcases/box.txt");
    std::fs::copy(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/smallpt.txt"),
        &scene,
    )
    .unwrap();
    // "Theirs" is our own render at the size and spp lookalike uses, so
    // ours must come out byte for byte the same; the doubtful pair's is
    // brightened by a gamma and looks different.
    let theirs = folder.join("renders/box.png");
    let scene_arg = scene.to_str().unwrap();
    let theirs_arg = theirs.to_str().unwrap();
    succeeds(&[
        "render", scene_arg, "-o", theirs_arg, "--width", "32", "--height", "24", "--spp", "4",
        "--quiet",
    ]);
    let bright = folder.join("renders/bright.png");
    let bright_arg = bright.to_str().unwrap();
    succeeds(&[
        "render", scene_arg, "-o", bright_arg, "--width", "64", "--height", "48", "--spp", "4",
        "--gamma", "2.2", "--quiet",
    ]);
    let pairs = dir.join("pairs.tsv");
    std::fs::write(
        &pairs,
        "# folder\tbase\tscene\trender\tpixels\tok|doubt\n\
         repo+one\t.\ttestcases/box.txt\trenders/box.png\t32x24\tok\n\
         repo+one\t.\ttestcases/missing.txt\trenders/box.png\t32x24\tok\n\
         repo+one\t.\ttestcases/box.txt\trenders/bright.png\t64x48\tdoubt\n",
    )
    .unwrap();
    let out = dir.join("out");
    let args = |only: &str| {
        let mut args = vec![
            "lookalike",
            pairs.to_str().unwrap(),
            "--width",
            "32",
            "--spp",
            "4",
        ];
        args.extend([
            "--out",
            out.to_str().unwrap(),
            "--only",
            only,
            "--jobs",
            "2",
        ]);
        args.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let ok_only: Vec<String> = args("ok");
    let ok_only: Vec<&str> = ok_only.iter().map(String::as_str).collect();
    let summary = succeeds(&ok_only);
    assert!(
        summary.starts_with("1 of 2 ok pairs look the same (1 failed)"),
        "{summary}"
    );
    let ours = out.join("images/repo-one__box.ours.png");
    assert_eq!(
        std::fs::read(&ours).unwrap(),
        std::fs::read(&theirs).unwrap()
    );
    let csv = std::fs::read_to_string(out.join("lookalike.csv")).unwrap();
    let lines: Vec<&str> = csv.lines().collect();
    assert_eq!(lines.len(), 3, "{csv}");
    assert!(
        lines[1].contains(",canonical,original,32,24,32x24,")
            && lines[1].contains(",0.000,0.000,same,0.00000,false,"),
        "{}",
        lines[1]
    );
    assert!(
        lines[2].contains(",failed,") && lines[2].contains("missing.txt"),
        "{}",
        lines[2]
    );
    let page = std::fs::read_to_string(out.join("index.html")).unwrap();
    // A row per pair (its scene and render in code), beside the table by renderer.
    assert_eq!(page.matches("</code><br><code>").count(), 2);
    for kind in ["ours", "theirs", "diff"] {
        assert!(
            out.join(format!("images/repo-one__box.{kind}.png"))
                .exists(),
            "{kind}"
        );
    }

    let all: Vec<String> = args("all");
    let all: Vec<&str> = all.iter().map(String::as_str).collect();
    let summary = succeeds(&all);
    assert!(
        summary.starts_with("1 of 2 ok pairs look the same, 0 of 1 doubtful pairs (1 failed)"),
        "{summary}"
    );
    let csv = std::fs::read_to_string(out.join("lookalike.csv")).unwrap();
    assert!(
        csv.lines()
            .nth(3)
            .is_some_and(|l| l.contains(",doubt,") && l.contains(",different,")),
        "{csv}"
    );
}
