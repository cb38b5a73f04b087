//! The binary tree collapsed `W` children at a time into wide nodes (the
//! largest interior child opened until there are `W`), depth first, and
//! the leaves then moved to the slots of their caller's groups.

use rayon::prelude::*;

use super::binary_tree::{BinaryNode, Bounds};
use super::wide::{MAX_COUNT, Node, W, quantise};

type Children = arrayvec::ArrayVec<Child, W>;

/// Collapses the binary tree (root at slot 0, not empty) into `W`-wide
/// nodes (root at 0); returns them and the depth of the deepest wide node.
///
/// The root's children are collapsed in parallel, each subtree into its
/// own list, and the lists are appended in order with their node targets
/// moved by where they land: the same nodes in the same order as one
/// depth-first pass. (The pass waits on memory: it reads binary nodes far
/// apart.)
pub(super) fn collapse(binary: &[BinaryNode]) -> (Vec<Node>, usize) {
    let children = root_children(binary);
    let subtrees: Vec<(Vec<Node>, Option<usize>)> = children
        .par_iter()
        .map(|child| {
            let mut nodes = Vec::new();
            let depth = subtree(binary, child, &mut nodes, 1);
            (nodes, depth)
        })
        .collect();
    let total = 1 + subtrees.iter().map(|(n, _)| n.len()).sum::<usize>();
    let mut nodes = Vec::with_capacity(total);
    nodes.push(node_over(binary, &children));
    let mut deepest = 0;
    for (i, (child, (subtree, depth))) in children.iter().zip(subtrees).enumerate() {
        match depth {
            Some(depth) => {
                let base = nodes.len() as u32;
                set_target(&mut nodes[0], i, base, 0);
                deepest = deepest.max(depth);
                nodes.extend(subtree.into_iter().map(|node| moved(node, base)));
            }
            None => set_leaf(&mut nodes[0], i, child),
        }
    }
    (nodes, deepest)
}

/// [`collapse`] in one depth-first pass (what the parallel one must equal).
#[cfg(test)]
pub(super) fn collapse_sequentially(binary: &[BinaryNode]) -> (Vec<Node>, usize) {
    let mut nodes = Vec::new();
    let depth = emit(binary, &root_children(binary), &mut nodes, 0);
    (nodes, depth)
}

/// The children of the root's wide node (a root leaf is its only child).
fn root_children(binary: &[BinaryNode]) -> Children {
    let root = &binary[0];
    if root.count == 0 {
        return wide_children(binary, 0);
    }
    let mut children = Children::new();
    children.push(Child::Leaf {
        bounds: root.bounds,
        first: root.offset,
        count: root.count,
    });
    children
}

/// `node` with its interior children's targets moved by `base` (leaf
/// targets are entries, which do not move).
fn moved(mut node: Node, base: u32) -> Node {
    for i in 0..W {
        if node.valid & (1 << i) != 0 && node.count[i] == 0 {
            node.child[i] += base;
        }
    }
    node
}

/// A child slot before it is written: an interior binary node or a run of
/// leaf entries.
#[derive(Clone, Copy)]
enum Child {
    Interior {
        slot: usize,
    },
    Leaf {
        bounds: Bounds,
        first: u32,
        count: u32,
    },
}

fn child_bounds(binary: &[BinaryNode], child: &Child) -> Bounds {
    match child {
        Child::Interior { slot } => binary[*slot].bounds,
        Child::Leaf { bounds, .. } => *bounds,
    }
}

fn area(b: &Bounds) -> f64 {
    let e = [0, 1, 2].map(|k| b.max[k] as f64 - b.min[k] as f64);
    e[0] * e[1] + e[1] * e[2] + e[2] * e[0]
}

/// The children of the wide node of the interior binary node at `slot`:
/// its binary children, the largest interior one opened until there are
/// `W`.
fn wide_children(binary: &[BinaryNode], slot: usize) -> Children {
    let mut open = arrayvec::ArrayVec::<usize, W>::new();
    open.push(slot + 1);
    open.push(binary[slot].offset as usize);
    while open.len() < W {
        let largest = open
            .iter()
            .enumerate()
            .filter(|(_, c)| binary[**c].count == 0)
            .max_by(|a, b| area(&binary[*a.1].bounds).total_cmp(&area(&binary[*b.1].bounds)));
        let Some((i, &slot)) = largest else {
            break;
        };
        open[i] = slot + 1;
        open.insert(i + 1, binary[slot].offset as usize);
    }
    open.iter()
        .map(|&c| {
            let node = &binary[c];
            if node.count > 0 {
                Child::Leaf {
                    bounds: node.bounds,
                    first: node.offset,
                    count: node.count,
                }
            } else {
                Child::Interior { slot: c }
            }
        })
        .collect()
}

/// The wide node over `children`, their targets not yet set.
fn node_over(binary: &[BinaryNode], children: &[Child]) -> Node {
    let boxes: arrayvec::ArrayVec<Bounds, W> =
        children.iter().map(|c| child_bounds(binary, c)).collect();
    quantise(&boxes)
}

/// Emits the wide subtree of `child` at `depth`: an interior binary
/// node's, or the node over a leaf too large for a node entry; returns its
/// deepest wide level, or `None` for a leaf that a node entry holds.
fn subtree(
    binary: &[BinaryNode],
    child: &Child,
    nodes: &mut Vec<Node>,
    depth: usize,
) -> Option<usize> {
    match *child {
        Child::Interior { slot } => Some(emit(binary, &wide_children(binary, slot), nodes, depth)),
        Child::Leaf {
            bounds,
            first,
            count,
        } if count as usize > MAX_COUNT => {
            Some(emit(binary, &leaf_runs(bounds, first, count), nodes, depth))
        }
        Child::Leaf { .. } => None,
    }
}

/// Emits the wide node over `children`, then their subtrees; returns the
/// deepest wide level below it.
fn emit(binary: &[BinaryNode], children: &[Child], nodes: &mut Vec<Node>, depth: usize) -> usize {
    let index = nodes.len();
    nodes.push(node_over(binary, children));
    let mut deepest = depth;
    for (i, child) in children.iter().enumerate() {
        let target = nodes.len() as u32;
        match subtree(binary, child, nodes, depth + 1) {
            Some(below) => {
                deepest = deepest.max(below);
                set_target(&mut nodes[index], i, target, 0);
            }
            None => set_leaf(&mut nodes[index], i, child),
        }
    }
    deepest
}

/// The entries `first..first + count` of one leaf too large for a node
/// entry, in `W` runs (each with the leaf's box).
fn leaf_runs(bounds: Bounds, first: u32, count: u32) -> Children {
    let part = count.div_ceil(W as u32);
    (0..W as u32)
        .filter(|i| i * part < count)
        .map(|i| Child::Leaf {
            bounds,
            first: first + i * part,
            count: part.min(count - i * part),
        })
        .collect()
}

/// Child `i` of `node` as the leaf `child` (a node entry holds it).
fn set_leaf(node: &mut Node, i: usize, child: &Child) {
    if let Child::Leaf { first, count, .. } = *child {
        set_target(node, i, first, count);
    }
}

fn set_target(node: &mut Node, i: usize, target: u32, count: u32) {
    node.child[i] = target;
    node.count[i] = count as u8;
}

/// Moves every leaf to a slot that is a multiple of `width` (leaves in
/// leaf order, each on from the previous one's last group) and returns
/// the item of each slot (`indices` holds them in leaf order), `u32::MAX`
/// for the slots that pad a leaf's last group.
pub(super) fn pad_leaves(nodes: &mut [Node], indices: &[u32], width: usize) -> Vec<u32> {
    // (first entry, node, child) of every leaf, in leaf order.
    let mut leaves: Vec<(u32, usize, usize)> = Vec::new();
    for (n, node) in nodes.iter().enumerate() {
        for i in 0..W {
            if node.valid & (1 << i) != 0 && node.count[i] > 0 {
                leaves.push((node.child[i], n, i));
            }
        }
    }
    leaves.par_sort_unstable();
    let mut slots = Vec::with_capacity(indices.len() + indices.len() / 2);
    for (first, n, i) in leaves {
        let count = nodes[n].count[i] as usize;
        nodes[n].child[i] = slots.len() as u32;
        let first = first as usize;
        slots.extend_from_slice(&indices[first..first + count]);
        slots.resize(slots.len().next_multiple_of(width), u32::MAX);
    }
    slots
}
