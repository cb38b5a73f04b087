//! `Medium { sigmaA r g b  sigmaS r g b  g x }`: a homogeneous participating
//! medium, at the top level (it fills the scene) or inside a material (it
//! fills that material's shapes).

use crate::color::Color;
use crate::medium::{HenyeyGreenstein, Medium};
use crate::scene::ast::Block;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::SceneError;

/// Reads a `Medium` block; coefficients must be finite and non-negative,
/// `g` strictly between -1 and 1. Absent fields are 0 (a clear medium).
pub fn build_medium(context: &mut Context, block: &Block) -> Result<Medium, SceneError> {
    let mut medium = Medium {
        sigma_a: Color::BLACK,
        sigma_s: Color::BLACK,
        phase: HenyeyGreenstein { g: 0.0 },
        cambrian_mist: None,
    };
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        let Some(key) = item.word() else {
            context.skip_item(item, "Medium")?;
            continue;
        };
        match key {
            "sigmaA" | "sigma_a" | "sigmaS" | "sigma_s" => {
                let at = cursor.here();
                let v = cursor.vec3(context, key)?;
                if v.iter().any(|c| *c < 0.0) {
                    return Err(context.error(
                        at,
                        format!(
                            "'{key}' must not be negative, found {} {} {}",
                            v.x, v.y, v.z
                        ),
                    ));
                }
                let color = Color::new(v.x, v.y, v.z);
                if key.ends_with('A') || key.ends_with('a') {
                    medium.sigma_a = color;
                } else {
                    medium.sigma_s = color;
                }
            }
            "g" => {
                let at = cursor.here();
                let g = cursor.number(context, key)?;
                if g.abs() >= 1.0 {
                    return Err(context.error(
                        at,
                        format!("the phase function's 'g' must be between -1 and 1, found {g}"),
                    ));
                }
                medium.phase.g = g;
            }
            _ => context.skip_field(&mut cursor, key, item.location, "Medium")?,
        }
    }
    Ok(medium)
}

#[cfg(test)]
mod tests {
    use crate::color::Color;
    use crate::scene::build::build_text;

    const CAMERA: &str = "PerspectiveCamera { width 2 height 2 }\n";

    #[test]
    fn top_level_and_material_media_are_read() {
        let scene = build_text(&format!(
            "{CAMERA}Medium {{ sigmaA 0.1 0.2 0.3 sigmaS 1 2 3 g 0.5 }}\n\
             Materials {{ Material {{ interface Medium {{ sigma_s 4 4 4 }} }} Material {{ color 1 1 1 }} }}"
        ))
        .expect("builds");
        let medium = scene.medium.expect("scene medium");
        assert_eq!(medium.sigma_a, Color::new(0.1, 0.2, 0.3));
        assert_eq!(medium.sigma_s, Color::new(1.0, 2.0, 3.0));
        assert_eq!(medium.phase.g, 0.5);
        let inside = scene.materials[0].interior.expect("interior");
        assert_eq!(
            (inside.sigma_s, inside.sigma_a),
            (Color::gray(4.0), Color::BLACK)
        );
        assert!(scene.materials[0].interface && !scene.materials[1].interface);
        assert!(scene.materials[1].interior.is_none());
    }

    #[test]
    fn bad_coefficients_are_located_errors() {
        let e = build_text(&format!("{CAMERA}Medium {{\n sigmaA 1 -1 0 }}")).expect_err("negative");
        assert!(e.contains("t.txt:3:9") && e.contains("negative"), "{e}");
        let e = build_text(&format!("{CAMERA}Medium {{ g 1 }}")).expect_err("g");
        assert!(e.contains("t.txt:2:12"), "{e}");
    }
}
