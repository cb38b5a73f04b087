//! The wide tree: binary nodes collapsed `W` children at a time, child
//! boxes in f32 rounded outward (a box never shrinks, so no hit is lost),
//! stored plane by plane so that the `W` slab tests run side by side.

use bytemuck::{Pod, Zeroable};

use super::build::{BinaryNode, Bounds};

/// Children per node: 8 was measured no faster on the 871k dragon.
pub(super) const W: usize = 4;

/// `W` children: their boxes, and where each leads.
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C, align(64))]
pub(super) struct Node {
    /// `min x, min y, min z, max x, max y, max z` of each child. Empty
    /// slots have `min = +inf`, `max = -inf`, which no ray enters.
    pub planes: [[f32; W]; 6],
    /// Interior child: its node. Leaf: its first entry.
    pub child: [u32; W],
    /// Leaf: its number of entries; 0 for interior children and empty slots.
    pub count: [u32; W],
}

impl Node {
    const EMPTY: Node = Node {
        planes: [
            [f32::INFINITY; W],
            [f32::INFINITY; W],
            [f32::INFINITY; W],
            [f32::NEG_INFINITY; W],
            [f32::NEG_INFINITY; W],
            [f32::NEG_INFINITY; W],
        ],
        child: [0; W],
        count: [0; W],
    };
}

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

/// Collapses the binary tree (root at slot 0, not empty) into `W`-wide
/// nodes (root at 0); returns them and the depth of the deepest wide node.
pub(super) fn collapse(binary: &[BinaryNode]) -> (Vec<Node>, usize) {
    let mut nodes = Vec::with_capacity(binary.len() / (W - 1) + 1);
    let depth = if binary[0].count > 0 {
        // A single leaf: one node with one child.
        let mut node = Node::EMPTY;
        set_child(&mut node, 0, &binary[0], binary[0].offset, binary[0].count);
        nodes.push(node);
        0
    } else {
        emit(binary, 0, &mut nodes, 0)
    };
    (nodes, depth)
}

fn set_child(node: &mut Node, i: usize, child: &BinaryNode, target: u32, count: u32) {
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
fn emit(binary: &[BinaryNode], slot: usize, nodes: &mut Vec<Node>, depth: usize) -> usize {
    // Open the largest interior child until there are `W`.
    let mut children = arrayvec::ArrayVec::<usize, W>::new();
    children.push(slot + 1);
    children.push(binary[slot].offset as usize);
    while children.len() < W {
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
    nodes.push(Node::EMPTY);
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
