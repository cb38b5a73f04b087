//! Image comparison metrics: RMSE, relative MSE, PSNR and SSIM here; FLIP
//! (`flip`), the look-alike criterion (`lookalike`), error maps
//! (`error_map`), box resampling (`resample`) and the report of
//! `pathtracer compare` (`report`) in their own files.
//!
//! `compare(test, reference)` measures a rendered image against a reference of the
//! same size. RMSE, relative MSE and PSNR use the linear values as stored, so HDR
//! images (e.g. PFM) are compared in linear radiance, unclamped. SSIM clamps each
//! channel to [0, 1] before taking Rec. 709 luminance (11x11 Gaussian window,
//! sigma 1.5, K1 = 0.01, K2 = 0.03, L = 1; see `metrics/ssim.rs`). A NaN in either image
//! propagates to RMSE, relative MSE and PSNR.

pub mod error_map;
pub mod flip;
pub mod lookalike;
pub mod report;
pub mod resample;
mod ssim;

use std::fmt;

use crate::image_io::Image;

/// Added to the squared reference value in the relative MSE denominator, so that
/// black reference pixels do not divide by zero; it matters only where the
/// reference is darker than about 0.1. 1e-2 is the usual choice in the
/// adaptive-rendering literature (e.g. Rousselle et al.).
pub const RELATIVE_MSE_EPSILON: f64 = 1e-2;

/// The peak signal assumed by PSNR: 1.0, white in linear units.
pub const PSNR_PEAK: f64 = 1.0;

/// The result of comparing a test image with a reference.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Comparison {
    /// Root mean squared error over all pixels and the three channels.
    pub rmse: f64,
    /// Mean over pixels and channels of `(a - b)^2 / (b^2 + RELATIVE_MSE_EPSILON)`,
    /// `b` the reference.
    pub rel_mse: f64,
    /// `10 log10(PSNR_PEAK^2 / MSE)` in decibels; `f64::INFINITY` for identical images.
    pub psnr: f64,
    /// Mean structural similarity on clamped luminance; 1 for identical images.
    pub ssim: f64,
}

/// Compares `test` with `reference`; the images must have the same size.
pub fn compare(test: &Image, reference: &Image) -> Result<Comparison, String> {
    for (name, image) in [("test", test), ("reference", reference)] {
        if image.pixels.len() != image.width * image.height {
            return Err(format!(
                "{name} image claims {}x{} pixels but holds {}",
                image.width,
                image.height,
                image.pixels.len()
            ));
        }
    }
    if (test.width, test.height) != (reference.width, reference.height) {
        return Err(format!(
            "image sizes differ: {}x{} against a {}x{} reference",
            test.width, test.height, reference.width, reference.height
        ));
    }
    if test.pixels.is_empty() {
        return Err("cannot compare empty images".to_string());
    }

    let mut squared_error = 0.0;
    let mut relative_error = 0.0;
    for (a, b) in test.pixels.iter().zip(&reference.pixels) {
        for (a, b) in [(a.r, b.r), (a.g, b.g), (a.b, b.b)] {
            let difference = (a - b) * (a - b);
            squared_error += difference;
            relative_error += difference / (b * b + RELATIVE_MSE_EPSILON);
        }
    }
    let samples = (test.pixels.len() * 3) as f64;
    let mse = squared_error / samples;
    let psnr = if mse == 0.0 {
        f64::INFINITY
    } else {
        10.0 * (PSNR_PEAK * PSNR_PEAK / mse).log10()
    };
    Ok(Comparison {
        rmse: mse.sqrt(),
        rel_mse: relative_error / samples,
        psnr,
        ssim: ssim::mean_ssim(test, reference),
    })
}

/// A JSON number, or `null` for infinity and NaN, which JSON cannot express.
pub(crate) fn json_number(value: f64) -> String {
    if value.is_finite() {
        // Debug prints the shortest exact form, e.g. `0.1`, `1.0`, `1e-7`: all valid JSON.
        format!("{value:?}")
    } else {
        "null".to_string()
    }
}

impl Comparison {
    /// One JSON object, `{"rmse": .., "rel_mse": .., "psnr": .., "ssim": ..}`.
    /// Non-finite values are written as `null`: in particular the infinite PSNR of
    /// identical images.
    pub fn to_json(&self) -> String {
        format!(
            "{{\"rmse\": {}, \"rel_mse\": {}, \"psnr\": {}, \"ssim\": {}}}",
            json_number(self.rmse),
            json_number(self.rel_mse),
            json_number(self.psnr),
            json_number(self.ssim)
        )
    }
}

impl fmt::Display for Comparison {
    /// `rmse 0.012345  rel_mse 0.001234  psnr 38.17 dB  ssim 0.98765` (psnr may be `inf`).
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "rmse {:.6}  rel_mse {:.6}  psnr {:.2} dB  ssim {:.5}",
            self.rmse, self.rel_mse, self.psnr, self.ssim
        )
    }
}

#[cfg(test)]
mod tests;
