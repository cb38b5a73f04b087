//! The object tree: groups, the global `MaterialIndex`, transforms, meshes, revolutions.

use std::collections::HashMap;
use std::path::PathBuf;
use std::sync::Arc;

use nalgebra::{Rotation3, Unit};

use crate::math::{Matrix, Vec3};
use crate::scene::ast::{Block, ItemKind};
use crate::scene::build::shapes::{Fields, build_shape};
use crate::scene::build::{Context, Cursor, obj, paths};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::{CurveKind, MeshData, Object, Profile};

/// Walks `Group` blocks; the current material is global state, as in the original.
pub struct ObjectBuilder {
    material_count: usize,
    current: usize,
    meshes: HashMap<PathBuf, Arc<MeshData>>,
}

impl ObjectBuilder {
    pub fn new(material_count: usize) -> Self {
        ObjectBuilder {
            material_count,
            current: 0,
            meshes: HashMap::new(),
        }
    }

    /// `Group { numObjects n (MaterialIndex i | object)* }`.
    pub fn group(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Object, SceneError> {
        let mut children = Vec::new();
        let mut expected = None;
        let mut found = 0usize;
        let mut cursor = Cursor::of(block);
        while let Some(item) = cursor.next() {
            match &item.kind {
                ItemKind::Block(child) => {
                    found += 1;
                    if let Some(object) = self.object(context, child, item.location)? {
                        children.push(object);
                    }
                }
                ItemKind::Word(key) if key == "numObjects" => {
                    expected = Some((cursor.integer(context, key)?, item.location));
                }
                ItemKind::Word(key) if key == "MaterialIndex" || key == "materialIndex" => {
                    self.select_material(context, &mut cursor, key)?;
                }
                ItemKind::Word(key) if key != "-" => {
                    context.skip_field(&mut cursor, key, item.location, &block.name)?
                }
                _ => context.skip_item(item, &block.name)?,
            }
        }
        if let Some((n, at)) = expected
            && n != found as i64
        {
            context.warn(
                at,
                format!("numObjects says {n} but {found} objects follow"),
            )?;
        }
        let _ = location;
        Ok(Object::Group(children))
    }

    fn select_material(
        &mut self,
        context: &mut Context,
        cursor: &mut Cursor,
        key: &str,
    ) -> Result<(), SceneError> {
        let at = cursor.here();
        let index = cursor.integer(context, key)?;
        if index < 0 || index as usize >= self.material_count {
            return Err(context.error(
                at,
                format!(
                    "material index {index} is out of range (the file has {} materials)",
                    self.material_count
                ),
            ));
        }
        self.current = index as usize;
        Ok(())
    }

    /// Any object block; `None` for skipped (unknown or unsupported) blocks.
    pub fn object(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Option<Object>, SceneError> {
        if let Some(shape) = build_shape(context, block, location, self.current)? {
            return Ok(Some(shape));
        }
        match block.name.as_str() {
            "Group" => self.group(context, block, location).map(Some),
            "Transform" => self.transform(context, block, location).map(Some),
            "TriangleMesh" | "Mesh" => self.mesh(context, block, location).map(Some),
            "RevSurface" => self.revolution(context, block, location).map(Some),
            "BezierCurve" | "BsplineCurve" => {
                context.warn(location, "a curve outside RevSurface is ignored".into())?;
                Ok(None)
            }
            "MotionBlur" | "Fractal" | "Portal" | "SceneGroup" => {
                context.unsupported("piu's MotionBlur/Fractal/Portal and SceneGroup are ignored");
                Ok(None)
            }
            other => {
                context.warn(location, format!("unknown object '{other}', skipped"))?;
                Ok(None)
            }
        }
    }

    /// `Transform { op* object }`: `M = M * Op` in reading order (Matrix4f: `Op * M`).
    fn transform(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Object, SceneError> {
        let mut matrix = Matrix::identity();
        let mut children = Vec::new();
        let mut cursor = Cursor::of(block);
        while let Some(item) = cursor.next() {
            match &item.kind {
                ItemKind::Word(op) => match op.as_str() {
                    "Translate" => {
                        matrix *= Matrix::new_translation(&cursor.vec3(context, op)?);
                    }
                    "Scale" => {
                        matrix *= Matrix::new_nonuniform_scaling(&cursor.vec3(context, op)?);
                    }
                    "UniformScale" => matrix *= Matrix::new_scaling(cursor.number(context, op)?),
                    "XRotate" | "YRotate" | "ZRotate" => {
                        let axis = match op.as_str() {
                            "XRotate" => Vec3::x(),
                            "YRotate" => Vec3::y(),
                            _ => Vec3::z(),
                        };
                        let degrees = cursor.number(context, op)?;
                        matrix *= rotation(axis, degrees);
                    }
                    "MaterialIndex" | "materialIndex" => {
                        self.select_material(context, &mut cursor, op)?
                    }
                    "-" => {}
                    _ => context.skip_field(&mut cursor, op, item.location, "Transform")?,
                },
                ItemKind::Block(inner) if inner.name == "Rotate" => {
                    let mut c = Cursor::of(inner);
                    let axis = c.vec3(context, "Rotate")?;
                    let degrees = c.number(context, "Rotate")?;
                    if axis.norm() < 1e-300 {
                        return Err(context.error(item.location, "rotation axis is zero".into()));
                    }
                    matrix *= rotation(axis, degrees);
                }
                ItemKind::Block(inner) if inner.name == "Matrix4f" || inner.name == "Matrix4d" => {
                    let mut c = Cursor::of(inner);
                    let mut values = [0.0; 16];
                    for value in &mut values {
                        *value = c.number(context, &inner.name)?;
                    }
                    matrix = Matrix::from_column_slice(&values) * matrix;
                }
                ItemKind::Block(inner) => {
                    if let Some(child) = self.object(context, inner, item.location)? {
                        children.push(child);
                    }
                }
                _ => context.skip_item(item, "Transform")?,
            }
        }
        let child = match children.len() {
            1 => children.pop().unwrap_or(Object::Group(Vec::new())),
            n => {
                context.warn(location, format!("Transform holds {n} objects, expected 1"))?;
                Object::Group(children)
            }
        };
        wrap(context, matrix, child, location)
    }

    /// `TriangleMesh { [smooth] obj_file path }`.
    fn mesh(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Object, SceneError> {
        let mut file = None;
        let mut smooth = false;
        let mut cursor = Cursor::of(block);
        while let Some(item) = cursor.next() {
            match item.word() {
                Some("obj_file") => {
                    let at = cursor.here();
                    file = Some((cursor.word(context, "obj_file")?, at));
                }
                Some("smooth") | Some("normalInterpolation") => smooth = true,
                Some("disableDiffuseTexture") | Some("disableNormalTexture") => {}
                Some(key) => context.skip_field(&mut cursor, key, item.location, &block.name)?,
                None => context.skip_item(item, &block.name)?,
            }
        }
        let Some((relative, at)) = file else {
            return Err(context.error(location, format!("{} needs 'obj_file'", block.name)));
        };
        let path = paths::resolve(relative, context.file, context.options).map_err(|tried| {
            context.error(
                at,
                format!(
                    "mesh '{relative}' not found (tried {})",
                    paths::describe_tried(&tried)
                ),
            )
        })?;
        let mesh = match self.meshes.get(&path) {
            Some(mesh) => mesh.clone(),
            None => {
                let (mesh, warnings) = obj::load_obj(&path).map_err(|e| context.error(at, e))?;
                for warning in warnings {
                    context.warn(at, warning)?;
                }
                let mesh = Arc::new(mesh);
                self.meshes.insert(path, mesh.clone());
                mesh
            }
        };
        Ok(Object::Mesh {
            mesh,
            smooth,
            material: self.current,
        })
    }

    /// `RevSurface { [axis v center c] profile Curve { controls [x y z]* } [position v] }`.
    fn revolution(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Object, SceneError> {
        let mut profile = None;
        let mut outer = Vec::new();
        for item in &block.items {
            if let Some(curve) = item.block() {
                profile = Some(read_profile(context, curve, item.location)?);
            } else if let Some(word) = item.word()
                && word != "profile"
            {
                outer.push(item.clone());
            } else if item.word().is_none() {
                outer.push(item.clone());
            }
        }
        let Some(profile) = profile else {
            return Err(context.error(location, "RevSurface needs a profile curve".into()));
        };
        let rest = Block {
            name: block.name.clone(),
            items: outer,
            close: block.close,
        };
        let f = Fields::read(context, &rest, location, &["axis", "center", "position"])?;
        let object = Object::Revolution {
            profile,
            material: self.current,
        };
        let mut matrix = Matrix::identity();
        if f.has("position") {
            matrix = Matrix::new_translation(&f.vec3(context, "position")?);
        }
        if f.has("axis") || f.has("center") {
            let axis = f.vec3_or(context, "axis", Vec3::y())?;
            let center = f.vec3_or(context, "center", Vec3::zeros())?;
            let turn = Rotation3::rotation_between(&Vec3::y(), &axis).unwrap_or_else(|| {
                Rotation3::from_axis_angle(&Vec3::x_axis(), std::f64::consts::PI)
            });
            matrix *= Matrix::new_translation(&center) * turn.to_homogeneous();
        }
        if matrix == Matrix::identity() {
            return Ok(object);
        }
        wrap(context, matrix, object, location)
    }
}

fn rotation(axis: Vec3, degrees: f64) -> Matrix {
    Rotation3::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians()).to_homogeneous()
}

/// A transform node with its inverse; a singular matrix is an error.
fn wrap(
    context: &Context,
    matrix: Matrix,
    child: Object,
    location: Location,
) -> Result<Object, SceneError> {
    let inverse = matrix
        .try_inverse()
        .filter(|inverse| inverse.iter().chain(matrix.iter()).all(|v| v.is_finite()));
    let Some(inverse) = inverse else {
        return Err(context.error(location, "the transform matrix is singular".into()));
    };
    Ok(Object::Transform {
        matrix,
        inverse,
        child: Box::new(child),
    })
}

fn read_profile(
    context: &mut Context,
    curve: &Block,
    location: Location,
) -> Result<Profile, SceneError> {
    let kind = match curve.name.as_str() {
        "BezierCurve" => CurveKind::Bezier,
        "BsplineCurve" => CurveKind::Bspline,
        other => {
            return Err(context.error(location, format!("unknown profile curve '{other}'")));
        }
    };
    let mut controls = Vec::new();
    for item in &curve.items {
        match &item.kind {
            ItemKind::List(point) => match point.as_slice() {
                [x, y, ..] if x.is_finite() && y.is_finite() => controls.push([*x, *y]),
                _ => {
                    return Err(
                        context.error(item.location, "a control point needs finite x and y".into())
                    );
                }
            },
            ItemKind::Word(w) if w == "controls" || w == "num_controls" => {}
            ItemKind::Number(_) => {}
            _ => context.skip_item(item, &curve.name)?,
        }
    }
    let needed = match kind {
        CurveKind::Bezier => 2,
        CurveKind::Bspline => 4,
    };
    if controls.len() < needed {
        return Err(context.error(
            location,
            format!("{} needs at least {needed} control points", curve.name),
        ));
    }
    Ok(Profile { kind, controls })
}
