//! Sine and cosine of an angle given in turns, for sampling directions.
//!
//! Every sampling routine turns a uniform number `u` into the angle `2 pi u`
//! and needs both its sine and cosine; the C library's `sincos` does a general
//! range reduction and costs several percent of a render. With the angle in
//! turns the reduction is exact: the nearest quarter turn is split off, and
//! the remainder, at most an eighth of a turn, goes through Taylor
//! polynomials whose truncation error is below 1e-16.

use std::f64::consts::FRAC_PI_2;

/// `(sin(2 pi u), cos(2 pi u))` for `u` in [0, 1]; agrees with the
/// library's `sin_cos` of `2 pi u` to 1e-15. (Plain arithmetic only: `round` and `mul_add` would be
/// library calls on the baseline x86-64 target.)
#[inline]
pub fn sin_cos_turns(u: f64) -> (f64, f64) {
    debug_assert!((0.0..=1.0).contains(&u), "{u}");
    let quarters = 4.0 * u.clamp(0.0, 1.0);
    let nearest = (quarters + 0.5) as i64;
    // In [-pi/4, pi/4]; `quarters - nearest` is exact.
    let r = (quarters - nearest as f64) * FRAC_PI_2;
    let (s, c) = sin_cos_small(r);
    match nearest & 3 {
        0 => (s, c),
        1 => (c, -s),
        2 => (-s, -c),
        _ => (-c, s),
    }
}

/// Taylor polynomials of sine (to r^15) and cosine (to r^16) for |r| <= pi/4.
#[inline]
fn sin_cos_small(r: f64) -> (f64, f64) {
    const S: [f64; 7] = [
        -1.0 / 6.0,
        1.0 / 120.0,
        -1.0 / 5040.0,
        1.0 / 362_880.0,
        -1.0 / 39_916_800.0,
        1.0 / 6_227_020_800.0,
        -1.0 / 1_307_674_368_000.0,
    ];
    const C: [f64; 8] = [
        -1.0 / 2.0,
        1.0 / 24.0,
        -1.0 / 720.0,
        1.0 / 40_320.0,
        -1.0 / 3_628_800.0,
        1.0 / 479_001_600.0,
        -1.0 / 87_178_291_200.0,
        1.0 / 20_922_789_888_000.0,
    ];
    let r2 = r * r;
    let mut s = S[6];
    for k in (0..6).rev() {
        s = s * r2 + S[k];
    }
    let mut c = C[7];
    for k in (0..7).rev() {
        c = c * r2 + C[k];
    }
    (r + r * r2 * s, 1.0 + r2 * c)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    #[test]
    fn matches_the_library_over_a_turn() {
        let n = 1_000_003;
        let mut worst: f64 = 0.0;
        for i in 0..=n {
            let u = i as f64 / n as f64;
            let (s, c) = sin_cos_turns(u);
            let (es, ec) = (2.0 * PI * u).sin_cos();
            worst = worst.max((s - es).abs()).max((c - ec).abs());
        }
        // The library's own angle 2 pi u is rounded: up to 4.4e-16 near u = 1.
        assert!(worst < 1e-15, "worst error {worst:e}");
    }

    #[test]
    fn quarter_turns_are_exact_and_signs_are_right() {
        assert_eq!(sin_cos_turns(0.0), (0.0, 1.0));
        assert_eq!(sin_cos_turns(0.25), (1.0, -0.0));
        assert_eq!(sin_cos_turns(0.5), (-0.0, -1.0));
        assert_eq!(sin_cos_turns(0.75), (-1.0, 0.0));
        assert_eq!(sin_cos_turns(1.0), (0.0, 1.0));
        let (s, c) = sin_cos_turns(0.125);
        assert!((s - c).abs() < 3e-16 && s > 0.0);
        let (s, c) = sin_cos_turns(0.625);
        assert!((s - c).abs() < 3e-16 && s < 0.0);
    }
}
