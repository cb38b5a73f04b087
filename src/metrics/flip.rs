//! FLIP, NVIDIA's perceptual difference of alternating images (Andersson et
//! al., "FLIP: A Difference Evaluator for Alternating Images", HPG 2020),
//! for LDR images: a per-pixel error in [0, 1] of how visible the change is
//! when one flips between the two images, at a given viewing distance.
//!
//! The values come from the reference implementation itself, NVIDIA's C++
//! code as the `nv-flip` crate (gfx-rs, used by wgpu's image tests) builds
//! it from its registry source with the machine's C++ compiler: the numbers
//! are FLIP's own to the last digit, with nothing of the paper re-derived
//! here where it could drift. The input is 8-bit display values, read as
//! sRGB as FLIP assumes: what a viewer shows of a BMP or PNG, which for the
//! PA framework writer's files (no gamma) is what their authors looked at.
//!
//! Viewing conditions are pixels per degree of visual angle; the default,
//! [`DEFAULT_PIXELS_PER_DEGREE`], is the paper's: a 0.7 m wide 3840-pixel
//! monitor seen from 0.7 m.

use super::error_map::ErrorMap;
use crate::image_io::DisplayImage;

/// 67 pixels per degree: [`pixels_per_degree`]`(0.7, 0.7, 3840)` rounded, as
/// the paper and the reference implementation use by default.
pub const DEFAULT_PIXELS_PER_DEGREE: f64 = 67.0;

/// Pixels per degree of visual angle of a monitor `monitor_width` metres
/// wide with `resolution_x` pixels across, seen from `distance` metres:
/// `distance * resolution_x / monitor_width * pi / 180`.
pub fn pixels_per_degree(distance: f64, monitor_width: f64, resolution_x: f64) -> f64 {
    distance * (resolution_x / monitor_width) * std::f64::consts::PI / 180.0
}

/// The per-pixel FLIP map of `test` against `reference` (same size) seen at
/// `pixels_per_degree`.
pub fn flip(
    test: &DisplayImage,
    reference: &DisplayImage,
    pixels_per_degree: f64,
) -> Result<ErrorMap, String> {
    test.validate("test")?;
    reference.validate("reference")?;
    if (test.width, test.height) != (reference.width, reference.height) {
        return Err(format!(
            "image sizes differ: {}x{} against a {}x{} reference",
            test.width, test.height, reference.width, reference.height
        ));
    }
    if !(pixels_per_degree.is_finite() && pixels_per_degree > 0.0) {
        return Err(format!(
            "pixels per degree must be a positive number, got {pixels_per_degree}"
        ));
    }
    let (width, height) = (
        u32::try_from(test.width).map_err(|_| "image too wide for FLIP".to_string())?,
        u32::try_from(test.height).map_err(|_| "image too tall for FLIP".to_string())?,
    );
    let bytes =
        |image: &DisplayImage| -> Vec<u8> { image.pixels.iter().flatten().copied().collect() };
    let map = nv_flip::flip(
        nv_flip::FlipImageRgb8::with_data(width, height, &bytes(reference)),
        nv_flip::FlipImageRgb8::with_data(width, height, &bytes(test)),
        pixels_per_degree as f32,
    );
    Ok(ErrorMap {
        width: test.width,
        height: test.height,
        values: map.to_vec().into_iter().map(f64::from).collect(),
    })
}

#[cfg(test)]
mod tests;
