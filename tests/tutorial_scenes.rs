//! The scenes of the first-scene tutorial (docs/guide/first-scene.md,
//! testcases/tutorial*.txt) render without warnings and show what the
//! tutorial says they show: the background, a ball lit from above, a box
//! with a red left wall and a green right wall.

use std::path::{Path, PathBuf};
use std::process::Command;

use pathtracer::color::Color;
use pathtracer::image_io::{Image, read_image};

const WIDTH: usize = 64;
const HEIGHT: usize = 48;

/// The tutorial's camera: eye (0, 5, 18.7) looking along -z, 40 degrees vertical.
const EYE: [f64; 3] = [0.0, 5.0, 18.7];
const HALF_ANGLE_DEGREES: f64 = 20.0;

fn temp_dir(name: &str) -> PathBuf {
    let dir =
        std::env::temp_dir().join(format!("pathtracer-tutorial-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Renders `testcases/<scene>` at 64x48 and `spp` into a PFM; asserts that it
/// succeeds with no warning, and returns the linear image.
fn render(scene: &str, spp: u32) -> Image {
    let dir = temp_dir(scene.trim_end_matches(".txt"));
    let out = dir.join("image.pfm");
    let scene = Path::new("testcases").join(scene);
    let output = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args([
            "render",
            scene.to_str().unwrap(),
            "-o",
            out.to_str().unwrap(),
        ])
        .args([
            "--width",
            &WIDTH.to_string(),
            "--height",
            &HEIGHT.to_string(),
        ])
        .args(["--spp", &spp.to_string(), "--quiet"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{}: {stderr}", scene.display());
    assert!(
        !stderr.contains("warning"),
        "{} warns: {stderr}",
        scene.display()
    );
    let image = read_image(&out).expect("the PFM reads back");
    assert_eq!((image.width, image.height), (WIDTH, HEIGHT));
    image
}

/// The pixel (column, row) that a world point projects to, computed here
/// from the camera's description, independently of the renderer's camera.
fn project(point: [f64; 3]) -> (i64, i64) {
    let tangent = HALF_ANGLE_DEGREES.to_radians().tan();
    let depth = EYE[2] - point[2];
    let x = (point[0] - EYE[0]) / depth / tangent;
    let y = (point[1] - EYE[1]) / depth / tangent;
    let half_height = HEIGHT as f64 / 2.0;
    let column = WIDTH as f64 / 2.0 + x * half_height;
    let row = half_height - y * half_height;
    (column.floor() as i64, row.floor() as i64)
}

/// The mean of the 3x3 pixels around where `point` projects.
fn around(image: &Image, point: [f64; 3]) -> Color {
    let (column, row) = project(point);
    assert!(
        (1..WIDTH as i64 - 1).contains(&column) && (1..HEIGHT as i64 - 1).contains(&row),
        "{point:?} projects to ({column}, {row}), too near the border"
    );
    let mut sum = Color::BLACK;
    for r in row - 1..=row + 1 {
        for c in column - 1..=column + 1 {
            sum += image.pixels[r as usize * image.width + c as usize];
        }
    }
    sum * (1.0 / 9.0)
}

/// The box's walls: red on the left, green on the right, white at the
/// back, and light enough in the whole image.
fn assert_box_walls(image: &Image) {
    let left = around(image, [-5.0, 6.0, -2.0]);
    let right = around(image, [5.0, 6.0, -2.0]);
    assert!(red_dominant(left), "left wall {left:?}");
    assert!(green_dominant(right), "right wall {right:?}");
    let back = around(image, [-3.0, 8.0, -5.0]);
    assert!(
        back.luminance() > 0.05 && !red_dominant(back) && !green_dominant(back),
        "back wall {back:?}"
    );
    assert!(mean(image) > 0.05, "the image is not black");
}

fn red_dominant(c: Color) -> bool {
    c.r > 2.0 * c.g && c.r > 2.0 * c.b
}

fn green_dominant(c: Color) -> bool {
    c.g > 2.0 * c.r && c.g > 2.0 * c.b
}

fn mean(image: &Image) -> f64 {
    image.pixels.iter().map(Color::luminance).sum::<f64>() / image.pixels.len() as f64
}

#[test]
fn step_1_every_ray_misses_and_brings_back_the_background() {
    let image = render("tutorial1_camera.txt", 4);
    for pixel in &image.pixels {
        for (value, expected) in [(pixel.r, 0.2), (pixel.g, 0.3), (pixel.b, 0.5)] {
            assert!((value - expected).abs() < 1e-6, "{pixel:?}");
        }
    }
}

#[test]
fn step_2_the_ball_is_lit_from_above_on_a_black_background() {
    let image = render("tutorial2_sphere.txt", 16);
    // Ball: centre (0, 4, 0), radius 3; the lamp at (0, 11, 2) above it.
    let top = around(&image, [0.0, 6.0, 5f64.sqrt()]);
    let underside = around(&image, [0.0, 1.5, 2.75f64.sqrt()]);
    assert!(top.luminance() > 0.1, "top of the ball {top:?}");
    assert!(
        underside.luminance() < 0.1 * top.luminance(),
        "underside {underside:?} against top {top:?}"
    );
    assert!(
        around(&image, [0.0, 10.5, 2.0]).luminance() > 1.0,
        "the lamp"
    );
    let corner = image.pixels[0];
    assert_eq!(corner.luminance(), 0.0, "the background is black");
}

#[test]
fn step_3_the_box_has_a_red_left_wall_and_a_green_right_wall() {
    let image = render("tutorial3_box.txt", 16);
    assert_box_walls(&image);
}

#[test]
fn step_4_the_cornell_box_keeps_its_walls_and_loads_its_mesh_and_texture() {
    let image = render("tutorial4_cornell.txt", 16);
    assert_box_walls(&image);
    let output = Command::new(env!("CARGO_BIN_EXE_pathtracer"))
        .args(["check", "testcases/tutorial4_cornell.txt"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs");
    let summary = String::from_utf8_lossy(&output.stdout);
    assert!(output.status.success(), "{summary}");
    // The torus of mesh/torus.obj (576 triangles) and the two lamp triangles.
    assert!(summary.contains("(578 triangles)"), "{summary}");
    assert!(summary.contains("1 textures"), "{summary}");
    assert!(summary.contains("look original"), "{summary}");
}
