//! Render jobs and merge through the command line: parts rendered by
//! separate processes (sample ranges, pixel regions) merge to the bytes of
//! one render, and parts of other renders are refused.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use pathtracer::render::film_file::read_film;

fn pathtracer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-jobs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn path(dir: &Path, name: &str) -> String {
    dir.join(name).to_string_lossy().into_owned()
}

/// smallpt's box (a mirror and a glass ball, light subpaths on), small.
const SCENE: [&str; 6] = [
    "testcases/smallpt.txt",
    "--width",
    "40",
    "--height",
    "30",
    "--quiet",
];

/// Runs `render` on the scene with `extra`, expecting success; its stdout.
fn render(extra: &[&str]) -> String {
    let mut args = vec!["render"];
    args.extend(SCENE);
    args.extend(extra);
    let out = pathtracer(&args);
    assert!(
        out.status.success(),
        "render {extra:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

fn merge(parts: &[String], output: &str) -> Output {
    let mut args = vec!["merge"];
    args.extend(parts.iter().map(String::as_str));
    args.extend(["-o", output]);
    pathtracer(&args)
}

fn merged(parts: &[String], output: &str) {
    let out = merge(parts, output);
    assert!(
        out.status.success(),
        "merge: {}",
        String::from_utf8_lossy(&out.stderr)
    );
}

fn refused(parts: &[String], output: &str) -> String {
    let out = merge(parts, output);
    assert!(!out.status.success(), "merge of {parts:?} was not refused");
    assert!(
        !Path::new(output).exists(),
        "a refused merge wrote {output}"
    );
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn same_bytes(a: &str, b: &str) -> bool {
    std::fs::read(a).expect(a) == std::fs::read(b).expect(b)
}

#[test]
fn three_sample_ranges_merge_to_the_bytes_of_one_render() {
    let dir = temp_dir("ranges");
    render(&["--spp", "64", "-o", &path(&dir, "whole.bmp")]);
    render(&["--spp", "64", "-o", &path(&dir, "whole.pfm")]);
    render(&["--samples", "0..64", "--film", &path(&dir, "whole.exr")]);
    let mut parts = Vec::new();
    for range in ["16..40", "0..16", "40..64"] {
        let part = path(&dir, &format!("{range}.exr"));
        let report = render(&["--samples", range, "--film", &part]);
        // Light subpaths ran, so their splats are part of what must merge.
        assert!(!report.contains(" 0 light subpaths"), "{report}");
        parts.push(part);
    }
    merged(&parts, &path(&dir, "merged.bmp"));
    merged(&parts, &path(&dir, "merged.pfm"));
    let mut args = vec!["merge", "--film"];
    let merged_film = path(&dir, "merged.exr");
    args.push(&merged_film);
    args.extend(parts.iter().map(String::as_str));
    assert!(pathtracer(&args).status.success());
    // The sums themselves are equal, not only the images they round to
    // (f64 sums in sample order differ in their last bits here).
    let (whole, whole_header) = read_film(Path::new(&path(&dir, "whole.exr"))).unwrap();
    let (merged, merged_header) = read_film(Path::new(&merged_film)).unwrap();
    assert_eq!(whole_header, merged_header);
    assert_eq!(
        (whole.splats, whole.light_paths),
        (merged.splats, merged.light_paths)
    );
    for (a, b) in whole.pixels.iter().zip(&merged.pixels) {
        assert_eq!(
            (a.sum, a.sum_of_squares, a.samples),
            (b.sum, b.sum_of_squares, b.samples)
        );
    }
    assert!(same_bytes(
        &path(&dir, "whole.bmp"),
        &path(&dir, "merged.bmp")
    ));
    assert!(same_bytes(
        &path(&dir, "whole.pfm"),
        &path(&dir, "merged.pfm")
    ));
    // A merged HDR image says how it was made, as a rendered one does:
    // the same settings and samples, and the parts instead of the seconds.
    let sidecar = |name: &str| std::fs::read_to_string(path(&dir, name)).expect(name);
    let (whole, merged) = (sidecar("whole.pfm.json"), sidecar("merged.pfm.json"));
    assert!(merged.contains("\"parts\": 3,"), "{merged}");
    let settings = |json: &str| {
        let start = json.find("\"seed\"").expect("seed");
        json[start..].to_string()
    };
    assert_eq!(settings(&whole), settings(&merged));
    let head = |json: &str| json[..json.find(", \"samples\"").expect("samples")].to_string();
    assert_eq!(head(&whole), head(&merged));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn crops_that_tile_the_image_merge_to_the_full_render() {
    let dir = temp_dir("crops");
    render(&["--spp", "12", "-o", &path(&dir, "whole.pfm")]);
    let mut parts = Vec::new();
    // Uneven tiles; the last one in two sample ranges.
    for (index, (crop, samples)) in [
        ("0,0,17,11", "0..12"),
        ("17,0,40,11", "0..12"),
        ("0,11,40,30", "0..5"),
        ("0,11,40,30", "5..12"),
    ]
    .into_iter()
    .enumerate()
    {
        let part = path(&dir, &format!("tile{index}.exr"));
        render(&["--crop", crop, "--samples", samples, "--film", &part]);
        parts.push(part);
    }
    merged(&parts, &path(&dir, "merged.pfm"));
    assert!(same_bytes(
        &path(&dir, "whole.pfm"),
        &path(&dir, "merged.pfm")
    ));
    // A missing tile is named, and --partial is the way to merge anyway.
    let message = refused(&parts[1..], &path(&dir, "gap.pfm"));
    assert!(message.contains("0,0,17,11: samples 0..12"), "{message}");
    let mut args = vec!["merge", "--partial", "-o"];
    let gap = path(&dir, "gap.pfm");
    args.push(&gap);
    args.extend(parts[1..].iter().map(String::as_str));
    assert!(pathtracer(&args).status.success());
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn overlapping_and_foreign_parts_are_refused() {
    let dir = temp_dir("refused");
    let part = |name: &str, extra: &[&str]| {
        let file = path(&dir, name);
        let mut args = vec!["--film", file.as_str()];
        args.extend(extra);
        render(&args);
        file
    };
    let first = part("a.exr", &["--samples", "0..4"]);
    let overlapping = part("b.exr", &["--samples", "2..6", "--crop", "10,10,20,20"]);
    let other_seed = part("c.exr", &["--samples", "4..8", "--seed", "9"]);
    let other_depth = part("d.exr", &["--samples", "4..8", "--max-depth", "3"]);
    let output = path(&dir, "out.bmp");
    let message = refused(&[first.clone(), overlapping.clone()], &output);
    assert!(
        message.contains("overlap") && message.contains("samples 2..4 of pixels 10,10,20,20"),
        "{message}"
    );
    let message = refused(&[first.clone(), other_seed], &output);
    assert!(message.contains("seed is 9"), "{message}");
    let message = refused(&[first.clone(), other_depth], &output);
    assert!(message.contains("max_depth is 3"), "{message}");
    // Another scene: the content hash differs.
    let other_scene = path(&dir, "other.exr");
    let out = pathtracer(&[
        "render",
        "testcases/showcase.txt",
        "--width",
        "40",
        "--height",
        "30",
        "--samples",
        "4..8",
        "--quiet",
        "--film",
        &other_scene,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let message = refused(&[first.clone(), other_scene], &output);
    assert!(message.contains("scene_hash is"), "{message}");
    // An image is not a film.
    render(&["--spp", "1", "-o", &path(&dir, "image.exr")]);
    let message = refused(&[first, path(&dir, "image.exr")], &output);
    assert!(message.contains("not a pathtracer film"), "{message}");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn job_options_without_a_film_are_refused() {
    let out = pathtracer(&[
        "render",
        "testcases/smallpt.txt",
        "--samples",
        "0..4",
        "-o",
        "output/never.bmp",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("need --film"));
}

#[test]
fn a_merged_film_never_replaces_one_of_its_parts() {
    let dir = temp_dir("inputs");
    let first = path(&dir, "a.exr");
    let second = path(&dir, "b.exr");
    render(&["--samples", "0..2", "--film", &first]);
    render(&["--samples", "2..4", "--film", &second]);
    let before = std::fs::read(&first).expect("part a");
    let out = pathtracer(&["merge", &first, &second, "--film", &first]);
    let message = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{message}");
    assert!(message.contains("a part to merge"), "{message}");
    assert_eq!(std::fs::read(&first).expect("part a"), before);
    let _ = std::fs::remove_dir_all(&dir);
}
