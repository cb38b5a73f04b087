//! Loading the images of the materials that some object actually uses.

use std::collections::{BTreeSet, HashMap};
use std::path::PathBuf;
use std::sync::Arc;

use crate::scene::build::material::{MaterialSpec, PathRef};
use crate::scene::build::{Context, paths};
use crate::scene::error::SceneError;
use crate::scene::model::{Material, Object};
use crate::texture::Texture;

/// Final materials and the texture table. Unused materials keep no images.
pub fn load_textures(
    context: &mut Context,
    specs: Vec<MaterialSpec>,
    root: &Object,
) -> Result<(Vec<Material>, Vec<Arc<Texture>>), SceneError> {
    let mut used = BTreeSet::new();
    root.for_each_leaf(&mut |leaf| {
        if let Some(m) = leaf.material() {
            used.insert(m);
        }
    });
    let mut textures = Vec::new();
    let mut cache: HashMap<PathBuf, usize> = HashMap::new();
    let mut materials = Vec::new();
    for (index, spec) in specs.into_iter().enumerate() {
        let mut material = spec.material;
        if used.contains(&index) {
            if let Some(path) = &spec.texture {
                material.texture = Some(load(context, path, &mut cache, &mut textures)?);
            }
            if let Some(path) = &spec.normal_map {
                material.normal_map = Some(load(context, path, &mut cache, &mut textures)?);
            }
        }
        materials.push(material);
    }
    Ok((materials, textures))
}

fn load(
    context: &mut Context,
    path: &PathRef,
    cache: &mut HashMap<PathBuf, usize>,
    textures: &mut Vec<Arc<Texture>>,
) -> Result<usize, SceneError> {
    let file = paths::resolve(&path.path, context.file, context.options).map_err(|tried| {
        context.error(
            path.location,
            format!(
                "texture '{}' not found (tried {})",
                path.path,
                paths::describe_tried(&tried)
            ),
        )
    })?;
    if let Some(&index) = cache.get(&file) {
        return Ok(index);
    }
    let texture = read_image(&file).map_err(|e| {
        context.error(
            path.location,
            format!("cannot read texture '{}': {e}", file.display()),
        )
    })?;
    textures.push(Arc::new(texture));
    let index = textures.len() - 1;
    cache.insert(file, index);
    Ok(index)
}

/// Decodes an image into linear [0, 1] texels (no gamma conversion).
pub fn read_image(file: &std::path::Path) -> Result<Texture, String> {
    let reader = image::ImageReader::open(file)
        .map_err(|e| e.to_string())?
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    let image = reader.decode().map_err(|e| e.to_string())?.to_rgb32f();
    let (width, height) = image.dimensions();
    let texels = image.pixels().map(|p| [p.0[0], p.0[1], p.0[2]]).collect();
    Ok(Texture {
        width: width as usize,
        height: height as usize,
        texels,
    })
}
