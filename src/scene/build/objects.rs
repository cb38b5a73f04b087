//! The object tree: groups, the global `MaterialIndex`, transforms, meshes, revolutions.

use nalgebra::Rotation3;

use crate::limits::MAX_NESTING;
use crate::limits::shown;
use crate::math::{Matrix, Vec3};
use crate::scene::MissingAssets;
use crate::scene::ast::{Block, ItemKind};
use crate::scene::build::degenerate::why_without_area;
use crate::scene::build::meshes::{MaterialChoice, Meshes};
use crate::scene::build::profile::read_profile;
use crate::scene::build::shapes::{Fields, build_shape};
use crate::scene::build::textures::MaterialImages;
use crate::scene::build::transform::wrap;
use crate::scene::build::{Context, Cursor, paths, transform};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::Object;

/// Walks `Group` blocks; the current material is global state, as in the original.
pub struct ObjectBuilder {
    material_count: usize,
    current: usize,
    /// The `MaterialIndex` that chose `current`; `None` while it is the
    /// implicit default (decides whether a mesh's `.mtl` materials apply).
    chosen: Option<MaterialChoice>,
    meshes: Meshes,
    /// How many objects enclose the one being built (a bound on the
    /// recursion, for trees that did not come through the parser's own).
    depth: usize,
}

impl ObjectBuilder {
    /// Distinct OBJ files read so far.
    pub fn meshes_loaded(&self) -> usize {
        self.meshes.len()
    }

    /// Time spent reading OBJ files.
    pub fn mesh_seconds(&self) -> f64 {
        self.meshes.seconds
    }

    /// The `.mtl` materials that meshes use, numbered from the scene's
    /// material count on (taken once, after all groups).
    pub fn take_materials(&mut self) -> Vec<MaterialImages> {
        self.meshes.take_materials()
    }

    pub fn new(material_count: usize) -> Self {
        ObjectBuilder {
            material_count,
            current: 0,
            chosen: None,
            meshes: Meshes::new(material_count),
            depth: 0,
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
                ItemKind::Word(key) if &**key == "numObjects" => {
                    expected = Some((cursor.integer(context, key)?, item.location));
                }
                ItemKind::Word(key) if &**key == "MaterialIndex" || &**key == "materialIndex" => {
                    self.select_material(context, &mut cursor, key)?;
                }
                ItemKind::Word(key) if &**key != "-" => {
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

    pub fn select_material(
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
        self.chosen = Some(MaterialChoice {
            index,
            location: at,
        });
        Ok(())
    }

    /// Any object block; `None` for skipped (unknown or unsupported) blocks.
    /// Objects nested deeper than `MAX_NESTING` are an error, not a stack overflow.
    pub fn object(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Option<Object>, SceneError> {
        if self.depth >= MAX_NESTING {
            return Err(context.error(
                location,
                format!("objects nested deeper than {MAX_NESTING} levels"),
            ));
        }
        self.depth += 1;
        let object = self.nested_object(context, block, location);
        self.depth -= 1;
        object
    }

    fn nested_object(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Option<Object>, SceneError> {
        if let Some(shape) = build_shape(context, block, location, self.current)? {
            if let Some(why) = why_without_area(&shape) {
                let message = format!("a {} {why}: it is left out", block.name);
                context.warn(location, message)?;
                return Ok(None);
            }
            return Ok(Some(shape));
        }
        match block.name.as_str() {
            "Group" => self.group(context, block, location).map(Some),
            "Transform" => transform::build_transform(self, context, block, location).map(Some),
            "TriangleMesh" | "Mesh" => self.mesh(context, block, location).map(Some),
            "RevSurface" => self.revolution(context, block, location),
            "BezierCurve" | "BsplineCurve" => {
                context.warn(location, "a curve outside RevSurface is ignored".into())?;
                Ok(None)
            }
            "MotionBlur" | "Fractal" | "Portal" | "SceneGroup" => {
                context.not_rendered(
                    location,
                    &block.name,
                    "piu's special objects are not implemented",
                )?;
                Ok(None)
            }
            other => {
                context.warn(
                    location,
                    format!("unknown object '{}', skipped", shown(other)),
                )?;
                Ok(None)
            }
        }
    }

    /// `TriangleMesh { [smooth] obj_file path }`. Shading normals: the OBJ's
    /// `vn` are always interpolated when it has them; `smooth` (or
    /// `normalInterpolation`) asks for interpolated normals also when it has
    /// none, which are then area-weighted vertex normals computed once per
    /// file (see `geometry::mesh`). Without either, triangles are flat.
    /// The file's `.mtl` materials apply as `meshes` says. A missing file
    /// is an error, or an empty group with `--missing-assets placeholder`.
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
                Some(key @ ("disableDiffuseTexture" | "disableNormalTexture")) => {
                    context.not_rendered(item.location, key, ".mtl textures are not read")?
                }
                Some(key) => context.skip_field(&mut cursor, key, item.location, &block.name)?,
                None => context.skip_item(item, &block.name)?,
            }
        }
        let Some((relative, at)) = file else {
            return Err(context.error(location, format!("{} needs 'obj_file'", block.name)));
        };
        let path = match paths::resolve(relative, context.file, context.options) {
            Ok(path) => path,
            Err(tried) => {
                let missing = paths::missing("mesh", relative, &tried);
                if context.options.missing_assets == MissingAssets::Error {
                    return Err(context.error(at, missing));
                }
                // --missing-assets placeholder: the mesh is left out.
                context.warn(at, format!("{missing}: left out"))?;
                return Ok(Object::Group(Vec::new()));
            }
        };
        let instance = self.meshes.instance(context, &path, at, self.chosen)?;
        Ok(Object::Mesh {
            mesh: instance.mesh,
            smooth,
            material: self.current,
            face_materials: instance.face_materials,
            overridden_mtl: instance.overridden_mtl,
        })
    }

    /// `RevSurface { [axis v center c] profile Curve { controls [x y z]* } [position v] }`;
    /// `None` (with a warning) when the profile sweeps no area.
    fn revolution(
        &mut self,
        context: &mut Context,
        block: &Block,
        location: Location,
    ) -> Result<Option<Object>, SceneError> {
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
        let Some(profile) = profile else {
            return Ok(None);
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
            return Ok(Some(object));
        }
        wrap(context, matrix, object, location).map(Some)
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::build::build_text;
    use crate::scene::model::Object;

    const HEAD: &str =
        "PerspectiveCamera { width 2 height 2 }\nMaterials { Material { } Material { } }\n";

    fn leaves(text: &str) -> Result<Vec<Object>, String> {
        let scene = build_text(&format!("{HEAD}{text}"))?;
        let mut out = Vec::new();
        scene.root.for_each_leaf(&mut |leaf| out.push(leaf.clone()));
        Ok(out)
    }

    fn material(object: &Object) -> usize {
        match object {
            Object::Sphere { material, .. } | Object::Plane { material, .. } => *material,
            _ => usize::MAX,
        }
    }

    #[test]
    fn material_index_is_global_state() {
        let objects = leaves(
            "Group { numObjects 3 Sphere { center 0 0 0 radius 1 }\n Group { MaterialIndex 1 - } \
             Plane { normal 0 1 0 offset 0 } }",
        )
        .expect("builds");
        assert_eq!(objects.iter().map(material).collect::<Vec<_>>(), [0, 1]);
    }

    #[test]
    fn bad_material_index_has_a_location() {
        let e = leaves("Group {\n  MaterialIndex 2\n}").expect_err("out of range");
        assert!(
            e.contains("t.txt:4:17") && e.contains("out of range"),
            "{e}"
        );
    }

    #[test]
    fn missing_number_and_missing_mesh() {
        let e = leaves("Group { Sphere { center 0 0 radius 1 } }").expect_err("short vector");
        assert!(e.contains("t.txt:3:"), "{e}");
        let e = leaves("Group { TriangleMesh { obj_file mesh/none.obj } }").expect_err("no mesh");
        assert!(
            e.contains("mesh/none.obj") && e.contains("t.txt:3:33"),
            "{e}"
        );
    }

    #[test]
    fn shapes_of_every_dialect() {
        let objects = leaves(
            "Group { Rectangle { point 0 0 0 x 1 0 0 y 0 1 0 }\n\
             Rectangle { x0 0 y0 0 x1 2 y1 3 n 0 d 4 }\n\
             Rectangle { center 0 0 0 dirLen 1 0 0 dirWid 0 0 1 len 2 wid 4 }\n\
             XZRectangle { points 0 0 1 1 offset 5 normal -1 }\n\
             MovingSphere { center0 0 0 0 center1 1 0 0 time0 0 time1 1 radius 1 }\n\
             Disk { center 0 0 0 normal 0 1 0 radius 2 }\n\
             RevSurface { profile BsplineCurve { controls [0 0 0] [1 1 0] [1 2 0] [0 3 0] } position 1 0 0 }\n\
             Wobble { a 1 } BezierCurve { controls [ 0 0 0 ] [ 1 1 0 ] } }",
        )
        .expect("builds");
        assert_eq!(objects.len(), 7);
        let Object::Rectangle { origin, edge_u, .. } = &objects[2] else {
            panic!()
        };
        assert_eq!((origin.x, origin.z, edge_u.x), (-1.0, -2.0, 2.0));
        let Object::Rectangle { edge_u, edge_v, .. } = &objects[3] else {
            panic!()
        };
        assert!(edge_u.cross(edge_v).y < 0.0);
        let Object::Sphere { motion, .. } = &objects[4] else {
            panic!()
        };
        assert_eq!(motion.x, 1.0);
        assert!(matches!(objects[6], Object::Revolution { .. }));
    }

    #[test]
    fn osb_speed_moves_the_sphere_backwards_and_move_vector_forwards() {
        let objects = leaves(
            "Group { Sphere { center 0 0 0 radius 1 speed 15 15 0 }\n\
             Sphere { center 0 0 0 radius 1 moveVector 1 2 0 } }",
        )
        .expect("builds");
        use crate::math::Vec3;
        let motions: Vec<Vec3> = objects
            .iter()
            .filter_map(|o| match o {
                Object::Sphere { motion, .. } => Some(*motion),
                _ => None,
            })
            .collect();
        assert_eq!(
            motions,
            [Vec3::new(-15.0, -15.0, 0.0), Vec3::new(1.0, 2.0, 0.0)]
        );
    }

    #[test]
    fn zero_materials_get_a_default() {
        let scene = build_text(
            "PerspectiveCamera { width 2 height 2 }\nGroup { Sphere { center 0 0 0 radius 1 } }",
        )
        .expect("builds");
        assert_eq!(scene.materials.len(), 1);
    }
}
