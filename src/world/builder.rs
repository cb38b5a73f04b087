//! Flattening the scene's object tree into world primitives.

use std::collections::HashMap;
use std::sync::Arc;

use super::Primitive;
use crate::geometry::{
    Disk, Mesh, Plane, Rectangle, Revolution, Shape, Sphere, Transform, Triangle,
};
use crate::scene::model::Object;

#[derive(Default)]
pub(super) struct Builder {
    pub(super) primitives: Vec<Primitive>,
    /// One geometry mesh per distinct `MeshData` allocation.
    meshes: HashMap<*const crate::scene::model::MeshData, Arc<Mesh>>,
}

impl Builder {
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
            } => (*radius != 0.0 && radius.is_finite())
                .then(|| Shape::Sphere(Sphere::new(*center, *radius, *motion))),
            Object::Plane { normal, offset, .. } => Plane::new(*normal, *offset).map(Shape::Plane),
            Object::Triangle { vertices, .. } => Some(Shape::Triangle(Triangle::new(*vertices))),
            Object::Rectangle {
                origin,
                edge_u,
                edge_v,
                ..
            } => Rectangle::new(*origin, *edge_u, *edge_v).map(Shape::Rectangle),
            Object::Disk {
                center,
                normal,
                radius,
                ..
            } => Disk::new(*center, *normal, *radius).map(Shape::Disk),
            Object::Mesh { mesh, smooth, .. } => {
                let shared = self
                    .meshes
                    .entry(Arc::as_ptr(mesh))
                    .or_insert_with(|| Arc::new(Mesh::new(Arc::clone(mesh))));
                Some(Shape::Mesh {
                    mesh: Arc::clone(shared),
                    smooth: *smooth,
                })
            }
            Object::Revolution { profile, .. } => {
                Revolution::new(profile).map(|r| Shape::Revolution(Arc::new(r)))
            }
        };
        let material = object.material().unwrap_or(0);
        if let Some(shape) = shape {
            let transform = transform
                .filter(|t| !t.is_identity())
                .map(|t| Box::new(t.clone()));
            self.primitives.push(Primitive {
                shape,
                transform,
                material,
            });
        }
    }
}
