//! OBJ meshes through `tobj`: triangulated, single-indexed, all models merged into one.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::path::Path;

use crate::math::{Point3, Vec3};
use crate::scene::model::MeshData;

/// Loads an OBJ file. `Ok((mesh, warnings))`; a missing `.mtl` is only a warning.
pub fn load_obj(path: &Path) -> Result<(MeshData, Vec<String>), String> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let loaded = catch_unwind(AssertUnwindSafe(|| tobj::load_obj(path, &options)))
        .map_err(|_| format!("cannot read mesh '{}': malformed OBJ", path.display()))?;
    let (models, materials) =
        loaded.map_err(|e| format!("cannot read mesh '{}': {e}", path.display()))?;
    let mut warnings = Vec::new();
    if let Err(e) = materials
        && !models.is_empty()
    {
        warnings.push(format!(
            "mesh '{}': materials not loaded ({e})",
            path.display()
        ));
    }
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
                        path.display(),
                        index
                    ));
                }
                *slot = global as u32;
            }
            mesh.triangles.push(triangle);
        }
    }
    let has_vertices = !mesh.positions.is_empty();
    mesh.normals = normals.filter(|_| has_vertices);
    mesh.uvs = uvs.filter(|_| has_vertices);
    Ok((mesh, warnings))
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
        let (mesh, warnings) = load_obj(&file).expect("loads");
        assert_eq!(mesh.positions.len(), 7);
        assert_eq!(mesh.triangles.len(), 3);
        assert!(mesh.triangles.iter().flatten().all(|&i| i < 7));
        assert_eq!(warnings.len(), 1);
        assert!(load_obj(&dir.join("none.obj")).is_err());
    }
}
