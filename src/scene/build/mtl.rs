//! The `.mtl` materials of OBJ meshes, converted to scene materials:
//!
//! | `.mtl` field | `Material` |
//! |---|---|
//! | `Kd` | `color` (white when absent) |
//! | `Ke` | `emission`: the triangles are emitters, sampled by next-event estimation |
//! | `map_Kd` | `texture`, the path relative to the `.mtl` file's folder (it replaces `Kd`, as scene textures replace `color`) |
//! | `Ks`, `Ns` | `phong: Phong { color: Ks, exponent: Ns }` when `Ks` is not black (`Ns` 1 when absent) |
//! | `d` < 1 (dissolve) | refract weight `1 - d`, diffuse weight `d` |
//! | `Ni` | `ior` when it is positive, else 1.5 |
//! | `map_Bump`, `bump` | a height map unless the image clearly is a normal map (see `textures`); `-bm` is its scale (1) |
//! | `norm` | a normal map unless the image is greyscale (then `-bm` is its scale too) |
//! | anything else (`Ka`, `illum`, `map_Ka`, `map_Ks`, `map_Ns`, `map_d`, `Tr`, `Tf`, `Pr`, ... and map options other than `-bm`) | not rendered: a warning names the field, the `.mtl` file and its line |
//!
//! A map whose image does not exist is dropped with a warning.

use std::path::{Path, PathBuf};

use crate::bsdf::phong::Phong;
use crate::color::Color;
use crate::limits::shown_path;
use crate::scene::build::Context;
use crate::scene::build::material::PathRef;
use crate::scene::build::obj::{MaterialLibrary, ObjMaterials};
use crate::scene::build::textures::{MapName, MaterialImages, SurfaceMapRef};
use crate::scene::error::{Location, SceneError};
use crate::scene::model::Material;

/// Converts the materials of an OBJ (`obj`, read at `at` in the scene).
pub fn convert(
    context: &mut Context,
    obj: &Path,
    materials: &ObjMaterials,
    at: Location,
) -> Result<Vec<MaterialImages>, SceneError> {
    let mut out = Vec::with_capacity(materials.materials.len());
    for (index, source) in materials.materials.iter().enumerate() {
        let Some(library) = materials
            .library_of
            .get(index)
            .and_then(|&l| materials.libraries.get(l))
        else {
            out.push(MaterialImages::plain(Material::DEFAULT));
            continue;
        };
        let mut reader = Reader {
            context: &mut *context,
            obj,
            library,
            name: &source.name,
            at,
        };
        out.push(reader.material(source)?);
    }
    Ok(out)
}

/// One material of one `.mtl` file being converted.
struct Reader<'a, 'b> {
    context: &'a mut Context<'b>,
    obj: &'a Path,
    library: &'a MaterialLibrary,
    name: &'a str,
    at: Location,
}

fn color(c: [f32; 3]) -> Color {
    Color::new(c[0] as f64, c[1] as f64, c[2] as f64)
}

impl Reader<'_, '_> {
    fn material(&mut self, source: &tobj::Material) -> Result<MaterialImages, SceneError> {
        let mut material = Material::DEFAULT;
        if let Some(kd) = self.finite("Kd", source.diffuse)? {
            material.color = color(kd);
        }
        if let Some(ke) = self.finite("Ke", source.emissive)? {
            material.emission = color(ke);
        }
        let shininess = self.finite("Ns", source.shininess.map(|n| [n]))?;
        if let Some(ks) = self.finite("Ks", source.specular)?.map(color)
            && !ks.is_black()
        {
            let exponent = shininess.map_or(1.0, |[n]| f64::from(n));
            material.phong = Some(Phong {
                color: ks,
                exponent,
            });
        }
        if let Some([d]) = self.finite("d", source.dissolve.map(|d| [d]))? {
            let d = (d as f64).clamp(0.0, 1.0);
            if d < 1.0 {
                material.diffuse = d;
                material.refract = 1.0 - d;
            }
        }
        if let Some([ni]) = self.finite("Ni", source.optical_density.map(|n| [n]))?
            && ni > 0.0
        {
            material.ior = ni as f64;
        }
        let texture = match &source.diffuse_texture {
            Some(value) => self.map(&["map_Kd"], value, false)?.map(|(path, _)| path),
            None => None,
        };
        let mut surface_maps = Vec::new();
        const BUMP_KEYS: [&str; 3] = ["map_Bump", "map_bump", "bump"];
        let named_maps = [
            (
                source.normal_texture.as_ref(),
                &BUMP_KEYS[..],
                MapName::Bump,
            ),
            (
                source.unknown_param.get("norm"),
                &["norm"][..],
                MapName::Normal,
            ),
        ];
        for (value, keys, named) in named_maps {
            if let Some(value) = value
                && let Some((path, scale)) = self.map(keys, value, true)?
            {
                surface_maps.push(SurfaceMapRef { path, named, scale });
            }
        }
        // Fields that are read but not rendered, warned in the order of their lines.
        let mut unrendered: Vec<String> = [
            ("Ka", source.ambient.is_some()),
            ("map_Ka", source.ambient_texture.is_some()),
            ("map_Ks", source.specular_texture.is_some()),
            ("map_Ns", source.shininess_texture.is_some()),
            ("map_d", source.dissolve_texture.is_some()),
            ("illum", source.illumination_model.is_some()),
        ]
        .into_iter()
        .filter(|(_, present)| *present)
        .map(|(key, _)| key.to_string())
        .chain(
            source
                .unknown_param
                .keys()
                .filter(|k| *k != "norm")
                .cloned(),
        )
        .collect();
        unrendered.sort_by_key(|key| line_of(&self.library.text, self.name, &[key]));
        for key in &unrendered {
            self.not_rendered(key, &format!("'{key}'"))?;
        }
        Ok(MaterialImages {
            material,
            texture,
            surface_maps,
        })
    }

    /// The image of a map field (`keys` are its spellings) and its `-bm`
    /// scale (1); `None`, with a warning, when the image is missing.
    fn map(
        &mut self,
        keys: &[&str],
        value: &str,
        takes_scale: bool,
    ) -> Result<Option<(PathRef, f64)>, SceneError> {
        let spec = parse_map(value);
        let mut scale = 1.0;
        for (option, arguments) in &spec.options {
            match (option.as_str(), arguments.as_slice()) {
                ("-bm", [value, ..]) if takes_scale => {
                    scale = value.parse().unwrap_or(1.0);
                }
                _ => self.not_rendered(keys[0], &format!("option '{option}' of '{}'", keys[0]))?,
            }
        }
        let folder = self.library.path.parent().unwrap_or(Path::new(""));
        let file = match find_image(folder, &spec.file) {
            Ok(file) => file,
            Err(reason) => {
                let message = format!(
                    "mesh '{}': image '{}' of '{}' in material '{}' {reason} ({}), ignored",
                    shown_path(self.obj),
                    shown_path(Path::new(&spec.file)),
                    keys[0],
                    self.name,
                    self.place(keys)
                );
                self.context.warn(self.at, message)?;
                return Ok(None);
            }
        };
        let path = PathRef {
            path: file.to_string_lossy().into_owned(),
            location: self.at,
        };
        Ok(Some((path, scale)))
    }

    /// `value` of field `key` if every number of it is finite; else a
    /// warning (the field keeps its default) and `None`.
    fn finite<const N: usize>(
        &mut self,
        key: &str,
        value: Option<[f32; N]>,
    ) -> Result<Option<[f32; N]>, SceneError> {
        match value {
            Some(numbers) if numbers.iter().any(|n| !n.is_finite()) => {
                let message = format!(
                    "mesh '{}': '{key}' of material '{}' is not a finite number ({}): its default instead",
                    shown_path(self.obj),
                    self.name,
                    self.place(&[key])
                );
                self.context.warn(self.at, message)?;
                Ok(None)
            }
            other => Ok(other),
        }
    }

    fn not_rendered(&mut self, key: &str, what: &str) -> Result<(), SceneError> {
        let message = format!(
            "mesh '{}': {what} of material '{}' is not rendered ({})",
            shown_path(self.obj),
            self.name,
            self.place(&[key])
        );
        self.context.warn(self.at, message)
    }

    /// `file.mtl:line` of the field.
    fn place(&self, keys: &[&str]) -> String {
        let line = line_of(&self.library.text, self.name, keys)
            .map_or_else(|| "?".to_string(), |l| l.to_string());
        format!("{}:{line}", shown_path(&self.library.path))
    }
}

/// The 1-based line of the first field spelled one of `keys` in material
/// `name` of `.mtl` text, else of its `newmtl` line.
pub fn line_of(text: &str, name: &str, keys: &[&str]) -> Option<usize> {
    let mut start = None;
    for (number, line) in text.lines().enumerate() {
        let line = line.trim();
        let first = line.split_whitespace().next();
        if first == Some("newmtl") {
            if start.is_some() {
                break;
            }
            if line["newmtl".len()..].trim() == name {
                start = Some(number + 1);
            }
        } else if start.is_some() && first.is_some_and(|f| keys.contains(&f)) {
            return Some(number + 1);
        }
    }
    start
}

/// A map field's value: options (`-name arguments...`) and the file name.
#[derive(Debug, PartialEq)]
struct MapSpec {
    options: Vec<(String, Vec<String>)>,
    file: String,
}

fn parse_map(value: &str) -> MapSpec {
    let mut words = value.split_whitespace().peekable();
    let mut options = Vec::new();
    while let Some(word) = words.peek().copied() {
        let is_option = word.len() > 1
            && word.starts_with('-')
            && word[1..].starts_with(|c: char| c.is_ascii_alphabetic());
        if !is_option {
            break;
        }
        words.next();
        let mut arguments = Vec::new();
        let single = matches!(word, "-imfchan" | "-type");
        while let Some(argument) = words.peek().copied() {
            let takes = if single {
                arguments.is_empty()
            } else {
                argument.parse::<f64>().is_ok() || matches!(argument, "on" | "off")
            };
            if !takes {
                break;
            }
            arguments.push(argument.to_string());
            words.next();
        }
        options.push((word.to_string(), arguments));
    }
    MapSpec {
        options,
        file: words.collect::<Vec<_>>().join(" "),
    }
}

/// The image `file` of a `.mtl` in `folder` (also with `\` read as `/`),
/// as an absolute path.
/// The image `file` of a map, relative to `folder` (backslashes read as
/// slashes if need be); or why it is not one: not found, a directory, a
/// pipe or device, a name too long.
fn find_image(folder: &Path, file: &str) -> Result<PathBuf, &'static str> {
    if file.is_empty() {
        return Err("not named");
    }
    let mut reason = "not found";
    for name in [file.to_string(), file.replace('\\', "/")] {
        let path = folder.join(name);
        match std::fs::metadata(&path) {
            Ok(metadata) if metadata.is_file() => {
                return std::path::absolute(path).map_err(|_| "not found");
            }
            Ok(metadata) if metadata.is_dir() => reason = "is a directory, not an image",
            Ok(_) => reason = "is not a regular file (a device, pipe or socket)",
            Err(e) if e.kind() == std::io::ErrorKind::InvalidFilename => {
                reason = "has a name too long for the file system"
            }
            Err(_) => {}
        }
    }
    Err(reason)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn map_options_and_spaces_in_names() {
        assert_eq!(
            parse_map("-bm 0.3 -s 1 2 1 -clamp on bump map.png"),
            MapSpec {
                options: vec![
                    ("-bm".into(), vec!["0.3".into()]),
                    ("-s".into(), vec!["1".into(), "2".into(), "1".into()]),
                    ("-clamp".into(), vec!["on".into()]),
                ],
                file: "bump map.png".into(),
            }
        );
        assert_eq!(parse_map("-imfchan r -2.png").file, "-2.png");
        assert_eq!(parse_map("wood.jpg").options, []);
    }

    #[test]
    fn fields_are_found_in_their_own_material() {
        let text = "# lib\nnewmtl a\nKd 1 1 1\nillum 2\n\nnewmtl b\nKa 0 0 0\nillum 1\n";
        assert_eq!(line_of(text, "b", &["illum"]), Some(8));
        assert_eq!(line_of(text, "a", &["illum"]), Some(4));
        assert_eq!(
            line_of(text, "a", &["Ka"]),
            Some(2),
            "not in a: its newmtl line"
        );
        assert_eq!(line_of(text, "c", &["Kd"]), None);
    }
}
