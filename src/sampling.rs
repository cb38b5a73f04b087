//! Direction sampling and the small optics formulas of the original estimator.

use crate::math::{Vec3, orthonormal_basis};
use crate::trig::sin_cos_turns;

/// A cosine-weighted direction about the unit normal `n` (pdf = cos / pi).
/// Unit to rounding: the frame is orthonormal, so no normalisation is spent.
pub fn cosine_hemisphere(n: &Vec3, u: [f64; 2]) -> Vec3 {
    let (sin, cos) = sin_cos_turns(u[0]);
    let r2 = u[1];
    let r = r2.sqrt();
    let (t, b) = orthonormal_basis(n);
    let direction = t * (cos * r) + b * (sin * r) + n * (1.0 - r2).max(0.0).sqrt();
    debug_assert!((direction.norm() - 1.0).abs() < 1e-9);
    direction
}

/// Mirror reflection of the incoming direction `d` about `n`.
pub fn reflect(d: &Vec3, n: &Vec3) -> Vec3 {
    d - n * (2.0 * n.dot(d))
}

/// The outcome of meeting a dielectric boundary (smallpt's model).
pub struct Dielectric {
    /// Fresnel reflectance (Schlick); 1 under total internal reflection.
    pub reflectance: f64,
    pub reflected: Vec3,
    /// `None` under total internal reflection.
    pub refracted: Option<Vec3>,
}

/// smallpt's glass: `d` the unit incoming direction, `facing` the unit normal
/// on the side the ray comes from, `entering` whether that side is the outside,
/// `ior` the index inside (outside is 1).
pub fn dielectric(d: &Vec3, facing: &Vec3, entering: bool, ior: f64) -> Dielectric {
    let n = if entering { *facing } else { -facing };
    let reflected = reflect(d, facing);
    let (nc, nt) = (1.0, ior);
    let eta = if entering { nc / nt } else { nt / nc };
    let cos_in = d.dot(facing);
    let cos2t = 1.0 - eta * eta * (1.0 - cos_in * cos_in);
    if cos2t < 0.0 {
        return Dielectric {
            reflectance: 1.0,
            reflected,
            refracted: None,
        };
    }
    let sign = if entering { 1.0 } else { -1.0 };
    let refracted = (d * eta - n * (sign * (cos_in * eta + cos2t.sqrt()))).normalize();
    let r0 = ((nt - nc) / (nt + nc)).powi(2);
    let c = 1.0 - if entering { -cos_in } else { refracted.dot(&n) };
    let reflectance = r0 + (1.0 - r0) * c.powi(5);
    Dielectric {
        reflectance,
        reflected,
        refracted: Some(refracted),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::Rng;

    #[test]
    fn cosine_hemisphere_has_the_cosine_mean() {
        // E[cos] under pdf cos/pi is 2/3.
        let n = Vec3::new(0.3, -0.5, 0.8).normalize();
        let mut rng = Rng::new(1, 2);
        let count = 200_000;
        let mut sum = 0.0;
        for _ in 0..count {
            let d = cosine_hemisphere(&n, [rng.next_f64(), rng.next_f64()]);
            assert!((d.norm() - 1.0).abs() < 1e-9);
            let c = d.dot(&n);
            assert!(c >= -1e-12);
            sum += c;
        }
        assert!((sum / count as f64 - 2.0 / 3.0).abs() < 0.003);
    }

    #[test]
    fn refraction_obeys_snell() {
        let n = Vec3::new(0.0, 1.0, 0.0);
        let d = Vec3::new(0.6, -0.8, 0.0);
        let glass = dielectric(&d, &n, true, 1.5);
        let t = glass.refracted.expect("no TIR entering glass");
        let sin_in = d.cross(&n).norm();
        let sin_out = t.cross(&n).norm();
        assert!((sin_in - 1.5 * sin_out).abs() < 1e-12);
        assert!(t.y < 0.0);
        assert!(glass.reflectance > 0.04 && glass.reflectance < 1.0);
    }

    #[test]
    fn total_internal_reflection_reflects_only() {
        let n = Vec3::new(0.0, 1.0, 0.0);
        // Leaving glass at a grazing angle.
        let d = Vec3::new(0.9, 0.1, 0.0).normalize();
        let glass = dielectric(&d, &-n, false, 1.5);
        assert!(glass.refracted.is_none());
        assert_eq!(glass.reflectance, 1.0);
        assert!(glass.reflected.y < 0.0);
        assert!(glass.reflected.iter().all(|c| c.is_finite()));
    }

    #[test]
    fn normal_incidence_reflectance_is_r0() {
        let n = Vec3::new(0.0, 0.0, 1.0);
        let glass = dielectric(&Vec3::new(0.0, 0.0, -1.0), &n, true, 1.5);
        assert!((glass.reflectance - 0.04).abs() < 1e-12);
    }
}
