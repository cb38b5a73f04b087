//! A ray prepared for the `W` slab tests of a wide node in f32, made
//! conservative: every box the f64 ray enters within `(t_min, t_max)` is
//! reported as hit.
//!
//! Per axis the near plane (min for a positive direction, max for a
//! negative one) is measured from the origin rounded so that the entry
//! distance can only shrink, and the far plane from the origin rounded the
//! other way; the remaining rounding (the f32 inverse, the subtraction and
//! the product, a few units in the last place each) is covered by growing
//! the exit distance by [`SLACK`] of itself. A NaN distance (origin on a
//! plane of an axis the ray is parallel to) keeps the previous bound.

use super::wide::{Node, W, round_down, round_up};
use crate::math::Ray;

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

pub(super) struct Ray4 {
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

impl Ray4 {
    #[inline]
    pub fn new(ray: &Ray, t_min: f64) -> Ray4 {
        let mut r = Ray4 {
            negative: [false; 3],
            origin_near: [0.0; 3],
            origin_far: [0.0; 3],
            inverse: [0.0; 3],
            t_min: round_down(t_min),
        };
        for k in 0..3 {
            let inverse = 1.0 / ray.direction[k];
            let (low, high) = (round_down(ray.origin[k]), round_up(ray.origin[k]));
            r.inverse[k] = inverse as f32;
            if inverse < 0.0 {
                r.negative[k] = true;
                r.origin_near[k] = low;
                r.origin_far[k] = high;
            } else {
                r.origin_near[k] = high;
                r.origin_far[k] = low;
            }
        }
        r
    }

    /// Entry distances of the `W` children and which of them the ray
    /// enters before `t_max` (bit `i` for child `i`).
    #[inline(always)]
    pub fn hit(&self, node: &Node, t_max: f32) -> ([f32; W], u32) {
        let mut near = [self.t_min; W];
        let mut far = [t_max; W];
        for k in 0..3 {
            let flip = self.negative[k] as usize;
            let (n, f) = (&node.planes[k + 3 * flip], &node.planes[k + 3 - 3 * flip]);
            let (step, origin) = (node.step(k), node.origin[k]);
            for i in 0..W {
                // Exact (see `wide::grid`), so the plane is the f32 the
                // build chose.
                let (n, f) = (plane(n[i], step, origin), plane(f[i], step, origin));
                let a = (n - self.origin_near[k]) * self.inverse[k];
                let b = (f - self.origin_far[k]) * self.inverse[k];
                near[i] = if a > near[i] { a } else { near[i] };
                far[i] = if b < far[i] { b } else { far[i] };
            }
        }
        let mut mask = 0;
        for i in 0..W {
            mask |= ((near[i] <= far[i] + far[i].abs() * SLACK) as u32) << i;
        }
        (near, mask & node.valid as u32)
    }
}

/// The plane `q` steps above `origin`: exact (see `wide::grid`), so a fused
/// multiply-add, where the target has one, gives the same f32.
#[inline(always)]
fn plane(q: u8, step: f32, origin: f32) -> f32 {
    if cfg!(target_feature = "fma") {
        (q as f32).mul_add(step, origin)
    } else {
        q as f32 * step + origin
    }
}
