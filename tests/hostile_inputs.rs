//! Inputs that were refused or misread (issue 30, case 11): TGA and PFM
//! textures, and `compare` of TGA images.
//!
//! `HOSTILE_BIN` runs them against another build.

mod common;

use std::path::Path;

use common::{fresh_dir, render_small, run_in};

/// An uncompressed 24-bit TGA of `width` x `height`, rows from the top,
/// every pixel `bgr`.
fn tga(path: &Path, width: u16, height: u16, bgr: [u8; 3]) {
    let mut bytes = vec![0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 0, 0];
    bytes.extend_from_slice(&width.to_le_bytes());
    bytes.extend_from_slice(&height.to_le_bytes());
    bytes.extend_from_slice(&[24, 0x20]);
    for _ in 0..width as usize * height as usize {
        bytes.extend_from_slice(&bgr);
    }
    std::fs::write(path, bytes).expect("write tga");
}

/// A scene whose one sphere wears `texture`.
fn texture_scene(dir: &Path, texture: &str) -> String {
    let scene = format!(
        "PerspectiveCamera {{ center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 width 8 height 8 }}\n\
         Lights {{ numLights 1 DirectionalLight {{ direction 0 0 -1 color 1 1 1 }} }}\n\
         Materials {{ numMaterials 1 Material {{ diffuseColor 1 1 1 texture {texture} }} }}\n\
         Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 0 radius 2 }} }}\n"
    );
    let name = format!("{texture}.txt");
    std::fs::write(dir.join(&name), scene).expect("write scene");
    name
}

#[test]
fn tga_and_pfm_textures_were_an_unrecognised_image_format() {
    let dir = fresh_dir("tga-pfm-textures");
    tga(&dir.join("red.tga"), 4, 2, [0, 0, 255]);
    let written = render_small(&dir, "box.pfm", &["--quiet"]);
    assert_eq!(written.code, Some(0), "{}", written.stderr);
    for texture in ["red.tga", "box.pfm"] {
        let scene = texture_scene(&dir, texture);
        let ran = run_in(&dir, &["check", &scene]);
        assert_eq!(ran.code, Some(0), "{texture}: {}", ran.stderr);
        assert!(ran.stdout.contains("1 textures"), "{}", ran.stdout);
    }
    // The TGA's colour reaches the image: the sphere is red.
    let scene = texture_scene(&dir, "red.tga");
    let ran = run_in(&dir, &["render", &scene, "-o", "red.pfm", "--quiet"]);
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    let bytes = std::fs::read(dir.join("red.pfm")).expect("image");
    let data = &bytes[bytes.len() - 8 * 8 * 12..];
    let centre = (4 * 8 + 4) * 12;
    let channel = |c: usize| {
        f32::from_le_bytes(
            data[centre + 4 * c..centre + 4 * c + 4]
                .try_into()
                .expect("4 bytes"),
        )
    };
    assert!(channel(0) > 0.1, "red {}", channel(0));
    assert_eq!((channel(1), channel(2)), (0.0, 0.0));
}

#[test]
fn compare_of_tga_images_was_an_unrecognised_image_format() {
    let dir = fresh_dir("tga-compare");
    tga(&dir.join("a.tga"), 8, 4, [10, 20, 30]);
    tga(&dir.join("b.tga"), 8, 4, [10, 20, 30]);
    let ran = run_in(&dir, &["compare", "a.tga", "b.tga"]);
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
    assert!(ran.stdout.contains("same"), "{}", ran.stdout);
}
