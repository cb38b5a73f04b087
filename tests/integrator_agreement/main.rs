//! The path integrator (NEE + MIS) and the original estimator agree in
//! expectation, scene by scene, and the path integrator is less noisy.
//!
//! Each scene is rendered K times per integrator with independent seeds at a
//! tiny size; the per-run image means (and a few pixels) of the two
//! integrators must agree within 4 combined standard errors.

#[path = "../common/mod.rs"]
mod common;
mod glossy;

use common::statistic;
use std::sync::Arc;

use pathtracer::bsdf::ConductorFresnel;
use pathtracer::bsdf::phong::Phong;
use pathtracer::color::Color;
use pathtracer::geometry::MeshData;
use pathtracer::integrator::{Integrator, original::MAX_DEPTH};
use pathtracer::math::{Matrix, Point3, Vec3};
use pathtracer::render::RenderSettings;
use pathtracer::sampler::SamplerKind;
use pathtracer::scene::model::{Coat, Light, Material, Object, Scene};
use pathtracer::texture::Texture;

const WIDTH: u32 = 8;
const HEIGHT: u32 = 8;
const RUNS: u64 = 32;

/// Per run: the pixel values (channel averages), row-major.
fn runs(scene: &Scene, integrator: Integrator, spp: u32) -> Vec<Vec<f64>> {
    let settings = RenderSettings {
        width: WIDTH,
        height: HEIGHT,
        spp,
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
    common::independent_runs(scene, &settings, 1000, RUNS)
}

fn image_mean(pixels: &[f64]) -> f64 {
    pixels.iter().sum::<f64>() / pixels.len() as f64
}

/// Asserts agreement of the image means and of a few pixels; returns the
/// median over pixels of the ratio of standard errors, original / path.
fn assert_agree(name: &str, scene: &Scene, spp: u32) -> f64 {
    let path = runs(scene, Integrator::Path, spp);
    let original = runs(scene, Integrator::Original, spp);
    let check = |what: &str, f: &dyn Fn(&[f64]) -> f64| {
        let (a, sa) = statistic(&path, f);
        let (b, sb) = statistic(&original, f);
        let combined = (sa * sa + sb * sb).sqrt();
        println!("{name} {what}: path {a:.5} ± {sa:.5}, original {b:.5} ± {sb:.5}");
        assert!(
            (a - b).abs() <= 4.0 * combined + 1e-12,
            "{name} {what}: path {a} ± {sa} vs original {b} ± {sb}"
        );
        (sa, sb)
    };
    check("image mean", &image_mean);
    let w = WIDTH as usize;
    for (x, y) in [(1, 1), (4, 3), (6, 6), (2, 5)] {
        check(&format!("pixel ({x}, {y})"), &move |p: &[f64]| p[y * w + x]);
    }
    let mut ratios: Vec<f64> = (0..path[0].len())
        .filter_map(|i| {
            let (_, sa) = statistic(&path, |p| p[i]);
            let (_, sb) = statistic(&original, |p| p[i]);
            (sa > 0.0).then_some(sb / sa)
        })
        .collect();
    ratios.sort_by(f64::total_cmp);
    let median = ratios.get(ratios.len() / 2).copied().unwrap_or(f64::NAN);
    println!("{name}: median per-pixel standard error ratio original / path: {median:.2}");
    median
}

fn diffuse(color: f64) -> Material {
    Material {
        color: Color::gray(color),
        ..Material::default()
    }
}

fn emitter(radiance: f64) -> Material {
    Material {
        color: Color::BLACK,
        emission: Color::gray(radiance),
        ..Material::default()
    }
}

fn plane(normal: Vec3, offset: f64, material: usize) -> Object {
    Object::Plane {
        normal,
        offset,
        material,
    }
}

fn sphere(center: Vec3, radius: f64, material: usize) -> Object {
    Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    }
}

/// A box from x, y in [-2, 2] and z in [-8, 1] around the camera at the origin
/// looking down -z; walls of materials 0 (grey), 1 (red), 2 (green).
fn box_walls() -> Vec<Object> {
    vec![
        plane(Vec3::y(), -2.0, 0),
        plane(Vec3::y(), 2.0, 0),
        plane(Vec3::x(), -2.0, 1),
        plane(Vec3::x(), 2.0, 2),
        plane(Vec3::z(), -8.0, 0),
        plane(Vec3::z(), 1.0, 0),
    ]
}

fn box_materials() -> Vec<Material> {
    vec![
        diffuse(0.7),
        Material {
            color: Color::new(0.75, 0.25, 0.25),
            ..Material::default()
        },
        Material {
            color: Color::new(0.25, 0.75, 0.25),
            ..Material::default()
        },
    ]
}

fn transform(matrix: Matrix, child: Object) -> Object {
    Object::Transform {
        matrix,
        inverse: matrix.try_inverse().expect("invertible"),
        child: Box::new(child),
    }
}

/// (a) Diffuse box, small emissive sphere, mirror and glass spheres, a faintly
/// emissive back wall (a plane: reached by BSDF sampling only).
fn cornell_spheres() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(20.0)); // 3
    materials.push(Material {
        color: Color::gray(0.95),
        diffuse: 0.0,
        specular: 1.0,
        ..Material::default()
    }); // 4
    materials.push(Material {
        color: Color::gray(0.95),
        diffuse: 0.0,
        refract: 1.0,
        ..Material::default()
    }); // 5
    materials.push(Material {
        emission: Color::new(0.05, 0.04, 0.03),
        ..diffuse(0.5)
    }); // 6
    let mut objects = box_walls();
    objects[4] = plane(Vec3::z(), -8.0, 6);
    objects.push(sphere(Vec3::new(0.0, 1.3, -6.0), 0.35, 3));
    objects.push(sphere(Vec3::new(-0.9, -1.4, -5.5), 0.6, 4));
    objects.push(sphere(Vec3::new(0.9, -1.4, -4.5), 0.6, 5));
    common::scene_with(materials, Object::Group(objects))
}

/// (b) A textured sphere and a textured floor (tiled), lit by a sphere light.
fn textured() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(8.0)); // 3
    materials.push(Material {
        texture: Some(0),
        ..diffuse(1.0)
    }); // 4
    let mut scene = {
        let mut objects = box_walls();
        objects[0] = plane(Vec3::y(), -2.0, 4);
        objects.push(sphere(Vec3::new(0.5, 1.2, -5.0), 0.5, 3));
        objects.push(sphere(Vec3::new(-0.4, -1.0, -5.0), 0.9, 4));
        common::scene_with(materials, Object::Group(objects))
    };
    scene.textures.push(Arc::new(Texture {
        width: 2,
        height: 2,
        texels: vec![
            [0.9, 0.1, 0.1],
            [0.1, 0.9, 0.1],
            [0.1, 0.1, 0.9],
            [0.9, 0.9, 0.9],
        ],
    }));
    scene
}

/// A unit square [-0.5, 0.5]^2 in the xz plane at y = 0, as two triangles.
fn quad_mesh() -> Arc<MeshData> {
    Arc::new(MeshData {
        framework_reading: None,
        positions: vec![
            Point3::new(-0.5, 0.0, -0.5),
            Point3::new(0.5, 0.0, -0.5),
            Point3::new(0.5, 0.0, 0.5),
            Point3::new(-0.5, 0.0, 0.5),
        ],
        normals: None,
        uvs: None,
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    })
}

/// (c) An emissive triangle mesh under a translation and non-uniform scale,
/// lighting diffuse planes, plus a diffuse mesh instance of the same data.
fn emissive_mesh() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(10.0)); // 3
    let mut objects = box_walls();
    let matrix = Matrix::new_translation(&Vec3::new(0.3, 1.9, -5.0))
        * Matrix::new_nonuniform_scaling(&Vec3::new(1.5, 1.0, 0.8))
        * Matrix::from_euler_angles(0.3, 0.0, 0.2);
    objects.push(transform(
        matrix,
        Object::Mesh {
            mesh: quad_mesh(),
            smooth: false,
            material: 3,
            face_materials: None,
        },
    ));
    objects.push(transform(
        Matrix::new_translation(&Vec3::new(-0.5, -1.0, -5.0)),
        Object::Mesh {
            mesh: quad_mesh(),
            smooth: false,
            material: 0,
            face_materials: None,
        },
    ));
    common::scene_with(materials, Object::Group(objects))
}

/// (d) No emitters: a point and a directional light (PA1 semantics).
fn point_lights() -> Scene {
    let mut materials = box_materials();
    materials.push(Material {
        color: Color::gray(0.9),
        diffuse: 0.5,
        specular: 0.5,
        ..Material::default()
    }); // 3
    let mut objects = box_walls();
    objects.push(sphere(Vec3::new(0.0, -1.0, -5.0), 0.8, 3));
    let mut scene = common::scene_with(materials, Object::Group(objects));
    scene.lights = vec![
        Light::Point {
            position: Point3::new(0.5, 1.5, -4.0),
            color: Color::gray(0.6),
        },
        Light::Directional {
            direction: Vec3::new(0.2, -1.0, -0.3),
            color: Color::new(0.3, 0.2, 0.1),
        },
    ];
    scene
}

/// (e) An emissive rectangle, a transformed emissive disk (an ellipse), and
/// a non-uniformly scaled emissive sphere (an ellipsoid: BSDF sampling only),
/// over a half-mirror, half-diffuse sphere.
fn emissive_rectangle() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(6.0)); // 3
    materials.push(Material {
        color: Color::gray(0.8),
        diffuse: 0.6,
        specular: 0.4,
        ..Material::default()
    }); // 4
    let mut objects = box_walls();
    objects.push(Object::Rectangle {
        origin: Point3::new(-0.6, 1.95, -5.6),
        edge_u: Vec3::new(1.2, 0.0, 0.0),
        edge_v: Vec3::new(0.0, -0.1, 1.0),
        material: 3,
    });
    objects.push(transform(
        Matrix::new_translation(&Vec3::new(-1.9, 0.0, -5.0))
            * Matrix::new_nonuniform_scaling(&Vec3::new(1.0, 2.0, 0.5)),
        Object::Disk {
            center: Point3::zeros(),
            normal: Vec3::new(1.0, 0.0, 0.3),
            radius: 0.4,
            material: 3,
        },
    ));
    objects.push(transform(
        Matrix::new_translation(&Vec3::new(1.5, 1.5, -6.5))
            * Matrix::new_nonuniform_scaling(&Vec3::new(1.0, 0.5, 1.0)),
        sphere(Vec3::zeros(), 0.3, 3),
    ));
    objects.push(sphere(Vec3::new(0.2, -1.2, -5.0), 0.7, 4));
    common::scene_with(materials, Object::Group(objects))
}

/// (f) A sphere light sunk into the ceiling, as smallpt and the coursework
/// scenes have it: light sampling takes the cap below the plane.
fn light_sunk_into_the_ceiling() -> Scene {
    let mut materials = box_materials();
    materials.push(emitter(12.0)); // 3
    materials.push(Material {
        color: Color::gray(0.9),
        diffuse: 0.0,
        refract: 1.0,
        ..Material::default()
    }); // 4
    let mut objects = box_walls();
    objects.push(sphere(Vec3::new(0.3, 2.7, -5.0), 0.9, 3));
    objects.push(sphere(Vec3::new(-0.8, -1.4, -5.0), 0.6, 0));
    objects.push(sphere(Vec3::new(0.9, -1.4, -4.0), 0.6, 4));
    common::scene_with(materials, Object::Group(objects))
}

#[test]
fn spheres_with_mirror_and_glass_agree_and_path_is_less_noisy() {
    let ratio = assert_agree("(a) spheres", &cornell_spheres(), 64);
    assert!(
        ratio >= 3.0,
        "path is only {ratio:.2}x less noisy than original"
    );
}

#[test]
fn textured_objects_agree() {
    assert_agree("(b) textured", &textured(), 64);
}

#[test]
fn transformed_emissive_mesh_agrees() {
    assert_agree("(c) mesh", &emissive_mesh(), 64);
}

#[test]
fn point_and_directional_lights_agree() {
    assert_agree("(d) point lights", &point_lights(), 256);
}

#[test]
fn emissive_rectangle_disk_and_ellipsoid_agree() {
    assert_agree("(e) rectangle", &emissive_rectangle(), 64);
}

#[test]
fn light_sunk_into_the_ceiling_agrees_and_path_is_less_noisy() {
    let ratio = assert_agree("(f) sunk light", &light_sunk_into_the_ceiling(), 64);
    assert!(
        ratio >= 3.0,
        "path is only {ratio:.2}x less noisy than original"
    );
}
