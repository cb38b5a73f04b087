//! Flattening the scene's object tree into world primitives.

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use super::{Primitive, ShapeRules};
use crate::geometry::MeshData;
use crate::geometry::{
    CavRevolution, Disk, Mesh, Plane, Rectangle, Revolution, RevolutionTest, SeededRevolution,
    Shape, Sphere, SphereTest, Transform, Triangle,
};
use crate::math::Matrix;
use crate::scene::model::Object;

/// The map that swaps y and z (its own inverse): a surface of revolution
/// about y becomes the same profile turned about z.
fn swap_y_z() -> Transform {
    let m = Matrix::new(
        1.0, 0.0, 0.0, 0.0, //
        0.0, 0.0, 1.0, 0.0, //
        0.0, 1.0, 0.0, 0.0, //
        0.0, 0.0, 0.0, 1.0,
    );
    Transform::new(m, m)
}

#[derive(Default)]
pub(super) struct Builder {
    pub(super) primitives: Vec<Primitive>,
    /// The look's rules for planes, spheres, triangles and surfaces of
    /// revolution.
    pub(super) rules: ShapeRules,
    /// One geometry mesh per distinct `MeshData` allocation.
    meshes: HashMap<*const MeshData, Arc<Mesh>>,
    /// The mesh data that some instance shades `smooth`.
    smooth: HashSet<*const MeshData>,
    /// Triangles of the cav tessellations built so far, and the most there
    /// may be ([`crate::limits::MAX_CAV_TESSELLATION_TRIANGLES`]).
    cav_triangles: usize,
    pub(super) cav_budget: usize,
    /// The surfaces built exact because their tessellation would pass it.
    pub(super) cav_exact_instead: usize,
}

impl Builder {
    /// A builder for the tree under `root`: it notes which meshes some
    /// instance shades smooth, so that their vertex normals are computed
    /// once, for all instances.
    pub(super) fn for_tree(root: &Object) -> Builder {
        let mut builder = Builder {
            cav_budget: crate::limits::MAX_CAV_TESSELLATION_TRIANGLES,
            ..Builder::default()
        };
        root.for_each_leaf(&mut |leaf| {
            if let Object::Mesh {
                mesh, smooth: true, ..
            } = leaf
            {
                builder.smooth.insert(Arc::as_ptr(mesh));
            }
        });
        builder
    }

    pub(super) fn visit(&mut self, object: &Object, transform: Option<&Transform>) {
        let shape = match object {
            Object::Group(children) => {
                for child in children {
                    self.visit(child, transform);
                }
                return;
            }
            Object::Transform {
                matrix,
                inverse,
                child,
            } => {
                let local = Transform::new(*matrix, *inverse);
                let combined = match transform {
                    Some(parent) => parent.compose(&local),
                    None => local,
                };
                self.visit(child, Some(&combined));
                return;
            }
            Object::Sphere {
                center,
                radius,
                motion,
                ..
            } => (*radius != 0.0 && radius.is_finite()).then(|| {
                let mut sphere = Sphere::new(*center, *radius, *motion);
                sphere.test = if self.rules.single_precision {
                    SphereTest::SinglePrecision
                } else {
                    self.rules.sphere_test
                };
                Shape::Sphere(sphere)
            }),
            Object::Plane { normal, offset, .. } => {
                Plane::new(*normal, *offset).map(|mut plane| {
                    plane.one_sided = self.rules.one_sided_planes;
                    plane.accepts_zero = self.rules.planes_accept_zero;
                    plane.single_precision = self.rules.single_precision;
                    if self.rules.cav_plane_frames {
                        plane = plane.with_cav_frame();
                    }
                    plane.single_precision_two_sided = self.rules.single_precision_planes;
                    Shape::Plane(plane)
                })
            }
            Object::Triangle { vertices, .. } => {
                let mut triangle = Triangle::new(*vertices);
                triangle.single_precision = self.rules.single_precision;
                Some(Shape::Triangle(triangle))
            }
            Object::Rectangle {
                origin,
                edge_u,
                edge_v,
                ..
            } => Rectangle::new(*origin, *edge_u, *edge_v).map(|mut rectangle| {
                rectangle.cambrian = self.rules.cambrian_rectangles;
                Shape::Rectangle(rectangle)
            }),
            Object::Disk {
                center,
                normal,
                radius,
                ..
            } => Disk::new(*center, *normal, *radius).map(Shape::Disk),
            Object::Mesh { mesh, smooth, .. } => {
                let single_precision = self.rules.single_precision;
                if let Some(framework) = self.framework_reading(mesh) {
                    let key = Arc::as_ptr(framework);
                    let shared = Arc::clone(self.meshes.entry(key).or_insert_with(|| {
                        let mut built = Mesh::new(Arc::clone(framework));
                        built.single_precision = single_precision;
                        Arc::new(built)
                    }));
                    return self.push(
                        object,
                        Shape::Mesh {
                            mesh: shared,
                            smooth: false,
                        },
                        transform,
                        None,
                    );
                }
                let key = Arc::as_ptr(mesh);
                let face_normals = self.rules.face_normals;
                let smooth_somewhere = self.smooth.contains(&key) && !face_normals;
                let shared = self.meshes.entry(key).or_insert_with(|| {
                    let data = if face_normals && mesh.normals.is_some() {
                        Arc::new(MeshData {
                            normals: None,
                            ..MeshData::clone(mesh)
                        })
                    } else {
                        Arc::clone(mesh)
                    };
                    let mut built = if smooth_somewhere {
                        Mesh::with_smooth_normals(data)
                    } else {
                        Mesh::new(data)
                    };
                    built.single_precision = single_precision;
                    Arc::new(built)
                });
                Some(Shape::Mesh {
                    mesh: Arc::clone(shared),
                    smooth: *smooth && !face_normals,
                })
            }
            Object::Revolution { profile, .. } => match self.rules.revolution_test {
                RevolutionTest::TessellationSeeded => {
                    SeededRevolution::new(profile).map(|r| Shape::SeededRevolution(Arc::new(r)))
                }
                RevolutionTest::CavMesh => {
                    let triangles = CavRevolution::triangle_count(profile);
                    if self.cav_triangles.saturating_add(triangles) <= self.cav_budget {
                        self.cav_triangles += triangles;
                        CavRevolution::new(profile).map(|r| Shape::CavRevolution(Arc::new(r)))
                    } else {
                        self.cav_exact_instead += 1;
                        Revolution::new(profile).map(|r| Shape::Revolution(Arc::new(r)))
                    }
                }
                test => Revolution::new(profile).map(|mut revolution| {
                    revolution.test = test;
                    Shape::Revolution(Arc::new(revolution))
                }),
            },
        };
        let about_z = self.rules.revolutions_about_z
            && matches!(object, Object::Revolution { .. })
            && shape.is_some();
        let swapped;
        let transform = if about_z {
            swapped = match transform {
                Some(parent) => parent.compose(&swap_y_z()),
                None => swap_y_z(),
            };
            Some(&swapped)
        } else {
            transform
        };
        let face_materials = match object {
            Object::Mesh { face_materials, .. } => face_materials.clone(),
            _ => None,
        };
        if let Some(shape) = shape {
            self.push(object, shape, transform, face_materials);
        }
    }

    /// The framework's reading of `mesh`, when the look reads OBJ files
    /// that way and it differs from the standard one. It is flat (the
    /// framework reads no `vn`) and its triangles have the mesh's own
    /// material: the framework reads no `.mtl` either.
    fn framework_reading<'m>(&self, mesh: &'m MeshData) -> Option<&'m Arc<MeshData>> {
        self.rules
            .framework_obj_reading
            .then_some(mesh.framework_reading.as_ref())
            .flatten()
    }

    fn push(
        &mut self,
        object: &Object,
        shape: Shape,
        transform: Option<&Transform>,
        face_materials: Option<Arc<[u32]>>,
    ) {
        let transform = transform
            .filter(|t| !t.is_identity())
            .map(|t| Box::new(t.clone()));
        self.primitives.push(Primitive {
            shape,
            transform,
            material: object.material().unwrap_or(0),
            face_materials,
        });
    }
}
