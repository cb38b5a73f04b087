//! The parameters of stochastic progressive photon mapping and their
//! defaults: photons per pass, the initial gathering radius (by default a
//! rule from the size of what the camera sees) and alpha, the share of new
//! photons each pass keeps (Hachisuka and Jensen 2009).

/// Alpha of Hachisuka and Jensen's paper (and of the coursework renderers):
/// each pass keeps this share of its photons, and the radius shrinks with it.
pub const DEFAULT_ALPHA: f64 = 0.7;

/// The default initial radius is the diagonal of the box around the first
/// pass's visible points divided by this: about ten pixels wide on the
/// course's Cornell boxes at 1024x768, blurry for the first passes only.
pub const RADIUS_DIVISOR: f64 = 200.0;

/// The most photons one pass may trace.
pub const MAX_PHOTONS_PER_PASS: u64 = 1 << 32;

/// What `--photons-per-pass`, `--initial-radius` and `--alpha` choose.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhotonSettings {
    /// Photons traced per pass (`None`: one per pixel, as pbrt-v4's default).
    pub photons_per_pass: Option<u64>,
    /// Gathering radius of every pixel before its first photons (`None`:
    /// [`RADIUS_DIVISOR`]'s rule).
    pub initial_radius: Option<f64>,
    /// In (0, 1]: the share of a pass's new photons that the pixel keeps.
    pub alpha: f64,
}

impl Default for PhotonSettings {
    fn default() -> Self {
        PhotonSettings {
            photons_per_pass: None,
            initial_radius: None,
            alpha: DEFAULT_ALPHA,
        }
    }
}

impl PhotonSettings {
    /// Photons per pass for an image of `pixels` pixels.
    pub fn photons(&self, pixels: u64) -> u64 {
        self.photons_per_pass
            .unwrap_or(pixels)
            .clamp(1, MAX_PHOTONS_PER_PASS)
    }

    /// The settings' errors, as a user reads them.
    pub fn check(&self) -> Result<(), String> {
        if !(self.alpha > 0.0 && self.alpha <= 1.0) {
            return Err(format!(
                "--alpha {}: expected a number above 0 and at most 1",
                self.alpha
            ));
        }
        if let Some(radius) = self.initial_radius
            && !(radius > 0.0 && radius.is_finite())
        {
            return Err(format!(
                "--initial-radius {radius}: expected a finite number above 0"
            ));
        }
        if let Some(photons) = self.photons_per_pass
            && !(1..=MAX_PHOTONS_PER_PASS).contains(&photons)
        {
            return Err(format!(
                "--photons-per-pass {photons}: expected 1 to {MAX_PHOTONS_PER_PASS}"
            ));
        }
        Ok(())
    }
}
