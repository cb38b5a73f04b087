//! W-Solaris's ray tests, computed as its renderer computes them: in single
//! precision (`float`), with its formulas and their order of operations,
//! and with no distance kept between a surface and the ray that leaves it
//! (`../shared/docs/looks.md`, section W-Solaris+computer-graphics).
//!
//! A ray leaves from the point its last ray reached, rounded to f32
//! ([`point_at`]); rounding puts that point inside or outside the surface
//! about half the time each, and from inside a sphere (or behind a
//! triangle) the ray finds the same surface again at a tiny distance and
//! scatters there again. In f64 the same thing happens less often (the
//! point rounds closer to the surface, and our spheres' roots are exact),
//! so the `wso` look tests its shapes here.
//!
//! Inputs are f64 values rounded to f32 on entry; distances come back as
//! the f32 values widened.

use crate::math::{Point3, Ray, Vec3};

/// A vector of three singles.
type Single = [f32; 3];

#[inline(always)]
fn single(v: &Vec3) -> Single {
    [v.x as f32, v.y as f32, v.z as f32]
}

#[inline(always)]
fn minus(a: Single, b: Single) -> Single {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

/// `a . b` added left to right, as their vector library does.
#[inline(always)]
fn dot(a: Single, b: Single) -> f32 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

#[inline(always)]
fn cross(a: Single, b: Single) -> Single {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Where `ray` is at `t`, in single precision: `origin + direction t`, the
/// point the next ray leaves from (theirs moves the ray's origin there).
#[inline]
pub fn point_at(ray: &Ray, t: f64) -> Point3 {
    let (origin, direction, t) = (single(&ray.origin), single(&ray.direction), t as f32);
    Point3::new(
        f64::from(origin[0] + direction[0] * t),
        f64::from(origin[1] + direction[1] * t),
        f64::from(origin[2] + direction[2] * t),
    )
}

/// The distance to a sphere by W-Solaris's test: half the usual `b` from
/// the centre seen from the origin (the direction taken as unit), the near
/// root when it is at least `t_min` (theirs: 0), else the far one; `None`
/// when the discriminant is not positive or neither root is in
/// `[t_min, t_max)`.
#[inline]
pub fn sphere(center: &Point3, radius: f64, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
    let to_center = minus(single(center), single(&ray.origin));
    let direction = single(&ray.direction);
    let radius = radius as f32;
    let b = -dot(to_center, direction);
    let c = dot(to_center, to_center) - radius * radius;
    let discriminant = b * b - c;
    if discriminant <= 0.0 || discriminant.is_nan() {
        return None;
    }
    let root = discriminant.sqrt();
    let (near, far) = (f64::from(-b - root), f64::from(-b + root));
    let within = |t: f64| t >= t_min && t < t_max;
    if within(near) {
        Some(near)
    } else {
        within(far).then_some(far)
    }
}

/// The distance to a plane `normal . p = offset` (`normal` unit) by
/// W-Solaris's test: hit only by rays travelling against the normal by more
/// than a cosine of 1e-6, and at distance `t_min` (theirs: 0) too.
#[inline]
pub fn plane(normal: &Vec3, offset: f64, ray: &Ray, t_min: f64, t_max: f64) -> Option<f64> {
    let normal = single(normal);
    let cosine = dot(normal, single(&ray.direction));
    if cosine > -1e-6 || cosine.is_nan() {
        return None;
    }
    let t = f64::from((offset as f32 - dot(normal, single(&ray.origin))) / cosine);
    (t >= t_min && t < t_max).then_some(t)
}

/// The distance to a plane `normal . p = offset` (`normal` unit) by
/// yangjunx21's test: `-(n . o - offset) / (n . d)` in single precision,
/// from either side, strictly beyond `t_min` (theirs: 0). A ray leaving
/// from a point that rounded to the far side of the plane meets it again
/// at a tiny distance, from behind.
#[inline]
pub fn plane_two_sided(
    normal: &Vec3,
    offset: f64,
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<f64> {
    let normal = single(normal);
    let denominator = dot(normal, single(&ray.direction));
    if denominator == 0.0 {
        return None;
    }
    let t = f64::from(-(dot(normal, single(&ray.origin)) - offset as f32) / denominator);
    (t > t_min && t < t_max).then_some(t)
}

/// W-Solaris's Möller–Trumbore: `(t, b1, b2)` for the hit at
/// `(1 - b1 - b2) p0 + b1 p1 + b2 p2`, `None` when the determinant is below
/// f32's epsilon in size, the hit is outside the triangle or `t` is not in
/// `(t_min, t_max)` (theirs: `t > 0`).
#[inline]
pub fn triangle(
    vertices: &[Point3; 3],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
) -> Option<(f64, f64, f64)> {
    let [p0, p1, p2] = vertices.map(|p| single(&p));
    let (origin, direction) = (single(&ray.origin), single(&ray.direction));
    let edge1 = minus(p1, p0);
    let edge2 = minus(p2, p0);
    let p = cross(direction, edge2);
    let determinant = dot(edge1, p);
    if determinant.abs() < f32::EPSILON || determinant.is_nan() {
        return None;
    }
    let inverse = 1.0 / determinant;
    let s = minus(origin, p0);
    let b1 = dot(s, p) * inverse;
    if !(0.0..=1.0).contains(&b1) {
        return None;
    }
    let q = cross(s, edge1);
    let b2 = dot(direction, q) * inverse;
    if !(b2 >= 0.0 && b1 + b2 <= 1.0) {
        return None;
    }
    let t = f64::from(dot(edge2, q) * inverse);
    (t > t_min && t < t_max).then_some((t, f64::from(b1), f64::from(b2)))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sphere_is_met_at_distance_zero_by_a_ray_leaving_a_point_on_it() {
        // (3, 4, 0) lies on the sphere of radius 5 exactly, in f32 too:
        // leaving outwards, the far root is 0, which W-Solaris accepts.
        let center = Point3::zeros();
        let out = Ray::new(Point3::new(3.0, 4.0, 0.0), Vec3::new(0.6, 0.8, 0.0), 0.0);
        assert_eq!(sphere(&center, 5.0, &out, 0.0, f64::INFINITY), Some(0.0));
        // Inwards, the near root is 0 too.
        let inwards = Ray::new(out.origin, -out.direction, 0.0);
        assert_eq!(
            sphere(&center, 5.0, &inwards, 0.0, f64::INFINITY),
            Some(0.0)
        );
        // From outside, the near root.
        let from_far = Ray::new(Point3::new(0.0, 0.0, -10.0), Vec3::z(), 0.0);
        assert_eq!(
            sphere(&center, 5.0, &from_far, 0.0, f64::INFINITY),
            Some(5.0)
        );
        assert_eq!(sphere(&center, 5.0, &from_far, 0.0, 5.0), None);
    }

    #[test]
    fn a_plane_is_met_against_its_normal_only_and_at_distance_zero() {
        let normal = Vec3::y();
        let down = Ray::new(Point3::new(0.5, -4.0, 2.0), Vec3::new(0.6, -0.8, 0.0), 0.0);
        assert_eq!(plane(&normal, -4.0, &down, 0.0, f64::INFINITY), Some(0.0));
        let from_above = Ray::new(Point3::new(0.5, 1.0, 2.0), -Vec3::y(), 0.0);
        assert_eq!(
            plane(&normal, -4.0, &from_above, 0.0, f64::INFINITY),
            Some(5.0)
        );
        // A cosine of -1e-7 is refused: nearly parallel rays pass.
        let grazing = Ray::new(from_above.origin, Vec3::new(1.0, -1e-7, 0.0), 0.0);
        assert_eq!(plane(&normal, -4.0, &grazing, 0.0, f64::INFINITY), None);
        let up = Ray::new(Point3::new(0.5, -5.0, 2.0), Vec3::y(), 0.0);
        assert_eq!(plane(&normal, -4.0, &up, 0.0, f64::INFINITY), None);
    }

    #[test]
    fn a_triangle_is_met_beyond_distance_zero_from_either_side() {
        let vertices = [Point3::zeros(), Point3::x(), Point3::y()];
        let down = Ray::new(Point3::new(0.25, 0.25, 2.0), -Vec3::z(), 0.0);
        assert_eq!(
            triangle(&vertices, &down, 0.0, f64::INFINITY),
            Some((2.0, 0.25, 0.25))
        );
        let up = Ray::new(Point3::new(0.25, 0.25, -2.0), Vec3::z(), 0.0);
        assert!(triangle(&vertices, &up, 0.0, f64::INFINITY).is_some());
        // From a point on it: t = 0 is refused (theirs: t > 0).
        let on = Ray::new(Point3::new(0.25, 0.25, 0.0), Vec3::z(), 0.0);
        assert_eq!(triangle(&vertices, &on, 0.0, f64::INFINITY), None);
        // A triangle whose determinant is below f32's epsilon is refused.
        let tiny = [Point3::zeros(), Point3::x() * 1e-4, Point3::y() * 1e-4];
        assert_eq!(triangle(&tiny, &down, 0.0, f64::INFINITY), None);
    }

    #[test]
    fn the_next_origin_is_the_hit_point_rounded_to_f32() {
        let ray = Ray::new(Point3::new(0.1, 0.2, 0.3), Vec3::new(0.0, 0.6, 0.8), 0.0);
        let point = point_at(&ray, 1.0 / 3.0);
        let expected = 0.3f32 + 0.8f32 * (1.0f32 / 3.0);
        assert_eq!(point.z, f64::from(expected));
        assert_ne!(point.z, ray.at(1.0 / 3.0).z);
        assert!(point.iter().all(|&c| c as f32 as f64 == c));
    }
}
