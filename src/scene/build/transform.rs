//! `Transform { op* object }`: the operations of §3.7, composed into a matrix and its inverse.

use nalgebra::{Rotation3, Unit};

use crate::math::{Matrix, Vec3};
use crate::scene::ast::{Block, ItemKind};
use crate::scene::build::objects::ObjectBuilder;
use crate::scene::build::{Context, Cursor};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::Object;

/// `Transform { op* object }`: `M = M * Op` in reading order (Matrix4f: `Op * M`).
pub fn build_transform(
    builder: &mut ObjectBuilder,
    context: &mut Context,
    block: &Block,
    location: Location,
) -> Result<Object, SceneError> {
    let mut matrix = Matrix::identity();
    let mut children = Vec::new();
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        match &item.kind {
            ItemKind::Word(op) => match &**op {
                "Translate" => {
                    matrix *= Matrix::new_translation(&cursor.vec3(context, op)?);
                }
                "Scale" => {
                    matrix *= Matrix::new_nonuniform_scaling(&cursor.vec3(context, op)?);
                }
                "UniformScale" => matrix *= Matrix::new_scaling(cursor.number(context, op)?),
                "XRotate" | "YRotate" | "ZRotate" => {
                    let axis = match &**op {
                        "XRotate" => Vec3::x(),
                        "YRotate" => Vec3::y(),
                        _ => Vec3::z(),
                    };
                    let degrees = cursor.number(context, op)?;
                    matrix *= rotation(axis, degrees);
                }
                "MaterialIndex" | "materialIndex" => {
                    builder.select_material(context, &mut cursor, op)?
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
                if let Some(child) = builder.object(context, inner, item.location)? {
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

fn rotation(axis: Vec3, degrees: f64) -> Matrix {
    Rotation3::from_axis_angle(&Unit::new_normalize(axis), degrees.to_radians()).to_homogeneous()
}

/// A transform node with its inverse; a singular matrix is an error.
pub fn wrap(
    context: &Context,
    matrix: Matrix,
    child: Object,
    location: Location,
) -> Result<Object, SceneError> {
    let inverse = matrix
        .try_inverse()
        .filter(|inverse| inverse.iter().chain(matrix.iter()).all(|v| v.is_finite()));
    let Some(inverse) = inverse else {
        return Err(context.error(location, not_invertible(&matrix)));
    };
    Ok(Object::Transform {
        matrix,
        inverse,
        child: Box::new(child),
    })
}

/// Why `matrix` has no usable inverse: entries or a determinant beyond
/// floating point (`Scale 1e300`), or a zero determinant (a zero scale).
fn not_invertible(matrix: &Matrix) -> String {
    let largest = matrix.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    if !largest.is_finite() {
        return "the transform matrix is not finite (a scale, translation or matrix entry \
                overflows)"
            .to_string();
    }
    let determinant = matrix.determinant();
    if !determinant.is_finite() || determinant.abs() > 1e300 {
        return format!(
            "the transform scales by too much to be inverted in floating point (an entry of \
             {largest:e})"
        );
    }
    if determinant == 0.0 {
        return "the transform matrix is singular (it flattens space: a zero scale?)".to_string();
    }
    format!("the transform cannot be inverted in floating point (determinant {determinant:e})")
}

#[cfg(test)]
mod tests {
    use crate::math::{Point3, transform_point};
    use crate::scene::build::build_text;
    use crate::scene::model::Object;

    const CAMERA: &str = "PerspectiveCamera { width 2 height 2 }\n";

    fn transform_of(body: &str) -> Result<Object, String> {
        let scene = build_text(&format!("{CAMERA}Group {{ Transform {{ {body} }} }}"))?;
        match scene.root {
            Object::Group(mut children) => Ok(children.remove(0)),
            other => Ok(other),
        }
    }

    #[test]
    fn first_written_op_is_applied_last() {
        let Ok(Object::Transform {
            matrix, inverse, ..
        }) = transform_of("Translate 1 0 0 Scale 2 2 2 Sphere { center 0 0 0 radius 1 }")
        else {
            panic!("not a transform");
        };
        let p = transform_point(&matrix, &Point3::new(1.0, 0.0, 0.0));
        assert!((p - Point3::new(3.0, 0.0, 0.0)).norm() < 1e-12);
        let back = transform_point(&inverse, &p);
        assert!((back - Point3::new(1.0, 0.0, 0.0)).norm() < 1e-12);
    }

    #[test]
    fn rotations_and_matrices() {
        let Ok(Object::Transform { matrix, .. }) =
            transform_of("YRotate 90 Rotate { 0 0 1 90 } Sphere { center 0 0 0 radius 1 }")
        else {
            panic!("not a transform");
        };
        // Rotate about z first (x -> y), then about y (y stays).
        let p = transform_point(&matrix, &Point3::new(1.0, 0.0, 0.0));
        assert!((p - Point3::new(0.0, 1.0, 0.0)).norm() < 1e-12, "{p}");
        let Ok(Object::Transform { matrix, .. }) = transform_of(
            "Matrix4f { 1 0 0 0  0 1 0 0  0 0 1 0  5 6 7 1 } Sphere { center 0 0 0 radius 1 }",
        ) else {
            panic!("not a transform");
        };
        let p = transform_point(&matrix, &Point3::zeros());
        assert!((p - Point3::new(5.0, 6.0, 7.0)).norm() < 1e-12);
    }

    #[test]
    fn singular_matrix_is_an_error_with_location() {
        let e = transform_of("Scale 1 0 1 Sphere { center 0 0 0 radius 1 }").expect_err("singular");
        assert!(e.contains("t.txt:2:9") && e.contains("singular"), "{e}");
    }
}
