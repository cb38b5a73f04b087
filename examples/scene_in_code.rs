//! A scene built in code and rendered through the one entry every render
//! takes: `RenderScene::build` turns the described scene and the render's
//! settings into the render-time scene, `render` fills a film from it.
//!
//!     cargo run --release --example scene_in_code [OUTPUT.bmp]
//!
//! A red sphere and a mirror sphere on a grey floor, under a spherical
//! light, in the physical look; written to `output/scene_in_code.bmp` by
//! default.

use std::path::PathBuf;

use pathtracer::math::{Point3, Vec3};
use pathtracer::scene::model::{Material, Object};
use pathtracer::{
    Color, Integrator, Look, RenderScene, RenderSettings, SamplerKind, Scene, render,
};

fn main() -> Result<(), String> {
    let output = std::env::args()
        .nth(1)
        .map(PathBuf::from)
        .unwrap_or_else(|| PathBuf::from("output/scene_in_code.bmp"));

    let materials = vec![
        Material {
            color: Color::new(0.75, 0.75, 0.75),
            ..Material::default()
        },
        Material {
            color: Color::new(0.8, 0.2, 0.2),
            ..Material::default()
        },
        Material {
            color: Color::new(0.95, 0.95, 0.95),
            diffuse: 0.0,
            specular: 1.0,
            ..Material::default()
        },
        Material {
            color: Color::BLACK,
            emission: Color::gray(12.0),
            ..Material::default()
        },
    ];
    let sphere = |center: Point3, radius: f64, material: usize| Object::Sphere {
        center,
        radius,
        motion: Vec3::zeros(),
        material,
    };
    let root = Object::Group(vec![
        Object::Plane {
            normal: Vec3::new(0.0, 1.0, 0.0),
            offset: -1.0,
            material: 0,
        },
        sphere(Point3::new(-0.6, -0.5, -3.0), 0.5, 1),
        sphere(Point3::new(0.6, -0.5, -3.5), 0.5, 2),
        sphere(Point3::new(0.0, 2.5, -3.0), 0.5, 3),
    ]);
    let mut scene = Scene::new(materials, root);
    scene.background = Color::gray(0.05);
    scene.camera.width = 160;
    scene.camera.height = 120;

    let look = Look::PHYSICAL;
    let settings = RenderSettings {
        width: scene.camera.width,
        height: scene.camera.height,
        spp: 64,
        seed: 0,
        threads: None,
        integrator: Integrator::Path,
        max_depth: look.max_depth,
        sampler: SamplerKind::Sobol,
        progress: false,
        progress_every: None,
        clamp: None,
        light_paths: true,
        look,
        dispersion: None,
    };
    let ready = RenderScene::build(scene, &settings.scene());
    let (image, stats) = render(&ready, &settings)?;
    if let Some(folder) = output.parent() {
        std::fs::create_dir_all(folder).map_err(|e| format!("{}: {e}", folder.display()))?;
    }
    pathtracer::image_io::write_image(&output, &image, Some(2.2))?;
    println!(
        "{}: {}x{} at {} spp, {:.2} M samples/s",
        output.display(),
        image.width,
        image.height,
        settings.spp,
        stats.samples_per_second() / 1e6
    );
    Ok(())
}
