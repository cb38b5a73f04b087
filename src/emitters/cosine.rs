//! Direction sampling about a world-space normal (light subpaths leave
//! emitters by the cosine).

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
}
