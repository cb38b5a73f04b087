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

pub(super) struct Ray4 {
    /// Plane row in [`Node::planes`] of the near and far plane of each axis.
    near: [usize; 3],
    far: [usize; 3],
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
            near: [0, 1, 2],
            far: [3, 4, 5],
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
                r.near[k] = 3 + k;
                r.far[k] = k;
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
    /// enters before `t_max`.
    #[inline(always)]
    pub fn hit(&self, node: &Node, t_max: f32) -> ([f32; W], [bool; W]) {
        let mut near = [self.t_min; W];
        let mut far = [t_max; W];
        for k in 0..3 {
            let (n, f) = (&node.planes[self.near[k]], &node.planes[self.far[k]]);
            for i in 0..W {
                let a = (n[i] - self.origin_near[k]) * self.inverse[k];
                let b = (f[i] - self.origin_far[k]) * self.inverse[k];
                near[i] = if a > near[i] { a } else { near[i] };
                far[i] = if b < far[i] { b } else { far[i] };
            }
        }
        let hit = std::array::from_fn(|i| near[i] <= far[i] + far[i].abs() * SLACK);
        (near, hit)
    }
}
