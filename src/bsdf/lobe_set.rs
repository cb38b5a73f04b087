//! A material's lobes and what does not depend on the hit (see the
//! module above): made once per material before rendering.

use arrayvec::ArrayVec;

use super::{AngularWeights, BsdfFlags, ConductorFresnel, Lobe, MAX_LOBES};
use crate::spectral::Dispersion;

/// The lobes of a material and what does not depend on the hit: their
/// weights, which of them take the hit's colour as their tint, and (when no
/// lobe's choice depends on the hit) their probabilities.
#[derive(Clone, Debug, Default)]
pub struct LobeSet {
    pub(super) lobes: ArrayVec<Lobe, MAX_LOBES>,
    pub(super) weights: [f64; MAX_LOBES],
    /// Whether the lobe's tint is the hit's colour (else it keeps its own).
    pub(super) tinted: [bool; MAX_LOBES],
    /// Whether a dielectric takes the rendering's Fresnel term (cav's glass
    /// keeps none).
    pub(super) follows_rules: [bool; MAX_LOBES],
    /// Probabilities, when they do not depend on the hit (every lobe tinted
    /// by the hit's colour, none with a Schlick term, no angular weights).
    pub(super) fixed: bool,
    pub(super) fixed_probabilities: [f64; MAX_LOBES],
    /// The probability of the continuous lobes, when fixed.
    pub(super) fixed_smooth: f64,
    /// cav's weights of lobes 0, 1, 2 (diffuse, conductor, dielectric).
    pub(super) angular: Option<AngularWeights>,
    pub(super) ior: f64,
    /// The dispersion of its dielectric lobe (none without one).
    pub(super) dispersion: Option<Dispersion>,
    pub(super) smooth_lobes: usize,
    /// The kinds of scattering of its lobes, and of its continuous lobes.
    pub(super) flags: BsdfFlags,
    pub(super) continuous: BsdfFlags,
    /// One Lambert lobe tinted by the hit's colour, nothing else.
    pub(super) single_lambert: bool,
}

impl LobeSet {
    /// No lobes yet, for a material whose dielectrics have index `ior`
    /// inside; with `angular` weights, the first three lobes pushed (diffuse,
    /// conductor, dielectric) take their weights per hit and are kept at
    /// any weight.
    pub fn new(ior: f64, angular: Option<AngularWeights>) -> LobeSet {
        LobeSet {
            ior,
            angular,
            ..LobeSet::default()
        }
    }

    /// Gives its dielectric lobe `dispersion` (an index per wavelength).
    pub fn set_dispersion(&mut self, dispersion: Option<Dispersion>) {
        self.dispersion = dispersion;
    }

    /// Adds `lobe` with `weight`; `tinted`: its tint becomes the hit's
    /// colour. Lobes beyond [`MAX_LOBES`] and non-positive weights are
    /// dropped. A dielectric is given as seen from outside.
    pub fn push(&mut self, lobe: Lobe, weight: f64, tinted: bool) {
        self.push_slot(lobe, weight, tinted, true);
    }

    /// [`LobeSet::push`], and `follows_rules`: whether a dielectric takes the
    /// rendering's Fresnel term (cav's glass keeps none).
    pub fn push_slot(&mut self, lobe: Lobe, weight: f64, tinted: bool, follows_rules: bool) {
        let usable = weight > 0.0 && weight.is_finite() || self.angular.is_some();
        if self.lobes.len() == MAX_LOBES || !usable {
            return;
        }
        let i = self.lobes.len();
        let delta = lobe.is_delta();
        self.flags = self.flags | lobe.flags();
        if !delta {
            self.continuous = self.continuous | lobe.flags();
            self.smooth_lobes += 1;
        }
        self.weights[i] = weight;
        self.tinted[i] = tinted;
        self.follows_rules[i] = follows_rules;
        self.lobes.push(lobe);
        self.single_lambert = self.lobes.len() == 1
            && self.tinted[0]
            && self.angular.is_none()
            && matches!(self.lobes[0], Lobe::Lambert(_));
        self.fix_probabilities();
    }

    /// The probabilities when they do not depend on the hit.
    fn fix_probabilities(&mut self) {
        let fixed = self.angular.is_none()
            && self.lobes.iter().zip(&self.tinted).all(|(lobe, &tinted)| {
                tinted
                    && !matches!(lobe, Lobe::Conductor(c) if c.fresnel == ConductorFresnel::Schlick)
            });
        self.fixed = fixed;
        let total: f64 = self.weights[..self.lobes.len()].iter().sum();
        self.fixed_smooth = 0.0;
        for i in 0..self.lobes.len() {
            self.fixed_probabilities[i] = if fixed { self.weights[i] / total } else { 0.0 };
            if !self.lobes[i].is_delta() {
                self.fixed_smooth += self.fixed_probabilities[i];
            }
        }
    }

    /// cav's angle-dependent weights, if the material has them.
    pub fn angular(&self) -> Option<AngularWeights> {
        self.angular
    }

    /// The index of refraction inside its dielectrics.
    pub fn ior(&self) -> f64 {
        self.ior
    }

    pub fn len(&self) -> usize {
        self.lobes.len()
    }

    /// The same lobes with dielectrics of index `ior` inside (the index of
    /// the material's dispersion at a path's wavelength); no allocation.
    pub fn with_ior(&self, ior: f64) -> LobeSet {
        let mut set = self.clone();
        set.ior = ior;
        for lobe in &mut set.lobes {
            lobe.set_ior(ior);
        }
        set
    }

    /// The weights of its mirror and smooth-glass lobes and its index of
    /// refraction, for the Whitted estimators that follow both at once
    /// (jefflyy's `reflective` and `transmissive`).
    pub fn mirror_and_glass(&self) -> (f64, f64, f64) {
        let mut mirror = 0.0;
        let mut glass = 0.0;
        for (lobe, weight) in self.lobes.iter().zip(&self.weights) {
            match lobe {
                Lobe::Conductor(c) if c.is_delta() => mirror += weight,
                Lobe::Dielectric(_) => glass += weight,
                _ => {}
            }
        }
        (mirror, glass, self.ior)
    }

    /// Whether a lobe is a delta lobe (a mirror or smooth glass).
    pub fn has_delta(&self) -> bool {
        self.smooth_lobes < self.lobes.len()
    }

    /// Its lobes with their weights (as built; angular weights replace
    /// the first three at a hit).
    pub fn weighted(&self) -> impl Iterator<Item = (&Lobe, f64)> {
        self.lobes.iter().zip(self.weights.iter().copied())
    }

    pub fn is_empty(&self) -> bool {
        self.lobes.is_empty()
    }
}
