//! rub's texture descriptor files: `texture FILE.txt` and `nTexture
//! FILE.txt` name a file `{ type-word fields }`: a `checkerTexture` is a
//! procedural colour at the world point, an `imageTexture` an ordinary
//! colour texture, an `nTexture` under `nTexture` a tangent-space normal
//! map. Errors and warnings about a descriptor's content are located in it.

mod common;

use std::path::{Path, PathBuf};

use pathtracer::color::Color;
use pathtracer::image_io::{Image, write_image};
use pathtracer::math::{Point3, Ray, Vec3};
use pathtracer::scene::model::Scene;
use pathtracer::scene::{LoadOptions, MissingAssets, load_scene};
use pathtracer::texture::Texture;
use pathtracer::texture::checker::Checker;

/// rub's layout: `root/testcases/scene.txt` next to its descriptors, paths
/// written from the root. Returns the scene file.
fn project(name: &str, descriptors: &[(&str, &str)], scene: &str) -> PathBuf {
    let root = std::env::temp_dir().join(format!("pt-rub-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&root);
    std::fs::create_dir_all(root.join("testcases")).expect("temp dir");
    for (file, text) in descriptors {
        std::fs::write(root.join(file), text).expect("descriptor");
    }
    // A 2x2 photo and a 2x2 tangent-space normal map (blue, tilted in x).
    let photo = Image {
        width: 2,
        height: 2,
        pixels: vec![
            Color::new(1.0, 0.0, 0.0),
            Color::new(0.0, 1.0, 0.0),
            Color::new(0.0, 0.0, 1.0),
            Color::gray(1.0),
        ],
    };
    write_image(&root.join("testcases/earth.png"), &photo, None).expect("png");
    let normal = Image {
        width: 2,
        height: 2,
        pixels: vec![Color::new(0.8, 0.5, 0.9); 4],
    };
    write_image(&root.join("testcases/normal.png"), &normal, None).expect("png");
    let file = root.join("testcases/scene.txt");
    std::fs::write(&file, scene).expect("scene");
    file
}

fn scene_text(material: &str) -> String {
    format!(
        "PerspectiveCamera {{ center 0 0 6 direction 0 0 -1 up 0 1 0 angle 30 width 8 height 8 defocusAngle 0 focusDist 1 }}\n\
         Materials {{ numMaterials 1\n Material {{ diffuseColor 1 1 1 perDiffuse 1 {material} cookTorrence 1.3 0.04 0 }}\n}}\n\
         Group {{ numObjects 1 MaterialIndex 0 Quad {{ origin -2 -2 0 u 4 0 0 v 0 4 0 }} }}\n"
    )
}

fn load(file: &Path, missing_assets: MissingAssets) -> Result<Scene, String> {
    let options = LoadOptions {
        missing_assets,
        ..LoadOptions::default()
    };
    load_scene(file, &options).map_err(|e| e.to_string())
}

fn shading_at(scene: &Scene, x: f64, y: f64) -> (Color, Vec3) {
    let scene = common::built(scene.clone());
    let ray = Ray::new(Point3::new(x, y, 5.0), -Vec3::z(), 0.0);
    let hit = scene.intersect(&ray).expect("hits the quad");
    let shading = scene.shade(&hit, &ray);
    (shading.color, shading.normal)
}

const CHECKER: &str =
    "{\n    checkerTexture\n    scale 2\n    colorEven 0.9 0.1 0.1\n    colorOdd 0.1 0.1 0.9\n}\n";

#[test]
fn a_checker_descriptor_colours_by_the_parity_of_the_world_cells() {
    let file = project(
        "checker",
        &[("testcases/checker.txt", CHECKER)],
        &scene_text("texture testcases/checker.txt"),
    );
    let scene = load(&file, MissingAssets::Error).expect("loads");
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let even = Color::new(0.9, 0.1, 0.1);
    let odd = Color::new(0.1, 0.1, 0.9);
    assert_eq!(
        scene.materials[0].checker,
        Some(Checker {
            scale: 2.0,
            even,
            odd
        })
    );
    assert_eq!(scene.materials[0].texture, None);
    for (x, y) in [
        (0.2f64, 0.2f64),
        (0.7, 0.2),
        (0.7, 0.7),
        (-0.2, 0.2),
        (-0.7, -1.3),
        (1.9, -0.1),
    ] {
        // On the quad z = 0: floor(2 z) = 0.
        let cells = (2.0 * x).floor() + (2.0 * y).floor();
        let expected = if cells.rem_euclid(2.0) == 0.0 {
            even
        } else {
            odd
        };
        assert_eq!(shading_at(&scene, x, y).0, expected, "at ({x}, {y})");
    }
}

#[test]
fn an_image_descriptor_is_a_colour_texture_and_an_ntexture_a_normal_map() {
    // rub's own earth.txt, byte for byte.
    let earth = "{\n    imageTexture\n    imagefile testcases/earth.png\n}\n";
    let normal = "{\n    nTexture\n    imagefile testcases/normal.png\n}\n";
    let file = project(
        "image",
        &[("testcases/earth.txt", earth), ("testcases/n.txt", normal)],
        &scene_text("texture testcases/earth.txt nTexture testcases/n.txt"),
    );
    let scene = load(&file, MissingAssets::Error).expect("loads");
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    let material = &scene.materials[0];
    let photo = &scene.textures[material.texture.expect("a colour texture")];
    assert_eq!((photo.width, photo.height), (2, 2));
    assert_eq!(photo.texels[0], [1.0, 0.0, 0.0]);
    let map = material.normal_map.expect("a normal map");
    assert_eq!(scene.textures[map].texels[0][2], (229.0f32 / 255.0));
    // The same images named directly give the same shading.
    let direct = project(
        "direct",
        &[],
        &scene_text("texture testcases/earth.png normal testcases/normal.png"),
    );
    let direct = load(&direct, MissingAssets::Error).expect("loads");
    for (x, y) in [(-1.5, 1.5), (1.5, 1.5), (-1.5, -1.5), (0.5, -1.0)] {
        let (color, normal) = shading_at(&scene, x, y);
        assert_eq!((color, normal), shading_at(&direct, x, y), "at ({x}, {y})");
        // Tilted towards +x by the map's red 0.8, still facing the camera.
        assert!(normal.x > 0.3 && normal.z > 0.5, "{normal:?}");
    }
}

/// `file:line:column` of an error or warning message.
fn place(message: &str, file: &Path, line: u32, column: u32) -> bool {
    message.starts_with(&format!("{}:{line}:{column}:", file.display()))
}

#[test]
fn errors_and_warnings_in_a_descriptor_are_located_in_it() {
    let cases = [
        (
            "{\n  marbleTexture\n}\n",
            2,
            3,
            "unknown texture type 'marbleTexture'",
        ),
        (
            "{ checkerTexture\n  scale two }\n",
            2,
            9,
            "expected a number after 'scale'",
        ),
        ("{ imageTexture }\n", 1, 16, "needs 'imagefile PATH'"),
        (
            "{ imageTexture imagefile\n   testcases/none.png }",
            2,
            4,
            "texture 'testcases/none.png' not found",
        ),
        (
            "checkerTexture { scale 1 }\n",
            1,
            1,
            "expected '{' and a type word",
        ),
        ("{ checkerTexture scale 1\n", 1, 1, "never closed"),
    ];
    for (index, (text, line, column, message)) in cases.into_iter().enumerate() {
        let file = project(
            &format!("error{index}"),
            &[("testcases/bad.txt", text)],
            &scene_text("texture testcases/bad.txt"),
        );
        let descriptor = file.with_file_name("bad.txt");
        let error = load(&file, MissingAssets::Error).expect_err(text);
        assert!(
            place(&error, &descriptor, line, column),
            "{text:?}: {error}"
        );
        assert!(error.contains(message), "{text:?}: {error}");
    }
    // A missing descriptor is an error where the scene names it.
    let file = project("nofile", &[], &scene_text("texture testcases/none.txt"));
    let error = load(&file, MissingAssets::Error).expect_err("missing descriptor");
    assert!(place(&error, &file, 3, 53), "{error}");
    assert!(error.contains("testcases/none.txt"), "{error}");
    // Unknown fields warn in the descriptor; the rest is read.
    let file = project(
        "unknown",
        &[(
            "testcases/c.txt",
            "{ checkerTexture\n scale 1 wobble 3 colorOdd 0 1 0 }",
        )],
        &scene_text("texture testcases/c.txt"),
    );
    let scene = load(&file, MissingAssets::Error).expect("loads");
    let descriptor = file.with_file_name("c.txt");
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
    assert!(place(&scene.warnings[0].to_string(), &descriptor, 2, 10));
    assert_eq!(
        scene.materials[0].checker.map(|c| c.odd),
        Some(Color::new(0.0, 1.0, 0.0))
    );
}

#[test]
fn missing_descriptors_and_their_images_take_placeholders_when_asked() {
    let file = project(
        "placeholder",
        &[(
            "testcases/gone.txt",
            "{ imageTexture imagefile testcases/gone.png }",
        )],
        &scene_text("texture testcases/gone.txt nTexture testcases/none.txt"),
    );
    assert!(load(&file, MissingAssets::Error).is_err());
    let scene = load(&file, MissingAssets::Placeholder).expect("loads");
    let material = &scene.materials[0];
    assert_eq!(
        *scene.textures[material.texture.expect("placeholder")],
        Texture::placeholder()
    );
    assert_eq!(material.normal_map, None);
    assert_eq!(scene.warnings.len(), 2, "{:?}", scene.warnings);
    let descriptor = file.with_file_name("gone.txt");
    assert!(
        scene
            .warnings
            .iter()
            .any(|w| w.file == descriptor && w.message.contains("gone.png"))
    );
    assert!(
        scene
            .warnings
            .iter()
            .any(|w| w.file == file && w.message.contains("none.txt"))
    );
}

#[test]
fn a_checker_under_ntexture_is_not_rendered_and_says_so() {
    let file = project(
        "checker-normal",
        &[("testcases/checker.txt", CHECKER)],
        &scene_text("nTexture testcases/checker.txt"),
    );
    let scene = load(&file, MissingAssets::Error).expect("loads");
    assert_eq!(scene.materials[0].normal_map, None);
    assert_eq!(scene.materials[0].checker, None);
    assert_eq!(scene.warnings.len(), 1, "{:?}", scene.warnings);
    assert!(scene.warnings[0].message.contains("not rendered"));
    assert_eq!(scene.warnings[0].location.line, 3);
}
