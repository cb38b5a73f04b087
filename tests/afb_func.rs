//! afb's `Func N` selectors: with `Texture FILE` and `Func N`, the texel of
//! a hit comes from its world point (or, for 7, the angle about a surface
//! of revolution and five times the ray distance), truncated, wrapped by a
//! double modulo, rows counted from the top of the file.

mod common;

use std::f64::consts::PI;
use std::path::PathBuf;

use pathtracer::color::Color;
use pathtracer::image_io::{Image, write_image};
use pathtracer::math::{Point3, Ray, Vec3};
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, load_scene};
use pathtracer::texture::uv_rule::UvRule;

const SIZE: usize = 4;

/// Texel (i, j) of the test image, j = 0 the top row: every texel distinct
/// (as decoded: 8-bit values over 255 in f32).
fn texel(i: usize, j: usize) -> Color {
    let byte = |b: usize| (b as f32 / 255.0) as f64;
    Color::new(byte(10 + 60 * i), byte(10 + 60 * j), byte(100))
}

/// A folder with `texture/grid.png` (SIZE x SIZE) and `scene.txt`.
fn scene(name: &str, text: &str) -> Scene {
    let dir = std::env::temp_dir().join(format!("pt-afb-{}-{name}", std::process::id()));
    std::fs::create_dir_all(dir.join("texture")).expect("temp dir");
    let image = Image {
        width: SIZE,
        height: SIZE,
        pixels: (0..SIZE * SIZE)
            .map(|k| texel(k % SIZE, k / SIZE))
            .collect(),
    };
    write_image(&dir.join("texture/grid.png"), &image, None).expect("png");
    let file: PathBuf = dir.join("scene.txt");
    std::fs::write(&file, text).expect("scene");
    let options = LoadOptions {
        base: Some(dir),
        ..LoadOptions::default()
    };
    load_scene(&file, &options).expect("loads")
}

const CAMERA: &str =
    "PerspectiveCamera { center 0 0 10 direction 0 0 -1 up 0 1 0 angle 30 width 8 height 8 }\n";

fn afb_material(func: i64) -> String {
    format!(
        "Material {{ diffuseColor 0.59 0.98 0.59\n Func {func}\n Texture ./texture/grid.png\n type 0}}"
    )
}

/// The colour and hit of the first surface along `ray`.
fn shade(scene: &Scene, ray: &Ray) -> (Color, Point3, f64) {
    let scene = common::built(scene.clone());
    let hit = scene.intersect(ray).expect("hit");
    (scene.shade(&hit, ray).color, hit.point, hit.t)
}

/// afb's index: trunc(c * size), then ((i % size) + size) % size.
fn afb_index(c: f64) -> usize {
    let i = (c * SIZE as f64).trunc() as i64;
    ((i % SIZE as i64 + SIZE as i64) % SIZE as i64) as usize
}

#[test]
fn func_1_and_6_read_the_xy_plane_over_a_four_unit_box_and_repeat_outside() {
    for func in [1, 6] {
        let text = format!(
            "{CAMERA}Materials {{ numMaterials 1 {} }}\nGroup {{ numObjects 1 MaterialIndex 0 Plane {{ normal 0 0 1 offset -2 }} }}\n",
            afb_material(func)
        );
        let scene = scene(&format!("front{func}"), &text);
        assert_eq!(scene.materials[0].uv_rule, Some(UvRule::FrontXy));
        assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
        for (x, y) in [
            (-1.9, 1.9),
            (0.3, -0.2),
            (1.2, -1.7),
            (2.6, 0.5),
            (-3.1, -2.4),
        ] {
            let ray = Ray::new(Point3::new(x, y, 10.0), -Vec3::z(), 0.0);
            let (color, point, _) = shade(&scene, &ray);
            let (a, b) = ((point.x + 2.0) / 4.0, (2.0 - point.y) / 4.0);
            assert_eq!(color, texel(afb_index(a), afb_index(b)), "at ({x}, {y})");
        }
    }
}

#[test]
fn func_2_to_5_read_a_quarter_of_the_image_repeating_every_unit_of_z() {
    for (func, normal, offset) in [
        (2, "0 1 0", -2),
        (3, "0 -1 0", -2),
        (4, "1 0 0", -2),
        (5, "-1 0 0", -2),
    ] {
        let text = format!(
            "{CAMERA}Materials {{ numMaterials 1 {} }}\nGroup {{ numObjects 1 MaterialIndex 0 Plane {{ normal {normal} offset {offset} }} }}\n",
            afb_material(func)
        );
        let scene = scene(&format!("side{func}"), &text);
        let floor = func <= 3;
        let mut rows = std::collections::BTreeSet::new();
        for z in [-1.6, -0.6, 0.4, 1.1, 1.9, 3.3] {
            for across in [-1.5, 0.7] {
                // Down onto the floor (y = 2 or -2 by the normal's sign) or
                // sideways onto the wall.
                let (origin, direction) = if floor {
                    let y = if func == 2 { 5.0 } else { -5.0 };
                    (Point3::new(across, y, z), Vec3::new(0.0, -y.signum(), 0.0))
                } else {
                    let x = if func == 4 { 5.0 } else { -5.0 };
                    (Point3::new(x, across, z), Vec3::new(-x.signum(), 0.0, 0.0))
                };
                let (color, point, _) = shade(&scene, &Ray::new(origin, direction, 0.0));
                let a = if floor {
                    (point.x + 2.0) / 4.0
                } else {
                    (point.y + 2.0) / 4.0
                };
                let b = (point.z + 2.0) / 4.0 - (point.z + 2.0).trunc() / 4.0;
                assert_eq!(
                    color,
                    texel(afb_index(a), afb_index(b)),
                    "Func {func} at z = {z}"
                );
                rows.insert(afb_index(b));
            }
        }
        assert_eq!(
            rows.into_iter().collect::<Vec<_>>(),
            vec![0],
            "only the top quarter"
        );
    }
}

#[test]
fn func_7_reads_the_angle_about_the_axis_in_radians_and_five_times_the_distance() {
    let text = format!(
        "{CAMERA}Materials {{ numMaterials 1 {} }}\nGroup {{ numObjects 1 MaterialIndex 0\n RevSurface {{ profile BezierCurve {{ controls [ 1 -1 0 ] [ 1.5 0 0 ] [ 1 1 0 ] }} }} }}\n",
        afb_material(7)
    );
    let scene = scene("revolution", &text);
    assert_eq!(scene.materials[0].uv_rule, Some(UvRule::Revolution));
    let mut columns = std::collections::BTreeSet::new();
    for (x, z, dx, dz) in [
        (0.2, 6.0, 0.0, -1.0),
        (6.0, 0.3, -1.0, 0.0),
        (-6.0, -0.4, 1.0, 0.0),
        (0.5, -6.0, 0.0, 1.0),
        (4.0, 4.2, -1.0, -1.0),
    ] {
        let ray = Ray::new(
            Point3::new(x, 0.1, z),
            Vec3::new(dx, 0.0, dz).normalize(),
            0.0,
        );
        let (color, point, t) = shade(&scene, &ray);
        let theta = (-point.z).atan2(point.x);
        let b = 5.0 * t - (5.0 * t).trunc();
        assert!(theta.abs() <= PI);
        assert_eq!(
            color,
            texel(afb_index(theta), afb_index(b)),
            "hit at {point:?}"
        );
        columns.insert(afb_index(theta));
    }
    assert!(columns.len() >= 3, "the angle picks columns: {columns:?}");
}

#[test]
fn func_0_keeps_the_shapes_uv_and_unknown_funcs_warn() {
    let text = format!(
        "{CAMERA}Materials {{ numMaterials 2 {}\n{} }}\nGroup {{ numObjects 2 MaterialIndex 0 Sphere {{ center 0 0 0 radius 1 }} MaterialIndex 1 Sphere {{ center 3 0 0 radius 1 }} }}\n",
        afb_material(0),
        afb_material(9)
    );
    let scene = scene("func0", &text);
    assert_eq!(scene.materials[0].uv_rule, None);
    assert_eq!(scene.materials[1].uv_rule, None);
    assert!(scene.materials[0].texture.is_some());
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
    assert!(scene.warnings[0].message.contains("Func 9"));
    assert!(!scene.warnings[0].message.contains("not rendered"));
}
