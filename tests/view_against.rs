//! `pathtracer view --against IMAGE`: the user's image measured against
//! ours as it converges: identical renders look the same with a FLIP of 0,
//! a different picture does not, and theirs and the heat map are served at
//! our size.

mod common;

use std::path::Path;
use std::time::Duration;

use common::{Answer, Viewer, command_in, finish, fresh_dir};

const SIZE: [&str; 6] = ["--width", "32", "--height", "24", "--spp", "16"];

/// The `against` object of a status, as text.
fn against(status: &Answer) -> String {
    let text = status.text();
    text.split("\"against\": ").nth(1).unwrap_or("").to_string()
}

fn render_png(dir: &Path, output: &str) {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/tutorial2_sphere.txt");
    let args = [
        &["render", scene.to_str().unwrap(), "-o", output, "--quiet"],
        &SIZE[..],
    ]
    .concat();
    let ran = finish(command_in(dir, &args));
    assert_eq!(ran.code, Some(0), "{}", ran.stderr);
}

/// Starts `view` of the tutorial's ball against `image` and waits for a
/// measure of the finished render.
fn measured(dir: &Path, image: &str) -> (Viewer, Answer) {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/tutorial2_sphere.txt");
    let viewer = Viewer::start(dir, &scene, &[&SIZE[..], &["--against", image]].concat());
    let status = viewer.wait_for("/status", Duration::from_secs(60), |a| {
        let text = a.text();
        let frame = text
            .split("\"frame\": ")
            .nth(1)
            .and_then(|r| r.split(',').next())
            .unwrap_or("")
            .to_string();
        text.contains("\"done\": true") && against(a).contains(&format!("\"frame\": {frame},"))
    });
    (viewer, status)
}

#[test]
fn our_own_render_looks_the_same_and_theirs_and_the_heat_map_are_served() {
    let dir = fresh_dir("view-against-same");
    render_png(&dir, "theirs.png");
    let (viewer, status) = measured(&dir, "theirs.png");
    let figures = against(&status);
    assert!(figures.contains("\"same\": true"), "{figures}");
    assert!(figures.contains("\"mean\": 0.000"), "{figures}");
    assert!(figures.contains("\"flip\": 0.00000"), "{figures}");
    for path in ["/against", "/heat"] {
        let frame = viewer.get(path);
        assert_eq!(frame.code, 200, "{path}");
        assert_eq!(&frame.body[..4], b"PTVD", "{path}");
        assert_eq!(frame.body.len(), 16 + 32 * 24 * 3, "{path}");
    }
    // The heat map of identical images is magma's darkest entry throughout.
    let heat = viewer.get("/heat").body;
    assert!(
        heat[16..].chunks(3).all(|p| p == &heat[16..19]),
        "a flat map"
    );
}

#[test]
fn a_different_picture_of_another_size_looks_different() {
    let dir = fresh_dir("view-against-other");
    // A 64x48 grey picture: the criterion resamples it to our size.
    let grey = pathtracer::image_io::Image {
        width: 64,
        height: 48,
        pixels: vec![pathtracer::color::Color::new(0.5, 0.5, 0.5); 64 * 48],
    };
    pathtracer::image_io::write_image(&dir.join("grey.png"), &grey, None).expect("write");
    let (viewer, status) = measured(&dir, "grey.png");
    let figures = against(&status);
    assert!(figures.contains("\"same\": false"), "{figures}");
    assert!(figures.contains("\"image\": \"grey.png\""), "{figures}");
    let theirs = viewer.get("/against");
    assert_eq!(theirs.body.len(), 16 + 32 * 24 * 3);
    // Grey resampled is grey: 127 (0.5 as the PNG writer stores it).
    assert!(
        theirs.body[16..].iter().all(|&b| b == 127),
        "{:?}",
        &theirs.body[16..22]
    );
}

#[test]
fn a_missing_against_image_is_refused_before_serving() {
    let dir = fresh_dir("view-against-missing");
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("testcases/tutorial2_sphere.txt");
    let ran = finish(command_in(
        &dir,
        &["view", scene.to_str().unwrap(), "--against", "nowhere.png"],
    ));
    assert_eq!(ran.code, Some(1), "{}", ran.stderr);
    assert!(ran.stderr.contains("nowhere.png"), "{}", ran.stderr);
    assert!(!ran.stdout.contains("http://"), "{}", ran.stdout);
}
