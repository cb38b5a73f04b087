//! OBJ `.mtl` materials: a box lit only by a `Ke` material renders, with the
//! same expectation for both integrators, and light sampling picks its
//! triangles; the fields map as the table of `scene::build::mtl` says,
//! unrendered fields warn with their line, and `MaterialIndex` overrides the
//! `.mtl` except in bow's dialect.

mod common;

use std::path::{Path, PathBuf};

use common::statistic;
use pathtracer::color::Color;
use pathtracer::integrator::{Integrator, original::MAX_DEPTH};
use pathtracer::math::Point3;
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::LoadOptions;
use pathtracer::scene::model::{Dialect, OWN_MATERIAL, Object, Scene};

/// A fresh folder for one test's files.
fn folder(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("pt-mtl-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// A quad as two triangles (vertex numbers from `first`), counter-clockwise
/// seen from where its normal points.
fn quad(obj: &mut String, first: &mut usize, corners: [[f64; 3]; 4]) {
    for [x, y, z] in corners {
        *obj += &format!("v {x} {y} {z}\n");
    }
    let i = *first;
    *obj += &format!("f {} {} {}\nf {} {} {}\n", i, i + 1, i + 2, i, i + 2, i + 3);
    *first += 4;
}

/// The Cornell-like box: white floor and ceiling, red and green side walls,
/// a back wall without `usemtl` (the scene's material) and a small lamp
/// under the ceiling whose only light is its `Ke`.
fn write_box(dir: &Path) {
    let mtl = "newmtl white\nKd 0.75 0.75 0.75\n\nnewmtl red\nKd 0.75 0.2 0.2\n\n\
               newmtl green\nKd 0.2 0.75 0.2\n\nnewmtl lamp\nKd 0 0 0\nKe 6 6 6\n";
    std::fs::write(dir.join("box.mtl"), mtl).expect("write mtl");
    let mut obj = String::from("mtllib box.mtl\n");
    let mut n = 1;
    quad(
        &mut obj,
        &mut n,
        [
            [-1., -1., -1.],
            [1., -1., -1.],
            [1., 1., -1.],
            [-1., 1., -1.],
        ],
    );
    obj += "usemtl white\n";
    quad(
        &mut obj,
        &mut n,
        [
            [-1., -1., 1.],
            [1., -1., 1.],
            [1., -1., -1.],
            [-1., -1., -1.],
        ],
    );
    quad(
        &mut obj,
        &mut n,
        [[-1., 1., -1.], [1., 1., -1.], [1., 1., 1.], [-1., 1., 1.]],
    );
    obj += "usemtl red\n";
    quad(
        &mut obj,
        &mut n,
        [
            [-1., -1., 1.],
            [-1., -1., -1.],
            [-1., 1., -1.],
            [-1., 1., 1.],
        ],
    );
    obj += "usemtl green\n";
    quad(
        &mut obj,
        &mut n,
        [[1., -1., -1.], [1., -1., 1.], [1., 1., 1.], [1., 1., -1.]],
    );
    obj += "usemtl lamp\n";
    let y = 0.98;
    quad(
        &mut obj,
        &mut n,
        [
            [-0.3, y, -0.3],
            [0.3, y, -0.3],
            [0.3, y, 0.3],
            [-0.3, y, 0.3],
        ],
    );
    std::fs::write(dir.join("box.obj"), obj).expect("write obj");
}

fn load(dir: &Path, text: &str, options: LoadOptions) -> Result<Scene, String> {
    let file = dir.join("scene.txt");
    std::fs::write(&file, text).expect("write scene");
    let options = LoadOptions {
        base: Some(dir.to_path_buf()),
        ..options
    };
    pathtracer::scene::load_scene(&file, &options).map_err(|e| e.to_string())
}

const BOX_SCENE: &str = "PerspectiveCamera { center 0 0 3.4 direction 0 0 -1 up 0 1 0 \
                         width 8 height 8 }\nMaterials { Material { color 0.5 0.5 0.5 } }\n\
                         Group { TriangleMesh { obj_file box.obj } }\n";

fn runs(scene: &Scene, integrator: Integrator) -> Vec<Vec<f64>> {
    let settings = RenderSettings {
        width: 8,
        height: 8,
        spp: 16,
        seed: 0,
        threads: None,
        integrator,
        max_depth: MAX_DEPTH,
        sampler: SamplerKind::Independent,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look: Default::default(),
        dispersion: None,
    };
    common::independent_runs(scene, &settings, 500, 24)
}

#[test]
fn box_lit_by_a_ke_material_renders_alike_with_both_integrators() {
    let dir = folder("box");
    write_box(&dir);
    let scene = load(&dir, BOX_SCENE, LoadOptions::default()).expect("loads");
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
    // The scene's material, then white, red, green, lamp.
    assert_eq!(scene.materials.len(), 5);
    assert_eq!(scene.materials[4].emission, Color::gray(6.0));
    assert!(scene.materials[..4].iter().all(|m| m.emission.is_black()));
    let mut faces = Vec::new();
    scene.root.for_each_leaf(&mut |leaf| {
        if let Object::Mesh {
            face_materials: Some(f),
            material,
            ..
        } = leaf
        {
            assert_eq!(*material, 0);
            faces = f.to_vec();
        }
    });
    assert_eq!(
        faces,
        [OWN_MATERIAL, OWN_MATERIAL, 1, 1, 1, 1, 2, 2, 3, 3, 4, 4]
    );

    // Light sampling finds the lamp's two triangles (and only them).
    let ready = common::built(scene.clone());
    let sample = ready
        .emitters()
        .sample(&Point3::new(0.0, -0.5, 0.0), 0.0, 0.3, [0.4, 0.6])
        .expect("the lamp is sampled");
    assert_eq!(sample.emission, Color::gray(6.0));
    assert!(
        (sample.point.y - 0.98).abs() < 1e-6 && sample.pdf > 0.0,
        "{sample:?}"
    );

    let path = runs(&scene, Integrator::Path);
    let original = runs(&scene, Integrator::Original);
    let mean = |p: &[f64]| p.iter().sum::<f64>() / p.len() as f64;
    let (a, sa) = statistic(&path, mean);
    let (b, sb) = statistic(&original, mean);
    println!("image mean: path {a:.5} ± {sa:.5}, original {b:.5} ± {sb:.5}");
    assert!(a > 0.01, "the Ke material lights the box: {a}");
    let combined = (sa * sa + sb * sb).sqrt();
    assert!(
        (a - b).abs() <= 4.0 * combined,
        "path {a} ± {sa}, original {b} ± {sb}"
    );
}

#[test]
fn mtl_fields_map_as_the_table_says_and_the_rest_warns_with_its_line() {
    let dir = folder("table");
    let grey = image::RgbImage::from_fn(4, 4, |x, _| image::Rgb([(x * 60) as u8; 3]));
    grey.save(dir.join("wood.png")).expect("png");
    let normals = image::RgbImage::from_fn(4, 4, |x, _| image::Rgb([126 + x as u8, 128, 250]));
    normals.save(dir.join("bricks.png")).expect("png");
    let mtl = "# test library\n\
               newmtl glassy\n\
               Kd 0.2 0.4 0.6\n\
               Ks 0.5 0.5 0.5\n\
               Ns 40\n\
               Ni 1.33\n\
               d 0.25\n\
               illum 7\n\
               Ka 0.1 0.1 0.1\n\
               Tf 1 1 1\n\
               \n\
               newmtl wood\n\
               map_Kd -s 2 2 1 wood.png\n\
               Ks 0 0 0\n\
               norm bricks.png\n\
               map_Bump -bm 0.5 wood.png\n\
               newmtl lost\n\
               map_Kd nowhere.png\n";
    std::fs::write(dir.join("lib.mtl"), mtl).expect("write mtl");
    let obj = "mtllib lib.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl glassy\nf 1 2 3\n\
               usemtl wood\nf 1 3 2\nusemtl lost\nf 2 3 1\n";
    std::fs::write(dir.join("m.obj"), obj).expect("write obj");
    let text = "PerspectiveCamera { width 2 height 2 }\nMaterials { Material { } }\n\
                Group { TriangleMesh { obj_file m.obj } }\n";
    let scene = load(&dir, text, LoadOptions::default()).expect("loads");
    let [_, glassy, wood, lost] = scene.materials.as_slice() else {
        panic!(
            "three .mtl materials after the scene's: {:?}",
            scene.materials.len()
        );
    };
    assert_eq!(
        glassy.color,
        Color::new(0.2, 0.4, 0.6).map(|c| c as f32 as f64)
    );
    let phong = glassy.phong.expect("Ks is not black");
    assert_eq!(phong.color, Color::gray(0.5));
    assert_eq!(phong.exponent, 40.0);
    assert_eq!(glassy.ior, 1.33f32 as f64);
    assert_eq!(
        (glassy.diffuse, glassy.specular, glassy.refract),
        (0.25, 0.0, 0.75)
    );
    let texture = wood.texture.expect("map_Kd");
    assert_eq!(scene.textures[texture].width, 4);
    assert!(wood.phong.is_none(), "black Ks");
    assert!(wood.normal_map.is_some(), "norm: a colour normal map");
    let bump = wood.bump.expect("map_Bump of a grey image");
    assert_eq!((bump.texture, bump.scale), (texture, 0.5));
    assert_eq!((wood.diffuse, wood.ior), (1.0, 1.5));
    assert!(lost.texture.is_none());

    let messages: Vec<&str> = scene.warnings.iter().map(|w| w.message.as_str()).collect();
    let warns = |field: &str, line: usize| {
        messages
            .iter()
            .any(|m| m.contains(field) && m.contains(&format!("lib.mtl:{line})")))
    };
    assert!(warns("'illum'", 8), "{messages:#?}");
    assert!(warns("'Ka'", 9), "{messages:#?}");
    assert!(warns("'Tf'", 10), "{messages:#?}");
    assert!(warns("option '-s' of 'map_Kd'", 13), "{messages:#?}");
    assert!(warns("nowhere.png", 18), "{messages:#?}");
    assert_eq!(messages.len(), 5, "{messages:#?}");
    assert!(scene.warnings.iter().all(|w| w.location.line == 3));
    let strict = LoadOptions {
        strict: true,
        ..LoadOptions::default()
    };
    let error = load(&dir, text, strict).expect_err("strict: warnings are errors");
    assert!(
        error.contains("'illum'") && error.contains("lib.mtl:8"),
        "{error}"
    );
}

#[test]
fn material_index_overrides_the_mtl_except_in_bow_dialect() {
    let dir = folder("override");
    write_box(&dir);
    let text = "PerspectiveCamera { width 2 height 2 }\nMaterials { Material { } Material { } }\n\
                Group {\n MaterialIndex 1\n TriangleMesh { obj_file box.obj } }\n";
    let face_materials = |scene: &Scene| {
        let mut found = None;
        scene.root.for_each_leaf(&mut |leaf| {
            if let Object::Mesh { face_materials, .. } = leaf {
                found = Some(face_materials.is_some());
            }
        });
        found.expect("a mesh")
    };
    let scene = load(&dir, text, LoadOptions::default()).expect("loads");
    assert!(!face_materials(&scene));
    assert_eq!(scene.materials.len(), 2, "no .mtl materials added");
    let [warning] = scene.warnings.as_slice() else {
        panic!("{:?}", scene.warnings);
    };
    assert!(
        warning.message.contains("box.obj")
            && warning
                .message
                .contains("overridden by MaterialIndex 1 (line 4)"),
        "{}",
        warning.message
    );
    let bow = LoadOptions {
        dialect: Some(Dialect::Bow),
        ..LoadOptions::default()
    };
    let scene = load(&dir, text, bow).expect("loads");
    assert!(face_materials(&scene));
    assert_eq!(scene.materials.len(), 6);
    assert!(scene.warnings.is_empty(), "{:?}", scene.warnings);
}
