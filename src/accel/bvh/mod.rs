//! A bounding volume hierarchy over boxes: binned-SAH build, flat nodes, and
//! allocation-free traversal (nearest hit with a shrinking `t_max`, and any hit).
//!
//! The BVH knows only boxes and their indices; callers keep the primitives and
//! answer the leaf tests through a closure.

use crate::math::{Aabb, Ray, inverse_direction};

/// Size of the largest traversal stack. The build never makes a tree deeper than
/// this, so traversal cannot overflow it.
const STACK_SIZE: usize = 64;
/// Stack sizes for shallower trees: a traversal zeroes its whole stack, which
/// for the 64 entries of a deep tree costs as much as a few box tests.
const SMALL_STACK: usize = 8;
const MEDIUM_STACK: usize = 32;
/// Deepest level the build may create (leaves are forced below it).
const MAX_DEPTH: usize = STACK_SIZE - 4;
/// Number of SAH bins per axis.
const BIN_COUNT: usize = 16;
/// Leaves at most this large are accepted when the SAH says so.
const MAX_LEAF_SIZE: usize = 4;
/// Cost of visiting an interior node relative to one primitive test.
const TRAVERSAL_COST: f64 = 1.0;

#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Aabb,
    /// Interior: index of the second child (the first child follows the node).
    /// Leaf: index of the first entry in `Bvh::indices`.
    offset: u32,
    /// Number of primitives; 0 for interior nodes.
    count: u32,
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

struct BuildItem {
    bounds: Aabb,
    centroid: [f64; 3],
    index: u32,
}

impl Bvh {
    /// Builds the tree over `boxes`; leaf callbacks receive indices into `boxes`.
    pub fn build(boxes: &[Aabb]) -> Bvh {
        let mut items: Vec<BuildItem> = boxes
            .iter()
            .enumerate()
            .filter(|(_, b)| b.is_valid())
            .map(|(i, b)| {
                let c = b.centroid();
                BuildItem {
                    bounds: *b,
                    centroid: [c.x, c.y, c.z],
                    index: i as u32,
                }
            })
            .collect();
        let mut bvh = Bvh {
            nodes: Vec::with_capacity(2 * items.len().max(1)),
            indices: Vec::with_capacity(items.len()),
            depth: 0,
        };
        if !items.is_empty() {
            bvh.build_node(&mut items, 0);
        }
        bvh
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

    fn build_node(&mut self, items: &mut [BuildItem], depth: usize) -> usize {
        let bounds = items
            .iter()
            .fold(Aabb::empty(), |acc, item| acc.union(&item.bounds));
        let node_index = self.nodes.len();
        self.nodes.push(Node {
            bounds,
            offset: 0,
            count: 0,
        });
        let split = if items.len() <= 1 || depth >= MAX_DEPTH {
            None
        } else {
            choose_split(items, &bounds)
        };
        let Some(mid) = split else {
            self.depth = self.depth.max(depth);
            self.make_leaf(node_index, items);
            return node_index;
        };
        let (left, right) = items.split_at_mut(mid);
        self.build_node(left, depth + 1);
        let second = self.build_node(right, depth + 1);
        self.nodes[node_index].offset = second as u32;
        node_index
    }

    fn make_leaf(&mut self, node_index: usize, items: &[BuildItem]) {
        self.nodes[node_index].offset = self.indices.len() as u32;
        self.nodes[node_index].count = items.len() as u32;
        self.indices.extend(items.iter().map(|item| item.index));
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

/// Chooses a binned-SAH split and partitions `items`; returns the split position,
/// or `None` when a leaf is cheaper.
fn choose_split(items: &mut [BuildItem], bounds: &Aabb) -> Option<usize> {
    let count = items.len();
    let mut centroid_bounds = Aabb::empty();
    for item in items.iter() {
        centroid_bounds = centroid_bounds.include_point(item.centroid.into());
    }
    let extent = centroid_bounds.extent();
    let parent_area = bounds.surface_area().max(f64::MIN_POSITIVE);
    let mut best: Option<(usize, usize, f64)> = None; // (axis, bin boundary, cost)
    for axis in 0..3 {
        if extent[axis] <= 0.0 || !extent[axis].is_finite() {
            continue;
        }
        let scale = BIN_COUNT as f64 / extent[axis];
        let bin_of = |c: f64| -> usize {
            (((c - centroid_bounds.min[axis]) * scale) as usize).min(BIN_COUNT - 1)
        };
        let mut bin_bounds = [Aabb::empty(); BIN_COUNT];
        let mut bin_counts = [0usize; BIN_COUNT];
        for item in items.iter() {
            let b = bin_of(item.centroid[axis]);
            bin_bounds[b] = bin_bounds[b].union(&item.bounds);
            bin_counts[b] += 1;
        }
        // Sweep from the right to get suffix areas and counts.
        let mut right_area = [0.0; BIN_COUNT];
        let mut right_count = [0usize; BIN_COUNT];
        let mut acc = Aabb::empty();
        let mut n = 0;
        for b in (1..BIN_COUNT).rev() {
            acc = acc.union(&bin_bounds[b]);
            n += bin_counts[b];
            right_area[b] = acc.surface_area();
            right_count[b] = n;
        }
        let mut acc = Aabb::empty();
        let mut n = 0;
        for b in 1..BIN_COUNT {
            acc = acc.union(&bin_bounds[b - 1]);
            n += bin_counts[b - 1];
            if n == 0 || right_count[b] == 0 {
                continue;
            }
            let cost = TRAVERSAL_COST
                + (acc.surface_area() * n as f64 + right_area[b] * right_count[b] as f64)
                    / parent_area;
            if best.is_none_or(|(_, _, c)| cost < c) {
                best = Some((axis, b, cost));
            }
        }
    }
    match best {
        Some((axis, boundary, cost)) => {
            if count <= MAX_LEAF_SIZE && cost >= count as f64 {
                return None;
            }
            let scale = BIN_COUNT as f64 / extent[axis];
            let min = centroid_bounds.min[axis];
            let mid = partition(items, |item| {
                ((((item.centroid[axis] - min) * scale) as usize).min(BIN_COUNT - 1)) < boundary
            });
            (mid > 0 && mid < count).then_some(mid)
        }
        None => {
            // All centroids coincide: split by count so leaves stay small.
            (count > MAX_LEAF_SIZE).then_some(count / 2)
        }
    }
}

/// Moves the items satisfying `left` to the front; returns how many there are.
fn partition(items: &mut [BuildItem], left: impl Fn(&BuildItem) -> bool) -> usize {
    let mut first = 0;
    for i in 0..items.len() {
        if left(&items[i]) {
            items.swap(first, i);
            first += 1;
        }
    }
    first
}

#[cfg(test)]
mod tests;
