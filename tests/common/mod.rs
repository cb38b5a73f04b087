//! Scenes built in code for the integrator tests.
#![allow(dead_code)]

use pathtracer::color::Color;
use pathtracer::math::Vec3;
use pathtracer::scene::model::{CameraDesc, Dialect, Material, Object, Scene};

/// A scene with the camera at the origin looking down -z, no objects.
pub fn empty_scene(materials: Vec<Material>, root: Object) -> Scene {
    Scene {
        camera: CameraDesc {
            center: Vec3::zeros(),
            direction: Vec3::new(0.0, 0.0, -1.0),
            up: Vec3::new(0.0, 1.0, 0.0),
            width: 16,
            height: 16,
            fov: None,
            canvas_distance: 0.0,
            focus_distance: 1.0,
            lens_radius: 0.0,
        },
        background: Color::BLACK,
        materials,
        textures: Vec::new(),
        lights: Vec::new(),
        root,
        dialect: Dialect::Canonical,
        warnings: Vec::new(),
        unsupported: Vec::new(),
    }
}

/// Path to the shared reference data, or `None` (with a note) when absent.
pub fn shared(relative: &str) -> Option<std::path::PathBuf> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../shared")
        .join(relative);
    if path.exists() {
        Some(path)
    } else {
        eprintln!("skipped: ../shared not found ({})", path.display());
        None
    }
}
