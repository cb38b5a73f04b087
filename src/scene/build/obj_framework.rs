//! An OBJ file as the course framework's loader reads it (hanna0911's
//! renderer, `looks.md`), next to the standard reading of `obj`.
//!
//! The framework keeps every `v` line and makes **one** triangle per `f`
//! line. A face written without slashes gives its first three indices (a
//! quad loses its second half). A face with a slash has its slashes read
//! as spaces and then its numbers read in pairs (position, texture): the
//! triangle is the first, third and fifth number. That is right for
//! `v/vt` and `v//vn` faces; for `v/vt/vn` faces it is (v of the first
//! corner, vn of the first corner, vt of the second), and the triangles
//! join unrelated vertices. Faces with a number missing or outside the
//! vertex list (which the framework reads out of bounds) are left out, and
//! so are triangles without area. No `vn` or `vt` are kept: triangles are
//! flat, their normal from their winding.

use std::sync::Arc;

use crate::geometry::MeshData;
use crate::math::Point3;
use crate::scene::build::degenerate::triangle_without_area;

/// The framework's reading of the OBJ `text`, or `None` when it makes the
/// same triangles as the standard reading: no face has a slash or more
/// than three corners.
pub fn framework_reading(text: &str) -> Option<Arc<MeshData>> {
    let mut differs = false;
    let mut positions = Vec::new();
    let mut faces: Vec<[i64; 3]> = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let mut xyz = [0.0; 3];
                for (slot, word) in xyz.iter_mut().zip(words) {
                    *slot = word.parse().unwrap_or(0.0);
                }
                positions.push(Point3::new(xyz[0], xyz[1], xyz[2]));
            }
            Some("f") => {
                let corners: Vec<&str> = words.collect();
                let slashed = corners.iter().any(|c| c.contains('/'));
                differs |= slashed || corners.len() > 3;
                if let Some(face) = face_indices(&corners, slashed) {
                    faces.push(face);
                }
            }
            _ => {}
        }
    }
    if !differs {
        return None;
    }
    let count = positions.len() as i64;
    let triangles = faces
        .into_iter()
        .filter(|face| face.iter().all(|&i| (1..=count).contains(&i)))
        .map(|face| face.map(|i| (i - 1) as u32))
        .filter(|t| {
            let [a, b, c] = t.map(|i| &positions[i as usize]);
            !triangle_without_area(a, b, c)
        })
        .collect();
    Some(Arc::new(MeshData {
        positions,
        normals: None,
        uvs: None,
        triangles,
        framework_reading: None,
    }))
}

/// The 1-based indices of the triangle the framework reads from a face's
/// `corners` (see the module docs); `None` when a number it needs is
/// missing or not an integer.
fn face_indices(corners: &[&str], slashed: bool) -> Option<[i64; 3]> {
    let numbers = corners
        .iter()
        .flat_map(|corner| corner.split('/'))
        .filter(|word| !word.is_empty());
    let picks: [usize; 3] = if slashed { [0, 2, 4] } else { [0, 1, 2] };
    let mut read = [0i64; 5];
    let mut filled = 0;
    for (slot, word) in read.iter_mut().zip(numbers) {
        *slot = word.parse().ok()?;
        filled += 1;
    }
    picks
        .iter()
        .all(|&p| p < filled)
        .then(|| picks.map(|p| read[p]))
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\n";

    fn triangles(faces: &str) -> Option<Vec<[u32; 3]>> {
        framework_reading(&format!("{SQUARE}{faces}")).map(|m| m.triangles.clone())
    }

    #[test]
    fn faces_of_plain_triangles_are_read_as_the_standard_reading() {
        assert_eq!(triangles("f 1 2 3\nf 1 3 4\n"), None);
    }

    #[test]
    fn a_quad_keeps_only_its_first_three_corners() {
        assert_eq!(triangles("f 1 2 3 4\n"), Some(vec![[0, 1, 2]]));
    }

    #[test]
    fn v_vt_vn_corners_are_read_in_pairs() {
        // Numbers 1 2 3 4 5 6 3 2 1, read as pairs (1, 2) (3, 4) (5, 6).
        assert_eq!(
            triangles("f 1/2/3 4/5/6 3/2/1\n"),
            Some(vec![[0, 2, 4]]),
            "(v of the first corner, vn of the first, vt of the second)"
        );
    }

    #[test]
    fn v_vt_and_v_vn_corners_are_read_right() {
        assert_eq!(triangles("f 1/4 2/5 3/6\n"), Some(vec![[0, 1, 2]]));
        assert_eq!(triangles("f 1//4 2//5 3//6\n"), Some(vec![[0, 1, 2]]));
    }

    #[test]
    fn faces_outside_the_vertex_list_or_without_area_are_left_out() {
        assert_eq!(
            triangles("f 1/1/7 2/2/2 3/3/3\nf 1/1/1 2/2/2 3/3/3\nf 1 2 3 4\n"),
            Some(vec![[0, 1, 2]]),
            "7 is past the six vertices; (1, 1, 2) has no area"
        );
        assert_eq!(triangles("f 1/2\n"), Some(vec![]));
    }

    #[test]
    fn crlf_lines_read_the_same() {
        assert_eq!(
            framework_reading("v 0 0 0\r\nv 1 0 0\r\nv 0 1 0\r\nf 1 2 3 1\r\n")
                .map(|m| m.triangles.clone()),
            Some(vec![[0, 1, 2]])
        );
    }
}
