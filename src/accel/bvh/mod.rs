//! A bounding volume hierarchy over boxes: binned-SAH build, flat nodes, and
//! allocation-free traversal (nearest hit with a shrinking `t_max`, and any hit).
//!
//! The BVH knows only boxes and their indices; callers keep the primitives and
//! answer the leaf tests through a closure.

mod build;

use crate::math::{Aabb, Ray, inverse_direction};
use build::{BinaryNode, Bounds, Item};

/// Size of the largest traversal stack. The build never makes a tree deeper than
/// this, so traversal cannot overflow it.
const STACK_SIZE: usize = 64;
/// Stack sizes for shallower trees: a traversal zeroes its whole stack, which
/// for the 64 entries of a deep tree costs as much as a few box tests.
const SMALL_STACK: usize = 8;
const MEDIUM_STACK: usize = 32;
/// Deepest level the build may create (leaves are forced below it).
const MAX_DEPTH: usize = STACK_SIZE - 4;

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Interior: index of the second child (the first child follows the node).
    /// Leaf: index of the first entry in `Bvh::indices`.
    offset: u32,
    /// Number of primitives; 0 for interior nodes.
    count: u32,
}

/// Copies the subtree at `slot` of the built tree to `nodes` in depth-first
/// order, without the gaps of the build.
fn compact(built: &[BinaryNode], slot: usize, nodes: &mut Vec<Node>) {
    let node = built[slot];
    let index = nodes.len();
    nodes.push(Node {
        bounds: node.bounds.to_aabb(),
        offset: node.offset,
        count: node.count,
    });
    if node.count == 0 {
        compact(built, slot + 1, nodes);
        nodes[index].offset = nodes.len() as u32;
        compact(built, node.offset as usize, nodes);
    }
}

/// A flattened BVH. Primitives with invalid boxes (empty, NaN) are left out and
/// therefore never reported.
#[derive(Clone, Debug, Default)]
pub struct Bvh {
    nodes: Vec<Node>,
    indices: Vec<u32>,
    /// Levels below the root of the deepest leaf: a traversal stack of
    /// `depth + 1` entries cannot overflow.
    depth: usize,
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
        let mut nodes = Vec::with_capacity(built.nodes.len());
        if !built.nodes.is_empty() {
            compact(&built.nodes, 0, &mut nodes);
        }
        Bvh {
            nodes,
            indices: built.items.iter().map(|item| item.index).collect(),
            depth: built.depth,
        }
    }

    /// The same tree with leaf entries numbered in leaf order (entry `k` is
    /// reported as `k`), and the original index of each: a caller that
    /// stores its primitives in this order reads each leaf's primitives from
    /// consecutive memory.
    pub fn into_leaf_order(mut self) -> (Bvh, Vec<u32>) {
        let order = std::mem::take(&mut self.indices);
        self.indices = (0..order.len() as u32).collect();
        (self, order)
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
        self.nodes.first().map_or_else(Aabb::empty, |n| n.bounds)
    }

    /// Nearest-hit traversal. `leaf(index, t_max)` tests primitive `index` and
    /// returns the distance of a hit closer than `t_max`, which then becomes the
    /// new `t_max`. Returns the final `t_max` (unchanged if nothing was hit).
    #[inline]
    pub fn traverse<F>(&self, ray: &Ray, t_min: f64, t_max: f64, leaf: F) -> f64
    where
        F: FnMut(usize, f64) -> Option<f64>,
    {
        if self.depth < SMALL_STACK {
            self.traverse_with::<SMALL_STACK, F>(ray, t_min, t_max, leaf)
        } else if self.depth < MEDIUM_STACK {
            self.traverse_with::<MEDIUM_STACK, F>(ray, t_min, t_max, leaf)
        } else {
            self.traverse_with::<STACK_SIZE, F>(ray, t_min, t_max, leaf)
        }
    }

    /// [`Bvh::traverse`] with a stack of `N > depth` entries.
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
        if self.nodes.is_empty() {
            return t_max;
        }
        let inverse = inverse_direction(&ray.direction);
        let origin = ray.origin;
        if self.nodes[0]
            .bounds
            .hit_distance(&origin, &inverse, t_min, t_max)
            .is_none()
        {
            return t_max;
        }
        let mut stack = [(0u32, 0.0f64); N];
        let mut top = 0usize;
        let mut current = 0usize;
        loop {
            let node = &self.nodes[current];
            if node.count > 0 {
                let start = node.offset as usize;
                for &index in &self.indices[start..start + node.count as usize] {
                    if let Some(t) = leaf(index as usize, t_max) {
                        t_max = t_max.min(t);
                    }
                }
            } else {
                let first = current + 1;
                let second = node.offset as usize;
                let hit_first = self.nodes[first]
                    .bounds
                    .hit_distance(&origin, &inverse, t_min, t_max);
                let hit_second = self.nodes[second]
                    .bounds
                    .hit_distance(&origin, &inverse, t_min, t_max);
                match (hit_first, hit_second) {
                    (Some(a), Some(b)) => {
                        let (near, far, far_t) = if a <= b {
                            (first, second, b)
                        } else {
                            (second, first, a)
                        };
                        stack[top] = (far as u32, far_t);
                        top += 1;
                        current = near;
                        continue;
                    }
                    (Some(_), None) => {
                        current = first;
                        continue;
                    }
                    (None, Some(_)) => {
                        current = second;
                        continue;
                    }
                    (None, None) => {}
                }
            }
            // Pop the next node that may still hold something nearer than t_max.
            loop {
                if top == 0 {
                    return t_max;
                }
                top -= 1;
                let (index, entry) = stack[top];
                if entry <= t_max {
                    current = index as usize;
                    break;
                }
            }
        }
    }

    /// Any-hit traversal: true as soon as `leaf(index)` reports a hit.
    #[inline]
    pub fn any<F>(&self, ray: &Ray, t_min: f64, t_max: f64, leaf: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        // Pushing both children of each node on a path keeps at most
        // `depth + 1` entries.
        if self.depth < SMALL_STACK {
            self.any_with::<SMALL_STACK, F>(ray, t_min, t_max, leaf)
        } else if self.depth < MEDIUM_STACK {
            self.any_with::<MEDIUM_STACK, F>(ray, t_min, t_max, leaf)
        } else {
            self.any_with::<STACK_SIZE, F>(ray, t_min, t_max, leaf)
        }
    }

    /// [`Bvh::any`] with a stack of `N > depth` entries.
    #[inline]
    fn any_with<const N: usize, F>(&self, ray: &Ray, t_min: f64, t_max: f64, mut leaf: F) -> bool
    where
        F: FnMut(usize) -> bool,
    {
        if self.nodes.is_empty() {
            return false;
        }
        let inverse = inverse_direction(&ray.direction);
        let origin = ray.origin;
        let mut stack = [0u32; N];
        let mut top = 1usize;
        while top > 0 {
            top -= 1;
            let current = stack[top] as usize;
            let node = &self.nodes[current];
            if node
                .bounds
                .hit_distance(&origin, &inverse, t_min, t_max)
                .is_none()
            {
                continue;
            }
            if node.count > 0 {
                let start = node.offset as usize;
                for &index in &self.indices[start..start + node.count as usize] {
                    if leaf(index as usize) {
                        return true;
                    }
                }
            } else {
                stack[top] = node.offset;
                stack[top + 1] = current as u32 + 1;
                top += 2;
            }
        }
        false
    }
}

#[cfg(test)]
mod tests;
