//! `pathtracer check`: parse and build scene files, one summary each.

use std::path::PathBuf;

use clap::Args;

use pathtracer::look::summary;
use pathtracer::scene::load_scene;

use super::SceneOptions;

#[derive(Args)]
pub struct CheckArgs {
    /// The scene files to read (the PA grammar or one of its dialects).
    #[arg(required = true)]
    scenes: Vec<PathBuf>,
    #[command(flatten)]
    scene_options: SceneOptions,
}

pub fn run(args: &CheckArgs) -> Result<(), String> {
    let mut failures = 0;
    for path in &args.scenes {
        match load_scene(path, &args.scene_options.load_options()) {
            Ok(scene) => {
                for warning in &scene.warnings {
                    pathtracer::stderr_line!("warning: {warning}");
                }
                say!("{}: {}", path.display(), summary(&scene));
            }
            Err(error) => {
                pathtracer::stderr_line!("error: {error}");
                failures += 1;
            }
        }
    }
    if failures > 0 {
        return Err(format!(
            "{failures} of {} scene files failed",
            args.scenes.len()
        ));
    }
    Ok(())
}
