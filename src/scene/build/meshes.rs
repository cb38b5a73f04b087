//! The OBJ files of a scene, each read once, and which material their
//! triangles get: the scene's current one, or the file's `.mtl` materials.
//!
//! The `.mtl` materials are used when no `MaterialIndex` precedes the mesh
//! in the scene (the current material is then the implicit default), or in
//! bow's dialect, whose renderer lets them win over `MaterialIndex`;
//! otherwise the scene's material wins, with a warning, and the `.mtl`
//! materials are kept as written (`OverriddenMtl`) for the looks whose
//! renderer lets them win (`emj`, see `render_scene::emily_jia_mtl`). Used `.mtl`
//! materials are converted once per file (see `mtl`) and appended to the
//! scene's materials; triangles without `usemtl` keep the scene's material.
//! A missing or unreadable `.mtl` is warned where its materials would be
//! used: not under a `MaterialIndex` that overrides them (the Stanford
//! dragon's `mtllib dragon.mtl`, which does not exist, in a scene that
//! gives the dragons their material).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use crate::geometry::MeshData;
use crate::limits::shown_path;
use crate::scene::build::textures::MaterialImages;
use crate::scene::build::{Context, mtl, obj};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::{Dialect, OWN_MATERIAL, OverriddenMtl};

/// The `MaterialIndex` that set the current material: its value and where.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MaterialChoice {
    pub index: i64,
    pub location: Location,
}

/// A mesh as one `TriangleMesh` uses it.
pub struct MeshInstance {
    pub mesh: Arc<MeshData>,
    /// Per triangle, when the `.mtl` materials apply (see `Object::Mesh`).
    pub face_materials: Option<Arc<[u32]>>,
    /// The `.mtl` materials, as written, when `MaterialIndex` overrides them.
    pub overridden_mtl: Option<Arc<OverriddenMtl>>,
}

/// One OBJ file, read.
struct MeshFile {
    mesh: Arc<MeshData>,
    materials: Option<obj::ObjMaterials>,
    /// Per triangle, the scene material index (after conversion), or
    /// [`OWN_MATERIAL`].
    face_materials: Option<Arc<[u32]>>,
    /// Warnings of its `.mtl` files, not given yet (see the module docs).
    library_warnings: Vec<String>,
    /// Its `.mtl` materials as written, once some `MaterialIndex` overrode them.
    overridden_mtl: Option<Arc<OverriddenMtl>>,
}

/// The scene's OBJ files and the `.mtl` materials they added.
pub struct Meshes {
    /// The scene's own materials come first; `.mtl` ones are numbered after them.
    first_material: usize,
    files: HashMap<PathBuf, MeshFile>,
    added: Vec<MaterialImages>,
    /// Time spent reading OBJ files.
    pub seconds: f64,
}

impl Meshes {
    pub fn new(first_material: usize) -> Meshes {
        Meshes {
            first_material,
            files: HashMap::new(),
            added: Vec::new(),
            seconds: 0.0,
        }
    }

    /// Distinct OBJ files read so far.
    pub fn len(&self) -> usize {
        self.files.len()
    }

    /// The `.mtl` materials added so far, in index order from
    /// `first_material`; taken once, after every mesh.
    pub fn take_materials(&mut self) -> Vec<MaterialImages> {
        std::mem::take(&mut self.added)
    }

    /// The mesh data of `path` (read at `at`) and, when its `.mtl`
    /// materials apply (see the module docs), its per-triangle materials.
    pub fn instance(
        &mut self,
        context: &mut Context,
        path: &Path,
        at: Location,
        chosen: Option<MaterialChoice>,
    ) -> Result<MeshInstance, SceneError> {
        if !self.files.contains_key(path) {
            let started = std::time::Instant::now();
            let loaded = obj::load_obj(path).map_err(|e| context.error(at, e))?;
            self.seconds += started.elapsed().as_secs_f64();
            context.assets.push(path.to_path_buf());
            if let Some(materials) = &loaded.materials {
                let libraries = materials.libraries.iter().map(|l| l.path.clone());
                context.assets.extend(libraries);
            }
            for warning in loaded.warnings {
                context.warn(at, warning)?;
            }
            if loaded.mesh.triangles.is_empty() {
                let message = format!(
                    "mesh '{}' has no triangles: nothing of it is rendered",
                    shown_path(path)
                );
                context.warn(at, message)?;
            }
            let file = MeshFile {
                mesh: Arc::new(loaded.mesh),
                materials: loaded.materials,
                face_materials: None,
                library_warnings: loaded.library_warnings,
                overridden_mtl: None,
            };
            self.files.insert(path.to_path_buf(), file);
        }
        let Some(file) = self.files.get_mut(path) else {
            return Err(context.error(at, format!("mesh '{}' was not kept", shown_path(path))));
        };
        let mesh = Arc::clone(&file.mesh);
        let overridden = chosen.filter(|_| context.dialect != Dialect::Bow);
        if overridden.is_none() {
            for warning in std::mem::take(&mut file.library_warnings) {
                context.warn(at, warning)?;
            }
        }
        let plain = |mesh| MeshInstance {
            mesh,
            face_materials: None,
            overridden_mtl: None,
        };
        let Some(materials) = &file.materials else {
            return Ok(plain(mesh));
        };
        if let Some(choice) = overridden {
            let message = format!(
                "mesh '{}': its .mtl materials are overridden by MaterialIndex {} (line {}), \
                 except in the emj look (emily-jia's loader lets them win)",
                shown_path(path),
                choice.index,
                choice.location.line
            );
            context.warn(at, message)?;
            let overridden = file
                .overridden_mtl
                .get_or_insert_with(|| Arc::new(as_written(materials)));
            return Ok(MeshInstance {
                overridden_mtl: Some(Arc::clone(overridden)),
                ..plain(mesh)
            });
        }
        if file.face_materials.is_none() {
            let first = self.first_material + self.added.len();
            let converted = mtl::convert(context, path, materials, at)?;
            self.added.extend(converted);
            let faces = materials
                .faces
                .iter()
                .map(|&m| match m {
                    OWN_MATERIAL => OWN_MATERIAL,
                    m => (first + m as usize).min(OWN_MATERIAL as usize - 1) as u32,
                })
                .collect();
            file.face_materials = Some(faces);
        }
        Ok(MeshInstance {
            mesh,
            face_materials: file.face_materials.clone(),
            overridden_mtl: None,
        })
    }
}

/// An OBJ's `.mtl` materials as written (see [`OverriddenMtl`]).
fn as_written(materials: &obj::ObjMaterials) -> OverriddenMtl {
    OverriddenMtl {
        libraries: materials
            .libraries
            .iter()
            .map(|library| library.text.clone())
            .collect(),
        materials: materials
            .materials
            .iter()
            .enumerate()
            .map(|(index, material)| {
                let library = materials.library_of.get(index).copied();
                (material.name.clone(), library.unwrap_or(usize::MAX))
            })
            .collect(),
        faces: materials.faces.iter().copied().collect(),
    }
}
