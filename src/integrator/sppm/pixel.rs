//! What each pixel keeps from pass to pass (Hachisuka and Jensen 2009): its
//! gathering radius `r`, photon count `N` and flux `tau`, and the light its
//! camera paths found directly; and the photons one pass gathers at its
//! visible point, summed in fixed point so that the sums do not depend on
//! the order in which threads add them.
//!
//! After a pass that gathered `M` photons of flux `phi` at visible point
//! throughput `beta`: `N' = N + alpha M`, `r' = r sqrt(N' / (N + M))`,
//! `tau' = (tau + beta phi) (r' / r)^2`. After `k` passes of `P` photons the
//! pixel is `direct / k + tau / (k P pi r^2)`.

use std::f64::consts::PI;
use std::sync::atomic::{AtomicU32, AtomicU64, Ordering};

use super::visible_point::VisiblePoint;
use crate::color::Color;

/// Fractional bits of the gathered flux (in photon power units).
const FRACTION_BITS: u32 = 32;
const SCALE: f64 = (1u64 << FRACTION_BITS) as f64;
/// The most one photon adds to one channel (in photon power units): below
/// 2^20, so that 2^12 such photons fit the sum before it could wrap.
const MAX_GATHERED: f64 = (1u64 << 20) as f64;

/// One pixel's state across passes.
#[derive(Clone, Copy, Debug)]
pub struct PixelState<'a> {
    pub radius: f64,
    /// `N`: photons kept.
    pub photons: f64,
    /// `tau`: flux kept (absolute power times reflectance).
    pub flux: Color,
    /// The sum over passes of the camera paths' direct light.
    pub direct: Color,
    /// This pass's visible point.
    pub visible: Option<VisiblePoint<'a>>,
}

impl PixelState<'_> {
    pub fn new(radius: f64) -> Self {
        PixelState {
            radius,
            photons: 0.0,
            flux: Color::BLACK,
            direct: Color::BLACK,
            visible: None,
        }
    }

    /// Takes a pass's gathered photons: `count` photons of summed `phi`
    /// (absolute), with `alpha`.
    pub fn update(&mut self, count: u32, phi: Color, alpha: f64) {
        let Some(visible) = self.visible else {
            return;
        };
        if count == 0 {
            return;
        }
        let m = count as f64;
        let kept = self.photons + alpha * m;
        let radius = self.radius * (kept / (self.photons + m)).sqrt();
        let shrink = (radius / self.radius).powi(2);
        self.flux = (self.flux + visible.beta * phi) * shrink;
        self.photons = kept;
        self.radius = radius;
    }

    /// The pixel's estimate after `passes` passes of `photons` photons each.
    pub fn radiance(&self, passes: u32, photons: u64) -> Color {
        if passes == 0 {
            return Color::BLACK;
        }
        let passes = passes as f64;
        let area = PI * self.radius * self.radius;
        let gathered = if area > 0.0 {
            self.flux / (passes * photons as f64 * area)
        } else {
            Color::BLACK
        };
        self.direct / passes + gathered
    }
}

/// The photons one pass gathers at each pixel's visible point.
pub struct Gathered {
    /// Three fixed-point channels per pixel.
    flux: Vec<AtomicU64>,
    count: Vec<AtomicU32>,
}

impl Gathered {
    pub fn try_new(pixels: usize) -> Result<Gathered, String> {
        let mut flux = Vec::new();
        let mut count = Vec::new();
        if flux.try_reserve_exact(3 * pixels).is_err() || count.try_reserve_exact(pixels).is_err() {
            return Err(format!(
                "cannot allocate the photon sums of {pixels} pixels: the system refused the memory"
            ));
        }
        flux.extend((0..3 * pixels).map(|_| AtomicU64::new(0)));
        count.extend((0..pixels).map(|_| AtomicU32::new(0)));
        Ok(Gathered { flux, count })
    }

    /// Adds one photon of `value` (in photon power units, finite and not
    /// negative) at `pixel`.
    #[inline]
    pub fn add(&self, pixel: usize, value: Color) {
        for (channel, v) in [value.r, value.g, value.b].into_iter().enumerate() {
            let fixed = (v.clamp(0.0, MAX_GATHERED) * SCALE).round() as u64;
            if fixed > 0 {
                self.flux[3 * pixel + channel].fetch_add(fixed, Ordering::Relaxed);
            }
        }
        self.count[pixel].fetch_add(1, Ordering::Relaxed);
    }

    /// Takes pixel `pixel`'s sums, leaving zeros: (photons, flux in units).
    pub fn take(&self, pixel: usize) -> (u32, Color) {
        let count = self.count[pixel].swap(0, Ordering::Relaxed);
        let channel = |c: usize| self.flux[3 * pixel + c].swap(0, Ordering::Relaxed) as f64 / SCALE;
        (count, Color::new(channel(0), channel(1), channel(2)))
    }
}
