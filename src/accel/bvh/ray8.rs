//! A ray prepared for the 8 slab tests of a wide node, side by side in f32
//! (`wide`'s 8-lane vectors: AVX where the target has it), made
//! conservative: every box the f64 ray enters within `(t_min, t_max)` is
//! reported as hit.
//!
//! Per axis the near plane (min for a positive direction, max for a
//! negative one) is measured from an f32 origin on the side that makes
//! the entry distance only shrink, and the far plane from one on the other
//! side (`bracket`); the remaining rounding (the f32 inverse, the subtraction and
//! the product, a few units in the last place each) is covered by growing
//! the exit distance by [`SLACK`] of itself. A NaN distance (origin on a
//! plane of an axis the ray is parallel to) keeps the previous bound.

use super::wide::{Node, W, round_down};
use crate::math::{Ray, Vec3};
use wide::{f32x8, i16x8, i32x8, u8x16};

/// Relative growth of exit distances, 16 f32 units of roundoff.
const SLACK: f32 = 1.0 / (1u32 << 20) as f32;

/// A traversal stack entry: a node (`count == 0`) or a leaf's entries, and
/// the distance at which the ray enters its box.
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Entry {
    pub target: u32,
    pub count: u32,
    pub t: f32,
}

impl Entry {
    /// The root node, entered before anything else.
    pub const ROOT: Entry = Entry {
        target: 0,
        count: 0,
        t: f32::NEG_INFINITY,
    };
}

pub(super) struct Ray8 {
    /// Whether the ray runs towards negative values along each axis: its
    /// near plane is then the box's max (row `3 + k` of [`Node::planes`])
    /// and its far plane the min (row `k`).
    negative: [bool; 3],
    /// The origin as the near and far planes see it.
    origin_near: [f32; 3],
    origin_far: [f32; 3],
    inverse: [f32; 3],
    t_min: f32,
}

impl Ray8 {
    #[inline]
    /// The ray with `inverse` its direction's inverse (`1 / d` per axis).
    pub fn new(ray: &Ray, inverse: &Vec3, t_min: f64) -> Ray8 {
        let mut r = Ray8 {
            negative: [false; 3],
            origin_near: [0.0; 3],
            origin_far: [0.0; 3],
            inverse: [0.0; 3],
            t_min: round_down(t_min),
        };
        for (k, &inverse) in inverse.iter().enumerate() {
            let (low, high) = bracket(ray.origin[k]);
            r.inverse[k] = inverse as f32;
            r.negative[k] = inverse < 0.0;
            (r.origin_near[k], r.origin_far[k]) = if r.negative[k] {
                (low, high)
            } else {
                (high, low)
            };
        }
        r
    }

    /// Entry distances of the `W` children and which of them the ray
    /// enters before `t_max` (bit `i` for child `i`).
    #[inline(always)]
    pub fn hit(&self, node: &Node, t_max: f32) -> ([f32; W], u32) {
        let mut near = f32x8::splat(self.t_min);
        let mut far = f32x8::splat(t_max);
        for k in 0..3 {
            let flip = self.negative[k] as usize;
            let (n, f) = (&node.planes[k + 3 * flip], &node.planes[k + 3 - 3 * flip]);
            let (step, origin) = (f32x8::splat(node.step(k)), f32x8::splat(node.origin[k]));
            // Exact (see `wide::grid`), so each plane is the f32 the build
            // chose, fused or not.
            let n = lanes(n).mul_add(step, origin);
            let f = lanes(f).mul_add(step, origin);
            let a = (n - f32x8::splat(self.origin_near[k])) * f32x8::splat(self.inverse[k]);
            let b = (f - f32x8::splat(self.origin_far[k])) * f32x8::splat(self.inverse[k]);
            // A NaN distance keeps the bound (the comparison is false).
            near = a.simd_gt(near).select(a, near);
            far = b.simd_lt(far).select(b, far);
        }
        let hit = near.simd_le(far + far.abs() * f32x8::splat(SLACK));
        (near.to_array(), hit.to_bitmask() & node.valid as u32)
    }
}

/// Eight grid coordinates as f32 lanes.
#[inline(always)]
fn lanes(q: &[u8; W]) -> f32x8 {
    let mut bytes = [0u8; 16];
    bytes[..W].copy_from_slice(q);
    f32x8::from_i32x8(i32x8::from_i16x8(i16x8::from_u8x16_low(u8x16::new(bytes))))
}

/// An f32 below and one above `v`, without branches: the nearest f32 moved
/// by at least one unit in the last place (and by the smallest subnormal,
/// for zero). Within two units of `v`, which only loosens the slab test a
/// little; an origin beyond the f32 range gives NaN or an infinity, whose
/// distances are NaN or infinite and bound nothing.
#[inline(always)]
fn bracket(v: f64) -> (f32, f32) {
    let f = v as f32;
    let step = f.abs() * f32::EPSILON + f32::from_bits(1);
    (f - step, f + step)
}
