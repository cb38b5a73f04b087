//! A one-paragraph description of a built scene, for `pathtracer check`.

use super::Look;
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
    let (look, why) = Look::detect(scene);
    let text = format!(
        "Dialect {}, look {} ({why}). Camera at ({}, {}, {}) looking along ({}, {}, {}), {fov}{lens}; \
         {}x{} pixels. {} materials, {objects} objects ({triangles} triangles), \
         {} textures, {} lights, {} warnings.",
        scene.dialect.name(),
        look.name,
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
    text + &media(scene)
}

/// What the scene's participating media are, or nothing without media.
fn media(scene: &Scene) -> String {
    let bounded = scene
        .materials
        .iter()
        .filter(|m| m.interior.is_some())
        .count();
    let filling = match &scene.medium {
        Some(m) => {
            let t = m.sigma_t();
            format!(
                "a medium fills the scene (sigma_t {} {} {}, g {})",
                t.r, t.g, t.b, m.phase.g
            )
        }
        None if bounded > 0 => "no medium fills the scene".to_string(),
        None => return String::new(),
    };
    format!(" Media: {filling}; {bounded} materials have a medium inside.")
}

#[cfg(test)]
mod tests {
    use crate::scene::build::build_text;

    #[test]
    fn mentions_dialect_camera_and_counts() {
        let scene = build_text(
            "PerspectiveCamera { width 4 height 3 angle 30 }\nMaterials { Material { specularRate 1 } }\n\
             Group { Sphere { center 0 0 0 radius 1 } Triangle { vertex0 0 0 0 vertex1 1 0 0 vertex2 0 1 0 } }",
        )
        .expect("builds");
        let text = super::summary(&scene);
        assert!(text.contains("canonical"), "{text}");
        assert!(text.contains("4x3 pixels"), "{text}");
        assert!(text.contains("30 degrees vertical"), "{text}");
        assert!(text.contains("2 objects (1 triangles)"), "{text}");
        assert!(!text.contains("Media"), "{text}");
        let scene = build_text(
            "PerspectiveCamera { width 4 height 3 mist 0.5 1 0 }\n\
             Materials { Material { interface Medium { sigmaS 1 1 1 } } }",
        )
        .expect("builds");
        let text = super::summary(&scene);
        let sigma = -(0.5f64.ln());
        assert!(
            text.contains(&format!(
                "Media: a medium fills the scene (sigma_t {sigma} {sigma} {sigma}"
            )) && text.contains("1 materials have a medium inside"),
            "{text}"
        );
    }
}
