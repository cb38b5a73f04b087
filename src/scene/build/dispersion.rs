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
