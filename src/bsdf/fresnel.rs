//! Fresnel reflectance of dielectric and conductor boundaries.

use crate::color::Color;

/// How a dielectric's reflectance is computed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum DielectricFresnel {
    /// Schlick's approximation with the cosine on the side of the lower
    /// index, as smallpt and the original renderer compute it.
    #[default]
    Schlick,
    /// The exact unpolarised reflectance of a smooth boundary.
    Exact,
    /// No reflection at all (cav's glass, whose reflection is a separate,
    /// angle-weighted lobe): only total internal reflection reflects.
    None,
    /// smallpt's roulette probability `0.25 + R / 2` (Schlick's R) used as
    /// the reflectance itself, unweighted (osb's glass).
    SmallptUnweighted,
}

/// Reflectance of a dielectric boundary for light arriving at `cos_i`
/// (> 0) from the side of index `eta_i`, the other side having `eta_t`;
/// 1 under total internal reflection.
pub fn dielectric(model: DielectricFresnel, cos_i: f64, eta_i: f64, eta_t: f64) -> f64 {
    let eta = eta_i / eta_t;
    let sin2_t = eta * eta * (1.0 - cos_i * cos_i).max(0.0);
    if sin2_t >= 1.0 {
        return 1.0;
    }
    let cos_t = (1.0 - sin2_t).sqrt();
    match model {
        DielectricFresnel::Schlick => {
            let r0 = ((eta_t - eta_i) / (eta_t + eta_i)).powi(2);
            // The cosine in the medium of the lower index.
            let c = if eta_i <= eta_t { cos_i } else { cos_t };
            r0 + (1.0 - r0) * (1.0 - c).powi(5)
        }
        DielectricFresnel::Exact => {
            let parallel = (eta_t * cos_i - eta_i * cos_t) / (eta_t * cos_i + eta_i * cos_t);
            let perpendicular = (eta_i * cos_i - eta_t * cos_t) / (eta_i * cos_i + eta_t * cos_t);
            0.5 * (parallel * parallel + perpendicular * perpendicular)
        }
        DielectricFresnel::None => 0.0,
        DielectricFresnel::SmallptUnweighted => {
            0.25 + 0.5 * dielectric(DielectricFresnel::Schlick, cos_i, eta_i, eta_t)
        }
    }
}

/// Schlick's approximation per channel from the reflectance `f0` at normal
/// incidence.
pub fn schlick(f0: Color, cos: f64) -> Color {
    let c = (1.0 - cos.clamp(0.0, 1.0)).powi(5);
    f0.map(|r| r + (1.0 - r) * c)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_incidence_and_total_internal_reflection() {
        for model in [DielectricFresnel::Schlick, DielectricFresnel::Exact] {
            assert!((dielectric(model, 1.0, 1.0, 1.5) - 0.04).abs() < 1e-12);
            assert!((dielectric(model, 1.0, 1.5, 1.0) - 0.04).abs() < 1e-12);
            // Leaving glass beyond the critical angle (41.8 degrees).
            assert_eq!(dielectric(model, 0.5, 1.5, 1.0), 1.0);
            assert!((dielectric(model, 1e-9, 1.0, 1.5) - 1.0).abs() < 1e-6);
        }
        assert_eq!(dielectric(DielectricFresnel::None, 0.9, 1.0, 1.5), 0.0);
        assert_eq!(dielectric(DielectricFresnel::None, 0.5, 1.5, 1.0), 1.0);
    }

    #[test]
    fn exact_reflectance_is_the_same_from_both_sides() {
        // Stokes: a ray and its refracted reverse see the same reflectance.
        let (eta_i, eta_t) = (1.0, 1.5);
        for cos_i in [0.2_f64, 0.5, 0.9] {
            let sin_t = (1.0 - cos_i * cos_i).sqrt() * eta_i / eta_t;
            let cos_t = (1.0 - sin_t * sin_t).sqrt();
            let a = dielectric(DielectricFresnel::Exact, cos_i, eta_i, eta_t);
            let b = dielectric(DielectricFresnel::Exact, cos_t, eta_t, eta_i);
            assert!((a - b).abs() < 1e-12, "{a} {b}");
        }
    }

    #[test]
    fn exact_reflectance_has_no_parallel_part_at_the_brewster_angle() {
        // Known value of the exact term: zero parallel reflectance at
        // Brewster's angle, so R = perpendicular / 2.
        let brewster = 1.5_f64.atan();
        let cos_i = brewster.cos();
        let exact = dielectric(DielectricFresnel::Exact, cos_i, 1.0, 1.5);
        let cos_t = brewster.sin();
        let perpendicular = ((cos_i - 1.5 * cos_t) / (cos_i + 1.5 * cos_t)).powi(2);
        assert!((exact - 0.5 * perpendicular).abs() < 1e-12);
    }
}
