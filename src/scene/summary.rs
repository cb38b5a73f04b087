//! A one-paragraph description of a built scene, for `pathtracer check`.

use crate::scene::model::{FovAxis, Object, Scene};

/// Dialect, camera, resolution and counts of a scene, in one paragraph.
pub fn summary(scene: &Scene) -> String {
    let mut objects = 0usize;
    let mut triangles = 0usize;
    scene.root.for_each_leaf(&mut |leaf| {
        objects += 1;
        triangles += match leaf {
            Object::Mesh { mesh, .. } => mesh.triangles.len(),
            Object::Triangle { .. } => 1,
            _ => 0,
        };
    });
    let c = &scene.camera;
    let fov = match c.fov {
        Some((angle, FovAxis::Vertical)) => format!("{angle} degrees vertical"),
        Some((angle, FovAxis::Horizontal)) => format!("{angle} degrees horizontal"),
        None => "the default field of view".to_string(),
    };
    let lens = if c.lens_radius >= 1e-4 {
        format!(
            ", lens radius {} focused at {}",
            c.lens_radius, c.focus_distance
        )
    } else {
        String::new()
    };
    let mut text = format!(
        "Dialect {}. Camera at ({}, {}, {}) looking along ({}, {}, {}), {fov}{lens}; \
         {}x{} pixels. {} materials, {objects} objects ({triangles} triangles), \
         {} textures, {} lights, {} warnings.",
        scene.dialect.name(),
        c.center.x,
        c.center.y,
        c.center.z,
        c.direction.x,
        c.direction.y,
        c.direction.z,
        c.width,
        c.height,
        scene.materials.len(),
        scene.textures.len(),
        scene.lights.len(),
        scene.warnings.len(),
    );
    if !scene.unsupported.is_empty() {
        text.push_str(&format!(
            " Not supported: {}.",
            scene.unsupported.join("; ")
        ));
    }
    text
}
