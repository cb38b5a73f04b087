//! `pathtracer render`: a scene file to an image, with a one-line summary.

use crate::commands::prepare;
use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;

use pathtracer::adaptive::{StoppingRule, render_adaptive};
use pathtracer::image_io::{
    PendingFile, check_writable, commit_together, encode_image, is_hdr, refuse_inputs,
};
use pathtracer::integrator::{Integrator, SceneView};
use pathtracer::render::{RenderSettings, SamplingPlan, render_into};
use pathtracer::scene::model::Scene;
use pathtracer::world::World;

use super::{EncodingOptions, SamplingOptions, default_output, load_for_render};

#[derive(Args)]
pub struct RenderArgs {
    scene: PathBuf,
    /// Output image (.bmp, .png, .pfm or .exr); default output/<scene name>.bmp.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Samples per pixel in total (spread over the 2x2 sub-pixels); with
    /// --target-error or --time-budget, the most that any pixel gets.
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Stop each pixel once its relative error (standard error of the mean
    /// luminance over the mean) is at most this, e.g. 0.01.
    #[arg(long)]
    target_error: Option<f64>,
    /// Stop the whole render within this many seconds of rendering.
    #[arg(long)]
    time_budget: Option<f64>,
    #[command(flatten)]
    encoding: EncodingOptions,
    /// Do not print the progress line.
    #[arg(long)]
    quiet: bool,
    /// Print the time of each phase and what the scene did not need.
    #[arg(long)]
    stats: bool,
    #[command(flatten)]
    sampling: SamplingOptions,
    #[command(flatten)]
    job: super::job::JobOptions,
}

pub fn run(args: &RenderArgs) -> Result<(), String> {
    if let Some(part) = &args.job.film {
        if args.output.is_some() || args.target_error.is_some() || args.time_budget.is_some() {
            return Err(
                "--film writes a film, not an image: no -o, --target-error or --time-budget"
                    .to_string(),
            );
        }
        let sampling = &args.sampling;
        return super::job::run(&args.scene, part, args.spp, &args.job, sampling, args.quiet);
    }
    args.job.check_without_film()?;
    let started = Instant::now();
    let output = args
        .output
        .clone()
        .unwrap_or_else(|| default_output(&args.scene, ".bmp"));
    // Refuse an unwritable output or a bad encoding before the scene is
    // read and rendered: the temporaries of the image and its sidecar exist
    // from here on.
    check_writable(&output, 1, 1)?;
    let encoding = args.encoding.encoding();
    encoding.check()?;
    let mut image_file = PendingFile::reserve(&output)?;
    let mut sidecar_file = match is_hdr(&output) {
        true => Some(PendingFile::reserve(&sidecar_path(&output))?),
        false => None,
    };
    let mut scene = load_for_render(&args.scene, &args.sampling.scene)?;
    let outputs: Vec<&PendingFile> = std::iter::once(&image_file)
        .chain(sidecar_file.as_ref())
        .collect();
    refuse_inputs(&outputs, &scene_inputs(&args.scene, &scene))?;
    let settings = args.sampling.settings(&scene, args.spp, !args.quiet);
    check_writable(&output, settings.width as usize, settings.height as usize)?;
    let world_start = Instant::now();
    let world = prepare(&mut scene, &settings);
    let world_seconds = world_start.elapsed().as_secs_f64();
    let rule = StoppingRule {
        target_error: args.target_error,
        time_budget: args.time_budget,
    };
    let mut film = args.sampling.film(&settings)?;
    let stats = if rule == StoppingRule::default() {
        render_into(&scene, &world, &settings, &mut film, 0..settings.spp)?
    } else {
        render_adaptive(&scene, &world, &settings, rule, &mut film)?
    };
    let image = film.to_image();
    if args.stats {
        print_phases(&scene, &world, &settings, world_seconds, stats.seconds);
    }
    image_file.write(&encode_image(&output, &image, &encoding)?)?;
    let pixels = (settings.width as u64 * settings.height as u64).max(1);
    if let Some(sidecar) = &mut sidecar_file {
        // HDR images are measurements: say how they were made, next to
        // them, and how an 8-bit output would have encoded them.
        let json = format!(
            "{{\"scene\": {:?}, \"width\": {}, \"height\": {}, \"spp\": {}, \"samples\": {}, \"seconds\": {:.6}, \"seed\": {}, \"integrator\": \"{}\", \"sampler\": \"{}\", \"max_depth\": {}, \"clamp\": {}, \"light_paths\": {}, \"look\": \"{}\", \"gamma\": {}, \"exposure\": {}, \"tonemap\": \"{}\"}}\n",
            args.scene.display().to_string(),
            settings.width,
            settings.height,
            stats.samples as f64 / pixels as f64,
            stats.samples,
            stats.seconds,
            settings.seed,
            settings.integrator.name(),
            settings.sampler.name(),
            settings.max_depth,
            settings.clamp.map_or("null".to_string(), |c| c.to_string()),
            settings.light_paths,
            settings.look.name,
            encoding.gamma.map_or("null".to_string(), |g| g.to_string()),
            encoding.exposure,
            encoding.tonemap.name(),
        );
        sidecar.write(json.as_bytes())?;
    }
    // The sidecar first, the image last: a new image always finds its own
    // sidecar beside it; a failure leaves both as they were.
    commit_together(sidecar_file.into_iter().chain([image_file]).collect())?;
    let (look, why) = args.sampling.look(&scene);
    say!(
        "{}: look {} ({why}), {} integrator, {}x{}, {:.1} spp spent, render {:.2} s ({:.2} s in all), {:.3} M samples/s, {} NaN/Inf samples dropped, {} fireflies{}",
        output.display(),
        look.name,
        settings.integrator.name(),
        settings.width,
        settings.height,
        stats.samples as f64 / pixels as f64,
        stats.seconds,
        started.elapsed().as_secs_f64(),
        stats.samples_per_second() / 1e6,
        stats.dropped,
        stats.fireflies,
        match settings.clamp {
            Some(c) => format!(" (clamped at luminance {c}: biased)"),
            None => String::new(),
        }
    );
    Ok(())
}

/// `IMAGE.json`, the sidecar of an HDR image.
fn sidecar_path(image: &Path) -> PathBuf {
    let mut sidecar = image.as_os_str().to_os_string();
    sidecar.push(".json");
    PathBuf::from(sidecar)
}

/// The files a render reads, which no output may replace.
pub fn scene_inputs<'a>(scene_file: &'a Path, scene: &'a Scene) -> Vec<(&'a str, &'a Path)> {
    std::iter::once(("the scene file", scene_file))
        .chain(
            scene
                .load
                .assets
                .iter()
                .map(|asset| ("a file the scene reads", asset.as_path())),
        )
        .collect()
}

/// `--stats`: the time of each phase, and the machinery a scene did not need.
fn print_phases(
    scene: &Scene,
    world: &World,
    settings: &RenderSettings,
    world_seconds: f64,
    render_seconds: f64,
) {
    let load = &scene.load;
    let plan = SamplingPlan::for_scene(scene);
    let skipped = |done: bool| {
        if done {
            ""
        } else {
            " (skipped: none in the scene)"
        }
    };
    say!("parse           {:9.4} s", load.parse_seconds);
    say!(
        "load meshes     {:9.4} s  {} OBJ files{}",
        load.mesh_seconds,
        load.meshes_loaded,
        skipped(load.meshes_loaded > 0)
    );
    say!(
        "load textures   {:9.4} s  {} images{}",
        load.texture_seconds,
        load.textures_loaded,
        skipped(load.textures_loaded > 0)
    );
    say!(
        "build world     {:9.4} s  {} primitives, {} triangles in BVHs",
        world_seconds,
        world.primitives().len(),
        world.triangle_count()
    );
    say!("render          {render_seconds:9.4} s");
    say!(
        "lens sampling   {}",
        if plan.lens {
            "on"
        } else {
            "off (no depth of field)"
        }
    );
    say!(
        "time sampling   {}",
        if plan.time {
            "on"
        } else {
            "off (nothing moves)"
        }
    );
    let view = SceneView::with_look(scene, world, settings.look);
    say!(
        "light subpaths  {}",
        match (settings.integrator, settings.light_paths, view.light_paths) {
            (Integrator::Original, _, _) => "off (original estimator)",
            (_, false, _) => "off (--no-light-paths)",
            _ if settings.look.one_sided_planes => "off (the look's planes are one-sided)",
            (_, true, false) => "off (no emitters, or no mirror or glass)",
            (_, true, true) => "on (caustics by light tracing and connections)",
        }
    );
}
