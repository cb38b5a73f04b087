//! The GGX (Trowbridge-Reitz) microfacet distribution, isotropic, in the
//! local shading frame (z the macro-normal): its density of normals, Smith's
//! masking term, and visible-normal sampling (Heitz, "Sampling the GGX
//! Distribution of Visible Normals", JCGT 7(4), 2018).
//!
//! Shadowing-masking is Smith's separable product `G1(wo) G1(wi)`, as in
//! Mitsuba 3, so that rough conductors and dielectrics agree with it.

use std::f64::consts::PI;

use crate::math::Vec3;
use crate::trig::sin_cos_turns;

/// Below this GGX `alpha`, a microfacet lobe is treated as perfectly smooth
/// (a delta lobe): its distribution is too narrow to evaluate in floating point.
pub const MIN_ROUGHNESS: f64 = 1e-3;

#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ggx {
    pub alpha: f64,
}

impl Ggx {
    /// Density of microfacet normals `h` per solid angle, projected:
    /// `D(h)` with `integral D(h) h.z dh = 1` over the upper hemisphere.
    #[inline]
    pub fn d(&self, h: &Vec3) -> f64 {
        if h.z <= 0.0 {
            return 0.0;
        }
        let a2 = self.alpha * self.alpha;
        let t = h.z * h.z * (a2 - 1.0) + 1.0;
        a2 / (PI * t * t)
    }

    /// Smith's `Lambda` for a direction `w` (against the macro-normal).
    #[inline]
    fn lambda(&self, w: &Vec3) -> f64 {
        let cos2 = w.z * w.z;
        let sin2 = (1.0 - cos2).max(0.0);
        if sin2 <= 0.0 {
            return 0.0;
        }
        let tan2 = sin2 / cos2;
        0.5 * ((1.0 + self.alpha * self.alpha * tan2).sqrt() - 1.0)
    }

    /// Smith's masking of microfacet `h` seen from `w`: 0 when `w` sees the
    /// back of the microfacet.
    #[inline]
    pub fn g1(&self, w: &Vec3, h: &Vec3) -> f64 {
        if w.dot(h) * w.z <= 0.0 {
            return 0.0;
        }
        1.0 / (1.0 + self.lambda(w))
    }

    /// Smith's separable shadowing-masking of `h` for the pair of directions.
    #[inline]
    pub fn g(&self, wo: &Vec3, wi: &Vec3, h: &Vec3) -> f64 {
        self.g1(wo, h) * self.g1(wi, h)
    }

    /// Density of the visible normals seen from `wo` (`wo.z > 0`):
    /// `G1(wo, h) max(0, wo . h) D(h) / wo.z`.
    #[inline]
    pub fn visible_pdf(&self, wo: &Vec3, h: &Vec3) -> f64 {
        if wo.z <= 0.0 {
            return 0.0;
        }
        self.g1(wo, h) * wo.dot(h).max(0.0) * self.d(h) / wo.z
    }

    /// A microfacet normal visible from `wo` (`wo.z > 0`), distributed by
    /// [`Ggx::visible_pdf`].
    pub fn sample_visible(&self, wo: &Vec3, u: [f64; 2]) -> Vec3 {
        let a = self.alpha;
        // The view direction in the hemisphere configuration (alpha = 1).
        let v = Vec3::new(a * wo.x, a * wo.y, wo.z).normalize();
        let length2 = v.x * v.x + v.y * v.y;
        let t1 = if length2 > 0.0 {
            Vec3::new(-v.y, v.x, 0.0) / length2.sqrt()
        } else {
            Vec3::x()
        };
        let t2 = v.cross(&t1);
        // A point of the projected disk, the half facing away squeezed.
        let r = u[0].sqrt();
        let (sin, cos) = sin_cos_turns(u[1]);
        let p1 = r * cos;
        let s = 0.5 * (1.0 + v.z);
        let p2 = (1.0 - s) * (1.0 - p1 * p1).max(0.0).sqrt() + s * r * sin;
        let n = t1 * p1 + t2 * p2 + v * (1.0 - p1 * p1 - p2 * p2).max(0.0).sqrt();
        // Back to the ellipsoid configuration.
        let h = Vec3::new(a * n.x, a * n.y, n.z.max(1e-12));
        h.normalize()
    }
}

impl Ggx {
    /// A reflection off a microfacet visible from `wo` (`wo.z > 0`): the
    /// direction, the microfacet normal and the density of the direction.
    pub fn sample_reflection(&self, wo: &Vec3, u: [f64; 2]) -> (Vec3, Vec3, f64) {
        let h = self.sample_visible(wo, u);
        let wi = reflect(wo, &h);
        (wi, h, self.visible_pdf(wo, &h) / (4.0 * wo.dot(&h)))
    }

    /// The density with which [`Ggx::sample_reflection`] gives `wi`.
    pub fn reflection_pdf(&self, wo: &Vec3, wi: &Vec3) -> f64 {
        if wo.z <= 0.0 {
            return 0.0;
        }
        let Some(h) = (wo + wi).try_normalize(1e-12) else {
            return 0.0;
        };
        let cos_h = wo.dot(&h);
        if cos_h <= 0.0 {
            return 0.0;
        }
        self.visible_pdf(wo, &h) / (4.0 * cos_h)
    }
}

/// Mirror reflection of `w` about the microfacet normal `h`.
#[inline]
pub fn reflect(w: &Vec3, h: &Vec3) -> Vec3 {
    h * (2.0 * w.dot(h)) - w
}

/// Refraction of `w` (on the side `h` points to, `w . h > 0`) through the
/// microfacet `h` from index `eta_w` into index `eta_t`; `None` under total
/// internal reflection.
#[inline]
pub fn refract(w: &Vec3, h: &Vec3, eta_w: f64, eta_t: f64) -> Option<Vec3> {
    let eta = eta_w / eta_t;
    let cos_w = w.dot(h);
    let sin2_t = eta * eta * (1.0 - cos_w * cos_w).max(0.0);
    if sin2_t >= 1.0 {
        return None;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    Some(h * (eta * cos_w - cos_t) - w * eta)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    /// Numerical integral over the upper hemisphere in (cos theta, phi).
    fn hemisphere_integral(f: impl Fn(&Vec3) -> f64) -> f64 {
        let (nt, np) = (2000, 64);
        let mut sum = 0.0;
        for i in 0..nt {
            // Midpoints in theta, denser where GGX peaks (near the pole).
            let theta = (i as f64 + 0.5) / nt as f64 * PI / 2.0;
            let (s, c) = theta.sin_cos();
            for j in 0..np {
                let phi = (j as f64 + 0.5) / np as f64 * 2.0 * PI;
                let w = Vec3::new(s * phi.cos(), s * phi.sin(), c);
                sum += f(&w) * s;
            }
        }
        sum * (PI / 2.0 / nt as f64) * (2.0 * PI / np as f64)
    }

    #[test]
    fn projected_normal_density_integrates_to_one() {
        for alpha in [0.05, 0.3, 1.0] {
            let ggx = Ggx { alpha };
            let total = hemisphere_integral(|h| ggx.d(h) * h.z);
            assert!((total - 1.0).abs() < 2e-3, "alpha {alpha}: {total}");
        }
    }

    #[test]
    fn visible_normals_integrate_to_one_and_match_their_samples() {
        let ggx = Ggx { alpha: 0.4 };
        let wo = Vec3::new(0.6, 0.1, 0.5).normalize();
        let total = hemisphere_integral(|h| ggx.visible_pdf(&wo, h));
        assert!((total - 1.0).abs() < 2e-3, "{total}");
        // Mean of h.z under the samples against the same under the density.
        let expected = hemisphere_integral(|h| ggx.visible_pdf(&wo, h) * h.z);
        let mut rng = Rng::new(3, 4);
        let n = 200_000;
        let mean: f64 = (0..n)
            .map(|_| ggx.sample_visible(&wo, [rng.next_f64(), rng.next_f64()]).z)
            .sum::<f64>()
            / n as f64;
        assert!((mean - expected).abs() < 3e-3, "{mean} vs {expected}");
    }

    #[test]
    fn refraction_obeys_snell_and_reverses() {
        let h = Vec3::z();
        let w = Vec3::new(0.5, 0.0, 0.75_f64.sqrt());
        let t = refract(&w, &h, 1.0, 1.5).expect("no TIR entering");
        assert!((t.norm() - 1.0).abs() < 1e-12);
        assert!(t.z < 0.0);
        assert!((w.cross(&h).norm() - 1.5 * t.cross(&h).norm()).abs() < 1e-12);
        let back = refract(&t, &-h, 1.5, 1.0).expect("reversible");
        assert!((back - w).norm() < 1e-12, "{back:?}");
        assert!(refract(&Vec3::new(0.9, 0.0, 0.19_f64.sqrt()), &h, 1.5, 1.0).is_none());
    }
}
