//! Loading the images of the materials that some object actually uses, and
//! deciding what a surface-map image is: a height (bump) map or a
//! tangent-space normal map.
//!
//! The key names a kind and the image can overrule it: a `bump`/`bumpMap`
//! (.mtl `bump`/`map_Bump`) image is a height map unless it clearly is a
//! normal map (not greyscale, mean blue at least 0.6, mean red and green
//! within 0.1 of 0.5); a `normal`/`normal_file` (.mtl `norm`) image is a
//! normal map unless it is greyscale (every texel with r, g and b within
//! 2/255 of each other). A height map's scale is the number after its path
//! (cyy's `bump path strength`), 1 by default.
//!
//! A path ending in `.txt` is one of rub's descriptor files (see
//! `descriptor`): a checker, or the image to use. An image that is not
//! found is an error at the place that names it, or with `--missing-assets
//! placeholder` a warning there and [`Texture::placeholder`] for a colour
//! texture, nothing for a normal or height map.

use std::collections::{BTreeSet, HashMap};
use std::path::PathBuf;
use std::sync::Arc;

use crate::limits::shown_path;
use crate::scene::MissingAssets;
use crate::scene::build::descriptor::{self, Descriptor};
use crate::scene::build::material::{MaterialSpec, PathRef};
use crate::scene::build::texture_file::read_texture_readings;
use crate::scene::build::{Context, paths};
use crate::scene::error::SceneError;
use crate::scene::model::{Bump, Material, Object};
use crate::texture::Texture;
use crate::texture::checker::Checker;

/// Which kind of key named a surface-map image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum MapName {
    /// `bump`, `bumpMap`, .mtl `bump` and `map_Bump`.
    Bump,
    /// `normal`, `normal_file`, .mtl `norm`.
    Normal,
}

/// A surface-map image as a material names it.
#[derive(Clone, Debug, PartialEq)]
pub struct SurfaceMapRef {
    pub path: PathRef,
    pub named: MapName,
    pub scale: f64,
}

/// A material and the images it names, before they are loaded.
#[derive(Clone, Debug, PartialEq)]
pub struct MaterialImages {
    pub material: Material,
    pub texture: Option<PathRef>,
    /// Normal and height maps (a `.mtl` may name one of each).
    pub surface_maps: Vec<SurfaceMapRef>,
}

impl MaterialImages {
    /// A scene material and the images it names.
    pub fn from_spec(spec: MaterialSpec) -> MaterialImages {
        MaterialImages {
            material: spec.material,
            texture: spec.texture,
            surface_maps: spec.surface_map.into_iter().collect(),
        }
    }

    /// A material that names no images.
    pub fn plain(material: Material) -> MaterialImages {
        MaterialImages {
            material,
            texture: None,
            surface_maps: Vec::new(),
        }
    }
}

/// The loaded images: the texture table, and the course framework's
/// reading of those whose reading differs from ours
/// ([`crate::scene::model::Scene::framework_readings`]).
pub type LoadedTextures = (Vec<Arc<Texture>>, HashMap<usize, Arc<Texture>>);

/// Final materials and the texture table. Unused materials keep no images.
pub fn load_textures(
    context: &mut Context,
    specs: Vec<MaterialImages>,
    root: &Object,
) -> Result<(Vec<Material>, LoadedTextures), SceneError> {
    let mut used = BTreeSet::new();
    root.for_each_leaf(&mut |leaf| {
        used.extend(leaf.materials());
    });
    let mut loader = Loader::default();
    let mut materials = Vec::new();
    for (index, spec) in specs.into_iter().enumerate() {
        let mut material = spec.material;
        if used.contains(&index) {
            if let Some(path) = &spec.texture {
                match loader.source(context, path, Role::Color)? {
                    Source::Image(texture) => material.texture = Some(texture),
                    Source::Checker(checker) => material.checker = Some(checker),
                    Source::Nothing => {}
                }
            }
            for map in &spec.surface_maps {
                let texture = match loader.source(context, &map.path, Role::SurfaceMap)? {
                    Source::Image(texture) => texture,
                    Source::Checker(_) => {
                        context.not_rendered(
                            map.path.location,
                            "a checkerTexture descriptor as a normal map",
                            "normal maps are images",
                        )?;
                        continue;
                    }
                    Source::Nothing => continue,
                };
                let replaced = if is_height_map(&loader.textures[texture], map.named) {
                    material
                        .bump
                        .replace(Bump {
                            texture,
                            scale: map.scale,
                        })
                        .is_some()
                } else {
                    material.normal_map.replace(texture).is_some()
                };
                if replaced {
                    context.warn(
                        map.path.location,
                        format!(
                            "'{}' replaces another map of the same kind (height or normal)",
                            map.path.path
                        ),
                    )?;
                }
            }
        }
        materials.push(material);
    }
    Ok((materials, (loader.textures, loader.framework_readings)))
}

/// What a material uses an image for (decides what a missing one becomes).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Role {
    /// A colour texture: the placeholder checker.
    Color,
    /// A normal or height map: left out.
    SurfaceMap,
}

/// What a texture key of a material gives.
enum Source {
    /// An image of the texture table.
    Image(usize),
    /// rub's procedural checker.
    Checker(Checker),
    /// Nothing: a missing surface map with `--missing-assets placeholder`.
    Nothing,
}

/// The texture table being filled, each file decoded once.
#[derive(Default)]
struct Loader {
    textures: Vec<Arc<Texture>>,
    /// The course framework's readings that differ from ours, by index.
    framework_readings: HashMap<usize, Arc<Texture>>,
    cache: HashMap<PathBuf, usize>,
    /// rub's descriptor files, each read once (by the path as written).
    descriptors: HashMap<String, Descriptor>,
    /// Index of the placeholder checker, once a texture is missing.
    placeholder: Option<usize>,
}

impl Loader {
    /// What the path of a texture key gives: an image, or for rub's
    /// descriptor files (`.txt`, see `descriptor`) what the file describes.
    fn source(
        &mut self,
        context: &mut Context,
        path: &PathRef,
        role: Role,
    ) -> Result<Source, SceneError> {
        if !descriptor::is_descriptor(&path.path) {
            return Ok(self
                .load(context, path, role)?
                .map_or(Source::Nothing, Source::Image));
        }
        let described = match self.descriptors.get(&path.path) {
            Some(described) => described.clone(),
            None => {
                let described = descriptor::read(context, path)?;
                self.descriptors
                    .insert(path.path.clone(), described.clone());
                described
            }
        };
        Ok(match described {
            Descriptor::Checker(checker) => Source::Checker(checker),
            Descriptor::Image(file) => {
                let image = PathRef {
                    path: file.to_string_lossy().into_owned(),
                    location: path.location,
                };
                self.load(context, &image, role)?
                    .map_or(Source::Nothing, Source::Image)
            }
            Descriptor::Missing => match role {
                Role::Color => Source::Image(self.placeholder()),
                Role::SurfaceMap => Source::Nothing,
            },
        })
    }

    /// The index of the image `path` names; a missing file is an error, or
    /// with `--missing-assets placeholder` a warning and the placeholder
    /// (colour textures) or `None` (surface maps).
    fn load(
        &mut self,
        context: &mut Context,
        path: &PathRef,
        role: Role,
    ) -> Result<Option<usize>, SceneError> {
        let file = match paths::resolve(&path.path, context.file, context.options) {
            Ok(file) => file,
            Err(tried) => {
                let missing = paths::missing("texture", &path.path, &tried);
                if context.options.missing_assets == MissingAssets::Error {
                    return Err(context.error(path.location, missing));
                }
                return match role {
                    Role::Color => {
                        context.warn(
                            path.location,
                            format!("{missing}: the placeholder checker instead"),
                        )?;
                        Ok(Some(self.placeholder()))
                    }
                    Role::SurfaceMap => {
                        context.warn(path.location, format!("{missing}: left out"))?;
                        Ok(None)
                    }
                };
            }
        };
        if let Some(&index) = self.cache.get(&file) {
            return Ok(Some(index));
        }
        let read = read_texture_readings(&file, context.options.memory_budget);
        let (texture, framework) = read.map_err(|e| {
            context.error(
                path.location,
                format!("cannot read texture '{}': {e}", shown_path(&file)),
            )
        })?;
        let index = self.push(texture);
        if let Some(framework) = framework {
            self.framework_readings.insert(index, Arc::new(framework));
        }
        context.assets.push(file.clone());
        self.cache.insert(file, index);
        Ok(Some(index))
    }

    fn push(&mut self, texture: Texture) -> usize {
        self.textures.push(Arc::new(texture));
        self.textures.len() - 1
    }

    fn placeholder(&mut self) -> usize {
        match self.placeholder {
            Some(index) => index,
            None => {
                let index = self.push(Texture::placeholder());
                self.placeholder = Some(index);
                index
            }
        }
    }
}

/// Whether the image named by a key of kind `named` is read as a height map
/// (else as a tangent-space normal map); see the module docs.
pub fn is_height_map(texture: &Texture, named: MapName) -> bool {
    match named {
        MapName::Bump => !looks_like_normal_map(texture),
        MapName::Normal => is_greyscale(texture),
    }
}

/// Every texel has r, g and b within 2/255 of each other (and a little
/// for the decoder's rounding).
fn is_greyscale(texture: &Texture) -> bool {
    const TOLERANCE: f32 = 2.0 / 255.0 + 1e-4;
    texture.texels.iter().all(|&[r, g, b]| {
        (r - g).abs() <= TOLERANCE && (r - b).abs() <= TOLERANCE && (g - b).abs() <= TOLERANCE
    })
}

/// Not greyscale, mostly blue, red and green centred on 0.5: what a
/// tangent-space normal map of a mostly flat surface looks like.
fn looks_like_normal_map(texture: &Texture) -> bool {
    if texture.texels.is_empty() || is_greyscale(texture) {
        return false;
    }
    let mut sum = [0.0f64; 3];
    for texel in &texture.texels {
        for (s, &c) in sum.iter_mut().zip(texel) {
            *s += c as f64;
        }
    }
    let [r, g, b] = sum.map(|s| s / texture.texels.len() as f64);
    b >= 0.6 && (r - 0.5).abs() <= 0.1 && (g - 0.5).abs() <= 0.1
}

#[cfg(test)]
mod tests {
    use super::*;

    fn image(texels: Vec<[f32; 3]>) -> Texture {
        Texture {
            width: texels.len(),
            height: 1,
            texels,
        }
    }

    #[test]
    fn the_image_overrules_the_key_only_when_it_is_clear() {
        let grey = image(vec![[0.2, 0.2, 0.2 + 2.0 / 255.0], [0.7, 0.7, 0.7]]);
        let normal = image(vec![[0.5, 0.5, 1.0], [0.55, 0.45, 0.9]]);
        let photo = image(vec![[0.9, 0.2, 0.1], [0.3, 0.6, 0.2]]);
        assert!(is_height_map(&grey, MapName::Bump));
        assert!(is_height_map(&grey, MapName::Normal));
        assert!(!is_height_map(&normal, MapName::Bump));
        assert!(!is_height_map(&normal, MapName::Normal));
        assert!(is_height_map(&photo, MapName::Bump));
        assert!(!is_height_map(&photo, MapName::Normal));
        // 3/255 apart is colour.
        let tinted = image(vec![[0.5, 0.5 + 3.0 / 255.0, 0.5]]);
        assert!(!is_height_map(&tinted, MapName::Normal));
    }
}
