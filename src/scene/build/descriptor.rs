//! rub's texture descriptor files (1rubbishyuan/path_tracing,
//! `src/scene_parser.cpp` `parseTexture`): a material's `texture FILE.txt`
//! or `nTexture FILE.txt` names a file holding one block
//!
//! | type word | fields | what it becomes |
//! |---|---|---|
//! | `checkerTexture` | `scale s`, `colorEven r g b`, `colorOdd r g b` (defaults 0, black, black, as rub's) | a [`Checker`] at the world point |
//! | `imageTexture`, `nTexture` | `imagefile PATH` | the image: a colour texture under `texture`, a normal map under `nTexture` |
//!
//! written `{ type-word fields }`. The type word chooses the kind and the
//! material's key the use, as in rub, whose two image classes read the
//! same texel. Errors and warnings in a descriptor carry its own
//! `file:line:column`; `PATH`, like the descriptor's own path, resolves as
//! the scene's paths do (rub opens both from its working directory, the
//! repository root). A checker under `nTexture` warns as not rendered.
//!
//! rub's renderer reads images with a 2.2 decode and places normal-map
//! texels in its own frame; those are conventions of its look, not of
//! the file: here the image is a texture read as every texture (values
//! over 255, no decode) and a normal map in tangent space like every
//! other (or, if it is greyscale, a height map: see `textures`).

use std::path::{Path, PathBuf};

use crate::color::Color;
use crate::limits::{MAX_SCENE_BYTES, read_within};
use crate::scene::MissingAssets;
use crate::scene::ast::{Block, Item};
use crate::scene::build::material::PathRef;
use crate::scene::build::{Context, Cursor, paths};
use crate::scene::error::{Location, SceneError};
use crate::texture::checker::Checker;

/// What a descriptor file describes.
#[derive(Clone, Debug, PartialEq)]
pub enum Descriptor {
    Checker(Checker),
    /// An image, its path resolved.
    Image(PathBuf),
    /// The descriptor or its image is missing (`--missing-assets
    /// placeholder`, warned).
    Missing,
}

/// Whether a texture path names a descriptor file rather than an image.
pub fn is_descriptor(path: &str) -> bool {
    path.ends_with(".txt")
}

/// Reads the descriptor that `named` (in the scene) names.
pub fn read(context: &mut Context, named: &PathRef) -> Result<Descriptor, SceneError> {
    let file = match paths::resolve(&named.path, context.file, context.options) {
        Ok(file) => file,
        Err(tried) => {
            let missing = paths::missing("texture descriptor", &named.path, &tried);
            return missing_file(context, named.location, missing);
        }
    };
    let text = read_within(&file, MAX_SCENE_BYTES, "limits::MAX_SCENE_BYTES").map_err(|e| {
        context.error(
            named.location,
            format!("cannot read texture descriptor: {e}"),
        )
    })?;
    let document = crate::scene::parse(&String::from_utf8_lossy(&text), &file)?;
    // Messages about the descriptor's content are located in it.
    let mut inner = Context {
        file: &file,
        options: context.options,
        dialect: context.dialect,
        warnings: Vec::new(),
        tally: Default::default(),
        assets: Vec::new(),
    };
    let result = describe(&mut inner, &document.items, context.file);
    context.warnings.append(&mut inner.take_warnings());
    context.assets.push(file.clone());
    context.assets.append(&mut inner.assets);
    result
}

/// With `--missing-assets placeholder` a warning and [`Descriptor::Missing`],
/// else the error.
fn missing_file(
    context: &mut Context,
    at: Location,
    message: String,
) -> Result<Descriptor, SceneError> {
    if context.options.missing_assets == MissingAssets::Error {
        return Err(context.error(at, message));
    }
    context.warn(
        at,
        format!(
            "{message}: the placeholder checker for a colour texture, nothing for a normal map"
        ),
    )?;
    Ok(Descriptor::Missing)
}

/// The descriptor's block; `scene` is the scene file (image paths resolve
/// from it).
fn describe(context: &mut Context, items: &[Item], scene: &Path) -> Result<Descriptor, SceneError> {
    let mut blocks = items.iter().filter(|item| item.block().is_some());
    let Some((block, location)) = blocks.next().and_then(|i| Some((i.block()?, i.location))) else {
        let at = items
            .first()
            .map_or(Location { line: 1, column: 1 }, |i| i.location);
        return Err(context.error(
            at,
            "expected a texture block '{ checkerTexture ... }' or '{ imageTexture imagefile PATH }'"
                .into(),
        ));
    };
    for item in items.iter().filter(|item| item.block().is_none()) {
        context.skip_item(item, "the texture descriptor")?;
    }
    for extra in blocks {
        context.warn(
            extra.location,
            "a texture descriptor holds one block; this one is skipped".into(),
        )?;
    }
    if !block.name.is_empty() {
        return Err(context.error(
            location,
            format!(
                "expected '{{' and a type word, found '{} {{' (write '{{ {} ... }}')",
                block.name, block.name
            ),
        ));
    }
    let mut cursor = Cursor::of(block);
    let at = cursor.here();
    let kind = cursor.word(context, "{")?;
    match kind {
        "checkerTexture" => checker(context, &mut cursor).map(Descriptor::Checker),
        "imageTexture" | "nTexture" => image(context, &mut cursor, kind, block, scene),
        other => Err(context.error(
            at,
            format!(
                "unknown texture type '{other}' (one of: checkerTexture, imageTexture, nTexture)"
            ),
        )),
    }
}

fn checker(context: &mut Context, cursor: &mut Cursor) -> Result<Checker, SceneError> {
    let mut checker = Checker {
        scale: 0.0,
        even: Color::BLACK,
        odd: Color::BLACK,
    };
    let color = |cursor: &mut Cursor, context: &Context, key: &str| {
        cursor.vec3(context, key).map(|v| Color::new(v.x, v.y, v.z))
    };
    while let Some(item) = cursor.next() {
        match item.word() {
            Some(key @ "scale") => checker.scale = cursor.number(context, key)?,
            Some(key @ "colorEven") => checker.even = color(cursor, context, key)?,
            Some(key @ "colorOdd") => checker.odd = color(cursor, context, key)?,
            Some(key) => context.skip_field(cursor, key, item.location, "checkerTexture")?,
            None => context.skip_item(item, "checkerTexture")?,
        }
    }
    Ok(checker)
}

fn image(
    context: &mut Context,
    cursor: &mut Cursor,
    kind: &str,
    block: &Block,
    scene: &Path,
) -> Result<Descriptor, SceneError> {
    let mut named = None;
    while let Some(item) = cursor.next() {
        match item.word() {
            Some(key @ "imagefile") => {
                let location = cursor.here();
                let path = cursor.word(context, key)?.to_string();
                named = Some(PathRef { path, location });
            }
            Some(key) => context.skip_field(cursor, key, item.location, kind)?,
            None => context.skip_item(item, kind)?,
        }
    }
    let Some(named) = named else {
        return Err(context.error(block.close, format!("{kind} needs 'imagefile PATH'")));
    };
    // The image resolves like the scene's paths, from the scene file.
    match paths::resolve(&named.path, scene, context.options) {
        Ok(file) => Ok(Descriptor::Image(file)),
        Err(tried) => {
            let missing = paths::missing("texture", &named.path, &tried);
            missing_file(context, named.location, missing)
        }
    }
}
