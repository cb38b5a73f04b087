//! A bounding volume hierarchy over boxes: a parallel binned-SAH build of a
//! binary tree (`binary_tree`), collapsed (`collapse`) into 8-wide nodes of two
//! cache lines with child boxes quantised outward to 8 bits (`wide`), and
//! allocation-free traversal that tests the eight child boxes at once
//! (`ray8`), nearest child first (`traverse`; nearest hit: with a
//! shrinking `t_max`; any hit: stops at the first). Nodes live in huge pages when the tree is large
//! (`accel::huge_pages`).
//!
//! The BVH knows only boxes and their indices; callers keep the primitives and
//! answer the leaf tests through a closure, one primitive at a time or, for
//! primitives stored in leaf order, one leaf (a run of slots) at a time.

mod binary_tree;
mod binning;
mod collapse;
mod ray8;
mod traverse;
mod wide;

use super::huge_pages::HugeArray;
use crate::math::{Aabb, Ray, Vec3};
use binary_tree::{Bounds, Item, Leaves, Settings};
use wide::Node;

/// Deepest binary level the build may create (leaves are forced below it).
const MAX_DEPTH: usize = 60;
/// Leaves of a tree over single primitives: at most 4, each test costing
/// one node visit.
const SINGLE: Leaves = Leaves {
    width: 1,
    group_cost: 1.0,
    max_size: 4,
};

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

/// What a build gives before its leaves are numbered.
struct Collapsed {
    nodes: Vec<Node>,
    indices: Vec<u32>,
    depth: usize,
    bounds: Option<Aabb>,
}

fn collapsed(boxes: &[Aabb], leaves: Leaves) -> Collapsed {
    use rayon::prelude::*;
    // In parallel, in the boxes' order (an indexed collect keeps it).
    let items: Vec<Item> = boxes
        .par_iter()
        .enumerate()
        .filter(|(_, b)| b.is_valid())
        .map(|(i, b)| Item {
            bounds: Bounds::from_aabb(b),
            index: i as u32,
        })
        .collect();
    let settings = Settings {
        leaves,
        max_depth: MAX_DEPTH,
    };
    // The exact (f64) bounds, for `may_hit`: the tree's are rounded to f32.
    // (Unions are exact, so the chunking does not change the result.)
    let exact = boxes
        .par_iter()
        .filter(|b| b.is_valid())
        .fold(Aabb::empty, |acc, b| acc.union(b))
        .reduce(Aabb::empty, |a, b| a.union(&b));
    let built = binary_tree::build(items, settings);
    if built.nodes.is_empty() {
        return Collapsed {
            nodes: Vec::new(),
            indices: Vec::new(),
            depth: 0,
            bounds: None,
        };
    }
    let (nodes, depth) = collapse::collapse(&built.nodes);
    Collapsed {
        nodes,
        indices: built.items.iter().map(|item| item.index).collect(),
        depth,
        bounds: Some(exact),
    }
}

impl Bvh {
    /// Builds the tree over `boxes`; leaf callbacks receive indices into `boxes`.
    pub fn build(boxes: &[Aabb]) -> Bvh {
        let c = collapsed(boxes, SINGLE);
        Bvh {
            nodes: HugeArray::from_slice(&c.nodes),
            indices: c.indices,
            leaf_order: false,
            depth: c.depth,
            bounds: c.bounds,
        }
    }

    /// Builds the tree for a caller that stores its primitives in leaf
    /// order, in groups of `width` slots that it tests at once (a group
    /// costing `group_cost` node visits in the SAH). Every leaf starts at a multiple
    /// of `width` and its slots run on from there (a leaf holds at most
    /// `width`, or 4 for single slots, unless the depth limit forces
    /// more); returns the tree and the
    /// primitive of each slot, `u32::MAX` for the slots that pad a leaf's
    /// last group. Leaf callbacks receive slots.
    pub fn build_in_leaf_order(boxes: &[Aabb], width: usize, group_cost: f64) -> (Bvh, Vec<u32>) {
        let width = width.max(1);
        let leaves = Leaves {
            width,
            group_cost,
            max_size: width.max(SINGLE.max_size),
        };
        let mut c = collapsed(boxes, leaves);
        let slots = collapse::pad_leaves(&mut c.nodes, &c.indices, width);
        let bvh = Bvh {
            nodes: HugeArray::from_slice(&c.nodes),
            indices: (0..c.indices.len() as u32).collect(),
            leaf_order: true,
            depth: c.depth,
            bounds: c.bounds,
        };
        (bvh, slots)
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
    fn may_hit(&self, ray: &Ray, inverse: &Vec3, t_min: f64, t_max: f64) -> bool {
        let Some(b) = &self.bounds else {
            return false;
        };
        let (near, far) = b.slabs(&ray.origin, inverse, t_min, t_max);
        // Grown by a few ulps for the rounding of the slab distances, so
        // that a hit on a face or corner of the bounds is never lost.
        near <= far + far.abs() * (4.0 * f64::EPSILON)
    }

    /// Nearest-hit traversal. `leaf(index, t_max)` tests primitive `index` and
    /// returns the distance of a hit closer than `t_max`, which then becomes the
    /// new `t_max`. Returns the final `t_max` (unchanged if nothing was hit).
    #[inline]
    pub fn traverse<F>(&self, ray: &Ray, t_min: f64, t_max: f64, mut leaf: F) -> f64
    where
        F: FnMut(usize, f64) -> Option<f64>,
    {
        let leaf = |first: usize, count: usize, mut t_max: f64| {
            let mut hit = None;
            for k in first..first + count {
                if let Some(t) = leaf(self.entry(k), t_max) {
                    t_max = t_max.min(t);
                    hit = Some(t_max);
                }
            }
            hit
        };
        // Leaves over separate primitives: nothing of theirs to prefetch.
        self.traverse_leaves(ray, t_min, t_max, leaf, |_| {})
    }

    /// Any-hit traversal: true as soon as `leaf(index)` reports a hit.
    #[inline]
    pub fn any<F>(&self, ray: &Ray, t_min: f64, t_max: f64, mut leaf: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        let leaf = |first: usize, count: usize| (first..first + count).any(|k| leaf(self.entry(k)));
        self.any_leaves(ray, t_min, t_max, leaf, |_| {})
    }
}

#[cfg(test)]
mod tests;
