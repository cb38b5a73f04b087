//! Line-by-line checks of OBJ text before `tobj` reads it, so that a bad
//! file is refused with its line: numbers that are not numbers or not
//! finite (NaN, inf, or beyond f32), and face indices outside the vertices.
//!
//! The checks mirror what `tobj` itself refuses (its errors carry no line)
//! and add one it lacks: a NaN or infinite coordinate, which it accepts.

/// A problem of an OBJ file: its line (from 1) and what is wrong.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ObjProblem {
    pub line: usize,
    pub message: String,
}

/// How many of each element the file defines (face indices may refer to
/// any of them: `tobj` resolves them once a model ends).
#[derive(Default)]
struct Counts {
    positions: usize,
    texture_coordinates: usize,
    normals: usize,
}

/// Checks the `v`, `vt`, `vn` and `f` lines of `text`.
pub fn check_obj_text(text: &str) -> Result<(), ObjProblem> {
    let mut counts = Counts::default();
    for line in text.lines() {
        match line.split_whitespace().next() {
            Some("v") => counts.positions += 1,
            Some("vt") => counts.texture_coordinates += 1,
            Some("vn") => counts.normals += 1,
            _ => {}
        }
    }
    let mut seen = Counts::default();
    for (index, line) in text.lines().enumerate() {
        let problem = |message: String| ObjProblem {
            line: index + 1,
            message,
        };
        let mut words = line.split_whitespace();
        let numbers: Vec<&str> = match words.next() {
            Some(kind @ ("v" | "vt" | "vn")) => {
                let values: Vec<&str> = words.collect();
                check_numbers(kind, &values).map_err(problem)?;
                match kind {
                    "v" => seen.positions += 1,
                    "vt" => seen.texture_coordinates += 1,
                    _ => seen.normals += 1,
                }
                continue;
            }
            Some("f") => words.collect(),
            _ => continue,
        };
        if numbers.len() < 3 {
            return Err(problem(format!(
                "a face needs at least 3 vertices, this line has {}",
                numbers.len()
            )));
        }
        for vertex in numbers {
            check_face_vertex(vertex, &seen, &counts).map_err(problem)?;
        }
    }
    Ok(())
}

/// The numbers of a `v` (x y z, then an optional w or r g b), `vt` (u v
/// and an optional w) or `vn` (x y z) line.
fn check_numbers(kind: &str, values: &[&str]) -> Result<(), String> {
    let (what, least) = match kind {
        "v" => ("vertex position", 3),
        "vt" => ("texture coordinate", 2),
        _ => ("vertex normal", 3),
    };
    if values.len() < least {
        return Err(format!(
            "a {what} needs {least} numbers, this line has {}",
            values.len()
        ));
    }
    if kind == "v" && !matches!(values.len(), 3 | 4 | 6) {
        return Err(format!(
            "a vertex position is x y z, optionally w or r g b; this line has {} numbers",
            values.len()
        ));
    }
    let mut parsed = Vec::with_capacity(values.len());
    for &value in values.iter().take(if kind == "v" { 6 } else { least }) {
        let number: f32 = value
            .parse()
            .map_err(|_| format!("{what}: '{value}' is not a number"))?;
        if !number.is_finite() {
            return Err(format!("{what}: '{value}' is not a finite number"));
        }
        parsed.push(number);
    }
    if kind == "v" && parsed.len() == 4 {
        let w = parsed[3];
        if w == 0.0 {
            return Err("vertex position: its w is 0 (x y z are divided by w)".to_string());
        }
        if parsed[..3].iter().any(|c| !(c / w).is_finite()) {
            return Err(format!(
                "vertex position: x y z divided by w {w} are not finite numbers"
            ));
        }
    }
    Ok(())
}

/// One `v`, `v/vt`, `v//vn` or `v/vt/vn` of a face: whole numbers that
/// name defined elements (from 1, or negative: back from the last one
/// defined before the face).
fn check_face_vertex(vertex: &str, seen: &Counts, total: &Counts) -> Result<(), String> {
    let parts: Vec<&str> = vertex.split('/').collect();
    if parts.len() > 3 || parts[0].is_empty() {
        return Err(format!(
            "face vertex '{vertex}' is not v, v/vt, v//vn or v/vt/vn"
        ));
    }
    let kinds = [
        ("vertex", seen.positions, total.positions),
        (
            "texture coordinate",
            seen.texture_coordinates,
            total.texture_coordinates,
        ),
        ("normal", seen.normals, total.normals),
    ];
    for (part, (what, before, defined)) in parts.iter().zip(kinds) {
        if part.is_empty() {
            continue;
        }
        let index: i64 = part
            .parse()
            .map_err(|_| format!("face vertex '{vertex}': '{part}' is not a whole number"))?;
        // tobj ignores texture coordinate and normal indices of a file
        // that defines none.
        if what != "vertex" && defined == 0 {
            continue;
        }
        let valid = match index {
            0 => false,
            i if i > 0 => i as u64 <= defined as u64,
            i => i.unsigned_abs() <= before as u64,
        };
        if !valid {
            return Err(format!(
                "face vertex '{vertex}': {what} index {index} is out of range ({before} defined \
                 before this line, {defined} in the file; indices count from 1, negative ones back \
                 from the last)"
            ));
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line_of(text: &str) -> Option<usize> {
        check_obj_text(text).err().map(|p| p.line)
    }

    #[test]
    fn good_files_pass() {
        let text = "# c\nv 0 0 0\nv 1 0 0 1\nv 0 1 0 1 0.5 0\nvt 0 0\nvn 0 0 1\n\
                    f 1/1/1 2/1/1 3/1/1\nf -3//-1 -2//-1 -1//-1\nf 1 2 3 4\nv 1 1 0\n";
        assert_eq!(check_obj_text(text), Ok(()));
    }

    #[test]
    fn bad_numbers_and_indices_name_their_line() {
        assert_eq!(line_of("v 0 0 0\nv nan 0 0\n"), Some(2));
        assert_eq!(line_of("v 0 0 inf\n"), Some(1));
        assert_eq!(line_of("v 0 0 1e39\n"), Some(1));
        assert_eq!(line_of("v 1 0 0 0\n"), Some(1));
        assert_eq!(line_of("v 1 0\n"), Some(1));
        assert_eq!(line_of("v 0 0 0\nvn 0 x 1\n"), Some(2));
        assert_eq!(line_of("v 0 0 0\n\nf 1 2 0\n"), Some(3));
        assert_eq!(line_of("v 0 0 0\nf 1 1 -2\n"), Some(2));
        assert_eq!(line_of("v 0 0 0\nf 1 1 5\n"), Some(2));
        assert_eq!(line_of("v 0 0 0\nvt 0 0\nf 1/2 1/1 1/1\n"), Some(3));
        assert_eq!(line_of("v 0 0 0\nf 1/1/1/1 1 1\n"), Some(2));
    }
}
