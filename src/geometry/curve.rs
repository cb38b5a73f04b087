//! Planar profile curves: Bezier curves of any degree and uniform cubic B-splines,
//! evaluated (point and derivative) on the parameter range [0, 1].

use nalgebra::Vector2;

/// Profile curve of a surface of revolution, in the xy plane, swept about y.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    pub kind: CurveKind,
    /// Control points (x, y); z of the file is dropped.
    pub controls: Vec<[f64; 2]>,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CurveKind {
    /// One Bezier curve of degree `controls.len() - 1`.
    Bezier,
    /// A uniform cubic B-spline (clamped to the range where it is defined).
    Bspline,
}

pub type Point2 = Vector2<f64>;

/// Control polygons up to this size are evaluated without allocating.
const STACK_CONTROLS: usize = 64;

#[derive(Clone, Debug)]
pub struct Curve {
    kind: CurveKind,
    controls: Vec<Point2>,
}

impl Curve {
    /// `None` with fewer than two control points or non-finite coordinates.
    /// A B-spline with fewer than four controls is evaluated as a Bezier curve.
    pub fn new(profile: &Profile) -> Option<Curve> {
        let controls: Vec<Point2> = profile
            .controls
            .iter()
            .map(|c| Point2::new(c[0], c[1]))
            .collect();
        if controls.len() < 2
            || controls
                .iter()
                .any(|c| !c.x.is_finite() || !c.y.is_finite())
        {
            return None;
        }
        let kind = if controls.len() < 4 {
            CurveKind::Bezier
        } else {
            profile.kind
        };
        Some(Curve { kind, controls })
    }

    pub fn kind(&self) -> CurveKind {
        self.kind
    }

    pub fn controls(&self) -> &[Point2] {
        &self.controls
    }

    /// Point and derivative d/du at `u` (outside [0, 1] the polynomial pieces extend).
    #[inline]
    pub fn evaluate(&self, u: f64) -> (Point2, Point2) {
        match self.kind {
            CurveKind::Bezier => bezier(&self.controls, u),
            CurveKind::Bspline => bspline(&self.controls, u),
        }
    }
}

/// De Casteljau: the last two points of the triangle give the point and the
/// derivative `n (b1 - b0)`. Its work is quadratic in the number of controls,
/// so long control polygons are summed in the Bernstein basis instead.
fn bezier(controls: &[Point2], u: f64) -> (Point2, Point2) {
    let n = controls.len();
    if n > STACK_CONTROLS {
        return long_bezier(controls, u);
    }
    let mut work = [Point2::zeros(); STACK_CONTROLS];
    work[..n].copy_from_slice(controls);
    de_casteljau(&mut work[..n], u)
}

/// A Bezier curve of many controls: the point is `sum B(n, i)(u) P_i` and the
/// derivative `n sum B(n - 1, i)(u) (P_(i+1) - P_i)`, each summed by
/// `bernstein_sum`. Outside [0, 1] the curve goes on along its end tangent
/// (a polynomial of high degree is useless there: it grows like `2^n`).
fn long_bezier(controls: &[Point2], u: f64) -> (Point2, Point2) {
    let end = u.clamp(0.0, 1.0);
    let degree = controls.len() - 1;
    let point = bernstein_sum(degree, end, |i| controls[i]);
    let tangent = bernstein_sum(degree - 1, end, |i| controls[i + 1] - controls[i]) * degree as f64;
    (point + tangent * (u - end), tangent)
}

/// Weights below this fraction of the largest one are left out of a sum.
const NEGLIGIBLE_WEIGHT: f64 = 1e-20;

/// `sum B(degree, i)(u) value(i)` for `u` in [0, 1]. The Bernstein weights
/// peak near `i = degree u` and fall off faster than a Gaussian of width
/// `sqrt(degree u (1 - u))` on either side; they are computed relative to
/// the peak by the ratio of neighbours, summed out from it until negligible,
/// and normalised by their sum (the weights sum to one). The work is about
/// the width of the peak (at most `degree + 1` terms), with no factorials
/// to overflow and no powers to underflow.
fn bernstein_sum(degree: usize, u: f64, value: impl Fn(usize) -> Point2) -> Point2 {
    let v = 1.0 - u;
    let peak = ((degree as f64 * u).round() as usize).min(degree);
    let mut total = value(peak);
    let mut weights = 1.0;
    // Upwards: w(i + 1) / w(i) = (degree - i) u / ((i + 1) v).
    let mut weight = 1.0;
    for i in peak..degree {
        let denominator = (i + 1) as f64 * v;
        if denominator <= 0.0 {
            break;
        }
        weight *= (degree - i) as f64 * u / denominator;
        if weight.is_nan() || weight <= NEGLIGIBLE_WEIGHT {
            break;
        }
        total += value(i + 1) * weight;
        weights += weight;
    }
    // Downwards: w(i - 1) / w(i) = i v / ((degree - i + 1) u).
    let mut weight = 1.0;
    for i in (1..=peak).rev() {
        let denominator = (degree - i + 1) as f64 * u;
        if denominator <= 0.0 {
            break;
        }
        weight *= i as f64 * v / denominator;
        if weight.is_nan() || weight <= NEGLIGIBLE_WEIGHT {
            break;
        }
        total += value(i - 1) * weight;
        weights += weight;
    }
    total / weights
}

fn de_casteljau(work: &mut [Point2], u: f64) -> (Point2, Point2) {
    let n = work.len();
    let s = 1.0 - u;
    // Reduce down to two points.
    for level in (2..n).rev() {
        for i in 0..level {
            work[i] = work[i] * s + work[i + 1] * u;
        }
    }
    let degree = (n - 1) as f64;
    (work[0] * s + work[1] * u, (work[1] - work[0]) * degree)
}

/// Uniform cubic B-spline over `n - 3` segments; u in [0, 1] spans all of them.
fn bspline(controls: &[Point2], u: f64) -> (Point2, Point2) {
    let segments = controls.len() - 3;
    let s = u * segments as f64;
    let i = (s.floor().max(0.0) as usize).min(segments - 1);
    let t = s - i as f64;
    let t2 = t * t;
    let t3 = t2 * t;
    let m = 1.0 - t;
    let basis = [
        m * m * m / 6.0,
        (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0,
        (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0,
        t3 / 6.0,
    ];
    let derivative = [
        -m * m / 2.0,
        (3.0 * t2 - 4.0 * t) / 2.0,
        (-3.0 * t2 + 2.0 * t + 1.0) / 2.0,
        t2 / 2.0,
    ];
    let mut point = Point2::zeros();
    let mut tangent = Point2::zeros();
    for k in 0..4 {
        point += controls[i + k] * basis[k];
        tangent += controls[i + k] * derivative[k];
    }
    (point, tangent * segments as f64)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn profile(kind: CurveKind, controls: &[[f64; 2]]) -> Curve {
        Curve::new(&Profile {
            kind,
            controls: controls.to_vec(),
        })
        .unwrap()
    }

    const VASE: [[f64; 2]; 7] = [
        [0.0, 0.0],
        [2.2, 0.0],
        [3.0, 1.5],
        [1.2, 3.0],
        [0.8, 4.0],
        [1.6, 5.0],
        [2.0, 5.6],
    ];

    const GLASS: [[f64; 2]; 8] = [
        [0.0, -0.46],
        [0.0, -0.46],
        [-0.35, -0.43],
        [-0.85, -0.28],
        [-1.11, 0.08],
        [-1.16, 1.1],
        [-0.99, 2.33],
        [-1.03, 2.5],
    ];

    fn assert_derivative_matches(curve: &Curve) {
        let h = 1e-6;
        for k in 0..=200 {
            let u = k as f64 / 200.0;
            let (_, derivative) = curve.evaluate(u);
            let (a, b) = (u - h, u + h);
            let finite = (curve.evaluate(b).0 - curve.evaluate(a).0) / (b - a);
            let error = (finite - derivative).norm();
            // B-spline derivatives are continuous, so knots are fine too.
            assert!(
                error < 1e-6 * (1.0 + derivative.norm()),
                "u={u}: {derivative:?} vs {finite:?}"
            );
        }
    }

    #[test]
    fn bezier_derivative_matches_finite_differences() {
        assert_derivative_matches(&profile(CurveKind::Bezier, &VASE));
        assert_derivative_matches(&profile(CurveKind::Bezier, &VASE[..2]));
        assert_derivative_matches(&profile(CurveKind::Bezier, &VASE[..3]));
    }

    #[test]
    fn bspline_derivative_matches_finite_differences() {
        assert_derivative_matches(&profile(CurveKind::Bspline, &GLASS));
        assert_derivative_matches(&profile(CurveKind::Bspline, &VASE));
    }

    #[test]
    fn bezier_interpolates_end_points() {
        let curve = profile(CurveKind::Bezier, &VASE);
        assert!((curve.evaluate(0.0).0 - Point2::new(0.0, 0.0)).norm() < 1e-15);
        assert!((curve.evaluate(1.0).0 - Point2::new(2.0, 5.6)).norm() < 1e-12);
        // End derivative is degree * (last - previous).
        let (_, d) = curve.evaluate(1.0);
        assert!((d - Point2::new(0.4, 0.6) * 6.0).norm() < 1e-12);
    }

    /// A polygon of `n` controls on a wavy line, for long curves.
    fn wavy(n: usize) -> Vec<[f64; 2]> {
        (0..n)
            .map(|i| [1.0 + 0.5 * (i as f64 * 0.37).sin(), i as f64 / n as f64])
            .collect()
    }

    #[test]
    fn long_bezier_sums_agree_with_de_casteljau() {
        for n in [STACK_CONTROLS + 1, 200, 1000] {
            let controls: Vec<Point2> = wavy(n).iter().map(|c| Point2::new(c[0], c[1])).collect();
            for k in 0..=50 {
                let u = k as f64 / 50.0;
                let (point, tangent) = long_bezier(&controls, u);
                let (expected, expected_tangent) = de_casteljau(&mut controls.clone(), u);
                assert!((point - expected).norm() < 1e-12, "n={n} u={u}");
                let error = (tangent - expected_tangent).norm();
                assert!(
                    error < 1e-9 * (1.0 + expected_tangent.norm()),
                    "n={n} u={u}"
                );
            }
        }
    }

    #[test]
    fn long_bezier_derivative_matches_finite_differences_and_extends_linearly() {
        let arc: Vec<[f64; 2]> = (0..4096)
            .map(|i| {
                let angle = i as f64 / 4095.0 * std::f64::consts::PI;
                [1.0 + 0.5 * angle.sin(), angle.cos()]
            })
            .collect();
        let curve = profile(CurveKind::Bezier, &arc);
        assert_derivative_matches(&curve);
        let (start, tangent) = curve.evaluate(0.0);
        let (before, _) = curve.evaluate(-0.1);
        assert!((before - (start - tangent * 0.1)).norm() < 1e-12);
    }

    #[test]
    fn bspline_with_tripled_end_point_starts_there() {
        let mut controls = vec![[0.0, -0.46]; 3];
        controls.extend_from_slice(&GLASS[2..]);
        let curve = profile(CurveKind::Bspline, &controls);
        assert!((curve.evaluate(0.0).0 - Point2::new(0.0, -0.46)).norm() < 1e-12);
    }
}
