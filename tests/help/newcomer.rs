//! What a render tells a newcomer, and where the help, README, Makefile and
//! guide describe the same thing: they agree.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use super::help;

fn root() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

fn pathtracer(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("the binary runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pathtracer-help-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 path")
}

/// The lines of `text` from the one containing `start` to the next blank
/// line (or option line of a help text).
fn paragraph(text: &str, start: &str) -> String {
    let mut lines = text.lines().skip_while(|line| !line.contains(start));
    let first = lines
        .next()
        .unwrap_or_else(|| panic!("no line with {start}"));
    std::iter::once(first)
        .chain(lines.take_while(|line| {
            let line = line.trim_start();
            !line.is_empty() && !line.starts_with("--") && !line.starts_with("- ")
        }))
        .flat_map(str::split_whitespace)
        .collect::<Vec<_>>()
        .join(" ")
}

#[test]
fn help_readme_and_guide_give_target_error_the_same_rule() {
    let floor = format!("{}", pathtracer::render::adaptive::ABSOLUTE_FLOOR);
    assert_eq!(floor, "0.001");
    let help = paragraph(&help(&["render"]), "--target-error <");
    let readme = std::fs::read_to_string(root().join("README.md")).expect("README");
    let readme = paragraph(&readme, "--target-error");
    let guide = std::fs::read_to_string(root().join("docs/guide/rendering.md")).expect("guide");
    let guide = paragraph(&guide, "- `--target-error E`");
    for (name, text) in [
        ("help", &help),
        ("README", &readme),
        ("rendering.md", &guide),
    ] {
        assert!(text.contains("relative error"), "{name}: {text}");
        assert!(text.contains("standard error"), "{name}: {text}");
        assert!(text.contains(&format!("+ {floor}")), "{name}: {text}");
    }
}

#[test]
fn converge_saves_its_reference_next_to_the_csv_as_its_help_says() {
    let help = help(&["converge"]);
    assert!(help.contains("saved next to the CSV"), "{help}");
    let dir = temp_dir("converge");
    let csv = dir.join("curve.csv");
    let out = pathtracer(&[
        "converge",
        "testcases/smallpt.txt",
        "--width",
        "8",
        "--height",
        "6",
        "--max-spp",
        "2",
        "--reference-spp",
        "4",
        "--csv",
        text(&csv),
        "--plot",
        text(&dir.join("curve.svg")),
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        dir.join("smallpt_reference.pfm").is_file(),
        "no reference beside the CSV"
    );

    // The plot of that curve, without --title, has a title.
    let svg = dir.join("plot.svg");
    let out = pathtracer(&["plot", &format!("ours={}", text(&csv)), "-o", text(&svg)]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(&svg).expect("the plot");
    assert!(
        svg.contains(r#"font-size="15">rel_mse against seconds</text>"#),
        "{svg}"
    );
}

#[test]
fn make_lookalike_takes_the_same_time_in_the_makefile_and_the_guide() {
    let about = |text: &str| -> String {
        let at = text.find("about ").expect("an 'about'");
        text[at..]
            .split_whitespace()
            .take(3)
            .collect::<Vec<_>>()
            .join(" ")
    };
    let makefile = std::fs::read_to_string(root().join("Makefile")).expect("Makefile");
    let before_target = &makefile[..makefile.find("\nlookalike:").expect("the target")];
    let comment = &before_target[before_target.rfind("\n\n").expect("its comment")..];
    let guide = std::fs::read_to_string(root().join("docs/guide/development.md")).expect("guide");
    let sentence = &guide[guide.find("`make lookalike`").expect("make lookalike")..];
    assert_eq!(about(comment), about(&sentence[..200]));
    assert!(about(comment).contains("minute"), "{comment}");
}

#[test]
fn a_linear_8_bit_image_is_followed_by_how_to_encode_it_for_display() {
    let dir = temp_dir("linear");
    let render = |name: &str, extra: &[&str]| {
        let output = dir.join(name);
        let mut args = vec!["render", "testcases/smallpt.txt", "-o", text(&output)];
        args.extend_from_slice(&["--width", "8", "--height", "6", "--spp", "1", "--quiet"]);
        args.extend_from_slice(extra);
        let out = pathtracer(&args);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stdout).expect("UTF-8")
    };
    let hint = "--gamma 2.2 writes a display-encoded image";
    let linear = render("linear.bmp", &[]);
    assert!(
        linear
            .lines()
            .nth(1)
            .is_some_and(|line| line.contains(hint)),
        "{linear}"
    );
    assert_eq!(linear.lines().count(), 2, "{linear}");
    for (name, extra) in [
        ("gamma.png", &["--gamma", "2.2"][..]),
        ("curve.bmp", &["--tonemap", "reinhard"][..]),
        ("linear.pfm", &[][..]),
    ] {
        let out = render(name, extra);
        assert!(!out.contains(hint), "{name}: {out}");
    }
}

#[test]
fn a_pa1_scene_says_that_it_renders_one_sample_per_pixel() {
    let dir = temp_dir("pa1");
    let render = |spp: &str| {
        let output = dir.join(format!("{spp}.bmp"));
        let out = pathtracer(&[
            "render",
            "testcases/tutorial1_camera.txt",
            "-o",
            text(&output),
            "--width",
            "8",
            "--height",
            "6",
            "--spp",
            spp,
            "--quiet",
        ]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stderr).expect("UTF-8")
    };
    let asked_more = render("40");
    assert!(
        asked_more.contains("note: the pa1 look") && asked_more.contains("1 spp, not the 40 asked"),
        "{asked_more}"
    );
    assert!(!render("1").contains("note:"));
}

#[test]
fn completions_for_bash_zsh_and_fish_name_the_commands_and_options() {
    for shell in ["bash", "zsh", "fish"] {
        let out = pathtracer(&["completions", shell]);
        assert!(out.status.success(), "{shell}");
        let script = String::from_utf8(out.stdout).expect("UTF-8");
        for word in [
            "pathtracer",
            "render",
            "converge",
            "target-error",
            "missing-assets",
        ] {
            assert!(script.contains(word), "{shell}: no {word}");
        }
    }
    let out = pathtracer(&["completions", "tcsh"]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn an_obj_missing_its_mtl_warns_only_where_the_mtl_would_be_used() {
    let dir = temp_dir("mtl");
    std::fs::write(
        dir.join("m.obj"),
        "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl red\nf 1 2 3\n",
    )
    .expect("write the mesh");
    let scene = |choice: &str| {
        format!(
            "PerspectiveCamera {{ center 0 0 5 direction 0 0 -1 up 0 1 0 angle 30 width 4 height 4 }}\n\
             Lights {{ numLights 0 }}\nBackground {{ color 0 0 0 }}\n\
             Materials {{ numMaterials 1 Material {{ diffuseColor 1 1 1 }} }}\n\
             Group {{ numObjects 1 {choice} TriangleMesh {{ obj_file m.obj }} }}\n"
        )
    };
    let check = |name: &str, choice: &str| {
        let file = dir.join(name);
        std::fs::write(&file, scene(choice)).expect("write the scene");
        let out = pathtracer(&["check", text(&file), "--base", text(&dir)]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        String::from_utf8(out.stderr).expect("UTF-8")
    };
    let used = check("used.txt", "");
    assert!(used.contains("gone.mtl"), "{used}");
    let overridden = check("overridden.txt", "MaterialIndex 0");
    assert!(!overridden.contains("warning"), "{overridden}");

    let dragons = root().join("../shared/scenes/report_scene11_dragons.txt");
    if !dragons.exists() {
        eprintln!("skipped the dragons: ../shared not found");
        return;
    }
    let out = pathtracer(&["check", text(&dragons)]);
    assert!(out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("warning"), "{stderr}");
}

#[test]
fn make_render_resumes_a_render_whose_checkpoint_is_there() {
    let dir = temp_dir("make");
    let image = dir.join("smallpt.bmp");
    let planned = || {
        let out = Command::new("make")
            .args(["-n", "render", &format!("OUT={}", text(&image))])
            .current_dir(root())
            .output();
        let Ok(out) = out else {
            return None;
        };
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let stdout = String::from_utf8(out.stdout).expect("UTF-8");
        let line = stdout
            .lines()
            .find(|line| line.contains(" render "))
            .map(str::to_string);
        Some(line.expect("make render runs the renderer"))
    };
    let Some(fresh) = planned() else {
        eprintln!("skipped: make not found");
        return;
    };
    assert!(
        fresh.contains(text(&image)) && !fresh.contains("--resume"),
        "{fresh}"
    );
    std::fs::write(dir.join("smallpt.bmp.checkpoint.exr"), b"").expect("a checkpoint");
    let resumed = planned().expect("make ran before");
    assert!(resumed.contains("--resume"), "{resumed}");
}
