//! Triangle meshes with their own BVH (`accel::LeafTriangles`); uvs when the
//! file has them.
//! One `Mesh` is built per distinct `MeshData` and shared by all its instances.
//!
//! Shading normals: the file's vertex normals (`vn`) are always interpolated
//! when it has them; a file without them is flat-shaded unless an instance
//! asks for `smooth`, which interpolates area-weighted vertex normals (the sum
//! of the unnormalised face normals around each vertex), computed once per
//! mesh ([`Mesh::with_smooth_normals`]).

use std::sync::Arc;

use super::triangle::surface_vertices;
use super::{Intersection, SurfaceHit, normalize_or};
use crate::accel::LeafTriangles;
use crate::math::{Aabb, Point3, Ray, Vec3};

/// Triangle mesh data as loaded from an OBJ file (object space).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MeshData {
    pub positions: Vec<Point3>,
    /// Per-vertex normals (same length as `positions`) when the file has them.
    pub normals: Option<Vec<Vec3>>,
    /// Per-vertex texture coordinates when the file has them.
    pub uvs: Option<Vec<[f64; 2]>>,
    pub triangles: Vec<[u32; 3]>,
    /// The same file as the course framework's loader reads it (flat, its
    /// own triangles: see `scene::build::obj_framework`), for the looks that
    /// read OBJ files that way; `None` when it reads the same triangles.
    pub framework_reading: Option<Arc<MeshData>>,
}

#[derive(Debug)]
pub struct Mesh {
    pub data: Arc<MeshData>,
    /// The valid triangles and their BVH, in its leaf order.
    triangles: LeafTriangles,
    /// Area-weighted vertex normals, for `smooth` instances of a file
    /// without `vn` (see the module docs).
    computed_normals: Option<Vec<Vec3>>,
    /// Tested by W-Solaris's triangle test in single precision
    /// (`single_precision::triangle`).
    pub single_precision: bool,
}

impl Mesh {
    /// Builds the triangle BVH. Triangles with out-of-range indices are left out.
    pub fn new(data: Arc<MeshData>) -> Mesh {
        let count = data.positions.len();
        let triangles = LeafTriangles::build(data.triangles.len(), |i| {
            let triangle = data.triangles[i];
            (!triangle.iter().any(|&i| i as usize >= count))
                .then(|| triangle.map(|i| data.positions[i as usize]))
        });
        Mesh {
            data,
            triangles,
            computed_normals: None,
            single_precision: false,
        }
    }

    /// [`Mesh::new`], and area-weighted vertex normals when the data has no
    /// normals of its own (for its `smooth` instances).
    pub fn with_smooth_normals(data: Arc<MeshData>) -> Mesh {
        let mut mesh = Mesh::new(data);
        if mesh.file_normals().is_none() {
            mesh.computed_normals = Some(area_weighted_normals(
                &mesh.data.positions,
                &mesh.data.triangles,
            ));
        }
        mesh
    }

    /// The area-weighted vertex normals, when they were computed.
    pub fn computed_normals(&self) -> Option<&[Vec3]> {
        self.computed_normals.as_deref()
    }

    /// The file's vertex normals, when there is one per vertex.
    fn file_normals(&self) -> Option<&[Vec3]> {
        self.data
            .normals
            .as_deref()
            .filter(|n| n.len() == self.data.positions.len())
    }

    pub fn triangle_count(&self) -> usize {
        self.data.triangles.len()
    }

    /// Bounds of the (valid) triangles, `None` for an empty mesh.
    pub fn bounds(&self) -> Option<Aabb> {
        (!self.triangles.is_empty()).then(|| self.triangles.bounds())
    }

    /// Nearest triangle hit: `u, v` are barycentrics, `index` the triangle.
    pub fn intersect(&self, ray: &Ray, t_min: f64, t_max: f64) -> Option<Intersection> {
        let hit = if self.single_precision {
            self.triangles
                .intersect_single_precision(ray, t_min, t_max)?
        } else {
            self.triangles.intersect(ray, t_min, t_max)?
        };
        Some(Intersection {
            t: hit.t,
            u: hit.b1,
            v: hit.b2,
            index: hit.index,
            slot: hit.slot,
        })
    }

    /// Whether any triangle lies on the ray within `(t_min, t_max)`.
    pub fn occluded(&self, ray: &Ray, t_min: f64, t_max: f64) -> bool {
        if self.single_precision {
            self.triangles.occluded_single_precision(ray, t_min, t_max)
        } else {
            self.triangles.occluded(ray, t_min, t_max)
        }
    }

    /// The surface at a hit: the file's vertex normals are interpolated when it
    /// has them, else the computed ones when `smooth` (see the module docs).
    pub fn surface(&self, _ray: &Ray, hit: &Intersection, smooth: bool) -> SurfaceHit {
        // The vertices from the triangle just tested (cached; a hit made
        // elsewhere looks them up), the file's indices only for its uvs and
        // normals.
        let [pa, pb, pc] = self
            .triangles
            .vertices(hit.slot, hit.index)
            .unwrap_or_else(|| {
                self.data.triangles[hit.index as usize].map(|i| self.data.positions[i as usize])
            });
        let (b1, b2) = (hit.u, hit.v);
        let b0 = 1.0 - b1 - b2;
        let mut surface = surface_vertices(&pa, &pb, &pc, b1, b2);
        let vertex_count = self.data.positions.len();
        let uvs = self
            .data
            .uvs
            .as_ref()
            .filter(|uvs| uvs.len() == vertex_count);
        let normals = match self.file_normals() {
            Some(normals) => Some(normals),
            None if smooth => self.computed_normals(),
            None => None,
        };
        if uvs.is_none() && normals.is_none() {
            return surface;
        }
        let [a, b, c] = self.data.triangles[hit.index as usize].map(|i| i as usize);
        if let Some(uvs) = uvs {
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
            let (edge1, edge2) = (pb - pa, pc - pa);
            let dpdu = (edge1 * dv2 - edge2 * dv1) / determinant;
            let dpdv = (edge2 * du1 - edge1 * du2) / determinant;
            let finite = |v: &Vec3| v.iter().all(|c| c.is_finite());
            if determinant != 0.0 && finite(&dpdu) && finite(&dpdv) {
                surface.dpdu = dpdu;
                surface.dpdv = dpdv;
            }
        }
        if let Some(normals) = normals {
            let n = normals[a] * b0 + normals[b] * b1 + normals[c] * b2;
            surface.shading_normal = normalize_or(n, surface.geometric_normal);
        }
        surface
    }
}

/// Per vertex, the normalised sum of the cross products `(p1 - p0) x (p2 - p0)`
/// of the triangles around it (each face weighted by its area); zero for a
/// vertex of no triangle with area. Triangles with out-of-range indices or
/// zero area are skipped.
pub fn area_weighted_normals(positions: &[Point3], triangles: &[[u32; 3]]) -> Vec<Vec3> {
    let mut sums = vec![Vec3::zeros(); positions.len()];
    for triangle in triangles {
        let vertex = |k: usize| positions.get(triangle[k] as usize);
        let (Some(a), Some(b), Some(c)) = (vertex(0), vertex(1), vertex(2)) else {
            continue;
        };
        let face = (b - a).cross(&(c - a));
        if !(face.norm_squared() > 0.0 && face.iter().all(|x| x.is_finite())) {
            continue;
        }
        for &i in triangle {
            sums[i as usize] += face;
        }
    }
    sums.into_iter()
        .map(|sum| normalize_or(sum, Vec3::zeros()))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn file_normals_and_uvs_are_interpolated_smooth_or_not() {
        let data = MeshData {
            framework_reading: None,
            positions: vec![Point3::zeros(), Point3::x(), Point3::y()],
            normals: Some(vec![Vec3::z(), Vec3::new(1.0, 0.0, 1.0), Vec3::z()]),
            uvs: Some(vec![[0.0, 0.0], [2.0, 0.0], [0.0, 4.0]]),
            triangles: vec![[0, 1, 2]],
        };
        let mesh = Mesh::new(Arc::new(data));
        let ray = Ray::new(Point3::new(0.5, 0.25, 1.0), -Vec3::z(), 0.0);
        let hit = mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        let smooth = mesh.surface(&ray, &hit, true);
        let plain = mesh.surface(&ray, &hit, false);
        let expected =
            (Vec3::z() * 0.25 + Vec3::new(1.0, 0.0, 1.0) * 0.5 + Vec3::z() * 0.25).normalize();
        assert!((smooth.shading_normal - expected).norm() < 1e-12);
        assert_eq!(plain.shading_normal, smooth.shading_normal);
        assert_eq!(smooth.geometric_normal, Vec3::z());
        assert!((smooth.uv[0] - 1.0).abs() < 1e-12 && (smooth.uv[1] - 1.0).abs() < 1e-12);
        // u = 2x and v = 4y in this parametrisation.
        assert!((smooth.dpdu - Vec3::x() / 2.0).norm() < 1e-12);
        assert!((smooth.dpdv - Vec3::y() / 4.0).norm() < 1e-12);
        // The file's normals win: nothing is computed.
        assert!(
            Mesh::with_smooth_normals(Arc::clone(&mesh.data))
                .computed_normals()
                .is_none()
        );
    }

    #[test]
    fn computed_normals_only_for_smooth_instances() {
        // A folded pair of triangles: the shared edge's vertices average both faces.
        let data = MeshData {
            framework_reading: None,
            positions: vec![
                Point3::zeros(),
                Point3::x(),
                Point3::new(0.0, 1.0, 0.0),
                Point3::new(0.0, -1.0, 1.0),
            ],
            normals: None,
            uvs: None,
            triangles: vec![[0, 1, 2], [1, 0, 3], [0, 0, 1]],
        };
        let mesh = Mesh::with_smooth_normals(Arc::new(data));
        let normals = mesh.computed_normals().expect("computed");
        assert!((normals[2] - Vec3::z()).norm() < 1e-12);
        // Face normals z (area 1/2) and (0, 1, 1) (area sqrt(2)/2), unnormalised.
        assert!((normals[3] - Vec3::new(0.0, 1.0, 1.0).normalize()).norm() < 1e-12);
        let shared = Vec3::new(0.0, 1.0, 2.0).normalize();
        assert!((normals[0] - shared).norm() < 1e-12);
        assert!((normals[1] - shared).norm() < 1e-12);
        let ray = Ray::new(Point3::new(0.2, 0.2, 1.0), -Vec3::z(), 0.0);
        let hit = mesh.intersect(&ray, 0.0, f64::INFINITY).unwrap();
        assert_eq!(mesh.surface(&ray, &hit, false).shading_normal, Vec3::z());
        assert_ne!(mesh.surface(&ray, &hit, true).shading_normal, Vec3::z());
    }

    #[test]
    fn out_of_range_indices_are_ignored() {
        let data = MeshData {
            framework_reading: None,
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
