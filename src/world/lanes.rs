//! The plain shapes' tests four at a time: untransformed planes and robust
//! spheres packed in `f64x4` lanes, tested without a branch per shape.
//!
//! Each lane computes exactly what the shape's own scalar test computes,
//! operation by operation (no fused multiply-add), so distances are the same
//! to the bit. A group is tested against one limit, where the scalar loop
//! lowered it shape by shape; taking, in shape order, the first strictly
//! smallest distance below the limit gives the same nearest hit (a root the
//! lower limit would have refused is never the smallest).

use wide::f64x4;

use crate::geometry::{Plane, Sphere};
use crate::math::{Ray, Vec3};

/// Shapes per group.
pub const LANES: usize = 4;

/// A ray's components in lanes, shared by every group it is tested against.
pub struct RayLanes {
    origin: [f64x4; 3],
    direction: [f64x4; 3],
    time: f64x4,
    /// `|direction|^2` and its inverse.
    a: f64x4,
    inverse_a: f64x4,
}

impl RayLanes {
    #[inline]
    pub fn new(ray: &Ray) -> RayLanes {
        let a = ray.direction.norm_squared();
        let splat = |v: f64| f64x4::splat(v);
        RayLanes {
            origin: [
                splat(ray.origin.x),
                splat(ray.origin.y),
                splat(ray.origin.z),
            ],
            direction: [
                splat(ray.direction.x),
                splat(ray.direction.y),
                splat(ray.direction.z),
            ],
            time: splat(ray.time),
            a: splat(a),
            inverse_a: splat(1.0 / a),
        }
    }
}

/// `x . y` as the scalar `Vec3::dot` adds it: `(x0 y0 + x1 y1) + x2 y2`.
#[inline(always)]
fn dot(x: &[f64x4; 3], y: &[f64x4; 3]) -> f64x4 {
    x[0] * y[0] + x[1] * y[1] + x[2] * y[2]
}

/// The lane holding the first strictly smallest distance among the lanes
/// set in `valid` (bit `i` for lane `i`).
#[inline]
fn first_smallest(t: f64x4, valid: u32, limit: f64) -> Option<(usize, f64)> {
    let t = t.to_array();
    let mut best: Option<(usize, f64)> = None;
    let mut bits = valid;
    while bits != 0 {
        let lane = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        if t[lane] < best.map_or(limit, |(_, b)| b) {
            best = Some((lane, t[lane]));
        }
    }
    best
}

/// One value of each of `shapes` per lane, 0 in the unused lanes.
fn pack<S>(shapes: &[(S, u32)], value: impl Fn(&S) -> f64) -> f64x4 {
    f64x4::new(std::array::from_fn(|i| {
        shapes.get(i).map_or(0.0, |(shape, _)| value(shape))
    }))
}

/// A vector of each of `shapes` in three lane sets, one per coordinate.
fn pack_vector<S>(shapes: &[(S, u32)], vector: impl Fn(&S) -> Vec3) -> [f64x4; 3] {
    std::array::from_fn(|axis| pack(shapes, |shape| vector(shape)[axis]))
}

/// All ones in the lanes that hold one of `shapes`.
fn used_lanes<S>(shapes: &[(S, u32)]) -> f64x4 {
    f64x4::new(std::array::from_fn(|i| {
        if i < shapes.len() { ALL_ONES } else { 0.0 }
    }))
}

/// The primitive indices of `shapes` per lane.
fn lane_indices<S>(shapes: &[(S, u32)]) -> [u32; LANES] {
    std::array::from_fn(|i| shapes.get(i).map_or(u32::MAX, |(_, index)| *index))
}

/// A lane mask's true value.
const ALL_ONES: f64 = f64::from_bits(u64::MAX);

/// A group of shapes in lanes: the distance each lane's shape returns and
/// the mask of the lanes that return one.
pub trait Lanes {
    fn distances(&self, ray: &RayLanes, t_min: f64, t_max: f64) -> (f64x4, f64x4);

    fn indices(&self) -> &[u32; LANES];

    /// The nearest hit below `limit`: (primitive index, distance).
    #[inline]
    fn nearest(&self, ray: &RayLanes, t_min: f64, limit: f64) -> Option<(u32, f64)> {
        let (t, valid) = self.distances(ray, t_min, limit);
        let (lane, t) = first_smallest(t, valid.to_bitmask(), limit)?;
        Some((self.indices()[lane], t))
    }

    /// Whether a shape of the group lies on the ray within `(t_min, t_max)`.
    #[inline]
    fn any(&self, ray: &RayLanes, t_min: f64, t_max: f64) -> bool {
        self.distances(ray, t_min, t_max).1.any()
    }
}

/// Up to four planes; unused lanes never hit.
#[derive(Clone, Debug)]
pub struct PlaneLanes {
    normal: [f64x4; 3],
    offset: f64x4,
    /// All ones in the lanes of one-sided planes.
    one_sided: f64x4,
    /// All ones in the lanes of planes hit at `t_min` itself too.
    accepts_zero: f64x4,
    /// All ones in the lanes that hold a plane.
    used: f64x4,
    indices: [u32; LANES],
}

impl PlaneLanes {
    /// A group of `planes` (at most [`LANES`]) with their primitive indices.
    pub fn new(planes: &[(Plane, u32)]) -> PlaneLanes {
        debug_assert!(planes.len() <= LANES);
        PlaneLanes {
            normal: pack_vector(planes, |p| p.normal),
            offset: pack(planes, |p| p.offset),
            one_sided: pack(planes, |p| if p.one_sided { ALL_ONES } else { 0.0 }),
            accepts_zero: pack(planes, |p| if p.accepts_zero { ALL_ONES } else { 0.0 }),
            used: used_lanes(planes),
            indices: lane_indices(planes),
        }
    }
}

impl Lanes for PlaneLanes {
    /// Distances of the lanes' hits and the mask of those in `(t_min, t_max)`
    /// ([`Plane::intersect`]'s test).
    #[inline(always)]
    fn distances(&self, ray: &RayLanes, t_min: f64, t_max: f64) -> (f64x4, f64x4) {
        let denominator = dot(&self.normal, &ray.direction);
        let zero = f64x4::ZERO;
        let refused = denominator.simd_eq(zero) | (self.one_sided & denominator.simd_gt(zero));
        let t = (self.offset - dot(&self.normal, &ray.origin)) / denominator;
        let start = f64x4::splat(t_min);
        let beyond_start = t.simd_gt(start) | (self.accepts_zero & t.simd_eq(start));
        let inside = beyond_start & t.simd_lt(f64x4::splat(t_max));
        (t, refused.bitselect(f64x4::ZERO, inside & self.used))
    }

    fn indices(&self) -> &[u32; LANES] {
        &self.indices
    }
}

/// Up to four spheres of the robust test; unused lanes never hit.
#[derive(Clone, Debug)]
pub struct SphereLanes {
    center: [f64x4; 3],
    motion: [f64x4; 3],
    radius: f64x4,
    used: f64x4,
    indices: [u32; LANES],
}

impl SphereLanes {
    /// A group of `spheres` (at most [`LANES`]) with their primitive indices.
    pub fn new(spheres: &[(Sphere, u32)]) -> SphereLanes {
        debug_assert!(spheres.len() <= LANES);
        SphereLanes {
            center: pack_vector(spheres, |s| s.center),
            motion: pack_vector(spheres, |s| s.motion),
            radius: pack(spheres, |s| s.radius),
            used: used_lanes(spheres),
            indices: lane_indices(spheres),
        }
    }
}

impl Lanes for SphereLanes {
    /// The distance each lane's sphere returns for `(t_min, t_max)` and the
    /// mask of lanes that return one (the robust quadratic of
    /// `Sphere::intersect`, with its early exit for spheres behind the ray).
    #[inline(always)]
    fn distances(&self, ray: &RayLanes, t_min: f64, t_max: f64) -> (f64x4, f64x4) {
        let zero = f64x4::ZERO;
        let center = [
            self.center[0] + self.motion[0] * ray.time,
            self.center[1] + self.motion[1] * ray.time,
            self.center[2] + self.motion[2] * ray.time,
        ];
        let f = [
            ray.origin[0] - center[0],
            ray.origin[1] - center[1],
            ray.origin[2] - center[2],
        ];
        let d = &ray.direction;
        let b = -dot(&f, d);
        let radius2 = self.radius * self.radius;
        let c = dot(&f, &f) - radius2;
        // Origin outside and moving away: both roots negative.
        let behind = if t_min >= 0.0 {
            c.simd_gt(zero) & b.simd_le(zero)
        } else {
            zero
        };
        let scale = b * ray.inverse_a;
        let perpendicular = [
            f[0] + d[0] * scale,
            f[1] + d[1] * scale,
            f[2] + d[2] * scale,
        ];
        let discriminant = ray.a * (radius2 - dot(&perpendicular, &perpendicular));
        // False for NaN (a zero direction) as for negative values.
        let real = discriminant.simd_ge(zero);
        let q = b + discriminant.sqrt().flip_signs(b);
        let q_zero = q.simd_eq(zero);
        let t0 = q_zero.bitselect(zero, c / q);
        let t1 = q_zero.bitselect(zero, q * ray.inverse_a);
        let swap = t0.simd_gt(t1);
        let (near, far) = (swap.bitselect(t1, t0), swap.bitselect(t0, t1));
        let (low, high) = (f64x4::splat(t_min), f64x4::splat(t_max));
        let near_in = near.simd_gt(low) & near.simd_lt(high);
        let far_in = far.simd_gt(low) & far.simd_lt(high);
        let t = near_in.bitselect(near, far);
        (
            t,
            behind.bitselect(zero, (near_in | far_in) & real & self.used),
        )
    }

    fn indices(&self) -> &[u32; LANES] {
        &self.indices
    }
}

/// Packs `shapes` into groups of [`LANES`].
pub fn groups<S, G>(shapes: &[(S, u32)], group: impl Fn(&[(S, u32)]) -> G) -> Vec<G> {
    shapes.chunks(LANES).map(group).collect()
}
