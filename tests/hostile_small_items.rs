//! The small items of issue 30 (case 14): unclear messages, and values that
//! were accepted without a word. Each test is named after what the old
//! build did; `HOSTILE_BIN` runs them against another build.

#![cfg(unix)]

mod common;

use std::path::Path;

use common::{fresh_dir, make_fifo, render_small, run_in};

const CAMERA: &str = "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 \
                      width 8 height 8 }\nMaterials { Material { diffuseColor 1 1 1 } }\n";

/// Writes `scene.txt` in `dir`: [`CAMERA`] and `group` as the group's body.
fn scene(dir: &Path, group: &str) {
    std::fs::write(
        dir.join("scene.txt"),
        format!("{CAMERA}Group {{ {group} }}\n"),
    )
    .expect("scene");
}

/// A scene whose one mesh is `obj` (the file's text).
fn mesh_scene(dir: &Path, obj: &str) {
    std::fs::write(dir.join("m.obj"), obj).expect("obj");
    scene(dir, "TriangleMesh { obj_file m.obj }");
}

/// `check scene.txt` in `dir`: exit code and stderr.
fn check(dir: &Path) -> (Option<i32>, String) {
    let ran = run_in(dir, &["check", "scene.txt"]);
    assert!(!ran.stderr.contains("panicked"), "{}", ran.stderr);
    (ran.code, ran.stderr)
}

#[test]
fn scale_1e300_was_reported_as_a_singular_matrix() {
    let dir = fresh_dir("scale-1e300");
    scene(
        &dir,
        "Transform { Scale 1e300 1e300 1e300 Sphere { center 0 0 0 radius 1 } }",
    );
    let (code, error) = check(&dir);
    assert_eq!(code, Some(1), "{error}");
    assert!(error.contains("scene.txt:3:"), "{error}");
    assert!(!error.contains("singular"), "{error}");
    assert!(error.contains("too much"), "{error}");
}

#[test]
fn the_first_mention_of_a_long_mesh_path_was_not_shortened() {
    let dir = fresh_dir("long-mesh-name");
    scene(
        &dir,
        &format!("TriangleMesh {{ obj_file {}.obj }}", "m".repeat(5500)),
    );
    let (code, error) = check(&dir);
    assert_eq!(code, Some(1), "{error}");
    let first = error.lines().next().unwrap_or_default();
    assert!(first.len() < 1000, "{} bytes: {first}", first.len());
}

#[test]
fn a_300_character_file_name_was_reported_as_not_found() {
    let dir = fresh_dir("name-too-long");
    scene(
        &dir,
        &format!("TriangleMesh {{ obj_file {}.obj }}", "n".repeat(300)),
    );
    let (code, error) = check(&dir);
    assert_eq!(code, Some(1), "{error}");
    assert!(error.contains("name too long"), "{error}");
    assert!(!error.contains("not found"), "{error}");
}

#[test]
fn map_kd_on_a_directory_a_pipe_or_dev_zero_was_not_found() {
    let dir = fresh_dir("map-kd-special");
    std::fs::create_dir_all(dir.join("folder.png")).expect("folder");
    let pipe = make_fifo(&dir.join("pipe.png"));
    std::os::unix::fs::symlink("/dev/zero", dir.join("zero.png")).expect("link");
    for (image, reason) in [
        ("folder.png", "is a directory"),
        ("pipe.png", "not a regular file"),
        ("zero.png", "not a regular file"),
    ] {
        if image == "pipe.png" && !pipe {
            continue;
        }
        std::fs::write(
            dir.join("m.mtl"),
            format!("newmtl m\nKd 1 1 1\nmap_Kd {image}\n"),
        )
        .expect("mtl");
        mesh_scene(
            &dir,
            "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nusemtl m\n\
             f 1/1 2/2 3/3\n",
        );
        let (code, error) = check(&dir);
        assert_eq!(code, Some(0), "{error}");
        assert!(error.contains(reason), "{image}: {error}");
        assert!(!error.contains("not found"), "{image}: {error}");
    }
}

#[test]
fn a_face_with_no_vertices_had_no_obj_line_and_f_1_2_was_accepted() {
    let dir = fresh_dir("short-faces");
    for face in ["f", "f 1 2"] {
        mesh_scene(&dir, &format!("v 0 0 0\nv 1 0 0\nv 0 1 0\n{face}\n"));
        let (code, error) = check(&dir);
        assert_eq!(code, Some(1), "{face}: {error}");
        assert!(error.contains("m.obj:4:"), "{face}: {error}");
        assert!(error.contains("at least 3 vertices"), "{face}: {error}");
    }
}

#[test]
fn control_bytes_of_the_scene_were_echoed_raw() {
    let dir = fresh_dir("control-bytes");
    scene(
        &dir,
        "Sphere { center 0 0 0 radius 1 \u{1b}P0;owned\u{7}\u{8} 3 }\n",
    );
    let (code, error) = check(&dir);
    assert_eq!(code, Some(0), "{error}");
    assert!(error.contains("unknown field"), "{error}");
    assert!(
        !error.chars().any(|c| c.is_control() && c != '\n'),
        "{error:?}"
    );
    assert!(error.contains("\\u{1b}"), "{error}");
}

#[test]
fn kd_nan_ke_inf_and_d_nan_in_an_mtl_were_accepted_silently() {
    let dir = fresh_dir("mtl-non-finite");
    std::fs::write(
        dir.join("m.mtl"),
        "newmtl m\nKd nan 1 1\nKe inf 0 0\nd nan\n",
    )
    .expect("mtl");
    mesh_scene(
        &dir,
        "mtllib m.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl m\nf 1 2 3\n",
    );
    let (code, error) = check(&dir);
    assert_eq!(code, Some(0), "{error}");
    for field in ["'Kd'", "'Ke'", "'d'"] {
        assert!(
            error
                .lines()
                .any(|l| l.contains(field) && l.contains("not a finite number")),
            "{field}: {error}"
        );
    }
}

#[test]
fn nan_clamp_target_error_time_budget_and_a_tiny_ppd_were_accepted() {
    let dir = fresh_dir("nan-options");
    for option in [
        ["--clamp", "nan"],
        ["--target-error", "nan"],
        ["--time-budget", "nan"],
        ["--time-budget", "1e300"],
    ] {
        let ran = render_small(&dir, "x.png", &option);
        assert_eq!(ran.code, Some(2), "{option:?}: {}", ran.stderr);
        assert!(ran.stderr.contains(option[0]), "{}", ran.stderr);
    }
    assert!(!dir.join("x.png").exists());
    let image = render_small(&dir, "a.png", &[]);
    assert_eq!(image.code, Some(0), "{}", image.stderr);
    let ran = run_in(&dir, &["compare", "a.png", "a.png", "--ppd", "1e-300"]);
    assert_eq!(ran.code, Some(2), "{}{}", ran.stdout, ran.stderr);
    assert!(!ran.stdout.contains("NaN"), "{}", ran.stdout);
}

#[test]
fn a_zero_or_parallel_camera_up_was_accepted_silently() {
    let dir = fresh_dir("camera-up");
    for up in ["0 0 0", "0 0 2"] {
        let text = format!(
            "PerspectiveCamera {{ center 0 0 10 direction 0 0 -1 up {up} angle 30 width 8 \
             height 8 }}\nMaterials {{ Material {{ diffuseColor 1 1 1 }} }}\n\
             Group {{ Sphere {{ center 0 0 0 radius 1 }} }}\n"
        );
        std::fs::write(dir.join("scene.txt"), text).expect("scene");
        let (code, error) = check(&dir);
        assert_eq!(code, Some(0), "{error}");
        assert!(
            error.contains("scene.txt:1:") && error.contains("camera up"),
            "{up}: {error}"
        );
    }
}

#[test]
fn an_empty_mesh_was_accepted_silently() {
    let dir = fresh_dir("empty-mesh");
    for obj in ["", "# nothing\nv 0 0 0\n"] {
        mesh_scene(&dir, obj);
        let (code, error) = check(&dir);
        assert_eq!(code, Some(0), "{error}");
        assert!(error.contains("no triangles"), "{obj:?}: {error}");
    }
}

#[test]
fn the_readme_said_an_output_in_a_missing_folder_fails_but_it_is_created() {
    let dir = fresh_dir("missing-folder");
    let ran = render_small(&dir, "new/deeper/x.png", &[]);
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    assert!(dir.join("new/deeper/x.png").is_file());
    // Output safety is documented in the guide's limits chapter.
    let limits =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/guide/limits.md"))
            .expect("docs/guide/limits.md");
    let text = limits.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(
        !text.contains("(a missing or read-only folder"),
        "the guide still says it fails"
    );
    assert!(
        text.contains("missing folders are created"),
        "the guide does not say so"
    );
}
