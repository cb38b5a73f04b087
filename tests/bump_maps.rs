//! Bump (height) maps: a linear height ramp tilts the shading normal by
//! exactly the slope it describes, a constant height changes nothing (also on
//! interpolated normals), and the coursework's bump scene loads its map as a
//! height map.

mod common;

use std::f64::consts::PI;
use std::sync::Arc;

use common::*;
use pathtracer::color::Color;
use pathtracer::geometry::MeshData;
use pathtracer::math::{Point3, Ray, Vec3, orthonormal_basis};
use pathtracer::scene::LoadOptions;
use pathtracer::scene::model::{Bump, Material, Object, Scene};
use pathtracer::texture::Texture;

/// A `width` x 4 height map whose grey value rises by `step` per column.
fn ramp(width: usize, step: f32) -> Texture {
    Texture {
        width,
        height: 4,
        texels: (0..4)
            .flat_map(|_| (0..width).map(move |i| [0.1 + step * i as f32; 3]))
            .collect(),
    }
}

fn constant(grey: f32) -> Texture {
    Texture {
        width: 8,
        height: 8,
        texels: vec![[grey; 3]; 64],
    }
}

/// `root` with one material bump-mapped by `map` at `scale`.
fn bumped_scene(root: Object, map: Texture, scale: f64) -> Scene {
    let material = Material {
        bump: Some(Bump { texture: 0, scale }),
        ..Material::DEFAULT
    };
    let mut scene = scene_with(vec![material], root);
    scene.textures.push(Arc::new(map));
    scene
}

/// The shading normal where `ray` hits, with and without the bump map.
fn normals(scene: &Scene, ray: &Ray) -> (Vec3, Vec3) {
    let ready = built(scene.clone());
    let hit = ready.intersect(ray).expect("hit");
    let bumped = ready.shade(&hit, ray).normal;
    let mut flat = scene.clone();
    flat.materials[0].bump = None;
    let plain = built(flat).shade(&hit, ray).normal;
    (bumped, plain)
}

#[test]
fn height_ramp_on_a_plane_tilts_by_its_slope() {
    // Plane y = 0: uv = 10 (p . e1, p . e2) in texels, tiled. Grey rises by
    // `step` per texel, so the height rises by scale * 2 step per texel, that
    // is 10 times that per world unit along e1.
    let (step, scale) = (0.01f32, 0.3);
    let scene = bumped_scene(
        Object::Plane {
            normal: Vec3::y(),
            offset: 0.0,
            material: 0,
        },
        ramp(64, step),
        scale,
    );
    let (e1, _) = orthonormal_basis(&Vec3::y());
    let slope = 10.0 * scale * 2.0 * step as f64;
    let expected = (Vec3::y() - e1 * slope).normalize();
    let mut checked = 0;
    for k in 0..40 {
        let target = e1 * (0.35 + 0.13 * k as f64) + Vec3::new(0.0, 0.0, 0.01);
        let ray = Ray::new(
            target + Vec3::new(0.2, 3.0, 0.1),
            -Vec3::new(0.2, 3.0, 0.1),
            0.0,
        );
        let hit = built(scene.clone()).intersect(&ray).expect("hit");
        // Away from the wrap-around of the ramp (texel 63 next to texel 0).
        let column = hit.uv[0].floor().rem_euclid(64.0);
        if !(1.0..=62.0).contains(&column) {
            continue;
        }
        let (bumped, plain) = normals(&scene, &ray);
        assert!((plain - Vec3::y()).norm() < 1e-12);
        let error = (bumped - expected).norm();
        assert!(
            error < 1e-6,
            "at u = {}: {bumped:?}, expected {expected:?}",
            hit.uv[0]
        );
        checked += 1;
    }
    assert!(checked > 30, "{checked}");
    println!("tilt {:.4} rad = atan({slope})", expected.angle(&Vec3::y()));
}

#[test]
fn height_ramp_on_a_sphere_tilts_by_its_slope() {
    // Unit uv: a step of 1/width; grey rises by `step` per column, so
    // dh/du = scale * 2 step * width; at the equator |dp/du| = 2 pi r.
    let (width, step, scale, radius) = (256usize, 0.002f32, 0.05, 1.5);
    let scene = bumped_scene(
        Object::Sphere {
            center: Point3::zeros(),
            radius,
            motion: Vec3::zeros(),
            material: 0,
        },
        ramp(width, step),
        scale,
    );
    let slope = scale * 2.0 * step as f64 * width as f64 / (2.0 * PI * radius);
    for angle in [0.3f64, 1.1, 2.0, 2.9, 4.0] {
        let outward = Vec3::new(angle.cos(), 0.0, angle.sin());
        let ray = Ray::new(outward * 5.0, -outward, 0.0);
        let (bumped, plain) = normals(&scene, &ray);
        assert!((plain - outward).norm() < 1e-12);
        // dp/du runs along (w.z, 0, -w.x): the normal leans the other way.
        let along_u = Vec3::new(outward.z, 0.0, -outward.x);
        let expected = (outward - along_u * slope).normalize();
        let error = (bumped - expected).norm();
        assert!(
            error < 1e-6,
            "angle {angle}: {bumped:?}, expected {expected:?}"
        );
    }
}

#[test]
fn constant_height_leaves_the_normal_unchanged() {
    let sphere = Object::Sphere {
        center: Point3::zeros(),
        radius: 1.0,
        motion: Vec3::zeros(),
        material: 0,
    };
    let plane = Object::Plane {
        normal: Vec3::new(0.3, 1.0, 0.2),
        offset: -0.5,
        material: 0,
    };
    // A triangle with vertex normals: the interpolated normal is not the
    // face normal, and must survive a flat height map.
    let data = MeshData {
        framework_reading: None,
        positions: vec![
            Point3::new(-1.0, -1.0, 0.0),
            Point3::new(1.0, -1.0, 0.0),
            Point3::new(0.0, 1.0, 0.0),
        ],
        normals: Some(vec![
            Vec3::new(-0.5, -0.3, 1.0).normalize(),
            Vec3::new(0.4, -0.2, 1.0).normalize(),
            Vec3::new(0.0, 0.6, 1.0).normalize(),
        ]),
        uvs: Some(vec![[0.0, 0.0], [1.0, 0.0], [0.5, 1.0]]),
        triangles: vec![[0, 1, 2]],
    };
    let mesh = Object::Mesh {
        mesh: Arc::new(data),
        smooth: true,
        material: 0,
        face_materials: None,
    };
    for (name, root) in [("sphere", sphere), ("plane", plane), ("mesh", mesh)] {
        let scene = bumped_scene(root, constant(0.8), 2.0);
        if name == "mesh" {
            let ray = Ray::new(Point3::new(0.0, 0.0, 5.0), -Vec3::z(), 0.0);
            let (_, plain) = normals(&scene, &ray);
            assert!(
                plain.angle(&Vec3::z()) > 0.05,
                "interpolated normal expected"
            );
        }
        for k in 0..10 {
            let x = -0.3 + 0.07 * k as f64;
            let ray = Ray::new(Point3::new(x, 0.1 * k as f64 - 0.6, 5.0), -Vec3::z(), 0.0);
            let (bumped, plain) = normals(&scene, &ray);
            assert!(
                (bumped - plain).norm() < 1e-12,
                "{name}: {bumped:?} vs {plain:?}"
            );
        }
    }
}

#[test]
fn w_solaris_bump_scene_loads_a_height_map() {
    let Some(scene_file) =
        shared_file("reference/coursework/W-Solaris+computer-graphics/testcases/scene17_bump.txt")
    else {
        return;
    };
    let scene = pathtracer::scene::load_scene(&scene_file, &LoadOptions::default())
        .expect("scene17_bump loads");
    let material = &scene.materials[0];
    let bump = material.bump.expect("material 0 has a bump map");
    assert_eq!(material.normal_map, None);
    assert_eq!(bump.scale, 1.0);
    // texture/rope.jpg is a greyscale JPEG (r = g = b in every texel).
    let rope = &scene.textures[bump.texture];
    assert_eq!((rope.width, rope.height), (359, 356));
    assert!(rope.texels.iter().all(|t| t[0] == t[1] && t[1] == t[2]));
    assert!(scene.materials[1..].iter().all(|m| m.bump.is_none()));
    assert_eq!(material.color, Color::new(0.9, 0.8, 0.8));
}

#[test]
fn the_key_names_the_kind_and_a_clear_image_overrules_it() {
    let dir = std::env::temp_dir().join(format!("pt-bump-keys-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let save = |name: &str, texel: fn(u32, u32) -> [u8; 3]| {
        let image = image::RgbImage::from_fn(8, 8, |x, y| image::Rgb(texel(x, y)));
        image.save(dir.join(name)).expect("write png");
    };
    save("grey.png", |x, y| [(x * 20 + y) as u8; 3]);
    save("normals.png", |x, _| [120 + x as u8, 130 - x as u8, 240]);
    save("photo.png", |x, y| [200, (x * 30) as u8, (y * 10) as u8]);
    let materials = [
        "bump grey.png 0.25",
        "normal grey.png",
        "bumpMap normals.png",
        "normal_file photo.png",
        "bump photo.png",
    ];
    let mut text = String::from("PerspectiveCamera { width 2 height 2 }\nMaterials {\n");
    for m in &materials {
        text += &format!("  Material {{ {m} }}\n");
    }
    text += "}\nGroup {\n";
    for i in 0..materials.len() {
        text += &format!("  MaterialIndex {i} Sphere {{ center 0 0 {i} radius 0.1 }}\n");
    }
    text += "}\n";
    let file = dir.join("keys.txt");
    std::fs::write(&file, text).expect("write scene");
    let options = LoadOptions {
        base: Some(dir.clone()),
        ..LoadOptions::default()
    };
    let scene = pathtracer::scene::load_scene(&file, &options).expect("loads");
    let kinds: Vec<(bool, Option<f64>)> = scene
        .materials
        .iter()
        .map(|m| (m.normal_map.is_some(), m.bump.map(|b| b.scale)))
        .collect();
    assert_eq!(
        kinds,
        [
            (false, Some(0.25)),
            (false, Some(1.0)),
            (true, None),
            (true, None),
            (false, Some(1.0)),
        ]
    );
    // One image, one texture, whatever it is read as.
    assert_eq!(scene.textures.len(), 3);
}
