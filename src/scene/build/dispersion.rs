//! Dispersion in scene files: Cambrian's `cauchy A B` in a material, which
//! its renderer uses only when the camera has the `dispersion` flag (without
//! it, `refractive_rate` for every wavelength); and yuzc19's `dispersion`
//! command-line flag, which gives every refractive material the indices
//! 1.6473, 1.6527 and 1.6726 for R, G and B (`--dispersion yuzc19`, see
//! [`apply_channels`]).

use crate::scene::build::material::MaterialSpec;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::Material;
use crate::spectral::Dispersion;

/// Reads `cauchy A B` (the index `A + B / λ²`, λ in micrometres).
pub fn read_cauchy(
    context: &mut Context,
    cursor: &mut Cursor,
    spec_dispersion: &mut Option<(Dispersion, Location)>,
    location: Location,
) -> Result<(), SceneError> {
    let a = cursor.number(context, "cauchy")?;
    let b = cursor.number(context, "cauchy")?;
    if !(a >= 1.0 && a.is_finite() && b >= 0.0 && b.is_finite()) {
        return context.warn(
            location,
            format!("'cauchy {a} {b}' is not rendered: A must be at least 1 and B at least 0"),
        );
    }
    *spec_dispersion = Some((Dispersion::Cauchy { a, b }, location));
    Ok(())
}

/// Keeps the materials' Cauchy coefficients when the camera has the
/// `dispersion` flag (at `camera_flag`), with a warning for each material's
/// coefficients when it has not, and for a flag that no material uses.
pub fn resolve(
    context: &mut Context,
    camera_flag: Option<Location>,
    specs: &mut [MaterialSpec],
) -> Result<(), SceneError> {
    let mut used = false;
    for spec in specs.iter_mut() {
        let Some((dispersion, at)) = spec.dispersion.take() else {
            continue;
        };
        if camera_flag.is_none() {
            context.not_rendered(
                at,
                "cauchy",
                "the camera has no 'dispersion' flag (one index, refractive_rate, as Cambrian's renderer)",
            )?;
        } else if spec.material.refract <= 0.0 {
            context.not_rendered(at, "cauchy", "the material does not refract")?;
        } else {
            spec.material.dispersion = Some(dispersion);
            used = true;
        }
    }
    if let Some(at) = camera_flag
        && !used
    {
        context.not_rendered(
            at,
            "dispersion",
            "no refractive material has 'cauchy' coefficients",
        )?;
    }
    Ok(())
}

/// Gives every refractive material of `materials` the index per channel of
/// `dispersion` (yuzc19's flag overrides every refractive material); the
/// number of materials changed.
pub fn apply_channels(materials: &mut [Material], dispersion: Dispersion) -> usize {
    let mut changed = 0;
    for material in materials.iter_mut().filter(|m| m.refract > 0.0) {
        material.dispersion = Some(dispersion);
        changed += 1;
    }
    changed
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::build::build_text;

    /// Cambrian's `bunny_only.txt`, cut down: a glass with `cauchy`, a
    /// diffuse floor, the camera's flag when `flag`.
    fn cambrian(flag: &str, glass: &str) -> String {
        format!(
            "PerspectiveCamera {{ center 0 0 1 direction 0 0 -1 up 0 1 0 angle 35 width 8 height 8 {flag} }}
Materials {{ numMaterials 2
  PhongMaterial {{ type {glass} color 0.99 0.99 0.99 emission 0 0 0 refractive_rate 1.5 cauchy 2.385 0.0117 }}
  PhongMaterial {{ type DIFF color 0.8 0.8 0.8 emission 0 0 0 refractive_rate 1 }}
}}
Group {{ numObjects 1 MaterialIndex 0 Sphere {{ center 0 0 -2 radius 0.5 }} }}"
        )
    }

    fn warnings_about(scene: &crate::scene::model::Scene, word: &str) -> Vec<String> {
        scene
            .warnings
            .iter()
            .map(|w| w.to_string())
            .filter(|w| w.contains(word))
            .collect()
    }

    #[test]
    fn cambrian_cauchy_with_the_camera_flag_is_rendered_without_a_warning() {
        let scene = build_text(&cambrian("dispersion", "REFR")).expect("builds");
        let cauchy = Dispersion::Cauchy {
            a: 2.385,
            b: 0.0117,
        };
        assert_eq!(scene.materials[0].dispersion, Some(cauchy));
        assert_eq!(scene.materials[0].ior, 1.5);
        assert_eq!(scene.materials[1].dispersion, None);
        assert!(
            warnings_about(&scene, "cauchy").is_empty(),
            "{:?}",
            scene.warnings
        );
        assert!(warnings_about(&scene, "dispersion").is_empty());
    }

    #[test]
    fn cauchy_without_the_camera_flag_warns_at_its_place_and_keeps_one_index() {
        let scene = build_text(&cambrian("", "REFR")).expect("builds");
        assert_eq!(scene.materials[0].dispersion, None);
        let warnings = warnings_about(&scene, "'cauchy' is not rendered");
        assert_eq!(warnings.len(), 1, "{:?}", scene.warnings);
        assert!(warnings[0].contains("t.txt:3:"), "{}", warnings[0]);
    }

    #[test]
    fn a_camera_flag_without_refractive_cauchy_materials_warns() {
        let scene = build_text(&cambrian("dispersion", "DIFF")).expect("builds");
        assert!(!scene.has_dispersion());
        assert_eq!(
            warnings_about(&scene, "the material does not refract").len(),
            1
        );
        let flag = warnings_about(&scene, "'dispersion' is not rendered");
        assert_eq!(flag.len(), 1, "{:?}", scene.warnings);
        assert!(flag[0].contains("t.txt:1:"), "{}", flag[0]);
    }

    #[test]
    fn bad_cauchy_coefficients_warn_and_a_missing_number_is_an_error() {
        let text = cambrian("dispersion", "REFR").replace("cauchy 2.385", "cauchy 0.5");
        let scene = build_text(&text).expect("builds");
        assert!(!scene.has_dispersion());
        assert_eq!(warnings_about(&scene, "'cauchy 0.5 0.0117'").len(), 1);
        let text = cambrian("dispersion", "REFR").replace("cauchy 2.385 0.0117", "cauchy 2.385");
        let error = build_text(&text).expect_err("B is missing");
        assert!(error.contains("t.txt:3:"), "{error}");
    }

    #[test]
    fn yuzc19s_flag_gives_every_refractive_material_its_channel_indices() {
        let glass = Material {
            diffuse: 0.0,
            refract: 1.0,
            ..Material::default()
        };
        let mut materials = vec![glass.clone(), Material::default(), glass];
        assert_eq!(apply_channels(&mut materials, Dispersion::YUZC19), 2);
        assert_eq!(materials[0].dispersion, Some(Dispersion::YUZC19));
        assert_eq!(materials[1].dispersion, None);
        assert_eq!(materials[2].dispersion, Some(Dispersion::YUZC19));
    }
}
