//! The 4-wide tree: binary nodes collapsed four children at a time, child
//! boxes in f32 rounded outward (a box never shrinks, so no hit is lost),
//! stored plane by plane so that the four slab tests run side by side.

use super::build::{BinaryNode, Bounds};

/// Four children: their boxes, and where each leads.
#[derive(Clone, Copy, Debug)]
#[repr(C, align(64))]
pub(super) struct Node4 {
    /// `min x, min y, min z, max x, max y, max z` of each child. Empty
    /// slots have `min = +inf`, `max = -inf`, which no ray enters.
    pub planes: [[f32; 4]; 6],
    /// Interior child: its node. Leaf: its first entry.
    pub child: [u32; 4],
    /// Leaf: its number of entries; 0 for interior children and empty slots.
    pub count: [u32; 4],
}

const EMPTY: Node4 = Node4 {
    planes: [
        [f32::INFINITY; 4],
        [f32::INFINITY; 4],
        [f32::INFINITY; 4],
        [f32::NEG_INFINITY; 4],
        [f32::NEG_INFINITY; 4],
        [f32::NEG_INFINITY; 4],
    ],
    child: [0; 4],
    count: [0; 4],
};

/// The largest f32 not above `v`.
pub(super) fn round_down(v: f64) -> f32 {
    let f = v as f32;
    if f as f64 > v { f.next_down() } else { f }
}

/// The smallest f32 not below `v`.
pub(super) fn round_up(v: f64) -> f32 {
    let f = v as f32;
    if (f as f64) < v { f.next_up() } else { f }
}

/// Collapses the binary tree (root at slot 0, not empty) into 4-wide nodes
/// (root at 0); returns them and the depth of the deepest wide node.
pub(super) fn collapse(binary: &[BinaryNode]) -> (Vec<Node4>, usize) {
    let mut nodes = Vec::with_capacity(binary.len() / 2 + 1);
    let depth = if binary[0].count > 0 {
        // A single leaf: one node with one child.
        let mut node = EMPTY;
        set_child(&mut node, 0, &binary[0], binary[0].offset, binary[0].count);
        nodes.push(node);
        0
    } else {
        emit(binary, 0, &mut nodes, 0)
    };
    (nodes, depth)
}

fn set_child(node: &mut Node4, i: usize, child: &BinaryNode, target: u32, count: u32) {
    let b: &Bounds = &child.bounds;
    for k in 0..3 {
        node.planes[k][i] = round_down(b.min[k]);
        node.planes[3 + k][i] = round_up(b.max[k]);
    }
    node.child[i] = target;
    node.count[i] = count;
}

fn area(b: &Bounds) -> f64 {
    let e = [0, 1, 2].map(|k| b.max[k] - b.min[k]);
    e[0] * e[1] + e[1] * e[2] + e[2] * e[0]
}

/// Emits the wide node of the interior binary node at `slot`, then its
/// interior children; returns the deepest wide level below it.
fn emit(binary: &[BinaryNode], slot: usize, nodes: &mut Vec<Node4>, depth: usize) -> usize {
    // Open the largest interior child until there are four.
    let mut children = arrayvec::ArrayVec::<usize, 4>::new();
    children.push(slot + 1);
    children.push(binary[slot].offset as usize);
    while children.len() < 4 {
        let largest = children
            .iter()
            .enumerate()
            .filter(|(_, c)| binary[**c].count == 0)
            .max_by(|a, b| area(&binary[*a.1].bounds).total_cmp(&area(&binary[*b.1].bounds)));
        let Some((i, &open)) = largest else {
            break;
        };
        children[i] = open + 1;
        children.insert(i + 1, binary[open].offset as usize);
    }
    let index = nodes.len();
    nodes.push(EMPTY);
    let mut deepest = depth;
    for (i, &c) in children.iter().enumerate() {
        let child = &binary[c];
        if child.count > 0 {
            set_child(&mut nodes[index], i, child, child.offset, child.count);
        } else {
            let target = nodes.len() as u32;
            deepest = deepest.max(emit(binary, c, nodes, depth + 1));
            set_child(&mut nodes[index], i, child, target, 0);
        }
    }
    deepest
}
