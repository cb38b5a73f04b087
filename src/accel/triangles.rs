//! Triangles in the leaf order of their BVH: a leaf's triangles sit side by
//! side with their vertices inline (no index to follow), in huge pages when
//! the mesh is large, so that a query reads one small block per leaf; the
//! hit's surface is then computed from the same, already cached, block.
//!
//! The tests are the f64 Möller–Trumbore of `geometry::triangle`, on the
//! edges `p1 - p0` and `p2 - p0` computed exactly as the mesh computes them,
//! so results are the same bit for bit as testing the mesh's triangles.

use bytemuck::{Pod, Zeroable};

use super::Bvh;
use super::huge_pages::HugeArray;
use crate::geometry::triangle::intersect_edges;
use crate::math::{Aabb, Point3, Ray};

/// The three vertices of a triangle and its index in the caller's list
/// (read with the vertices, from the same cache line, when it is hit).
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
#[repr(C)]
struct Packed {
    vertices: [[f64; 3]; 3],
    original: u32,
    /// Explicit padding to 80 bytes (plain data has no hidden bytes).
    unused: u32,
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
    packed: HugeArray<Packed>,
}

impl LeafTriangles {
    /// Builds the BVH over the `count` triangles `triangle(i)`; `None`
    /// (an invalid triangle) is left out and never reported.
    pub fn build(count: usize, triangle: impl Fn(usize) -> Option<[Point3; 3]>) -> LeafTriangles {
        let boxes: Vec<Aabb> = (0..count)
            .map(|i| match triangle(i) {
                Some(t) => t.iter().fold(Aabb::empty(), |b, p| b.include_point(*p)),
                None => Aabb::empty(),
            })
            .collect();
        let (bvh, original) = Bvh::build(&boxes).into_leaf_order();
        let packed = HugeArray::from_fn(original.len(), |slot| Packed {
            // Only valid triangles have a valid box, so only they are in
            // the tree.
            vertices: triangle(original[slot] as usize)
                .unwrap_or_default()
                .map(|p| [p.x, p.y, p.z]),
            original: original[slot],
            unused: 0,
        });
        LeafTriangles { bvh, packed }
    }

    /// Number of triangles in the tree.
    pub fn len(&self) -> usize {
        self.packed.len()
    }

    pub fn is_empty(&self) -> bool {
        self.packed.is_empty()
    }

    /// Bounds of the triangles in the tree.
    pub fn bounds(&self) -> Aabb {
        self.bvh.bounds()
    }

    /// The vertices of the triangle at `slot`, if that is the caller's
    /// triangle `index`.
    pub fn vertices(&self, slot: u32, index: u32) -> Option<[Point3; 3]> {
        let packed = self.packed.get(slot as usize)?;
        (packed.original == index).then(|| packed.vertices.map(Point3::from))
    }

    #[inline(always)]
    fn test(&self, slot: usize, ray: &Ray, t_min: f64, t_max: f64) -> Option<(f64, f64, f64)> {
        let [p0, p1, p2] = self.packed[slot].vertices.map(Point3::from);
        intersect_edges(&p0, &(p1 - p0), &(p2 - p0), ray, t_min, t_max)
    }

    /// The nearest triangle with `t_min < t < t_max`.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<TriangleHit> {
        let mut best = None;
        self.bvh.traverse(ray, t_min, t_max, |slot, t_max| {
            let (t, b1, b2) = self.test(slot, ray, t_min, t_max)?;
            best = Some(TriangleHit {
                t,
                b1,
                b2,
                slot: slot as u32,
                index: self.packed[slot].original,
            });
            Some(t)
        });
        best
    }

    /// Whether any triangle lies on the ray with `t_min < t < t_max`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.bvh.any(ray, t_min, t_max, |slot| {
            self.test(slot, ray, t_min, t_max).is_some()
        })
    }
}
