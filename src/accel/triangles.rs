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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::triangle::intersect_vertices;
    use crate::math::Vec3;
    use crate::rng::Rng;

    /// A bumpy grid of triangles (every inner edge and vertex shared), a
    /// few random ones, and an invalid entry that must never be reported.
    fn triangles(rng: &mut Rng) -> Vec<Option<[Point3; 3]>> {
        let n = 40;
        let height = |i: usize, j: usize| ((i * 7 + j * 3) % 5) as f64 * 0.01;
        let p = |i: usize, j: usize| {
            Point3::new(i as f64 / n as f64, j as f64 / n as f64, height(i, j))
        };
        let mut list = Vec::new();
        for i in 0..n {
            for j in 0..n {
                list.push(Some([p(i, j), p(i + 1, j), p(i + 1, j + 1)]));
                list.push(Some([p(i, j), p(i + 1, j + 1), p(i, j + 1)]));
            }
        }
        list.push(None);
        for _ in 0..300 {
            let a = Point3::new(rng.next_f64(), rng.next_f64(), rng.next_f64() * 0.5 + 0.1);
            let e = |rng: &mut Rng| Vec3::new(rng.next_f64(), rng.next_f64(), rng.next_f64()) * 0.1;
            list.push(Some([a, a + e(rng), a + e(rng)]));
        }
        list
    }

    #[test]
    fn queries_equal_brute_force_bit_for_bit_on_shared_edges_and_vertices() {
        let mut rng = Rng::new(31, 32);
        let list = triangles(&mut rng);
        let tree = LeafTriangles::build(list.len(), |i| list[i]);
        assert_eq!(tree.len(), list.len() - 1);
        let valid: Vec<(u32, [Point3; 3])> = list
            .iter()
            .enumerate()
            .filter_map(|(i, t)| t.map(|t| (i as u32, t)))
            .collect();
        let mut hits = 0;
        for k in 0..5000 {
            // Aim at vertices, edge points and random points of the grid.
            let (_, t) = valid[(rng.next_f64() * valid.len() as f64) as usize];
            let s = rng.next_f64();
            let target = match k % 3 {
                0 => t[1],
                1 => t[0] + (t[2] - t[0]) * s,
                _ => Point3::new(rng.next_f64(), rng.next_f64(), 0.02),
            };
            let origin = Point3::new(rng.next_f64() * 3.0 - 1.0, rng.next_f64() * 3.0 - 1.0, 1.5);
            let ray = Ray::new(origin, target - origin, 0.0);
            let t_max = if k % 4 == 0 {
                1.0 + rng.next_f64()
            } else {
                f64::INFINITY
            };
            let brute = valid
                .iter()
                .filter_map(|(i, [a, b, c])| {
                    intersect_vertices(a, b, c, &ray, 0.0, t_max).map(|h| (h.0, *i))
                })
                .min_by(|x, y| x.0.total_cmp(&y.0));
            let found = tree.intersect(&ray, 0.0, t_max);
            assert_eq!(
                found.map(|h| h.t.to_bits()),
                brute.map(|b| b.0.to_bits()),
                "{ray:?}"
            );
            assert_eq!(tree.occluded(&ray, 0.0, t_max), brute.is_some());
            if let Some(hit) = found {
                hits += 1;
                let vertices = tree.vertices(hit.slot, hit.index).expect("slot holds it");
                assert_eq!(Some(vertices), list[hit.index as usize]);
                let [a, b, c] = vertices;
                let again = intersect_vertices(&a, &b, &c, &ray, 0.0, t_max).expect("hit");
                assert_eq!((again.1, again.2), (hit.b1, hit.b2));
                // Another triangle's index at that slot is looked up elsewhere.
                assert_eq!(tree.vertices(hit.slot, hit.index + 1), None);
            }
        }
        assert!(hits > 2000, "{hits} hits");
    }
}
