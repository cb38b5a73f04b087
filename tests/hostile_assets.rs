//! Hostile and careless input (issue 12): images too large for memory,
//! mesh and texture files that are huge, binary, directories, devices,
//! truncated or decompression bombs, NaN in OBJ files, out-of-range
//! settings, empty curves, and radiance that a f32 output cannot hold.
//!
//! Each test spawns the binary, as a user meets it (`HOSTILE_BIN` runs them
//! against another build, e.g. one without the fixes). Big files are sparse
//! (`File::set_len`): nothing here writes more than a few kilobytes.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

fn pathtracer(args: &[&str]) -> Output {
    let binary =
        std::env::var("HOSTILE_BIN").unwrap_or_else(|_| env!("CARGO_BIN_EXE_pathtracer").into());
    Command::new(binary)
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn temp_dir(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("pathtracer-hostile-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

fn text(path: &Path) -> &str {
    path.to_str().expect("a UTF-8 temp path")
}

/// A scene of `width` x `height` with one object (`object`) of material 0
/// (`material`).
fn scene(dir: &Path, width: u32, height: u32, material: &str, object: &str) -> PathBuf {
    let file = dir.join("scene.txt");
    std::fs::write(
        &file,
        format!(
            "PerspectiveCamera {{\n  center 0 0 10\n  direction 0 0 -1\n  up 0 1 0\n  angle 30\n  \
             width {width}\n  height {height}\n}}\nMaterials {{ numMaterials 1 Material {{ {material} }} }}\n\
             Group {{\n  numObjects 1\n  MaterialIndex 0\n  {object}\n}}\n"
        ),
    )
    .expect("write scene");
    file
}

fn mesh_scene(dir: &Path, mesh: &Path) -> PathBuf {
    let object = format!("TriangleMesh {{ obj_file {} }}", text(mesh));
    scene(dir, 16, 16, "color 1 1 1", &object)
}

fn texture_scene(dir: &Path, texture: &Path) -> PathBuf {
    let material = format!("color 1 1 1 texture {}", text(texture));
    scene(dir, 16, 16, &material, "Sphere { center 0 0 0 radius 1 }")
}

/// `check SCENE`: it fails, and its error message.
fn check_fails(scene: &Path, extra: &[&str]) -> String {
    let mut args = vec!["check", text(scene)];
    args.extend_from_slice(extra);
    let out = pathtracer(&args);
    let stderr = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(!out.status.success(), "accepted: {stderr}");
    stderr
}

#[test]
fn a_16384_square_scene_passed_check_and_then_allocated_13_gb() {
    let dir = temp_dir("big-scene");
    let file = scene(
        &dir,
        16384,
        16384,
        "color 1 1 1",
        "Sphere { center 0 0 0 radius 1 }",
    );
    let error = check_fails(&file, &[]);
    // Located at the value of the scene's width, with what is needed, the budget and the flag.
    assert!(error.contains("scene.txt:6:9:"), "{error}");
    assert!(
        error.contains("GiB") && error.contains("4.0 GiB"),
        "{error}"
    );
    assert!(error.contains("--max-memory"), "{error}");
    let raised = pathtracer(&["check", text(&file), "--max-memory", "96G"]);
    assert!(
        raised.status.success(),
        "{}",
        String::from_utf8_lossy(&raised.stderr)
    );
}

#[test]
fn width_and_height_flags_of_8192_took_3_gb_resident() {
    let dir = temp_dir("big-flags");
    let file = scene(
        &dir,
        8,
        8,
        "color 1 1 1",
        "Sphere { center 0 0 0 radius 1 }",
    );
    let image = dir.join("out.bmp");
    let out = pathtracer(&[
        "render",
        text(&file),
        "-o",
        text(&image),
        "--spp",
        "1",
        "--quiet",
        "--width",
        "8192",
        "--height",
        "8192",
    ]);
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "rendered");
    assert!(error.contains("--width 8192 --height 8192"), "{error}");
    assert!(error.contains("--max-memory"), "{error}");
    assert!(!image.exists());
}

#[test]
fn an_obj_larger_than_the_limit_was_read_whole() {
    let dir = temp_dir("huge-obj");
    let mesh = dir.join("huge.obj");
    let file = std::fs::File::create(&mesh).expect("create");
    // Sparse: one byte over the limit, nothing written.
    file.set_len(pathtracer::limits::MAX_MESH_BYTES + 1)
        .expect("sparse file");
    let error = check_fails(&mesh_scene(&dir, &mesh), &[]);
    assert!(error.contains("MAX_MESH_BYTES"), "{error}");
    assert!(error.contains("huge.obj"), "{error}");
}

#[test]
fn an_obj_of_zeros_was_accepted_as_an_empty_mesh() {
    let dir = temp_dir("zero-obj");
    let mesh = dir.join("zeros.obj");
    std::fs::File::create(&mesh)
        .and_then(|f| f.set_len(1 << 20))
        .expect("sparse file");
    let error = check_fails(&mesh_scene(&dir, &mesh), &[]);
    assert!(error.contains("not a text OBJ file"), "{error}");
}

#[test]
fn a_directory_or_dev_zero_as_a_mesh_or_texture_was_not_found() {
    let dir = temp_dir("not-files");
    let folder = dir.join("folder.obj");
    std::fs::create_dir_all(&folder).expect("dir");
    let error = check_fails(&mesh_scene(&dir, &folder), &[]);
    assert!(error.contains("is a directory"), "{error}");
    let error = check_fails(&texture_scene(&dir, &folder), &[]);
    assert!(error.contains("is a directory"), "{error}");
    if Path::new("/dev/zero").exists() {
        let error = check_fails(&mesh_scene(&dir, Path::new("/dev/zero")), &[]);
        assert!(error.contains("is not a regular file"), "{error}");
        let error = check_fails(&texture_scene(&dir, Path::new("/dev/zero")), &[]);
        assert!(error.contains("is not a regular file"), "{error}");
    }
}

#[test]
fn obj_errors_had_no_line_number() {
    let dir = temp_dir("obj-line");
    let mesh = dir.join("bad.obj");
    std::fs::write(&mesh, "v 0 0 0\nv 1 0 0\nv 0 1 0\n# fine so far\nf 1 2 7\n").expect("write");
    let error = check_fails(&mesh_scene(&dir, &mesh), &[]);
    assert!(error.contains("bad.obj:5:"), "{error}");
    assert!(error.contains("out of range"), "{error}");
}

#[test]
fn nan_obj_vertices_were_accepted_without_a_word() {
    let dir = temp_dir("obj-nan");
    for (name, value) in [("nan.obj", "nan"), ("inf.obj", "inf"), ("big.obj", "1e39")] {
        let mesh = dir.join(name);
        std::fs::write(&mesh, format!("v 0 0 0\nv 1 0 0\nv 0 {value} 0\nf 1 2 3\n"))
            .expect("write");
        let error = check_fails(&mesh_scene(&dir, &mesh), &[]);
        assert!(error.contains(&format!("{name}:3:")), "{error}");
        assert!(error.contains("not a finite number"), "{error}");
    }
}

#[test]
fn a_texture_larger_than_the_limit_was_read_whole() {
    let dir = temp_dir("huge-texture");
    let image = dir.join("huge.png");
    std::fs::File::create(&image)
        .and_then(|f| f.set_len(pathtracer::limits::MAX_TEXTURE_BYTES + 1))
        .expect("sparse file");
    let error = check_fails(&texture_scene(&dir, &image), &[]);
    assert!(error.contains("MAX_TEXTURE_BYTES"), "{error}");
}

/// A PNG chunk: length, type, data, CRC-32 of type and data.
fn png_chunk(kind: &[u8; 4], data: &[u8]) -> Vec<u8> {
    let mut crc = 0xFFFF_FFFFu32;
    for &byte in kind.iter().chain(data) {
        crc ^= byte as u32;
        for _ in 0..8 {
            crc = if crc & 1 == 1 {
                (crc >> 1) ^ 0xEDB8_8320
            } else {
                crc >> 1
            };
        }
    }
    let mut chunk = (data.len() as u32).to_be_bytes().to_vec();
    chunk.extend_from_slice(kind);
    chunk.extend_from_slice(data);
    chunk.extend_from_slice(&(!crc).to_be_bytes());
    chunk
}

#[test]
fn a_small_png_claiming_60000_squared_was_decoded() {
    let dir = temp_dir("png-bomb");
    let mut header = Vec::new();
    header.extend_from_slice(&60_000u32.to_be_bytes());
    header.extend_from_slice(&60_000u32.to_be_bytes());
    header.extend_from_slice(&[8, 2, 0, 0, 0]);
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    png.extend(png_chunk(b"IHDR", &header));
    // A zlib stream of one stored zero byte: the first row's filter, no more.
    let idat = [
        0x78, 0x01, 0x01, 0x01, 0x00, 0xFE, 0xFF, 0x00, 0x00, 0x01, 0x00, 0x01,
    ];
    png.extend(png_chunk(b"IDAT", &idat));
    png.extend(png_chunk(b"IEND", &[]));
    let image = dir.join("bomb.png");
    std::fs::write(&image, &png).expect("write");
    let error = check_fails(&texture_scene(&dir, &image), &[]);
    assert!(error.contains("60000x60000"), "{error}");
    assert!(error.contains("--max-memory"), "{error}");
}

#[test]
fn a_truncated_bmp_said_failed_to_fill_whole_buffer() {
    let dir = temp_dir("bmp-truncated");
    // A 16x16 24-bit BMP cut after 5 of its 16 rows.
    let row = 48u32;
    let mut bmp = b"BM".to_vec();
    for value in [54 + row * 16, 0, 54, 40, 16, 16] {
        bmp.extend_from_slice(&value.to_le_bytes());
    }
    bmp.extend_from_slice(&1u16.to_le_bytes());
    bmp.extend_from_slice(&24u16.to_le_bytes());
    for value in [0, row * 16, 0, 0, 0, 0] {
        bmp.extend_from_slice(&value.to_le_bytes());
    }
    bmp.extend(std::iter::repeat_n(0x80u8, row as usize * 5));
    let image = dir.join("cut.bmp");
    std::fs::write(&image, &bmp).expect("write");
    let error = check_fails(&texture_scene(&dir, &image), &[]);
    assert!(error.contains("cut.bmp"), "{error}");
    assert!(error.contains("truncated"), "{error}");
    assert!(
        error.contains("16x16") && error.contains("822 bytes"),
        "{error}"
    );
}

#[test]
fn max_depth_4294967295_was_accepted() {
    let dir = temp_dir("max-depth");
    let file = scene(
        &dir,
        8,
        8,
        "color 1 1 1",
        "Sphere { center 0 0 0 radius 1 }",
    );
    let image = dir.join("out.bmp");
    let out = pathtracer(&[
        "render",
        text(&file),
        "-o",
        text(&image),
        "--spp",
        "1",
        "--quiet",
        "--max-depth",
        "4294967295",
    ]);
    let error = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "rendered");
    assert!(error.contains("10000"), "{error}");
}

#[test]
fn converge_with_max_spp_0_and_plots_of_empty_or_nan_data_exited_0() {
    let dir = temp_dir("empty-curves");
    let file = scene(
        &dir,
        8,
        8,
        "color 1 1 1",
        "Sphere { center 0 0 0 radius 1 }",
    );
    let csv = dir.join("c.csv");
    let out = pathtracer(&[
        "converge",
        text(&file),
        "--max-spp",
        "0",
        "--reference-spp",
        "1",
        "--csv",
        text(&csv),
        "--plot",
        text(&dir.join("c.svg")),
    ]);
    assert!(!out.status.success(), "converge --max-spp 0 succeeded");
    assert!(!csv.exists());
    let header = "spp,seconds,rmse,rel_mse,ssim\n";
    for (name, body) in [
        ("empty.csv", header.to_string()),
        ("nan.csv", format!("{header}1,NaN,1,NaN,1\n2,0.5,1,nan,1\n")),
    ] {
        let data = dir.join(name);
        std::fs::write(&data, body).expect("write");
        let svg = dir.join(format!("{name}.svg"));
        let out = pathtracer(&["plot", &format!("a={}", text(&data)), "-o", text(&svg)]);
        let error = String::from_utf8_lossy(&out.stderr);
        assert!(!out.status.success(), "plotted {name}");
        assert!(error.contains("no point to plot"), "{error}");
        assert!(!svg.exists());
    }
}

/// The float values of a little-endian RGB PFM.
fn pfm_values(bytes: &[u8]) -> Vec<f32> {
    let mut newlines = 0;
    let start = bytes
        .iter()
        .position(|&b| {
            newlines += (b == b'\n') as usize;
            newlines == 3
        })
        .expect("a PFM header")
        + 1;
    bytes[start..]
        .chunks_exact(4)
        .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect()
}

#[test]
fn emission_1e300_left_inf_pixels_while_the_summary_said_0_dropped() {
    let dir = temp_dir("hot-light");
    let source = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/smallpt.txt"),
    )
    .expect("smallpt");
    let hot = dir.join("hot.txt");
    std::fs::write(
        &hot,
        source.replace("emission 12 12 12", "emission 1e300 1e300 1e300"),
    )
    .expect("write");
    let image = dir.join("hot.pfm");
    let out = pathtracer(&[
        "render",
        text(&hot),
        "-o",
        text(&image),
        "--spp",
        "4",
        "--width",
        "32",
        "--height",
        "24",
        "--quiet",
    ]);
    let summary = String::from_utf8_lossy(&out.stdout);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let values = pfm_values(&std::fs::read(&image).expect("the PFM"));
    assert_eq!(values.len(), 32 * 24 * 3);
    assert!(
        values.iter().all(|v| v.is_finite()),
        "inf or NaN in the PFM"
    );
    assert!(!summary.contains(" 0 NaN/Inf samples dropped"), "{summary}");
}
