//! Triangles in the leaf order of their BVH, four to a block: a leaf's
//! triangles fill one block (its unused lanes hold a zero triangle, which
//! no ray hits), their vertices inline and lane by lane, so that a leaf is
//! one read of consecutive memory and its four tests run side by side.
//! Blocks live in huge pages when the mesh is large, and the hit's surface
//! is computed from the same, already cached, block.
//!
//! The tests are the f64 Möller–Trumbore of `geometry::triangle`, operation
//! for operation (edges `p1 - p0` and `p2 - p0`, nalgebra's cross and dot
//! products), so results are the same bit for bit as testing the mesh's
//! triangles. A mesh whose coordinates are all f32 values (those read from
//! OBJ files are) keeps them as f32, which halves the memory a query reads
//! and changes no result: the f64 test sees the same numbers.

mod block;

use super::Bvh;
use super::huge_pages::HugeArray;
use crate::math::{Aabb, Point3, Ray};
use block::{Block, Block32, Block64, LANES, LaneHits, Lanes, test, test_single_precision};

/// SAH cost of testing one block, in node visits.
const BLOCK_COST: f64 = 1.0;

/// The blocks of a mesh, in the precision its coordinates need.
#[derive(Clone, Debug)]
enum Blocks {
    Single(HugeArray<Block32>),
    Double(HugeArray<Block64>),
}

impl Default for Blocks {
    fn default() -> Self {
        Blocks::Single(HugeArray::default())
    }
}

/// A triangle hit: distance, barycentrics of `p1` and `p2`, the slot
/// (leaf-order position) of the triangle and its index in the caller's list.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleHit {
    pub t: f64,
    pub b1: f64,
    pub b2: f64,
    pub slot: u32,
    pub index: u32,
}

/// A BVH over triangles and the triangles in its leaf order.
#[derive(Clone, Debug, Default)]
pub struct LeafTriangles {
    bvh: Bvh,
    blocks: Blocks,
    len: usize,
}

impl LeafTriangles {
    /// Builds the BVH over the `count` triangles `triangle(i)`; `None`
    /// (an invalid triangle) is left out and never reported.
    pub fn build(
        count: usize,
        triangle: impl Fn(usize) -> Option<[Point3; 3]> + Sync,
    ) -> LeafTriangles {
        use rayon::prelude::*;
        // Each triangle's box, and whether its coordinates are all f32
        // values (only triangles with a valid box go into the tree).
        let (boxes, f32_coords): (Vec<Aabb>, Vec<bool>) = (0..count)
            .into_par_iter()
            .map(|i| match triangle(i) {
                Some(t) => (
                    t.iter().fold(Aabb::empty(), |b, p| b.include_point(*p)),
                    t.iter().all(|p| p.iter().all(|&c| c as f32 as f64 == c)),
                ),
                None => (Aabb::empty(), true),
            })
            .unzip();
        let single = boxes
            .par_iter()
            .zip(&f32_coords)
            .all(|(b, &f32_coords)| f32_coords || !b.is_valid());
        let (bvh, slots) = Bvh::build_in_leaf_order(&boxes, LANES, BLOCK_COST);
        // Only valid triangles have a valid box, so only they are in the
        // tree.
        let lanes = |block: usize| -> Lanes {
            std::array::from_fn(|lane| {
                let index = *slots
                    .get(block * LANES + lane)
                    .filter(|&&i| i != u32::MAX)?;
                let vertices = triangle(index as usize)?;
                Some((index, vertices))
            })
        };
        let count = slots.len() / LANES;
        let blocks = if single {
            Blocks::Single(HugeArray::from_fn(count, |b| Block::from_lanes(&lanes(b))))
        } else {
            Blocks::Double(HugeArray::from_fn(count, |b| Block::from_lanes(&lanes(b))))
        };
        LeafTriangles {
            len: bvh.len(),
            bvh,
            blocks,
        }
    }

    /// Number of triangles in the tree.
    pub fn len(&self) -> usize {
        self.len
    }

    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// Bounds of the triangles in the tree.
    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    /// Whether the vertices are kept in single precision (all are f32
    /// values).
    pub fn is_single_precision(&self) -> bool {
        matches!(self.blocks, Blocks::Single(_))
    }

    /// The vertices of the triangle at `slot`, if that is the caller's
    /// triangle `index`.
    pub fn vertices(&self, slot: u32, index: u32) -> Option<[Point3; 3]> {
        let (block, lane) = (slot as usize / LANES, slot as usize % LANES);
        let coords = match &self.blocks {
            Blocks::Single(blocks) => blocks
                .get(block)
                .filter(|b| b.original[lane] == index)?
                .coords(),
            Blocks::Double(blocks) => blocks
                .get(block)
                .filter(|b| b.original[lane] == index)?
                .coords(),
        };
        Some(std::array::from_fn(|v| {
            Point3::new(
                coords[3 * v][lane],
                coords[3 * v + 1][lane],
                coords[3 * v + 2][lane],
            )
        }))
    }

    /// The nearest triangle with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<TriangleHit> {
        match &self.blocks {
            Blocks::Single(blocks) => nearest(&self.bvh, blocks, ray, t_min, t_max, test),
            Blocks::Double(blocks) => nearest(&self.bvh, blocks, ray, t_min, t_max, test),
        }
    }

    /// Whether any triangle lies on the ray with `t_min < t < t_max`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match &self.blocks {
            Blocks::Single(blocks) => any(&self.bvh, blocks, ray, t_min, t_max, test),
            Blocks::Double(blocks) => any(&self.bvh, blocks, ray, t_min, t_max, test),
        }
    }

    /// [`LeafTriangles::intersect`] by W-Solaris's test in single precision
    /// (`geometry::single_precision::triangle`).
    pub fn intersect_single_precision(
        &self,
        ray: &Ray,
        t_min: f64,
        t_max: f64,
    ) -> Option<TriangleHit> {
        match &self.blocks {
            Blocks::Single(blocks) => {
                nearest(&self.bvh, blocks, ray, t_min, t_max, test_single_precision)
            }
            Blocks::Double(blocks) => {
                nearest(&self.bvh, blocks, ray, t_min, t_max, test_single_precision)
            }
        }
    }

    /// [`LeafTriangles::occluded`] by W-Solaris's test in single precision.
    pub fn occluded_single_precision(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        match &self.blocks {
            Blocks::Single(blocks) => {
                any(&self.bvh, blocks, ray, t_min, t_max, test_single_precision)
            }
            Blocks::Double(blocks) => {
                any(&self.bvh, blocks, ray, t_min, t_max, test_single_precision)
            }
        }
    }
}

/// The blocks of the slots `first..first + count` (a leaf starts a block).
#[inline(always)]
fn leaf_blocks(first: usize, count: usize) -> std::ops::Range<usize> {
    first / LANES..(first + count).div_ceil(LANES)
}

#[inline(always)]
fn nearest<B: Block>(
    bvh: &Bvh,
    blocks: &[B],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    test: impl Fn(&[[f64; LANES]; 9], &Ray, f64, f64) -> LaneHits,
) -> Option<TriangleHit> {
    let mut best = None;
    let leaf = |first: usize, count: usize, mut t_max: f64| {
        let mut found = None;
        for b in leaf_blocks(first, count) {
            let block = &blocks[b];
            let hits = test(&block.coords(), ray, t_min, t_max);
            // The nearest lane, the first of equals (as testing the lanes
            // one by one with a shrinking t_max would find).
            let mut nearest: Option<usize> = None;
            for lane in 0..LANES {
                if hits.mask & (1 << lane) != 0 && nearest.is_none_or(|n| hits.t[lane] < hits.t[n])
                {
                    nearest = Some(lane);
                }
            }
            if let Some(lane) = nearest {
                t_max = hits.t[lane];
                found = Some(t_max);
                best = Some(TriangleHit {
                    t: t_max,
                    b1: hits.b1[lane],
                    b2: hits.b2[lane],
                    slot: (b * LANES + lane) as u32,
                    index: block.original()[lane],
                });
            }
        }
        found
    };
    bvh.traverse_leaves(ray, t_min, t_max, leaf, |first| prefetch(blocks, first));
    best
}

#[inline(always)]
fn any<B: Block>(
    bvh: &Bvh,
    blocks: &[B],
    ray: &Ray,
    t_min: f64,
    t_max: f64,
    test: impl Fn(&[[f64; LANES]; 9], &Ray, f64, f64) -> LaneHits,
) -> bool {
    let leaf = |first: usize, count: usize| {
        leaf_blocks(first, count).any(|b| test(&blocks[b].coords(), ray, t_min, t_max).mask != 0)
    };
    bvh.any_leaves(ray, t_min, t_max, leaf, |first| prefetch(blocks, first))
}

/// Starts reading the block of the leaf at slot `first`.
#[inline(always)]
fn prefetch<B: Block>(blocks: &[B], first: usize) {
    if let Some(block) = blocks.get(first / LANES) {
        crate::accel::prefetch(block);
    }
}

#[cfg(test)]
mod tests;
