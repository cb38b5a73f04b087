//! Command line: parses arguments, calls the library, prints errors, sets the
//! exit code. No rendering logic lives here.

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Instant;

use clap::{Args, Parser, Subcommand};

use pathtracer::image_io::{check_writable, read_image, write_image};
use pathtracer::metrics::compare;
use pathtracer::integrator::Integrator;
use pathtracer::render::{RenderSettings, render};
use pathtracer::scene::model::{Dialect, Scene};
use pathtracer::scene::{LoadOptions, load_scene};
use pathtracer::world::World;

#[derive(Parser)]
#[command(name = "pathtracer", version, about = "A path tracer for PA scene files")]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Parse and build scene files and print a summary of each.
    Check {
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        #[command(flatten)]
        scene_options: SceneOptions,
    },
    /// Render a scene file to an image.
    Render(RenderArgs),
    /// Compare an image with a reference: RMSE, relative MSE, PSNR, SSIM.
    Compare {
        /// The image under test (BMP, PNG or PFM).
        image: PathBuf,
        /// The reference image.
        reference: PathBuf,
        /// Print JSON instead of text.
        #[arg(long)]
        json: bool,
    },
}

#[derive(Args, Clone)]
struct SceneOptions {
    /// Directory that relative mesh and texture paths resolve against first.
    #[arg(long)]
    base: Option<PathBuf>,
    /// Read the file as this dialect instead of detecting it.
    #[arg(long, value_parser = parse_dialect)]
    dialect: Option<Dialect>,
    /// Treat warnings (unknown fields, count mismatches, ...) as errors.
    #[arg(long)]
    strict: bool,
}

#[derive(Args)]
struct RenderArgs {
    scene: PathBuf,
    /// Output image (.bmp, .png or .pfm); default output/<scene name>.bmp.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Samples per pixel in total (spread over the 2x2 sub-pixels).
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Seed of the random sequence: the same seed gives the same image.
    #[arg(long, default_value_t = 0)]
    seed: u64,
    /// Worker threads (default: one per core).
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=1024))]
    threads: Option<u32>,
    /// Image width, overriding the scene's camera.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
    width: Option<u32>,
    /// Image height, overriding the scene's camera.
    #[arg(long, value_parser = clap::value_parser!(u32).range(1..=65536))]
    height: Option<u32>,
    /// Gamma for 8-bit output (2.2 for smallpt-style images; default: none,
    /// as the PA framework writer).
    #[arg(long)]
    gamma: Option<f64>,
    /// Do not print the progress line.
    #[arg(long)]
    quiet: bool,
    #[command(flatten)]
    scene_options: SceneOptions,
}

fn parse_dialect(name: &str) -> Result<Dialect, String> {
    Dialect::from_name(name).ok_or_else(|| {
        let names: Vec<&str> = Dialect::ALL.iter().map(|d| d.name()).collect();
        format!("unknown dialect '{name}' (one of: {})", names.join(", "))
    })
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Check {
            scenes,
            scene_options,
        } => check(&scenes, &scene_options),
        Command::Render(args) => render_command(&args),
        Command::Compare {
            image,
            reference,
            json,
        } => compare_command(&image, &reference, json),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(message) => {
            eprintln!("error: {message}");
            ExitCode::FAILURE
        }
    }
}

fn load_options(options: &SceneOptions) -> LoadOptions {
    LoadOptions {
        base: options.base.clone(),
        dialect: options.dialect,
        strict: options.strict,
    }
}

fn check(scenes: &[PathBuf], options: &SceneOptions) -> Result<(), String> {
    let mut failures = 0;
    for path in scenes {
        match load_scene(path, &load_options(options)) {
            Ok(scene) => {
                for warning in &scene.warnings {
                    eprintln!("warning: {warning}");
                }
                println!("{}: {} materials", path.display(), scene.materials.len());
            }
            Err(error) => {
                eprintln!("error: {error}");
                failures += 1;
            }
        }
    }
    if failures > 0 {
        return Err(format!("{failures} of {} scene files failed", scenes.len()));
    }
    Ok(())
}

fn render_command(args: &RenderArgs) -> Result<(), String> {
    let started = Instant::now();
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| default_output(&args.scene));
    // Refuse an unwritable output before the scene is read and rendered.
    check_writable(&output, 1, 1)?;
    let scene = load_scene(&args.scene, &load_options(&args.scene_options))
        .map_err(|e| e.to_string())?;
    report_scene_warnings(&scene);
    let width = args.width.unwrap_or(scene.camera.width);
    let height = args.height.unwrap_or(scene.camera.height);
    check_writable(&output, width as usize, height as usize)?;
    let world = World::build(&scene);
    let settings = RenderSettings {
        width,
        height,
        spp: args.spp,
        seed: args.seed,
        threads: args.threads.map(|t| t as usize),
        integrator: Integrator::Original,
        progress: !args.quiet,
    };
    let (image, stats) = render(&scene, &world, &settings)?;
    write_image(&output, &image, args.gamma)
        .map_err(|e| format!("{}: {e}", output.display()))?;
    println!(
        "{}: {}x{}, {} spp, render {:.2} s ({:.2} s in all), {:.3} M samples/s, {} NaN/Inf samples dropped",
        output.display(),
        settings.width,
        settings.height,
        settings.spp,
        stats.seconds,
        started.elapsed().as_secs_f64(),
        stats.samples_per_second() / 1e6,
        stats.dropped
    );
    Ok(())
}

fn compare_command(image: &Path, reference: &Path, json: bool) -> Result<(), String> {
    let test = read_image(image)?;
    let reference_image = read_image(reference)?;
    let comparison = compare(&test, &reference_image)?;
    if json {
        println!("{}", comparison.to_json());
    } else {
        println!("{comparison}");
    }
    Ok(())
}

fn report_scene_warnings(scene: &Scene) {
    for warning in &scene.warnings {
        eprintln!("warning: {warning}");
    }
    for feature in &scene.unsupported {
        eprintln!("warning: not rendered yet: {feature}");
    }
}

fn default_output(scene: &Path) -> PathBuf {
    let stem = scene
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_else(|| "render".to_string());
    Path::new("output").join(format!("{stem}.bmp"))
}
