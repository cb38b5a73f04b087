//! What a BSDF at a hit does, in [`BsdfFlags`]: its kinds of scattering,
//! the probability that a sample is of some kinds, the `f` of a diffuse
//! continuous part (what light subpaths connect to), and the way the path carries light ([`TransportMode`]).

use std::f64::consts::FRAC_1_PI;

use super::{Bsdf, BsdfFlags, BsdfSample, TransportMode};
use crate::color::Color;
use crate::math::Vec3;

/// A lobe's `flags` for a sample that left to local `z` (positive: the
/// side of `wo`): reflection or transmission, for lobes that do both.
#[inline]
pub(super) fn on_side(flags: BsdfFlags, z: f64) -> BsdfFlags {
    let both = BsdfFlags::REFLECTION | BsdfFlags::TRANSMISSION;
    if !flags.contains(both) {
        flags
    } else if z > 0.0 {
        flags.without(BsdfFlags::TRANSMISSION)
    } else {
        flags.without(BsdfFlags::REFLECTION)
    }
}

impl<'a> Bsdf<'a> {
    /// The kinds of scattering of its lobes.
    #[inline]
    pub fn flags(&self) -> BsdfFlags {
        self.set.flags
    }

    /// The kinds of scattering of its continuous lobes.
    #[inline]
    pub fn continuous_flags(&self) -> BsdfFlags {
        self.set.continuous
    }

    /// The same BSDF on a surface whose transport is not the same both
    /// ways, `geometric` its geometric normal on the side of `wo`.
    #[inline]
    pub fn on_nonreciprocal(mut self, geometric: &Vec3) -> Bsdf<'a> {
        self.nonreciprocal = Some(*geometric);
        self
    }

    /// The same BSDF for a path that carries `mode`.
    #[inline]
    pub fn transporting(mut self, mode: TransportMode) -> Bsdf<'a> {
        self.mode = mode;
        self
    }

    /// The probability that [`Bsdf::sample`] chooses a lobe of one of the
    /// kinds of `kinds` (with [`BsdfFlags::CONTINUOUS`]: the probability of
    /// a continuous direction, which light sampling divides by).
    #[inline]
    pub fn probability(&self, kinds: BsdfFlags) -> f64 {
        if self.set.fixed && kinds == BsdfFlags::CONTINUOUS {
            return self.set.fixed_smooth;
        }
        self.with_mixture(|_, p| {
            (0..self.set.lobes.len())
                .filter(|&i| self.set.lobes[i].flags().intersects(kinds))
                .map(|i| p[i])
                .sum()
        })
    }

    /// `f` of the continuous part when it is diffuse reflection only (what
    /// a caustic connection needs); `None` when it is not, or empty.
    #[inline]
    pub fn diffuse_f(&self) -> Option<Color> {
        let set = self.set;
        if !set.continuous.is_diffuse_reflection_only() || set.smooth_lobes == 0 {
            return None;
        }
        if set.single_lambert {
            return Some(self.color * (set.weights[0] * FRAC_1_PI));
        }
        self.with_mixture(|weights, _| {
            let mut f = Color::BLACK;
            for (i, lobe) in set.lobes.iter().enumerate() {
                if !lobe.is_delta() {
                    f += self.tint(i) * weights[i];
                }
            }
            Some(f * FRAC_1_PI)
        })
    }

    /// `sample` as the path's transport sees it: marked when it crosses a
    /// non-reciprocal surface, and refused there (a delta direction) for
    /// importance.
    #[inline(always)]
    pub(super) fn transported(&self, mut sample: BsdfSample) -> Option<BsdfSample> {
        if let Some(geometric) = self.nonreciprocal
            && geometric.dot(&sample.wi) < 0.0
        {
            if self.mode == TransportMode::Importance && sample.is_delta() {
                return None;
            }
            sample.flags = sample.flags | BsdfFlags::NONRECIPROCAL;
        }
        Some(sample)
    }
}
