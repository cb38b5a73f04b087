//! Binned-SAH build of the binary tree, in parallel.
//!
//! Each node is binned once on all three axes (box and centroid bounds per
//! bin), so the children's bounds come from the bins and never from another
//! pass over the items. Subtrees above [`PARALLEL_ITEMS`] are built with
//! `rayon::join` and large nodes are binned in parallel chunks; the bins
//! merge exactly (unions and counts), and every subtree writes into its own
//! range of the node array (a subtree over `n` items owns `2n - 1` slots:
//! the node, then its first child's range, then its second's), so the tree is
//! the same for any number of threads. Unused slots stay as gaps.
//!
//! Items and nodes hold f32 boxes rounded outward (28 and 32 bytes, were
//! 56): the passes over the items are bound by memory, and the wide nodes
//! keep f32 planes anyway.

use super::binning::{BIN_COUNT, Binning, Bins};
use super::wide::{round_down, round_up};
use crate::math::Aabb;

/// Cost of visiting an interior node, the unit of [`Leaves::group_cost`].
const TRAVERSAL_COST: f64 = 1.0;
/// Subtrees over more items than this build their children in parallel.
const PARALLEL_ITEMS: usize = 4096;

/// A node of the binary tree.
#[derive(Clone, Copy, Debug)]
pub(super) struct BinaryNode {
    pub bounds: Bounds,
    /// Interior: slot of the second child (the first child follows the node).
    /// Leaf: index of the first item.
    pub offset: u32,
    /// Number of items; 0 for interior nodes.
    pub count: u32,
}

/// A box as the build handles it: the f64 box rounded outward to f32
/// planes, which halves the memory that the passes over the items read
/// and write (the build is bound by it; the wide nodes keep f32 planes
/// anyway), in plain arrays so that unions compile to packed min/max.
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    pub min: [f32; 3],
    pub max: [f32; 3],
}

impl Bounds {
    pub const EMPTY: Bounds = Bounds {
        min: [f32::INFINITY; 3],
        max: [f32::NEG_INFINITY; 3],
    };

    /// The smallest f32 box that contains `b` (beyond the f32 range, an
    /// infinite plane).
    pub fn from_aabb(b: &Aabb) -> Bounds {
        Bounds {
            min: [b.min.x, b.min.y, b.min.z].map(round_down),
            max: [b.max.x, b.max.y, b.max.z].map(round_up),
        }
    }

    #[inline]
    pub(super) fn union(&self, other: &Bounds) -> Bounds {
        Bounds {
            min: [0, 1, 2].map(|k| lesser(self.min[k], other.min[k])),
            max: [0, 1, 2].map(|k| greater(self.max[k], other.max[k])),
        }
    }

    #[inline]
    fn include(&self, p: &[f32; 3]) -> Bounds {
        Bounds {
            min: [0, 1, 2].map(|k| lesser(self.min[k], p[k])),
            max: [0, 1, 2].map(|k| greater(self.max[k], p[k])),
        }
    }

    fn surface_area(&self) -> f64 {
        let e = [0, 1, 2].map(|k| self.max[k] as f64 - self.min[k] as f64);
        if e.iter().any(|&e| e < 0.0) {
            return 0.0;
        }
        2.0 * (e[0] * e[1] + e[1] * e[2] + e[2] * e[0])
    }
}

#[inline]
fn lesser(a: f32, b: f32) -> f32 {
    if a < b { a } else { b }
}

#[inline]
fn greater(a: f32, b: f32) -> f32 {
    if a > b { a } else { b }
}

/// What the SAH knows of leaves: their primitives are tested `width` at a
/// time (a group), each group costing `group_cost` node visits, and a leaf
/// holds at most `max_size` of them unless the depth limit forces more.
#[derive(Clone, Copy, Debug)]
pub(super) struct Leaves {
    pub width: usize,
    pub group_cost: f64,
    pub max_size: usize,
}

impl Leaves {
    /// Cost of a leaf of `count` primitives.
    #[inline]
    fn cost(&self, count: u32) -> f64 {
        count.div_ceil(self.width as u32) as f64 * self.group_cost
    }
}

/// How a tree is built: its leaves and the binary depth at which leaves
/// are forced.
#[derive(Clone, Copy, Debug)]
pub(super) struct Settings {
    pub leaves: Leaves,
    pub max_depth: usize,
}

#[derive(Clone, Copy)]
pub(super) struct Item {
    pub bounds: Bounds,
    pub index: u32,
}

impl Item {
    #[inline]
    pub(super) fn centroid(&self) -> [f32; 3] {
        // Halves first: no overflow near the ends of the f32 range.
        [0, 1, 2].map(|k| self.bounds.min[k] * 0.5 + self.bounds.max[k] * 0.5)
    }
}

/// The built tree: node slots (root at 0), items in leaf order, and the
/// depth of the deepest leaf.
pub(super) struct Built {
    pub nodes: Vec<BinaryNode>,
    pub items: Vec<Item>,
    #[allow(dead_code)]
    pub depth: usize,
}

/// What a node knows about its items before it is split.
#[derive(Clone, Copy)]
struct Range {
    bounds: Bounds,
    centroids: Bounds,
    /// Position of the first item in the whole item array.
    first: u32,
}

/// Builds the tree over `items` (all with valid boxes).
pub(super) fn build(mut items: Vec<Item>, settings: Settings) -> Built {
    if items.is_empty() {
        return Built {
            nodes: Vec::new(),
            items,
            depth: 0,
        };
    }
    let empty = BinaryNode {
        bounds: Bounds::EMPTY,
        offset: 0,
        count: 0,
    };
    let mut nodes = vec![empty; 2 * items.len() - 1];
    let range = bounds_of(&items, 0);
    let depth = build_node(&mut items, &mut nodes, 0, range, 0, &settings);
    Built {
        nodes,
        items,
        depth,
    }
}

fn bounds_of(items: &[Item], first: u32) -> Range {
    let (bounds, centroids) = items
        .iter()
        .fold((Bounds::EMPTY, Bounds::EMPTY), |(b, c), item| {
            (b.union(&item.bounds), c.include(&item.centroid()))
        });
    Range {
        bounds,
        centroids,
        first,
    }
}

/// Builds the subtree over `items` into `nodes` (its own `2n - 1` slots,
/// the first at absolute slot `slot`); returns the depth of its deepest leaf.
fn build_node(
    items: &mut [Item],
    nodes: &mut [BinaryNode],
    slot: u32,
    range: Range,
    depth: usize,
    settings: &Settings,
) -> usize {
    nodes[0].bounds = range.bounds;
    let split = if items.len() <= 1 || depth >= settings.max_depth {
        None
    } else {
        choose_split(items, &range, &settings.leaves)
    };
    let Some((mid, left, right)) = split else {
        nodes[0].offset = range.first;
        nodes[0].count = items.len() as u32;
        return depth;
    };
    let second = slot + 2 * mid as u32;
    nodes[0].offset = second;
    nodes[0].count = 0;
    let (left_nodes, right_nodes) = nodes[1..].split_at_mut(2 * mid - 1);
    let (left_items, right_items) = items.split_at_mut(mid);
    let left = Range {
        first: range.first,
        ..left
    };
    let right = Range {
        first: range.first + mid as u32,
        ..right
    };
    let parallel = left_items.len() + right_items.len() > PARALLEL_ITEMS;
    let mut left_job = || build_node(left_items, left_nodes, slot + 1, left, depth + 1, settings);
    let mut right_job = || build_node(right_items, right_nodes, second, right, depth + 1, settings);
    let (a, b) = if parallel {
        rayon::join(left_job, right_job)
    } else {
        (left_job(), right_job())
    };
    a.max(b)
}

/// Chooses a binned-SAH split and partitions `items`; returns the split
/// position and what both sides know, or `None` when a leaf is cheaper.
fn choose_split(
    items: &mut [Item],
    range: &Range,
    leaves: &Leaves,
) -> Option<(usize, Range, Range)> {
    let count = items.len();
    let binning = Binning::new(&range.centroids, count);
    let used = binning.bins;
    let parent_area = range.bounds.surface_area().max(f64::MIN_POSITIVE);
    let mut bins = Bins::new();
    binning.fill_parallel(items, &mut bins);
    let mut best: Option<(usize, usize, f64)> = None; // (axis, bin boundary, cost)
    for axis in 0..3 {
        if binning.scale[axis] == 0.0 {
            continue;
        }
        let (bounds, counts) = (&bins.bounds(axis), &bins.counts[axis]);
        // Sweep from the right to get suffix areas and counts.
        let mut right_area = [0.0; BIN_COUNT];
        let mut right_count = [0u32; BIN_COUNT];
        let mut acc = Bounds::EMPTY;
        let mut n = 0;
        for b in (1..used).rev() {
            acc = acc.union(&bounds[b]);
            n += counts[b];
            right_area[b] = acc.surface_area();
            right_count[b] = n;
        }
        let mut acc = Bounds::EMPTY;
        let mut n = 0;
        for b in 1..used {
            acc = acc.union(&bounds[b - 1]);
            n += counts[b - 1];
            if n == 0 || right_count[b] == 0 {
                continue;
            }
            let cost = TRAVERSAL_COST
                + (acc.surface_area() * leaves.cost(n)
                    + right_area[b] * leaves.cost(right_count[b]))
                    / parent_area;
            if best.is_none_or(|(_, _, c)| cost < c) {
                best = Some((axis, b, cost));
            }
        }
    }
    let Some((axis, boundary, cost)) = best else {
        // All centroids coincide: split by count so leaves stay small.
        return (count > leaves.max_size).then(|| {
            let mid = count / 2;
            (
                mid,
                bounds_of(&items[..mid], 0),
                bounds_of(&items[mid..], 0),
            )
        });
    };
    if count <= leaves.max_size && cost >= leaves.cost(count as u32) {
        return None;
    }
    let (mid, left_centroids, right_centroids) = partition(items, &binning, axis, boundary);
    let side = |bins: &[Bounds]| bins.iter().fold(Bounds::EMPTY, |a, b| a.union(b));
    let split_bins = bins.bounds(axis);
    let left = Range {
        bounds: side(&split_bins[..boundary]),
        centroids: left_centroids,
        first: 0,
    };
    let right = Range {
        bounds: side(&split_bins[boundary..used]),
        centroids: right_centroids,
        first: 0,
    };
    (mid > 0 && mid < count).then_some((mid, left, right))
}

/// Moves the items of the bins below `boundary` to the front; returns how
/// many there are and the centroid bounds of both sides.
fn partition(
    items: &mut [Item],
    binning: &Binning,
    axis: usize,
    boundary: usize,
) -> (usize, Bounds, Bounds) {
    let mut first = 0;
    let (mut left, mut right) = (Bounds::EMPTY, Bounds::EMPTY);
    for i in 0..items.len() {
        let c = items[i].centroid();
        if binning.bin(axis, c[axis]) < boundary {
            left = left.include(&c);
            items.swap(first, i);
            first += 1;
        } else {
            right = right.include(&c);
        }
    }
    (first, left, right)
}
