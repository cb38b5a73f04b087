//! The traversal loops: nearest hit and any hit over leaves (runs of
//! slots), nearest child first, with a stack on the call's own frame.
//!
//! The loop keeps the entry it visits next in hand: a node whose ray hits
//! one child goes straight on to it, and of several the nearest is kept and
//! the others pushed farthest first, so that they pop nearest first.
//!
//! Every child a node's test hits is prefetched at once (its node, or
//! through `prefetch_leaf` its leaf's primitives), so that the memory
//! reads of the children visited later overlap the work on the nearest
//! one: on the 871k dragon, whose blocks do not fit the cache, 16-19% more
//! closest hits and 24% more any hits per second.

use super::ray8::{Entry, Ray8};
use super::wide::{self, Node, W as WIDTH};
use super::{Bvh, MAX_DEPTH};
use crate::math::{Ray, inverse_direction};

/// Traversal stack sizes: a node pushes at most `WIDTH - 1` entries more
/// than it pops, so a tree of wide depth `d` needs at most
/// `(WIDTH - 1) d + WIDTH`. A traversal zeroes its whole stack, so shallow
/// trees use a short one.
const SMALL_STACK: usize = 16;
const MEDIUM_STACK: usize = 64;
const STACK_SIZE: usize = (WIDTH - 1) * MAX_DEPTH + WIDTH;

impl Bvh {
    /// Stack entries a traversal of a tree of wide depth `depth` may need.
    fn stack_needed(depth: usize) -> usize {
        (WIDTH - 1) * depth + WIDTH
    }

    /// Nearest-hit traversal over leaves: `leaf(first, count, t_max)` tests
    /// the slots `first..first + count` and returns the distance of the
    /// nearest hit closer than `t_max`, which then becomes the new `t_max`.
    /// Returns the final `t_max` (unchanged if nothing was hit).
    /// `prefetch_leaf(first)` may start reading the primitives of the leaf
    /// at `first`, which the traversal may test soon.
    #[inline]
    pub fn traverse_leaves<F, P>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        leaf: F,
        prefetch_leaf: P,
    ) -> f64
    where
        F: FnMut(usize, usize, f64) -> Option<f64>,
        P: Fn(usize),
    {
        let inverse = inverse_direction(&ray.direction);
        if !self.may_hit(ray, &inverse, t_min, t_max) {
            return t_max;
        }
        let r = Ray8::new(ray, &inverse, t_min);
        if Self::stack_needed(self.depth) <= SMALL_STACK {
            self.nearest::<SMALL_STACK, _, _>(&r, t_max, leaf, prefetch_leaf)
        } else if Self::stack_needed(self.depth) <= MEDIUM_STACK {
            self.nearest::<MEDIUM_STACK, _, _>(&r, t_max, leaf, prefetch_leaf)
        } else {
            self.nearest::<STACK_SIZE, _, _>(&r, t_max, leaf, prefetch_leaf)
        }
    }

    /// Any-hit traversal over leaves: true as soon as `leaf(first, count)`
    /// reports a hit among the slots `first..first + count`
    /// (`prefetch_leaf` as for [`Bvh::traverse_leaves`]).
    #[inline]
    pub fn any_leaves<F, P>(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
        leaf: F,
        prefetch_leaf: P,
    ) -> bool
    where
        F: FnMut(usize, usize) -> bool,
        P: Fn(usize),
    {
        let inverse = inverse_direction(&ray.direction);
        if !self.may_hit(ray, &inverse, t_min, t_max) {
            return false;
        }
        let r = Ray8::new(ray, &inverse, t_min);
        if Self::stack_needed(self.depth) <= SMALL_STACK {
            self.first::<SMALL_STACK, _, _>(&r, t_max, leaf, prefetch_leaf)
        } else if Self::stack_needed(self.depth) <= MEDIUM_STACK {
            self.first::<MEDIUM_STACK, _, _>(&r, t_max, leaf, prefetch_leaf)
        } else {
            self.first::<STACK_SIZE, _, _>(&r, t_max, leaf, prefetch_leaf)
        }
    }

    /// [`Bvh::traverse_leaves`] with a stack of `N` entries.
    #[inline]
    fn nearest<const N: usize, F, P>(
        &self,
        r: &Ray8,
        mut t_max: f64,
        mut leaf: F,
        prefetch_leaf: P,
    ) -> f64
    where
        F: FnMut(usize, usize, f64) -> Option<f64>,
        P: Fn(usize),
    {
        let nodes: &[Node] = &self.nodes;
        let mut limit = wide::round_up(t_max);
        let mut stack = [Entry::default(); N];
        let mut top = 0usize;
        let mut current = Entry::ROOT;
        loop {
            if current.count > 0 {
                if let Some(t) = leaf(current.target as usize, current.count as usize, t_max) {
                    t_max = t_max.min(t);
                    limit = wide::round_up(t_max);
                }
            } else {
                let node = &nodes[current.target as usize];
                let (near, mask) = r.hit(node, limit);
                if mask != 0 {
                    prefetch_children(nodes, node, mask, &prefetch_leaf);
                    current = descend(node, &near, mask, &mut stack, &mut top);
                    continue;
                }
            }
            // The next entry the ray still enters before the nearest hit.
            loop {
                if top == 0 {
                    return t_max;
                }
                top -= 1;
                current = stack[top];
                if current.t <= limit {
                    break;
                }
            }
        }
    }

    /// [`Bvh::any_leaves`] with a stack of `N` entries.
    #[inline]
    fn first<const N: usize, F, P>(
        &self,
        r: &Ray8,
        t_max: f64,
        mut leaf: F,
        prefetch_leaf: P,
    ) -> bool
    where
        F: FnMut(usize, usize) -> bool,
        P: Fn(usize),
    {
        let nodes: &[Node] = &self.nodes;
        let limit = wide::round_up(t_max);
        let mut stack = [Entry::default(); N];
        let mut top = 0usize;
        let mut current = Entry::ROOT;
        loop {
            if current.count > 0 {
                if leaf(current.target as usize, current.count as usize) {
                    return true;
                }
            } else {
                // Nearest child first, as for the nearest hit: the first
                // surface along the ray is met soonest.
                let node = &nodes[current.target as usize];
                let (near, mask) = r.hit(node, limit);
                if mask != 0 {
                    prefetch_children(nodes, node, mask, &prefetch_leaf);
                    current = descend(node, &near, mask, &mut stack, &mut top);
                    continue;
                }
            }
            if top == 0 {
                return false;
            }
            top -= 1;
            current = stack[top];
        }
    }
}

/// Starts reading the children in `mask`: both cache lines of an
/// interior child's node, a leaf's primitives through `prefetch_leaf`.
#[inline(always)]
fn prefetch_children(nodes: &[Node], node: &Node, mask: u32, prefetch_leaf: &impl Fn(usize)) {
    let mut bits = mask;
    while bits != 0 {
        let i = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        if node.count[i] > 0 {
            prefetch_leaf(node.child[i] as usize);
        } else if let Some(child) = nodes.get(node.child[i] as usize) {
            crate::accel::prefetch(child);
        }
    }
}

/// The nearest of the children in `mask` (entry distances `near`), which
/// the traversal visits next; the others are pushed farthest first, so
/// that they are popped nearest first.
#[inline(always)]
fn descend<const N: usize>(
    node: &Node,
    near: &[f32; WIDTH],
    mask: u32,
    stack: &mut [Entry; N],
    top: &mut usize,
) -> Entry {
    let child = |i: usize| Entry {
        target: node.child[i],
        count: node.count[i] as u32,
        t: near[i],
    };
    let first = mask.trailing_zeros() as usize;
    let rest = mask & (mask - 1);
    if rest == 0 {
        return child(first);
    }
    let second = rest.trailing_zeros() as usize;
    if rest & (rest - 1) == 0 {
        let (a, b) = (child(first), child(second));
        let (nearer, farther) = if b.t < a.t { (b, a) } else { (a, b) };
        stack[*top] = farther;
        *top += 1;
        return nearer;
    }
    // Three or more: insertion into the stack, farthest first.
    let bottom = *top;
    let mut bits = mask;
    while bits != 0 {
        let i = bits.trailing_zeros() as usize;
        bits &= bits - 1;
        let mut k = *top;
        while k > bottom && stack[k - 1].t < near[i] {
            stack[k] = stack[k - 1];
            k -= 1;
        }
        stack[k] = child(i);
        *top += 1;
    }
    *top -= 1;
    stack[*top]
}
