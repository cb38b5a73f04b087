//! Triangle meshes with their own BVH; smooth normals and uvs when the file has them.
//! One `Mesh` is built per distinct `MeshData` and shared by all its instances.

use std::sync::Arc;

use super::triangle::{intersect_edges, surface_vertices};
use super::{Intersection, SurfaceHit, normalize_or};
use crate::accel::Bvh;
use crate::math::{Aabb, Point3, Ray, Vec3};
use crate::scene::model::MeshData;

#[derive(Debug)]
pub struct Mesh {
    pub data: Arc<MeshData>,
    /// Over `packed`, in its (leaf) order.
    bvh: Bvh,
    /// The valid triangles in BVH leaf order, ready for the intersection
    /// test: a leaf's triangles are adjacent in memory, with no index to
    /// follow to their vertices.
    packed: Vec<PackedTriangle>,
    /// Index in `data.triangles` of each packed triangle.
    original: Vec<u32>,
}

/// A triangle as its intersection test reads it.
#[derive(Clone, Copy, Debug)]
struct PackedTriangle {
    p0: Point3,
    /// `p1 - p0` and `p2 - p0`.
    edge1: Vec3,
    edge2: Vec3,
}

impl Mesh {
    /// Builds the triangle BVH. Triangles with out-of-range indices are left out.
    pub fn new(data: Arc<MeshData>) -> Mesh {
        let count = data.positions.len();
        let boxes: Vec<Aabb> = data
            .triangles
            .iter()
            .map(|triangle| {
                if triangle.iter().any(|&i| i as usize >= count) {
                    return Aabb::empty();
                }
                triangle.iter().fold(Aabb::empty(), |b, &i| {
                    b.include_point(data.positions[i as usize])
                })
            })
            .collect();
        let (bvh, original) = Bvh::build(&boxes).into_leaf_order();
        let packed = original
            .iter()
            .map(|&index| {
                let [a, b, c] = data.triangles[index as usize].map(|i| data.positions[i as usize]);
                PackedTriangle {
                    p0: a,
                    edge1: b - a,
                    edge2: c - a,
                }
            })
            .collect();
        Mesh {
            data,
            bvh,
            packed,
            original,
        }
    }

    pub fn triangle_count(&self) -> usize {
        self.data.triangles.len()
    }

    /// Bounds of the (valid) triangles, `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Aabb> {
        (!self.bvh.is_empty()).then(|| self.bvh.bounds())
    }

    /// Nearest triangle hit: `u, v` are barycentrics, `index` the triangle.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let mut best = None;
        self.bvh.traverse(ray, t_min, t_max, |slot, t_max| {
            let triangle = &self.packed[slot];
            let (t, b1, b2) = intersect_edges(
                &triangle.p0,
                &triangle.edge1,
                &triangle.edge2,
                ray,
                t_min,
                t_max,
            )?;
            best = Some(Intersection {
                t,
                u: b1,
                v: b2,
                index: self.original[slot],
            });
            Some(t)
        });
        best
    }

    /// Whether any triangle lies on the ray within `(t_min, t_max)`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        self.bvh.any(ray, t_min, t_max, |slot| {
            let triangle = &self.packed[slot];
            intersect_edges(
                &triangle.p0,
                &triangle.edge1,
                &triangle.edge2,
                ray,
                t_min,
                t_max,
            )
            .is_some()
        })
    }

    /// The surface at a hit; `smooth` interpolates the vertex normals when present.
    pub fn surface(&self, _ray: &Ray, hit: &Intersection, smooth: bool) -> SurfaceHit {
        let [a, b, c] = self.data.triangles[hit.index as usize].map(|i| i as usize);
        let p = &self.data.positions;
        let (b1, b2) = (hit.u, hit.v);
        let b0 = 1.0 - b1 - b2;
        let mut surface = surface_vertices(&p[a], &p[b], &p[c], b1, b2);
        if let Some(uvs) = self.data.uvs.as_ref().filter(|uvs| uvs.len() == p.len()) {
            let (t0, t1, t2) = (uvs[a], uvs[b], uvs[c]);
            surface.uv = [
                b0 * t0[0] + b1 * t1[0] + b2 * t2[0],
                b0 * t0[1] + b1 * t1[1] + b2 * t2[1],
            ];
            // p - p0 = dpdu (u - u0) + dpdv (v - v0) on the triangle: solve the
            // 2x2 system of its two edges. Collinear uvs keep the barycentric
            // derivatives (finite, in the plane).
            let (du1, dv1) = (t1[0] - t0[0], t1[1] - t0[1]);
            let (du2, dv2) = (t2[0] - t0[0], t2[1] - t0[1]);
            let determinant = du1 * dv2 - dv1 * du2;
            let (edge1, edge2) = (p[b] - p[a], p[c] - p[a]);
            let dpdu = (edge1 * dv2 - edge2 * dv1) / determinant;
            let dpdv = (edge2 * du1 - edge1 * du2) / determinant;
            let finite = |v: &Vec3| v.iter().all(|c| c.is_finite());
            if determinant != 0.0 && finite(&dpdu) && finite(&dpdv) {
                surface.dpdu = dpdu;
                surface.dpdv = dpdv;
            }
        }
        if smooth && let Some(normals) = self.data.normals.as_ref().filter(|n| n.len() == p.len()) {
            let n = normals[a] * b0 + normals[b] * b1 + normals[c] * b2;
            surface.shading_normal = normalize_or(n, surface.geometric_normal);
        }
        surface
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smooth_normals_and_uvs_are_interpolated() {
        let data = MeshData {
            positions: vec![Point3::zeros(), Point3::x(), Point3::y()],
            normals: Some(vec![Vec3::z(), Vec3::new(1.0, 0.0, 1.0), Vec3::z()]),
            uvs: Some(vec![[0.0, 0.0], [2.0, 0.0], [0.0, 4.0]]),
            triangles: vec![[0, 1, 2]],
        };
        let mesh = Mesh::new(Arc::new(data));
        let ray = Ray::new(Point3::new(0.5, 0.25, 1.0), -Vec3::z(), 0.0);
        let hit = mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let smooth = mesh.surface(&ray, &hit, true);
        let flat = mesh.surface(&ray, &hit, false);
        assert_eq!(flat.shading_normal, Vec3::z());
        let expected =
            (Vec3::z() * 0.25 + Vec3::new(1.0, 0.0, 1.0) * 0.5 + Vec3::z() * 0.25).normalize();
        assert!((smooth.shading_normal - expected).norm() < 1e-12);
        assert_eq!(smooth.geometric_normal, Vec3::z());
        assert!((smooth.uv[0] - 1.0).abs() < 1e-12 && (smooth.uv[1] - 1.0).abs() < 1e-12);
        // u = 2x and v = 4y in this parametrisation.
        assert!((smooth.dpdu - Vec3::x() / 2.0).norm() < 1e-12);
        assert!((smooth.dpdv - Vec3::y() / 4.0).norm() < 1e-12);
    }

    #[test]
    fn out_of_range_indices_are_ignored() {
        let data = MeshData {
            positions: vec![Point3::zeros(), Point3::x(), Point3::y()],
            normals: None,
            uvs: None,
            triangles: vec![[0, 1, 7], [0, 1, 2]],
        };
        let mesh = Mesh::new(Arc::new(data));
        let ray = Ray::new(Point3::new(0.25, 0.25, 1.0), -Vec3::z(), 0.0);
        assert_eq!(mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap().index, 1);
    }
}
