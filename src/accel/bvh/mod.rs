//! A bounding volume hierarchy over boxes: a parallel binned-SAH build of a
//! binary tree (`build`), collapsed into 4-wide nodes with f32 boxes rounded
//! outward (`wide`), and allocation-free traversal that tests four child
//! boxes at once, nearest child first (nearest hit: with a shrinking
//! `t_max`; any hit: stops at the first). Nodes live in huge pages when the
//! tree is large (`accel::huge_pages`).
//!
//! The BVH knows only boxes and their indices; callers keep the primitives and
//! answer the leaf tests through a closure.

mod build;
mod ray4;
mod wide;

use super::huge_pages::HugeArray;
use crate::math::{Aabb, Ray, inverse_direction};
use build::{Bounds, Item};
use ray4::{Entry, Ray4};
use wide::{Node, W as WIDTH};

/// Deepest binary level the build may create (leaves are forced below it).
const MAX_DEPTH: usize = 60;
/// Traversal stack sizes: a node pushes at most `WIDTH` entries and pops
/// one, so a tree of wide depth `d` needs at most `(WIDTH - 1) d + WIDTH`.
/// A traversal zeroes its whole stack, so shallow trees use a short one.
const SMALL_STACK: usize = 16;
const MEDIUM_STACK: usize = 64;
const STACK_SIZE: usize = (WIDTH - 1) * MAX_DEPTH + WIDTH;

/// A flattened BVH. Primitives with invalid boxes (empty, NaN) are left out and
/// therefore never reported.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: HugeArray<Node>,
    indices: Vec<u32>,
    /// Whether `indices[k] == k` (leaf order): leaf tests then skip the
    /// lookup, one dependent memory access less per leaf.
    leaf_order: bool,
    /// Levels of wide nodes below the root.
    depth: usize,
    /// Exact bounds of everything in the tree.
    bounds: Option<Aabb>,
}

impl Bvh {
    /// Builds the tree over `boxes`; leaf callbacks receive indices into `boxes`.
    pub fn build(boxes: &[Aabb]) -> Bvh {
        let items: Vec<Item> = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.is_valid())
            .map(|(i, b)| Item {
                bounds: Bounds::from_aabb(b),
                index: i as u32,
            })
            .collect();
        let built = build::build(items, MAX_DEPTH);
        if built.nodes.is_empty() {
            return Bvh::default();
        }
        let (nodes, depth) = wide::collapse(&built.nodes);
        Bvh {
            nodes: HugeArray::from_slice(&nodes),
            indices: built.items.iter().map(|item| item.index).collect(),
            leaf_order: false,
            depth,
            bounds: Some(built.nodes[0].bounds.to_aabb()),
        }
    }

    /// The same tree with leaf entries numbered in leaf order (entry `k` is
    /// reported as `k`), and the original index of each: a caller that
    /// stores its primitives in this order reads each leaf's primitives from
    /// consecutive memory.
    pub fn into_leaf_order(mut self) -> (Bvh, Vec<u32>) {
        let order = std::mem::take(&mut self.indices);
        self.indices = (0..order.len() as u32).collect();
        self.leaf_order = true;
        (self, order)
    }

    /// The primitive of leaf entry `k`.
    #[inline(always)]
    fn entry(&self, k: usize) -> usize {
        if self.leaf_order {
            k
        } else {
            self.indices[k] as usize
        }
    }

    /// Number of primitives in the tree.
    pub fn len(&self) -> usize {
        self.indices.len()
    }

    pub fn is_empty(&self) -> bool {
        self.indices.is_empty()
    }

    /// Bounds of everything in the tree (empty box for an empty tree).
    pub fn bounds(&self) -> Aabb {
        self.bounds.unwrap_or_else(Aabb::empty)
    }

    /// Whether the ray may enter the exact (f64) bounds of the tree: most rays
    /// of a scene miss most meshes, and this test is cheaper than preparing
    /// the f32 ray and its stack.
    #[inline]
    fn may_hit(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        let Some(b) = &self.bounds else {
            return false;
        };
        let (near, far) = b.slabs(
            &ray.origin,
            &inverse_direction(&ray.direction),
            t_min,
            t_max,
        );
        // Grown by a few ulps for the rounding of the slab distances, so
        // that a hit on a face or corner of the bounds is never lost.
        near <= far + far.abs() * (4.0 * f64::EPSILON)
    }

    /// Nearest-hit traversal. `leaf(index, t_max)` tests primitive `index` and
    /// returns the distance of a hit closer than `t_max`, which then becomes the
    /// new `t_max`. Returns the final `t_max` (unchanged if nothing was hit).
    #[inline]
    pub fn traverse<F>(&self, ray: &Ray, t_min: f64, t_max: f64, leaf: F) -> f64
    where
        F: FnMut(usize, f64) -> Option<f64>,
    {
        if Self::stack_needed(self.depth) <= SMALL_STACK {
            self.traverse_with::<SMALL_STACK, F>(ray, t_min, t_max, leaf)
        } else if Self::stack_needed(self.depth) <= MEDIUM_STACK {
            self.traverse_with::<MEDIUM_STACK, F>(ray, t_min, t_max, leaf)
        } else {
            self.traverse_with::<STACK_SIZE, F>(ray, t_min, t_max, leaf)
        }
    }

    /// Stack entries a traversal of a tree of wide depth `depth` may need.
    fn stack_needed(depth: usize) -> usize {
        (WIDTH - 1) * depth + WIDTH
    }

    /// [`Bvh::traverse`] with a stack of [`Bvh::stack_needed`] entries.
    #[inline]
    fn traverse_with<const N: usize, F>(
        &self,
        ray: &Ray,
        t_min: f64,
        mut t_max: f64,
        mut leaf: F,
    ) -> f64
    where
        F: FnMut(usize, f64) -> Option<f64>,
    {
        if !self.may_hit(ray, t_min, t_max) {
            return t_max;
        }
        let r = Ray4::new(ray, t_min);
        let mut limit = wide::round_up(t_max);
        let mut stack = [Entry::default(); N];
        stack[0] = Entry {
            target: 0,
            count: 0,
            t: f32::NEG_INFINITY,
        };
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let entry = stack[top];
            if entry.t > limit {
                continue;
            }
            if entry.count > 0 {
                let start = entry.target as usize;
                for k in start..start + entry.count as usize {
                    if let Some(t) = leaf(self.entry(k), t_max) {
                        t_max = t_max.min(t);
                        limit = wide::round_up(t_max);
                    }
                }
                continue;
            }
            let node = &self.nodes[entry.target as usize];
            let (near, hit) = r.hit(node, limit);
            // Push the hit children farthest first, so the nearest is next.
            let first = top;
            for i in 0..WIDTH {
                if hit[i] {
                    let mut k = top;
                    while k > first && stack[k - 1].t < near[i] {
                        stack[k] = stack[k - 1];
                        k -= 1;
                    }
                    stack[k] = Entry {
                        target: node.child[i],
                        count: node.count[i],
                        t: near[i],
                    };
                    top += 1;
                }
            }
        }
        t_max
    }

    /// Any-hit traversal: true as soon as `leaf(index)` reports a hit.
    #[inline]
    pub fn any<F>(&self, ray: &Ray, t_min: f64, t_max: f64, leaf: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        if Self::stack_needed(self.depth) <= SMALL_STACK {
            self.any_with::<SMALL_STACK, F>(ray, t_min, t_max, leaf)
        } else if Self::stack_needed(self.depth) <= MEDIUM_STACK {
            self.any_with::<MEDIUM_STACK, F>(ray, t_min, t_max, leaf)
        } else {
            self.any_with::<STACK_SIZE, F>(ray, t_min, t_max, leaf)
        }
    }

    /// [`Bvh::any`] with a stack of [`Bvh::stack_needed`] entries.
    #[inline]
    fn any_with<const N: usize, F>(&self, ray: &Ray, t_min: f64, t_max: f64, mut leaf: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        if !self.may_hit(ray, t_min, t_max) {
            return false;
        }
        let r = Ray4::new(ray, t_min);
        let limit = wide::round_up(t_max);
        let mut stack = [Entry::default(); N];
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let entry = stack[top];
            if entry.count > 0 {
                let start = entry.target as usize;
                for k in start..start + entry.count as usize {
                    if leaf(self.entry(k)) {
                        return true;
                    }
                }
                continue;
            }
            let node = &self.nodes[entry.target as usize];
            let (near, hit) = r.hit(node, limit);
            // Nearest child first, as for the nearest hit: the first
            // surface along the ray is met soonest.
            let first = top;
            for i in 0..WIDTH {
                if hit[i] {
                    let mut k = top;
                    while k > first && stack[k - 1].t < near[i] {
                        stack[k] = stack[k - 1];
                        k -= 1;
                    }
                    stack[k] = Entry {
                        target: node.child[i],
                        count: node.count[i],
                        t: near[i],
                    };
                    top += 1;
                }
            }
        }
        false
    }
}

#[cfg(test)]
mod tests;
