//! The command line as a user meets it: determinism, exit codes, error
//! messages with positions, and no half-written or clobbered outputs.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn pathtracer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-cli-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Renders smallpt's box at `size` and `spp` into `out`; `extra` adds options.
fn render_smallpt_with(out: &Path, size: (u32, u32), spp: u32, extra: &[&str]) -> Output {
    let (width, height, spp) = (size.0.to_string(), size.1.to_string(), spp.to_string());
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
        &spp,
    ];
    args.extend_from_slice(extra);
    pathtracer(&args)
}

fn render_smallpt(out: &Path, threads: &str, seed: &str) -> Output {
    render_smallpt_with(
        out,
        (40, 30),
        8,
        &["--threads", threads, "--seed", seed, "--quiet"],
    )
}

#[test]
fn same_seed_gives_identical_bytes_for_one_and_two_threads() {
    let dir = temp_dir("determinism");
    let one = dir.join("one.bmp");
    let two = dir.join("two.bmp");
    let other_seed = dir.join("other.bmp");
    for (path, threads, seed) in [(&one, "1", "5"), (&two, "2", "5"), (&other_seed, "2", "6")] {
        let out = render_smallpt(path, threads, seed);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
    }
    let a = std::fs::read(&one).unwrap();
    let b = std::fs::read(&two).unwrap();
    let c = std::fs::read(&other_seed).unwrap();
    assert_eq!(a.len(), 54 + 40 * 30 * 3, "a 24-bit BMP of 40x30");
    assert!(a == b, "1 and 2 threads differ");
    assert!(a != c, "another seed gives the same image");
    // The image is not black: the light and the walls are visible.
    assert!(a[54..].iter().any(|&v| v > 100));
}

#[test]
fn a_syntax_error_names_file_line_and_column_and_writes_nothing() {
    let dir = temp_dir("syntax");
    let scene = dir.join("broken.txt");
    std::fs::write(
        &scene,
        "PerspectiveCamera {\n  center 0 0 10\n  direction 0 0 -1\n  up 0 1 0\n  width 8\n  height 8\n}\nMaterials { numMaterials 1 Material { color 1 1 1 } }\nGroup {\n  numObjects 1\n  MaterialIndex 0\n  Sphere { center 0 0 0 radius }\n}\n",
    )
    .unwrap();
    let image = dir.join("out.bmp");
    std::fs::write(&image, b"previous image").unwrap();
    let out = pathtracer(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        image.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("broken.txt:12:"),
        "no position in: {stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert_eq!(std::fs::read(&image).unwrap(), b"previous image");
}

#[test]
fn a_missing_mesh_is_an_error_naming_the_path() {
    let dir = temp_dir("mesh");
    let scene = dir.join("mesh.txt");
    std::fs::write(
        &scene,
        "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 width 8 height 8 }\nMaterials { numMaterials 1 Material { color 1 1 1 } }\nGroup { numObjects 1 MaterialIndex 0 TriangleMesh { obj_file mesh/not_there.obj } }\n",
    )
    .unwrap();
    let image = dir.join("mesh.bmp");
    let out = pathtracer(&[
        "render",
        scene.to_str().unwrap(),
        "-o",
        image.to_str().unwrap(),
        "--quiet",
    ]);
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.contains("not_there.obj"), "{stderr}");
    assert!(!image.exists());
}

#[test]
fn missing_assets_placeholder_renders_and_checks_with_a_warning_naming_the_file() {
    let dir = temp_dir("placeholder");
    let scene = dir.join("gone.txt");
    std::fs::write(
        &scene,
        "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 width 8 height 8 }\nMaterials { numMaterials 1 Material { color 1 1 1 texture texture/gone.png } }\nGroup { numObjects 2 MaterialIndex 0 Sphere { center 0 0 0 radius 1 } TriangleMesh { obj_file mesh/not_there.obj } }\n",
    )
    .unwrap();
    let image = dir.join("gone.bmp");
    let scene = scene.to_str().unwrap();
    let render = |extra: &[&str]| {
        let mut args = vec!["render", scene, "-o", image.to_str().unwrap(), "--quiet"];
        args.extend_from_slice(extra);
        pathtracer(&args)
    };
    assert!(!render(&[]).status.success(), "the default is an error");
    assert!(!render(&["--missing-assets", "error"]).status.success());
    let out = render(&["--missing-assets", "placeholder"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains(&format!(
            "{scene}:2:59: texture 'texture/gone.png' not found"
        )),
        "{stderr}"
    );
    assert!(stderr.contains("not_there.obj"), "{stderr}");
    assert!(image.exists());
    let out = pathtracer(&["check", scene, "--missing-assets", "placeholder"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let out = pathtracer(&["check", scene, "--missing-assets", "maybe"]);
    assert!(!out.status.success());
}

#[test]
fn exposure_and_tonemap_change_8_bit_outputs_only_and_default_to_the_plain_writer() {
    let dir = temp_dir("tonemap");
    let render = |name: &str, extra: &[&str]| {
        let path = dir.join(name);
        let out = render_smallpt_with(&path, (24, 18), 4, &[&["--quiet"], extra].concat());
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        path
    };
    let plain = std::fs::read(render("plain.bmp", &[])).unwrap();
    let explicit = render("explicit.bmp", &["--exposure", "0", "--tonemap", "none"]);
    assert!(
        plain == std::fs::read(explicit).unwrap(),
        "the defaults are the plain writer"
    );
    let darker = std::fs::read(render(
        "reinhard.bmp",
        &["--tonemap", "reinhard", "--exposure", "-1"],
    ))
    .unwrap();
    assert_eq!(darker.len(), plain.len());
    // BMP pixel data starts at byte 54: no channel gets brighter, some darker.
    let pairs = || plain[54..].iter().zip(&darker[54..]);
    assert!(pairs().all(|(p, d)| d <= p));
    assert!(pairs().any(|(p, d)| d < p));
    // HDR output stays linear; its sidecar says how 8-bit output would encode it.
    let hdr = render("hdr.pfm", &["--tonemap", "aces", "--exposure", "1.5"]);
    let linear = render("linear.pfm", &[]);
    assert!(std::fs::read(&hdr).unwrap() == std::fs::read(&linear).unwrap());
    let sidecar = std::fs::read_to_string(dir.join("hdr.pfm.json")).unwrap();
    assert!(
        sidecar.contains("\"exposure\": 1.5, \"tonemap\": \"aces\""),
        "{sidecar}"
    );
    assert!(sidecar.contains("\"gamma\": null"), "{sidecar}");
    // convert applies the same encoding to a PFM.
    let converted = dir.join("converted.bmp");
    let out = pathtracer(&[
        "convert",
        linear.to_str().unwrap(),
        converted.to_str().unwrap(),
        "--tonemap",
        "reinhard",
        "--exposure=-1",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let bytes = std::fs::read(&converted).unwrap();
    // Values of the PFM are the render's rounded to f32: a byte may move by one.
    assert!(
        bytes[54..]
            .iter()
            .zip(&darker[54..])
            .all(|(c, d)| c.abs_diff(*d) <= 1)
    );
    let out = pathtracer(&[
        "convert",
        linear.to_str().unwrap(),
        converted.to_str().unwrap(),
        "--tonemap",
        "filmic",
    ]);
    assert!(!out.status.success());
}

#[test]
fn an_unknown_output_format_is_refused_before_rendering() {
    let dir = temp_dir("format");
    let out = render_smallpt(&dir.join("image.xyz"), "1", "0");
    assert!(!out.status.success());
    assert!(!dir.join("image.xyz").exists());
}

#[test]
fn check_reports_every_shared_scene() {
    let shared = Path::new(env!("CARGO_MANIFEST_DIR")).join("../shared/scenes");
    if !shared.exists() {
        eprintln!("skipped: ../shared not found");
        return;
    }
    let mut args = vec!["check".to_string()];
    for name in [
        "report_scene11_dragons.txt",
        "report_scene15_spheres.txt",
        "report_scene16_vase.txt",
    ] {
        args.push(shared.join(name).to_string_lossy().into_owned());
    }
    let args: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = pathtracer(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let stdout = String::from_utf8_lossy(&out.stdout);
    assert_eq!(stdout.matches("report_scene").count(), 3, "{stdout}");
}

#[test]
fn every_project_testcase_renders_without_nan() {
    let dir = temp_dir("testcases");
    let mut count = 0;
    for entry in std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases")).unwrap()
    {
        let scene = entry.unwrap().path();
        if scene.extension().is_none_or(|e| e != "txt") {
            continue;
        }
        let out = dir.join("image.pfm");
        let output = pathtracer(&[
            "render",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
            "--width",
            "32",
            "--height",
            "24",
            "--spp",
            "8",
            "--quiet",
        ]);
        let stdout = String::from_utf8_lossy(&output.stdout);
        assert!(
            output.status.success(),
            "{}: {}",
            scene.display(),
            String::from_utf8_lossy(&output.stderr)
        );
        assert!(stdout.contains(" 0 NaN/Inf samples dropped"), "{stdout}");
        // An HDR result carries its sample count in a sidecar: 8, or 1 for
        // a file of the course framework, which its ray caster renders with
        // one ray per pixel (the tutorial's first step is one).
        let sidecar = std::fs::read_to_string(dir.join("image.pfm.json")).unwrap();
        let spp = if sidecar.contains("\"look\": \"pa1\"") {
            1
        } else {
            8
        };
        assert!(sidecar.contains(&format!("\"spp\": {spp},")), "{sidecar}");
        count += 1;
    }
    assert!(count >= 3, "{count} testcases");
}

#[test]
fn stats_say_whether_bounces_are_split() {
    // smallpt's box has a mirror and a glass ball under a small light.
    let dir = temp_dir("split-stats");
    let out = dir.join("x.pfm");
    let stats = |extra: &[&str]| {
        let output = render_smallpt_with(&out, (16, 12), 1, &[&["--stats"], extra].concat());
        assert!(output.status.success(), "{output:?}");
        let text = String::from_utf8_lossy(&output.stderr).into_owned()
            + &String::from_utf8_lossy(&output.stdout);
        text.lines()
            .find(|line| line.starts_with("split bounces"))
            .unwrap_or_else(|| panic!("no split line in {text}"))
            .to_string()
    };
    assert!(stats(&[]).contains("on (8 bounces"), "{}", stats(&[]));
    assert!(stats(&["--no-light-paths"]).contains("off (--no-light-paths)"));
    assert!(stats(&["--integrator", "original"]).contains("off (path integrator"));
    let _ = std::fs::remove_dir_all(&dir);
}
