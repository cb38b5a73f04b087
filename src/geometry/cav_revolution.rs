//! CaveSpiderLZJ's surface of revolution: a triangle mesh of the profile
//! that finds the hit, then ten short Newton steps that move it a little
//! and pick the normal (`CaveSpiderLZJ/PathTracingFinal:include/revsurface.hpp`,
//! `include/curve.hpp`, `src/mesh.cpp` at `6970e2d`, the oracle's state).
//!
//! The facts it follows:
//! - The profile is sampled by its own parameter `s`: a Bezier curve (one
//!   polynomial of degree `n - 1` for `n` controls) at `s = k / (m - 1)`,
//!   `k < m = 20 (n - 1)`; a cubic B-spline over the uniform knots
//!   `i / (n + 3)` at `s = (60 + k) / (20 (n + 3))`, `k < m = 20 (n - 3)`,
//!   so the last sample stops one step short of the curve's end.
//! - Each sample is turned about y to 40 angles `a = 2 pi i / 40`, as
//!   `(x cos a, y, x sin a)`; two triangles join samples `k`, `k + 1` of
//!   neighbouring angles (`(i, k), (i + 1, k + 1), (i, k + 1)` and
//!   `(i, k), (i + 1, k), (i + 1, k + 1)`), the last angle joined to the first.
//! - A ray meets the nearest triangle. The iteration starts from its
//!   distance, the angle of its point (`atan(z / x)`, plus pi where `x <= 0`
//!   and 2 pi where `x > 0 >= z`) and the mean of its three vertices' sample
//!   numbers `k` over `m` (not over `m - 1`, and not mapped to a B-spline's
//!   knot range: a B-spline is evaluated at that number as its own `s`).
//! - Ten steps `x - 0.02 J^-1 F(x)` on `x = (t, s, angle)` with
//!   `F = origin + t direction - (x(s) cos a, y(s), x(s) sin a)`, whose
//!   Jacobian takes the profile's **unit** tangent for its derivative in `s`
//!   (so the step in `s` is the true one times the tangent's length). A step
//!   that would take `s` out of [0, 1] ends the iteration, unmade. Outside
//!   its knot range a B-spline is the sum of the basis functions that reach
//!   there (it shrinks towards the origin).
//! - The normal is the profile's unit tangent at the `s` of the last step
//!   made (the one before the last update), turned by the final angle, and
//!   faces the ray; the hit is `origin + t direction` with the final `t`, if
//!   beyond the ray's start (else the ray misses, whatever lies behind).
//! - Its texture coordinates are (angle / 2 pi, `s` clamped to [0, 1]).
//!
//! Their arithmetic is single precision; so is the iteration here.

use std::f64::consts::PI;
use std::sync::Arc;

use super::cav_sphere::{LEAVING_OFFSET, MIN_DISTANCE};
use super::curve::{Curve, CurveKind};
use super::{Intersection, Mesh, MeshData, Profile, SurfaceHit, UvMapping};
use super::{derivatives_or_fallback, normalize_or};
use crate::math::{Aabb, Point3, Ray, Vec3};

/// Profile samples per span (per control of a B-spline, per degree of a
/// Bezier curve): their `RESOLUTION`.
const SAMPLES_PER_SPAN: usize = 20;
/// Angles around the axis: their `THETA_RES`.
const ANGLES: usize = 40;
/// Their `ITER`.
const STEPS: usize = 10;
/// The fraction of each Newton step taken: their `LEARNING_RATE`.
const STEP_FRACTION: f32 = 0.02;
/// Their 2 pi, written 6.2831852: in single precision one step below
/// `TAU`.
const TURN: f32 = f32::from_bits(0x40C9_0FDA);

#[derive(Debug)]
pub struct CavRevolution {
    kind: CurveKind,
    controls: Vec<[f64; 2]>,
    /// Our curve, for a Bezier profile (the same polynomial as theirs).
    bezier: Option<Curve>,
    tessellation: Mesh,
    /// Where each triangle starts the iteration in `s`: its vertices'
    /// sample numbers summed, over three times the number of samples.
    start_s: Vec<f32>,
}

/// The point and unit tangent of the profile at `s`, as theirs rounds them.
#[derive(Clone, Copy, Debug)]
struct ProfilePoint {
    point: [f32; 2],
    tangent: [f32; 2],
}

impl CavRevolution {
    /// `None` for a profile with fewer than two controls (or a B-spline
    /// with fewer than four, which theirs refuses), non-finite controls, or
    /// a tessellation with no triangle.
    pub fn new(profile: &Profile) -> Option<CavRevolution> {
        let n = profile.controls.len();
        let finite = profile.controls.iter().flatten().all(|c| c.is_finite());
        if n < 2 || !finite || (profile.kind == CurveKind::Bspline && n < 4) {
            return None;
        }
        let bezier = match profile.kind {
            CurveKind::Bezier => Some(Curve::new(profile)?),
            CurveKind::Bspline => None,
        };
        let mut surface = CavRevolution {
            kind: profile.kind,
            controls: profile.controls.clone(),
            bezier,
            tessellation: Mesh::new(Arc::new(MeshData::default())),
            start_s: Vec::new(),
        };
        let samples: Vec<[f32; 2]> = surface
            .sample_parameters()
            .into_iter()
            .map(|s| surface.profile_at(s).point)
            .collect();
        let m = samples.len();
        if m < 2 {
            return None;
        }
        let mut positions = Vec::with_capacity(m * ANGLES);
        for i in 0..ANGLES {
            let angle = f64::from(-(i as f32) / ANGLES as f32 * TURN);
            // Turned by -angle about y: (x cos a, y, x sin a) for a = -angle.
            let (sin, cos) = (-angle).sin_cos();
            for p in &samples {
                let (x, y) = (f64::from(p[0]), f64::from(p[1]));
                positions.push(Point3::new(x * cos, y, x * sin));
            }
        }
        let mut triangles = Vec::with_capacity(2 * ANGLES * (m - 1));
        let mut start_s = Vec::with_capacity(triangles.capacity());
        let at = |i: usize, k: usize| ((i % ANGLES) * m + k) as u32;
        for i in 0..ANGLES {
            for k in 0..m - 1 {
                triangles.push([at(i, k), at(i + 1, k + 1), at(i, k + 1)]);
                start_s.push((3 * k + 2) as f32 / (3 * m) as f32);
                triangles.push([at(i, k), at(i + 1, k), at(i + 1, k + 1)]);
                start_s.push((3 * k + 1) as f32 / (3 * m) as f32);
            }
        }
        if !positions.iter().all(|p| p.iter().all(|c| c.is_finite())) {
            return None;
        }
        surface.tessellation = Mesh::new(Arc::new(MeshData {
            positions,
            normals: None,
            uvs: None,
            triangles,
            framework_reading: None,
        }));
        surface.start_s = start_s;
        Some(surface)
    }

    /// The triangles of `profile`'s tessellation (2 x 40 x (samples - 1)),
    /// known before it is built.
    pub fn triangle_count(profile: &Profile) -> usize {
        let n = profile.controls.len();
        let samples = match profile.kind {
            CurveKind::Bezier => n.saturating_sub(1),
            CurveKind::Bspline => n.saturating_sub(3),
        } * SAMPLES_PER_SPAN;
        2 * ANGLES * samples.saturating_sub(1)
    }

    /// The tessellation's bounds (the steps move a hit a little off them).
    pub fn bounds(&self) -> Option<Aabb> {
        self.tessellation.bounds()
    }

    /// Their profile samples' parameters (see the module docs).
    fn sample_parameters(&self) -> Vec<f64> {
        let n = self.controls.len();
        match self.kind {
            CurveKind::Bezier => {
                let m = (n - 1) * SAMPLES_PER_SPAN;
                (0..m).map(|k| k as f64 / (m - 1) as f64).collect()
            }
            CurveKind::Bspline => {
                let m = (n - 3) * SAMPLES_PER_SPAN;
                let denominator = ((n + 3) * SAMPLES_PER_SPAN) as f64;
                (0..m)
                    .map(|k| (3 * SAMPLES_PER_SPAN + k) as f64 / denominator)
                    .collect()
            }
        }
    }

    /// Point and unit tangent at their parameter `s` (in [0, 1]).
    fn profile_at(&self, s: f64) -> ProfilePoint {
        let (point, derivative) = match &self.bezier {
            Some(curve) => {
                let (p, d) = curve.evaluate(s);
                ([p.x, p.y], [d.x, d.y])
            }
            None => uniform_bspline(&self.controls, s),
        };
        let round = |v: [f64; 2]| [v[0] as f32, v[1] as f32];
        let tangent = round(derivative);
        let length = (tangent[0] * tangent[0] + tangent[1] * tangent[1]).sqrt();
        ProfilePoint {
            point: round(point),
            tangent: [tangent[0] / length, tangent[1] / length],
        }
    }

    /// The tessellation's nearest hit beyond `t_min`, moved by the steps;
    /// `u` of the result is the final `s`, `v` the final angle, and `index`
    /// holds the bits of the `s` whose tangent gives the normal
    /// (`f32::to_bits`). `None` when the tessellation is missed or the
    /// steps end at a distance not within `(t_min, t_max)`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        // cav's rays leave 1e-5 along their direction and count hits from a
        // distance of 1e-4, in the object's space with a unit direction.
        let length = ray.direction.norm();
        if length == 0.0 || !length.is_finite() {
            return None;
        }
        let unit = ray.direction / length;
        let start = Ray::new(ray.origin + unit * LEAVING_OFFSET, unit, ray.time);
        let min_distance = f64::from(MIN_DISTANCE);
        let seed = self
            .tessellation
            .intersect(&start, min_distance, f64::INFINITY)?;
        let o = start.origin.map(|c| c as f32);
        let d = unit.map(|c| c as f32);
        let t = seed.t as f32;
        let p = o + d * t;
        let quadrant = if p.x > 0.0 {
            if p.z > 0.0 { 0.0 } else { 2.0 }
        } else {
            1.0
        };
        let angle = (p.z / p.x).atan() + quadrant * std::f32::consts::PI;
        let mut x = [t, self.start_s[seed.index as usize], angle];
        let mut normal_s = x[1];
        for _ in 0..STEPS {
            let (sin, cos) = x[2].sin_cos();
            normal_s = x[1];
            let at = self.profile_at(f64::from(x[1]));
            let ([vx, vy], [tx, ty]) = (at.point, at.tangent);
            let f = [
                o.x + x[0] * d.x - cos * vx,
                o.y + x[0] * d.y - vy,
                o.z + x[0] * d.z - sin * vx,
            ];
            let jacobian = [
                [d.x, -cos * tx, sin * vx],
                [d.y, -ty, 0.0],
                [d.z, -sin * tx, -cos * vx],
            ];
            let step = solve(&jacobian, &f);
            let next = [
                x[0] - STEP_FRACTION * step[0],
                x[1] - STEP_FRACTION * step[1],
                x[2] - STEP_FRACTION * step[2],
            ];
            // A parameter that is not a number goes on (and ends a miss).
            if next[1] < 0.0 || next[1] > 1.0 {
                break;
            }
            x = next;
        }
        if !(x[0] > MIN_DISTANCE && x.iter().all(|c| c.is_finite())) {
            return None;
        }
        let t = (f64::from(x[0]) + LEAVING_OFFSET) / length;
        (t > t_min && t < t_max).then(|| Intersection {
            t,
            u: f64::from(x[1]),
            v: f64::from(x[2]),
            index: normal_s.to_bits(),
            slot: 0,
        })
    }

    /// The hit `origin + t direction`, the normal of the profile's tangent
    /// at the steps' `s` turned by their angle, facing the ray; uv = (angle /
    /// 2 pi, `s` clamped to [0, 1]).
    pub fn surface(&self, ray: &Ray, hit: &Intersection) -> SurfaceHit {
        let normal_s = f32::from_bits(hit.index);
        let at = self.profile_at(f64::from(normal_s));
        let (tx, ty) = (f64::from(at.tangent[0]), f64::from(at.tangent[1]));
        let (sin, cos) = hit.v.sin_cos();
        let radial = Vec3::new(cos, 0.0, sin);
        let mut normal = normalize_or(Vec3::new(ty * cos, -tx, ty * sin), radial);
        if ray.direction.dot(&normal) > 0.0 {
            normal = -normal;
        }
        let final_point = self.profile_at(hit.u.clamp(0.0, 1.0)).point;
        let x = f64::from(final_point[0]);
        let along_circle = Vec3::new(-x * sin, 0.0, x * cos) * (2.0 * PI);
        let along_profile = Vec3::new(tx * cos, ty, tx * sin);
        let (dpdu, dpdv) = derivatives_or_fallback(along_circle, along_profile, &normal);
        SurfaceHit {
            point: ray.at(hit.t),
            geometric_normal: normal,
            shading_normal: normal,
            dpdu,
            dpdv,
            uv: [hit.v / (2.0 * PI), hit.u.clamp(0.0, 1.0)],
            uv_mapping: UvMapping::Unit,
        }
    }
}

/// `J^-1 f` by cofactors; zero for a singular `J` (theirs inverts it to the
/// zero matrix).
fn solve(j: &[[f32; 3]; 3], f: &[f32; 3]) -> [f32; 3] {
    let c00 = j[1][1] * j[2][2] - j[1][2] * j[2][1];
    let c01 = -(j[1][0] * j[2][2] - j[1][2] * j[2][0]);
    let c02 = j[1][0] * j[2][1] - j[1][1] * j[2][0];
    let c10 = -(j[0][1] * j[2][2] - j[0][2] * j[2][1]);
    let c11 = j[0][0] * j[2][2] - j[0][2] * j[2][0];
    let c12 = -(j[0][0] * j[2][1] - j[0][1] * j[2][0]);
    let c20 = j[0][1] * j[1][2] - j[0][2] * j[1][1];
    let c21 = -(j[0][0] * j[1][2] - j[0][2] * j[1][0]);
    let c22 = j[0][0] * j[1][1] - j[0][1] * j[1][0];
    let determinant = j[0][0] * c00 + j[0][1] * c01 + j[0][2] * c02;
    if determinant == 0.0 {
        return [0.0; 3];
    }
    // The inverse is the transposed cofactor matrix over the determinant.
    [
        (c00 * f[0] + c10 * f[1] + c20 * f[2]) / determinant,
        (c01 * f[0] + c11 * f[1] + c21 * f[2]) / determinant,
        (c02 * f[0] + c12 * f[1] + c22 * f[2]) / determinant,
    ]
}

/// A cubic B-spline of `controls` over the uniform knots `i / (n + 3)`
/// (`n` controls), at any `s` in [0, 1]: the sum of the basis functions
/// `b(s (n + 3) - i)` of the controls, with its derivative. Outside the
/// knot range `[3, n] / (n + 3)` fewer than four reach `s`.
fn uniform_bspline(controls: &[[f64; 2]], s: f64) -> ([f64; 2], [f64; 2]) {
    let scale = (controls.len() + 3) as f64;
    let position = s * scale;
    let mut point = [0.0; 2];
    let mut derivative = [0.0; 2];
    // Only the four controls whose basis function reaches `s`: i in
    // (position - 4, position].
    if !position.is_finite() {
        return (point, derivative);
    }
    let last = position.floor().clamp(-1.0, controls.len() as f64 - 1.0);
    let first = (last - 3.0).max(0.0) as usize;
    let reaching = controls
        .iter()
        .enumerate()
        .take(last.max(0.0) as usize + 1)
        .skip(first);
    for (i, c) in reaching {
        let (weight, slope) = cardinal_cubic(position - i as f64);
        point = [point[0] + weight * c[0], point[1] + weight * c[1]];
        derivative = [
            derivative[0] + slope * scale * c[0],
            derivative[1] + slope * scale * c[1],
        ];
    }
    (point, derivative)
}

/// The cubic B-spline of unit knots on [0, 4] and its derivative at `x`.
fn cardinal_cubic(x: f64) -> (f64, f64) {
    if !(0.0..4.0).contains(&x) {
        return (0.0, 0.0);
    }
    if x < 1.0 {
        (x * x * x / 6.0, x * x / 2.0)
    } else if x < 2.0 {
        (
            (-3.0 * x * x * x + 12.0 * x * x - 12.0 * x + 4.0) / 6.0,
            (-9.0 * x * x + 24.0 * x - 12.0) / 6.0,
        )
    } else if x < 3.0 {
        (
            (3.0 * x * x * x - 24.0 * x * x + 60.0 * x - 44.0) / 6.0,
            (9.0 * x * x - 48.0 * x + 60.0) / 6.0,
        )
    } else {
        let r = 4.0 - x;
        (r * r * r / 6.0, -r * r / 2.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cylinder of radius 1 from y = 0 to 3 (a straight Bezier profile).
    fn cylinder() -> CavRevolution {
        let controls = (0..4).map(|i| [1.0, f64::from(i)]).collect();
        CavRevolution::new(&Profile {
            kind: CurveKind::Bezier,
            controls,
        })
        .expect("a surface")
    }

    /// A ray from distance 10 towards the axis at angle `angle` and height `y`.
    fn inwards(angle: f64, y: f64) -> Ray {
        let radial = Vec3::new(angle.cos(), 0.0, angle.sin());
        Ray::new(Point3::new(0.0, y, 0.0) + radial * 10.0, -radial, 0.0)
    }

    #[test]
    fn the_tessellation_has_their_rings_and_angles() {
        // A Bezier curve of n controls: 20 (n - 1) samples, both ends in.
        assert_eq!(cylinder().tessellation.data.positions.len(), 60 * ANGLES);
        // A B-spline: 20 (n - 3), the last one short of the end.
        let controls: Vec<[f64; 2]> = (0..8).map(|i| [1.0, f64::from(i)]).collect();
        let spline = CavRevolution::new(&Profile {
            kind: CurveKind::Bspline,
            controls,
        })
        .expect("a surface");
        let data = &spline.tessellation.data;
        assert_eq!(data.positions.len(), 100 * ANGLES);
        assert_eq!(data.triangles.len(), 2 * 99 * ANGLES);
        let count = |surface: &CavRevolution| surface.tessellation.data.triangles.len();
        let profile = |kind, n: i32| Profile {
            kind,
            controls: (0..n).map(|i| [1.0, f64::from(i)]).collect(),
        };
        assert_eq!(
            CavRevolution::triangle_count(&profile(CurveKind::Bspline, 8)),
            count(&spline)
        );
        assert_eq!(
            CavRevolution::triangle_count(&profile(CurveKind::Bezier, 4)),
            count(&cylinder())
        );
        let top = data.positions.iter().fold(f64::MIN, |m, p| m.max(p.y));
        // The curve ends at y = 6 (the mean of the last controls 5, 6, 7).
        assert!(top < 6.0 - 1e-3 && top > 6.0 - 0.1, "{top}");
    }

    #[test]
    fn a_hit_moves_a_fifth_of_the_way_from_the_facet_to_the_surface() {
        // Across the middle of a facet (angles 0 and 2 pi / 40 on either
        // side) the facet lies cos(pi / 40) from the axis, the surface 1:
        // ten steps of 2% of Newton's step take 1 - 0.98^10 of the gap.
        let surface = cylinder();
        let half = PI / ANGLES as f64;
        let ray = inwards(half, 1.5);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).expect("a hit");
        let facet = 10.0 - half.cos();
        let moved = (facet - hit.t) / (facet - 9.0);
        let expected = 1.0 - 0.98f64.powi(10);
        assert!((moved - expected).abs() < 0.02, "{moved} vs {expected}");
        // Across a ring of vertices the facet is the surface.
        let on_edge = surface.intersect(&inwards(0.0, 1.5), 0.0, f64::INFINITY);
        assert!((on_edge.expect("a hit").t - 9.0).abs() < 1e-5);
    }

    #[test]
    fn a_ray_going_on_through_the_facet_finds_nothing_beyond() {
        // The hit lies in front of the facet; a ray going on from it meets
        // the facet again, where the steps end behind the ray's start: a
        // miss, though the far side of the cylinder lies ahead.
        let surface = cylinder();
        let ray = inwards(PI / ANGLES as f64, 1.5);
        let hit = surface.intersect(&ray, 0.0, f64::INFINITY).expect("a hit");
        let on = Ray::new(ray.at(hit.t), ray.direction, 0.0);
        assert_eq!(surface.intersect(&on, 0.0, f64::INFINITY), None);
        // From inside, the far side is found.
        let inside = Ray::new(Point3::new(0.0, 1.5, 0.0), ray.direction, 0.0);
        let far = surface
            .intersect(&inside, 0.0, f64::INFINITY)
            .expect("a hit");
        assert!((far.t - 1.0).abs() < 0.01, "{}", far.t);
    }

    #[test]
    fn the_normal_faces_the_ray_and_uv_is_the_angle_and_parameter() {
        let surface = cylinder();
        for (angle, y) in [(0.3, 0.5), (2.0, 1.5), (4.0, 2.5)] {
            for ray in [
                inwards(angle, y),
                Ray::new(Point3::new(0.0, y, 0.0), -inwards(angle, y).direction, 0.0),
            ] {
                let hit = surface.intersect(&ray, 0.0, f64::INFINITY).expect("a hit");
                let at = surface.surface(&ray, &hit);
                assert!(at.geometric_normal.dot(&ray.direction) < -0.99);
                assert!((at.uv[0] * 2.0 * PI - angle).abs() < 1e-3, "{:?}", at.uv);
                // y = 3 s on this profile.
                assert!((at.uv[1] * 3.0 - y).abs() < 0.1, "{:?}", at.uv);
            }
        }
    }

    #[test]
    fn a_bspline_starts_at_its_sample_number_as_its_own_parameter() {
        // A B-spline cylinder of 8 controls has its knot range [3, 8] / 11.
        // A hit near its bottom starts at s = k / m near 0, outside that
        // range, where fewer basis functions reach: the profile there is
        // not the cylinder's wall, and the ten steps keep its tilt.
        let controls: Vec<[f64; 2]> = (0..8).map(|i| [1.0, f64::from(i)]).collect();
        let spline = CavRevolution::new(&Profile {
            kind: CurveKind::Bspline,
            controls,
        })
        .expect("a surface");
        let tilt = |y: f64| {
            let ray = inwards(0.0, y);
            let hit = spline.intersect(&ray, 0.0, f64::INFINITY).expect("a hit");
            spline.surface(&ray, &hit).geometric_normal.y.abs()
        };
        // The curve runs from y = 1 to 6; its middle s = k / m is right.
        assert!(tilt(3.5) < 0.05, "{}", tilt(3.5));
        assert!(tilt(1.2) > 0.2, "{}", tilt(1.2));
    }

    #[test]
    fn a_uniform_bspline_sums_every_control_whose_basis_reaches() {
        // Against the sum over all controls, inside and outside the knot
        // range (where fewer than four reach).
        let controls: Vec<[f64; 2]> = (0..9)
            .map(|i| [f64::from(i).sin() + 2.0, f64::from(i * i) * 0.1])
            .collect();
        let scale = (controls.len() + 3) as f64;
        for i in 0..=200 {
            let s = f64::from(i) / 200.0;
            let mut full = ([0.0; 2], [0.0; 2]);
            for (j, c) in controls.iter().enumerate() {
                let (w, d) = cardinal_cubic(s * scale - j as f64);
                full.0 = [full.0[0] + w * c[0], full.0[1] + w * c[1]];
                full.1 = [full.1[0] + d * scale * c[0], full.1[1] + d * scale * c[1]];
            }
            let (point, derivative) = uniform_bspline(&controls, s);
            for axis in 0..2 {
                assert!((point[axis] - full.0[axis]).abs() < 1e-12, "{s}");
                assert!((derivative[axis] - full.1[axis]).abs() < 1e-9, "{s}");
            }
        }
    }

    #[test]
    fn a_uniform_bspline_inside_its_knot_range_is_ours() {
        let controls = [[0.0, 0.0], [1.0, 2.0], [3.0, 1.0], [4.0, 4.0], [2.0, 5.0]];
        let profile = Profile {
            kind: CurveKind::Bspline,
            controls: controls.to_vec(),
        };
        let ours = Curve::new(&profile).expect("a curve");
        for i in 0..=10 {
            let u = f64::from(i) / 10.0;
            // Our u in [0, 1] is their s in [3, 5] / 8.
            let s = (3.0 + 2.0 * u) / 8.0;
            let (point, derivative) = uniform_bspline(&controls, s);
            let (p, d) = ours.evaluate(u);
            assert!((point[0] - p.x).abs() < 1e-12 && (point[1] - p.y).abs() < 1e-12);
            // d/du = d/ds * 2 / 8.
            assert!(
                (derivative[0] * 0.25 - d.x).abs() < 1e-9,
                "{derivative:?} {d:?}"
            );
            assert!((derivative[1] * 0.25 - d.y).abs() < 1e-9);
        }
    }
}
