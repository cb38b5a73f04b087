//! RGB colours as spectra and back: a smooth, nonnegative partition of
//! unity `B_r, B_g, B_b` over the visible range (the positive parts of the
//! linear sRGB colour matching functions, each divided by their sum), so
//! that a colour `c` is the spectrum `s_c(λ) = Σ_j c_j B_j(λ)` (white is
//! flat 1, a reflectance in [0, 1] stays in [0, 1]); and the sensor that
//! reads a spectrum back as RGB, the dual basis
//! `c̃_k(λ) = Σ_m (G⁻¹)_km B_m(λ)` with the Gram matrix `G_km = ∫ B_k B_m`,
//! so that `∫ c̃_k s_c dλ = c_k` exactly: one colour goes round unchanged,
//! and a grey scene renders in expectation as its RGB rendering does.
//!
//! The colour matching functions are the multi-lobe Gaussian fit of the CIE
//! 1931 2° observer by Wyman, Sloan and Shirley ("Simple Analytic
//! Approximations to the CIE XYZ Color Matching Functions", JCGT 2013),
//! turned into linear sRGB by the XYZ-to-sRGB matrix of IEC 61966-2-1.
//! The fit's tails have the wrong colour (beyond 730 nm its ȳ outlasts x̄,
//! which made deep red light green; below 390 nm it turns violet
//! green-blue), while the true spectral locus hardly moves there: outside
//! [`FIT_SHORTEST`], [`FIT_LONGEST`] the basis keeps its value at the
//! nearer end.

use std::sync::OnceLock;

use crate::color::Color;

/// The shortest wavelength a path is given, in nanometres.
pub const LAMBDA_MIN: f64 = 360.0;
/// The longest wavelength a path is given, in nanometres.
pub const LAMBDA_MAX: f64 = 830.0;

/// Below this wavelength (nm) the basis is its value here: the fit's
/// violet (red 0.15, blue 0.85), where the CIE 1931 locus's end, x 0.1741,
/// y 0.0050, gives red 0.15, blue 0.85 in the basis.
pub const FIT_SHORTEST: f64 = 420.0;
/// Above this wavelength (nm) the basis is its value here: pure red, as
/// the CIE 1931 locus is from about 610 nm on.
pub const FIT_LONGEST: f64 = 650.0;

/// Intervals of the Gram matrix's quadrature (Simpson, 0.05 nm).
const GRAM_INTERVALS: usize = 9400;

/// The piecewise Gaussian of the fit: width `left` below the mean, `right`
/// above it.
fn lobe(nm: f64, mean: f64, left: f64, right: f64) -> f64 {
    let width = if nm < mean { left } else { right };
    let t = (nm - mean) / width;
    (-0.5 * t * t).exp()
}

/// The CIE 1931 colour matching functions x̄, ȳ, z̄ at `nm` (the fit).
pub fn cie_xyz(nm: f64) -> [f64; 3] {
    let x = 1.056 * lobe(nm, 599.8, 37.9, 31.0) + 0.362 * lobe(nm, 442.0, 16.0, 26.7)
        - 0.065 * lobe(nm, 501.1, 20.4, 26.2);
    let y = 0.821 * lobe(nm, 568.8, 46.9, 40.5) + 0.286 * lobe(nm, 530.9, 16.3, 31.1);
    let z = 1.217 * lobe(nm, 437.0, 11.8, 36.0) + 0.681 * lobe(nm, 459.0, 26.0, 13.8);
    [x, y, z]
}

/// The linear sRGB colour matching functions at `nm` (negative where a
/// wavelength's colour is outside the sRGB gamut).
pub fn srgb_matching(nm: f64) -> [f64; 3] {
    let [x, y, z] = cie_xyz(nm);
    [
        3.2404542 * x - 1.5371385 * y - 0.4985314 * z,
        -0.9692660 * x + 1.8760108 * y + 0.0415560 * z,
        0.0556434 * x - 0.2040259 * y + 1.0572252 * z,
    ]
}

/// The partition of unity `B_r, B_g, B_b` at `nm`: nonnegative, summing
/// to 1 (zero outside [`LAMBDA_MIN`], [`LAMBDA_MAX`]; constant outside
/// [`FIT_SHORTEST`], [`FIT_LONGEST`]).
pub fn basis(nm: f64) -> [f64; 3] {
    if !(LAMBDA_MIN..=LAMBDA_MAX).contains(&nm) {
        return [0.0; 3];
    }
    let positive = srgb_matching(nm.clamp(FIT_SHORTEST, FIT_LONGEST)).map(|v| v.max(0.0));
    let sum: f64 = positive.iter().sum();
    if sum > 0.0 {
        positive.map(|v| v / sum)
    } else {
        [1.0 / 3.0; 3]
    }
}

/// The spectrum of colour `c` at a wavelength whose basis values are `b`.
#[inline]
pub fn spectrum_at(b: &[f64; 3], c: Color) -> f64 {
    b[0] * c.r + b[1] * c.g + b[2] * c.b
}

/// The sensor (dual basis) `c̃(λ)` at `nm`, as an RGB triple.
pub fn sensor(nm: f64) -> Color {
    let b = basis(nm);
    let g = inverse_gram();
    let row = |k: usize| g[k][0] * b[0] + g[k][1] * b[1] + g[k][2] * b[2];
    Color::new(row(0), row(1), row(2))
}

/// `G⁻¹`, computed once.
fn inverse_gram() -> &'static [[f64; 3]; 3] {
    static INVERSE: OnceLock<[[f64; 3]; 3]> = OnceLock::new();
    INVERSE.get_or_init(|| invert(&gram()))
}

/// `G_km = ∫ B_k B_m dλ` by Simpson's rule.
fn gram() -> [[f64; 3]; 3] {
    let h = (LAMBDA_MAX - LAMBDA_MIN) / GRAM_INTERVALS as f64;
    let mut g = [[0.0; 3]; 3];
    for i in 0..=GRAM_INTERVALS {
        let weight = if i == 0 || i == GRAM_INTERVALS {
            1.0
        } else if i % 2 == 1 {
            4.0
        } else {
            2.0
        };
        let b = basis(LAMBDA_MIN + h * i as f64);
        for k in 0..3 {
            for m in 0..3 {
                g[k][m] += weight * b[k] * b[m];
            }
        }
    }
    g.map(|row| row.map(|v| v * h / 3.0))
}

/// The inverse of a 3x3 matrix (the Gram matrix is symmetric positive
/// definite, far from singular).
fn invert(a: &[[f64; 3]; 3]) -> [[f64; 3]; 3] {
    let cofactor =
        |r0: usize, r1: usize, c0: usize, c1: usize| a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
    let c = [
        [
            cofactor(1, 2, 1, 2),
            -cofactor(1, 2, 0, 2),
            cofactor(1, 2, 0, 1),
        ],
        [
            -cofactor(0, 2, 1, 2),
            cofactor(0, 2, 0, 2),
            -cofactor(0, 2, 0, 1),
        ],
        [
            cofactor(0, 1, 1, 2),
            -cofactor(0, 1, 0, 2),
            cofactor(0, 1, 0, 1),
        ],
    ];
    let determinant = a[0][0] * c[0][0] + a[0][1] * c[0][1] + a[0][2] * c[0][2];
    // The inverse is the transposed cofactor matrix over the determinant.
    let mut inverse = [[0.0; 3]; 3];
    for (r, row) in inverse.iter_mut().enumerate() {
        for (k, value) in row.iter_mut().enumerate() {
            *value = c[k][r] / determinant;
        }
    }
    inverse
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `∫ f` over the range by the midpoint rule with `n` intervals (a
    /// different rule and grid than the Gram matrix's).
    fn integrate(n: usize, f: impl Fn(f64) -> f64) -> f64 {
        let h = (LAMBDA_MAX - LAMBDA_MIN) / n as f64;
        (0..n)
            .map(|i| f(LAMBDA_MIN + h * (i as f64 + 0.5)))
            .sum::<f64>()
            * h
    }

    #[test]
    fn the_basis_is_a_nonnegative_partition_of_unity() {
        for i in 0..=470 {
            let b = basis(LAMBDA_MIN + i as f64);
            assert!(b.iter().all(|&v| v >= 0.0), "{b:?}");
            assert!((b.iter().sum::<f64>() - 1.0).abs() < 1e-12, "{b:?}");
        }
        // Each basis function is the largest somewhere: red at long
        // wavelengths, green in the middle, blue at short ones.
        let largest = |nm: f64| {
            let b = basis(nm);
            (0..3).max_by(|&i, &j| b[i].total_cmp(&b[j])).unwrap_or(0)
        };
        assert_eq!([largest(650.0), largest(540.0), largest(450.0)], [0, 1, 2]);
    }

    #[test]
    fn light_beyond_the_visible_ends_keeps_the_colour_of_the_ends() {
        // Deep red light is red (the fit alone made 740-830 nm green, half
        // of the green sensor's weight), and the shortest wavelengths are
        // violet as the CIE locus's end is (the fit alone made them
        // green-blue).
        let locus_end = |x: f64, y: f64| {
            let xyz = [x / y, 1.0, (1.0 - x - y) / y];
            let m = [
                [3.2404542, -1.5371385, -0.4985314],
                [-0.9692660, 1.8760108, 0.0415560],
                [0.0556434, -0.2040259, 1.0572252],
            ];
            let rgb = m.map(|row| (row[0] * xyz[0] + row[1] * xyz[1] + row[2] * xyz[2]).max(0.0));
            let sum: f64 = rgb.iter().sum();
            rgb.map(|v| v / sum)
        };
        let violet = locus_end(0.1741, 0.0050);
        let red = locus_end(0.7347, 0.2653);
        for nm in (0..=60).map(|i| LAMBDA_MIN + i as f64) {
            let b = basis(nm);
            assert!(
                (0..3).all(|k| (b[k] - violet[k]).abs() < 0.01),
                "{nm}: {b:?}"
            );
        }
        for nm in (0..=180).map(|i| 650.0 + i as f64) {
            assert_eq!(basis(nm), red, "{nm}");
            let s = sensor(nm);
            assert!(s.r > 0.0 && s.g < 0.0 && s.b < 0.0, "{nm}: {s:?}");
        }
    }

    #[test]
    fn the_sensor_reads_each_basis_function_back_as_its_channel() {
        for k in 0..3 {
            for j in 0..3 {
                let value = integrate(200_000, |nm| {
                    let s = sensor(nm);
                    [s.r, s.g, s.b][k] * basis(nm)[j]
                });
                let expected = if k == j { 1.0 } else { 0.0 };
                assert!((value - expected).abs() < 1e-4, "∫ c̃_{k} B_{j} = {value}");
            }
        }
    }

    #[test]
    fn a_colour_goes_round_unchanged() {
        let c = Color::new(0.9, 0.35, 0.1);
        let round = |k: usize| {
            integrate(100_000, |nm| {
                let s = sensor(nm);
                [s.r, s.g, s.b][k] * spectrum_at(&basis(nm), c)
            })
        };
        let back = Color::new(round(0), round(1), round(2));
        assert!(
            (back.r - c.r).abs() + (back.g - c.g).abs() + (back.b - c.b).abs() < 1e-4,
            "{back:?}"
        );
    }

    #[test]
    fn the_fit_peaks_where_the_cie_functions_do() {
        // ȳ peaks near 555 nm at about 1, x̄ near 600 nm at about 1.06,
        // z̄ near 445 nm at about 1.78.
        let peak = |k: usize| {
            (3600..=8300)
                .map(|i| i as f64 / 10.0)
                .max_by(|&a, &b| cie_xyz(a)[k].total_cmp(&cie_xyz(b)[k]))
                .unwrap_or(0.0)
        };
        assert!((peak(0) - 599.0).abs() < 5.0, "{}", peak(0));
        assert!((peak(1) - 556.0).abs() < 5.0, "{}", peak(1));
        assert!((peak(2) - 446.0).abs() < 5.0, "{}", peak(2));
        assert!((cie_xyz(555.0)[1] - 1.0).abs() < 0.02);
    }
}
