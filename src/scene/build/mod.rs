//! Build stage: syntax tree -> `Scene` (dialects, names, files, validation).

mod camera;
mod cursor;
mod degenerate;
mod descriptor;
mod dialect;
pub mod dispersion;
mod light_blocks;
mod lobes;
mod material;
mod medium;
mod meshes;
mod mtl;
mod obj;
mod obj_check;
mod obj_framework;
mod objects;
mod paths;
mod profile;
mod shapes;
mod texture_file;
mod textures;
mod transform;
mod warning_tally;
mod weights;

use std::path::Path;

use crate::color::Color;
use crate::limits::shown;
use crate::scene::LoadOptions;
use crate::scene::ast::{Block, Document, ItemKind};
use crate::scene::error::{Diagnostic, Location, SceneError};
use crate::scene::model::{Material, Object, Scene};

pub use cursor::Cursor;
pub use dialect::{detect_dialect, distinct_words};
use warning_tally::WarningTally;

/// State shared by every build step: where we are, what went wrong so far.
pub struct Context<'a> {
    pub file: &'a Path,
    pub options: &'a LoadOptions,
    pub dialect: crate::scene::model::Dialect,
    pub warnings: Vec<Diagnostic>,
    /// Counts warnings by kind: only the first few of each are kept.
    pub tally: WarningTally,
    /// Files read besides the scene file (see [`LoadStats::assets`]).
    ///
    /// [`LoadStats::assets`]: crate::scene::model::LoadStats::assets
    pub assets: Vec<std::path::PathBuf>,
}

impl Context<'_> {
    pub fn error(&self, location: Location, message: String) -> SceneError {
        SceneError::At(self.diagnostic(location, message))
    }

    fn diagnostic(&self, location: Location, message: String) -> Diagnostic {
        Diagnostic {
            file: self.file.to_path_buf(),
            location,
            message,
        }
    }

    /// Records a warning; in strict mode the warning is returned as the error.
    pub fn warn(&mut self, location: Location, message: String) -> Result<(), SceneError> {
        if self.options.strict {
            return Err(self.error(location, message));
        }
        if self.tally.admit(&message, location) {
            self.warnings.push(self.diagnostic(location, message));
        }
        Ok(())
    }

    /// The warnings kept, and one for each kind of which more were counted.
    pub fn take_warnings(&mut self) -> Vec<Diagnostic> {
        let mut warnings = std::mem::take(&mut self.warnings);
        for (location, message) in std::mem::take(&mut self.tally).summaries() {
            warnings.push(self.diagnostic(location, message));
        }
        warnings
    }

    /// Warns that `field`, read at `location`, is not rendered, and why
    /// (`--strict` makes it an error): nothing a file says is dropped silently.
    pub fn not_rendered(
        &mut self,
        location: Location,
        field: &str,
        why: &str,
    ) -> Result<(), SceneError> {
        self.warn(location, format!("'{field}' is not rendered: {why}"))
    }

    /// Skips an unknown key and the numbers after it, with a warning.
    pub fn skip_field(
        &mut self,
        cursor: &mut Cursor,
        key: &str,
        location: Location,
        block: &str,
    ) -> Result<(), SceneError> {
        cursor.take_numbers();
        self.warn(
            location,
            format!(
                "unknown field '{}' in {}, skipped",
                shown(key),
                shown(block)
            ),
        )
    }

    /// Handles an item that is not a key: a nested block or a stray value.
    pub fn skip_item(
        &mut self,
        item: &crate::scene::ast::Item,
        block: &str,
    ) -> Result<(), SceneError> {
        match &item.kind {
            ItemKind::Block(b) => self.warn(
                item.location,
                format!(
                    "unknown block '{}' in {}, skipped",
                    shown(&b.name),
                    shown(block)
                ),
            ),
            ItemKind::Word(w) if &**w == "-" => Ok(()),
            _ => self.warn(
                item.location,
                format!(
                    "unexpected {} in {}, skipped",
                    item.describe(),
                    shown(block)
                ),
            ),
        }
    }
}

/// Builds a scene from a parsed document. `file` locates messages and relative paths.
pub fn build(document: &Document, file: &Path, options: &LoadOptions) -> Result<Scene, SceneError> {
    let dialect = options.dialect.unwrap_or_else(|| detect_dialect(document));
    let mut context = Context {
        file,
        options,
        dialect,
        warnings: Vec::new(),
        tally: WarningTally::default(),
        assets: Vec::new(),
    };
    let mut camera_block = None;
    let mut background = Color::BLACK;
    let mut material_blocks: Vec<&Block> = Vec::new();
    let mut group_blocks: Vec<(&Block, Location)> = Vec::new();
    let mut lights = Vec::new();
    let mut scene_medium = None;
    for item in &document.items {
        let Some(block) = item.block() else {
            context.skip_item(item, "the file")?;
            continue;
        };
        match block.name.as_str() {
            "PerspectiveCamera" | "DepthCamera" | "LensCamera" | "RealCamera"
            | "OrthographicCamera" | "FisheyeCamera" => {
                if camera_block.is_some() {
                    context.warn(
                        item.location,
                        "a second camera block replaces the first".into(),
                    )?;
                }
                camera_block = Some((block, item.location));
            }
            "Lights" | "DiskLights" => {
                lights.extend(light_blocks::build_lights(&mut context, block)?)
            }
            "Background" => background = build_background(&mut context, block)?,
            "Medium" => {
                if scene_medium.is_some() {
                    context.warn(
                        item.location,
                        "a second scene-wide Medium replaces the first".into(),
                    )?;
                }
                scene_medium = Some(medium::build_medium(&mut context, block)?);
            }
            "Materials" => material_blocks.push(block),
            "Group" => group_blocks.push((block, item.location)),
            "Textures" => {
                context.not_rendered(item.location, "Textures", "texture tables are not read")?
            }
            "Global" => context.not_rendered(
                item.location,
                "Global",
                "render settings come from the command line",
            )?,
            "Objects" => {
                context.not_rendered(item.location, "Objects", "instance tables are not read")?
            }
            other => context.warn(
                item.location,
                format!("unknown top-level block '{}', skipped", shown(other)),
            )?,
        }
    }
    let Some((camera_block, camera_location)) = camera_block else {
        return Err(context.error(
            Location { line: 1, column: 1 },
            "the file has no camera block (PerspectiveCamera)".into(),
        ));
    };
    let camera::CameraBlock {
        camera,
        mist,
        dispersion,
    } = camera::build_camera(&mut context, camera_block, camera_location)?;
    if let Some((mist, at)) = mist {
        if scene_medium.is_some() {
            context.warn(
                at,
                "'mist' is not rendered: the scene's Medium block replaces it".into(),
            )?;
        } else {
            scene_medium = Some(mist.medium());
        }
    }
    let mut specs = Vec::new();
    for block in material_blocks {
        specs.extend(material::build_materials(&mut context, block)?);
    }
    if specs.is_empty() {
        specs.push(material::MaterialSpec::new(Material::default()));
    }
    dispersion::resolve(&mut context, dispersion, &mut specs)?;
    let mut objects = objects::ObjectBuilder::new(specs.len());
    let mut roots = Vec::new();
    for (block, location) in group_blocks {
        roots.push(objects.group(&mut context, block, location)?);
    }
    // Scene materials, then the .mtl materials that meshes use, then the
    // materials of the emitting disks and parallelograms of lights.
    let mut specs: Vec<textures::MaterialImages> = specs
        .into_iter()
        .map(textures::MaterialImages::from_spec)
        .collect();
    specs.extend(objects.take_materials());
    for (material, object) in light_blocks::emitting_geometry(&lights, specs.len()) {
        specs.push(textures::MaterialImages::plain(material));
        roots.push(object);
    }
    let root = match roots.len() {
        1 => roots.pop().unwrap_or(Object::Group(Vec::new())),
        _ => Object::Group(roots),
    };
    let texture_start = std::time::Instant::now();
    let (materials, (textures, framework_readings)) =
        textures::load_textures(&mut context, specs, &root)?;
    let load = crate::scene::model::LoadStats {
        mesh_seconds: objects.mesh_seconds(),
        meshes_loaded: objects.meshes_loaded(),
        texture_seconds: texture_start.elapsed().as_secs_f64(),
        textures_loaded: textures.len(),
        assets: std::mem::take(&mut context.assets),
        ..Default::default()
    };
    Ok(Scene {
        camera,
        background,
        materials,
        textures,
        framework_readings,
        lights,
        root,
        medium: scene_medium,
        dialect,
        source: file.to_path_buf(),
        words: distinct_words(document),
        warnings: context.take_warnings(),
        load,
    })
}

fn build_background(context: &mut Context, block: &Block) -> Result<Color, SceneError> {
    let mut color = Color::BLACK;
    let mut cursor = Cursor::of(block);
    while let Some(item) = cursor.next() {
        match item.word() {
            Some("color") => {
                let c = cursor.vec3(context, "color")?;
                color = Color::new(c.x, c.y, c.z);
            }
            Some(key @ ("cubeMap" | "texture")) => {
                context.not_rendered(item.location, key, "the background is one colour")?;
                if matches!(cursor.peek().map(|i| &i.kind), Some(ItemKind::Word(_))) {
                    cursor.next();
                }
            }
            Some(key) => context.skip_field(&mut cursor, key, item.location, "Background")?,
            None => context.skip_item(item, "Background")?,
        }
    }
    Ok(color)
}

/// Parses and builds scene text (a file `t.txt` in the working directory), for tests.
#[cfg(test)]
pub(crate) fn build_text(text: &str) -> Result<Scene, String> {
    let file = Path::new("t.txt");
    let document = crate::scene::parse::parse(text, file).map_err(|e| e.to_string())?;
    build(&document, file, &LoadOptions::default()).map_err(|e| e.to_string())
}
