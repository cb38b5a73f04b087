//! OBJ meshes through `tobj`: triangulated, single-indexed, all models merged
//! into one, with the `.mtl` materials of their faces (converted by `mtl`).

use std::cell::RefCell;
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::{Path, PathBuf};

use crate::geometry::MeshData;
use crate::limits::shown_path;
use crate::limits::{MAX_MESH_BYTES, read_within};
use crate::math::{Point3, Vec3};
use crate::scene::build::degenerate::triangle_without_area;
use crate::scene::build::{obj_check, obj_framework};
use crate::scene::model::OWN_MATERIAL;

/// A `.mtl` file as read: where it is and its text (to find the lines of
/// fields for messages).
#[derive(Clone, Debug)]
pub struct MaterialLibrary {
    pub path: PathBuf,
    pub text: String,
}

/// An OBJ file's `.mtl` materials and which triangle uses which.
#[derive(Clone, Debug)]
pub struct ObjMaterials {
    pub materials: Vec<tobj::Material>,
    /// Per material: its library (index into `libraries`).
    pub library_of: Vec<usize>,
    pub libraries: Vec<MaterialLibrary>,
    /// Per triangle: an index into `materials`, or [`OWN_MATERIAL`] (no
    /// `usemtl`, or an unknown name).
    pub faces: Vec<u32>,
}

/// A loaded OBJ: the mesh, its `.mtl` materials when some face uses one,
/// and warnings: of the mesh (triangles left out), and of its `.mtl` files
/// (missing or unreadable), which matter only where they would be used.
pub struct LoadedObj {
    pub mesh: MeshData,
    pub materials: Option<ObjMaterials>,
    pub warnings: Vec<String>,
    pub library_warnings: Vec<String>,
}

/// Loads an OBJ file; a missing `.mtl` is only a warning, and so are
/// triangles without area (left out, counted in one warning per file).
pub fn load_obj(path: &Path) -> Result<LoadedObj, String> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let text = read_obj_text(path)?;
    obj_check::check_obj_text(&text)
        .map_err(|problem| format!("{}:{}: {}", shown_path(path), problem.line, problem.message))?;
    let folder = path.parent().unwrap_or(Path::new("")).to_path_buf();
    // tobj calls this once per `mtllib`, in order, and appends the materials
    // it returns: record each library with its text and material count.
    let libraries = RefCell::new(Vec::<(MaterialLibrary, usize)>::new());
    let library_warnings = RefCell::new(Vec::new());
    // Each library is read once however often `mtllib` names it (a repeat
    // adds no material), and all of them together within MAX_MESH_BYTES.
    let read_already = RefCell::new(Vec::<PathBuf>::new());
    let bytes_read = RefCell::new(0u64);
    let load_library = |name: &Path| {
        let full = folder.join(name);
        let identity = std::fs::canonicalize(&full).unwrap_or_else(|_| full.clone());
        if read_already.borrow().contains(&identity) {
            return Ok(Default::default());
        }
        read_already.borrow_mut().push(identity);
        let room = MAX_MESH_BYTES.saturating_sub(*bytes_read.borrow());
        let text = match read_within(
            &full,
            room,
            "limits::MAX_MESH_BYTES, for all of a mesh's .mtl files",
        ) {
            Ok(bytes) => {
                *bytes_read.borrow_mut() += bytes.len() as u64;
                String::from_utf8_lossy(&bytes).into_owned()
            }
            Err(e) => {
                library_warnings.borrow_mut().push(format!(
                    "mesh '{}': materials not loaded ({e})",
                    shown_path(path)
                ));
                return Err(tobj::LoadError::OpenFileFailed);
            }
        };
        let result = tobj::load_mtl_buf(&mut text.as_bytes());
        match &result {
            Ok((materials, _)) => libraries
                .borrow_mut()
                .push((MaterialLibrary { path: full, text }, materials.len())),
            Err(e) => library_warnings.borrow_mut().push(format!(
                "mesh '{}': materials of '{}' not loaded ({e})",
                shown_path(path),
                shown_path(&full)
            )),
        }
        result
    };
    let mut reader = text.as_bytes();
    let loaded = catch_unwind(AssertUnwindSafe(|| {
        tobj::load_obj_buf(&mut reader, &options, load_library)
    }))
    .map_err(|_| format!("cannot read mesh '{}': malformed OBJ", shown_path(path)))?;
    let (models, materials) =
        loaded.map_err(|e| format!("cannot read mesh '{}': {e}", shown_path(path)))?;
    let mut warnings = Vec::new();
    let mut faces = Vec::new();
    let mut flat = 0usize;
    let mut mesh = MeshData::default();
    let mut normals: Option<Vec<Vec3>> = Some(Vec::new());
    let mut uvs: Option<Vec<[f64; 2]>> = Some(Vec::new());
    for model in &models {
        let m = &model.mesh;
        let offset = mesh.positions.len();
        let count = m.positions.len() / 3;
        mesh.positions.extend(
            m.positions
                .chunks_exact(3)
                .map(|p| Point3::new(p[0] as f64, p[1] as f64, p[2] as f64)),
        );
        if m.normals.len() == m.positions.len() {
            if let Some(n) = normals.as_mut() {
                n.extend(
                    m.normals
                        .chunks_exact(3)
                        .map(|v| Vec3::new(v[0] as f64, v[1] as f64, v[2] as f64)),
                );
            }
        } else {
            normals = None;
        }
        if m.texcoords.len() / 2 == count && m.texcoords.len() % 2 == 0 {
            if let Some(t) = uvs.as_mut() {
                t.extend(
                    m.texcoords
                        .chunks_exact(2)
                        .map(|t| [t[0] as f64, t[1] as f64]),
                );
            }
        } else {
            uvs = None;
        }
        for face in m.indices.chunks_exact(3) {
            let mut triangle = [0u32; 3];
            for (slot, &index) in triangle.iter_mut().zip(face) {
                let global = offset + index as usize;
                if index as usize >= count || global > u32::MAX as usize {
                    return Err(format!(
                        "mesh '{}': vertex index {} out of range",
                        shown_path(path),
                        index
                    ));
                }
                *slot = global as u32;
            }
            let [a, b, c] = triangle.map(|i| &mesh.positions[i as usize]);
            if triangle_without_area(a, b, c) {
                flat += 1;
                continue;
            }
            mesh.triangles.push(triangle);
            faces.push(m.material_id.map_or(OWN_MATERIAL, |id| id as u32));
        }
    }
    if flat > 0 {
        warnings.push(format!(
            "mesh '{}': {flat} of {} triangles have no area (corners on one line): they are left out",
            shown_path(path),
            flat + mesh.triangles.len()
        ));
    }
    mesh.framework_reading = obj_framework::framework_reading(&text);
    let has_vertices = !mesh.positions.is_empty();
    mesh.normals = normals.filter(|_| has_vertices);
    mesh.uvs = uvs.filter(|_| has_vertices);
    let materials = materials.unwrap_or_default();
    let mut library_of = Vec::new();
    let mut libraries_read = Vec::new();
    for (index, (library, count)) in libraries.into_inner().into_iter().enumerate() {
        library_of.extend(std::iter::repeat_n(index, count));
        libraries_read.push(library);
    }
    let count = materials.len() as u32;
    for face in &mut faces {
        if *face >= count {
            *face = OWN_MATERIAL;
        }
    }
    let used = faces.iter().any(|&m| m != OWN_MATERIAL);
    let complete = library_of.len() == materials.len();
    let materials = (used && complete).then_some(ObjMaterials {
        materials,
        library_of,
        libraries: libraries_read,
        faces,
    });
    Ok(LoadedObj {
        mesh,
        materials,
        warnings,
        library_warnings: library_warnings.into_inner(),
    })
}

/// The text of an OBJ file: a regular file within [`MAX_MESH_BYTES`]
/// (checked before it is read), with no NUL byte (a binary file, or a
/// sparse file of zeros, is not an OBJ). Other bytes that are not UTF-8
/// (comments in a legacy encoding) are decoded lossily.
fn read_obj_text(path: &Path) -> Result<String, String> {
    let bytes = read_within(path, MAX_MESH_BYTES, "limits::MAX_MESH_BYTES")
        .map_err(|e| format!("cannot read mesh: {e}"))?;
    if let Some(offset) = bytes.iter().position(|&b| b == 0) {
        let line = 1 + bytes[..offset].iter().filter(|&&b| b == b'\n').count();
        return Err(format!(
            "{}:{line}: not a text OBJ file (a NUL byte at offset {offset})",
            shown_path(path)
        ));
    }
    Ok(String::from_utf8_lossy(&bytes).into_owned())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn negative_indices_crlf_quads_and_missing_mtl() {
        let dir = std::env::temp_dir().join(format!("pt-obj-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let file = dir.join("q.obj");
        let text = "mtllib nothere.mtl\r\nv 0 0 0\r\nv 1 0 0\r\nv 1 1 0\r\nv 0 1 0\r\nf -4 -3 -2 -1\r\no second\r\nv 0 0 1\r\nv 1 0 1\r\nv 0 1 1\r\nf 5 6 7\r\n";
        std::fs::write(&file, text).expect("write");
        let LoadedObj {
            mesh,
            materials,
            warnings,
            library_warnings,
        } = load_obj(&file).expect("loads");
        assert!(materials.is_none());
        assert_eq!(mesh.positions.len(), 7);
        assert_eq!(mesh.triangles.len(), 3);
        assert!(mesh.triangles.iter().flatten().all(|&i| i < 7));
        assert!(warnings.is_empty(), "{warnings:?}");
        assert_eq!(library_warnings.len(), 1, "{library_warnings:?}");
        assert!(load_obj(&dir.join("none.obj")).is_err());
    }

    #[test]
    fn an_obj_repeating_mtllib_2000_times_read_the_mtl_2000_times() {
        let dir = std::env::temp_dir().join(format!("pt-obj-repeat-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        std::fs::write(
            dir.join("a.mtl"),
            "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n",
        )
        .expect("write");
        let mut text = "mtllib a.mtl\nmtllib ./a.mtl\n".repeat(1000);
        text.push_str("v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl blue\nf 1 2 3\n");
        let file = dir.join("repeat.obj");
        std::fs::write(&file, text).expect("write");
        let loaded = load_obj(&file).expect("loads");
        let materials = loaded.materials.expect("the face uses a material");
        assert_eq!(materials.libraries.len(), 1);
        assert_eq!(materials.materials.len(), 2);
        assert_eq!(materials.faces, [1]);
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
    }

    #[test]
    fn faces_know_their_mtl_material_and_its_library() {
        let dir = std::env::temp_dir().join(format!("pt-obj-mtl-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        std::fs::write(dir.join("a.mtl"), "newmtl red\nKd 1 0 0\n").expect("write");
        std::fs::write(dir.join("b.mtl"), "newmtl lamp\nKe 5 5 5\n").expect("write");
        let text = "mtllib a.mtl\nmtllib b.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n\
                    f 1 2 3\nusemtl lamp\nf 2 4 3\nusemtl red\nf 1 2 4\nusemtl nothere\nf 1 3 4\n";
        let file = dir.join("m.obj");
        std::fs::write(&file, text).expect("write");
        let loaded = load_obj(&file).expect("loads");
        assert!(loaded.warnings.is_empty(), "{:?}", loaded.warnings);
        let materials = loaded.materials.expect("faces use materials");
        assert_eq!(materials.faces, [OWN_MATERIAL, 1, 0, OWN_MATERIAL]);
        assert_eq!(materials.library_of, [0, 1]);
        assert_eq!(materials.materials[1].name, "lamp");
        assert!(materials.libraries[1].path.ends_with("b.mtl"));
        assert!(materials.libraries[1].text.contains("Ke 5 5 5"));
    }
}
