//! `pathtracer render`: a scene file to an image, with a one-line summary.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use clap::Args;

use pathtracer::adaptive::{StoppingRule, progress_for, render_adaptive};
use pathtracer::checkpoint::{
    CHECKPOINT_SECONDS, CheckpointStats, Checkpoints, checkpoint_path, render_resumable,
};
use pathtracer::image_io::{
    Encoding, PendingFile, check_writable, commit_together, encode_image, is_hdr, refuse_inputs,
};
use pathtracer::integrator::{Integrator, split};
use pathtracer::interrupt;
use pathtracer::photon_render;
use pathtracer::render::{Progress, RenderSettings, Renderer};
use pathtracer::render_job::{Crop, JobHeader};
use pathtracer::render_scene::RenderScene;

use super::sidecar::{Made, sidecar_json, sidecar_path};
use super::{
    EncodingOptions, SamplingOptions, default_output, linear_output_hint, load_for_render,
    render_scene,
};

#[derive(Args)]
pub struct RenderArgs {
    /// The scene file to render (the PA grammar or one of its dialects).
    scene: PathBuf,
    /// Output image (.bmp, .png, .pfm or .exr); default output/<scene name>.bmp.
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Samples per pixel in total (spread over the 2x2 sub-pixels); with
    /// --target-error or --time-budget, the most that any pixel gets.
    #[arg(long, default_value_t = 40, value_parser = clap::value_parser!(u32).range(1..))]
    spp: u32,
    /// Stop each pixel once its relative error is at most this, e.g. 0.01:
    /// once the standard error of its mean luminance (the largest in its
    /// 3x3 neighbourhood) is at most TARGET_ERROR x mean + 0.001.
    #[arg(long, value_parser = super::parse_positive)]
    target_error: Option<f64>,
    /// Stop the whole render within this many seconds of rendering (up to
    /// a year).
    #[arg(long, value_parser = parse_time_budget)]
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
    /// Write the film to OUTPUT.checkpoint.exr every SECONDS while
    /// rendering (default 60; 0: only when SIGINT or SIGTERM stops the
    /// render), so that --resume can continue it.
    #[arg(long, value_name = "SECONDS", value_parser = parse_interval)]
    checkpoint: Option<f64>,
    /// Continue the render from OUTPUT.checkpoint.exr (same scene and
    /// settings); without one, start from the first sample.
    #[arg(long)]
    resume: bool,
    /// Re-trace sample I of pixel (X, Y) alone (Y from the top) and print
    /// its path: vertices, lobes, weights and every term it adds; no image
    /// is written.
    #[arg(long, value_name = "X,Y,I", value_parser = super::debug_sample::parse)]
    debug_sample: Option<super::debug_sample::Which>,
}

/// A time budget: more than 0 and at most a year of seconds.
fn parse_time_budget(text: &str) -> Result<f64, String> {
    match text.trim().parse::<f64>() {
        Ok(seconds) if seconds > 0.0 && seconds <= 365.0 * 86400.0 => Ok(seconds),
        _ => Err(format!(
            "'{text}': seconds, more than 0 and at most 31536000 (a year)"
        )),
    }
}

/// A checkpoint interval: 0 (none while rendering) or 0.1 s to a day.
fn parse_interval(text: &str) -> Result<f64, String> {
    match text.parse::<f64>() {
        Ok(seconds) if seconds == 0.0 || (0.1..=86400.0).contains(&seconds) => Ok(seconds),
        _ => Err(format!("'{text}': seconds, 0 or from 0.1 to 86400")),
    }
}

pub fn run(args: &RenderArgs) -> Result<(), String> {
    if let Some(which) = args.debug_sample {
        return super::debug_sample::run(&args.scene, which, args.spp, &args.sampling);
    }
    if let Some(part) = &args.job.film {
        if args.output.is_some() || args.target_error.is_some() || args.time_budget.is_some() {
            return Err(
                "--film writes a film, not an image: no -o, --target-error or --time-budget"
                    .to_string(),
            );
        }
        if args.checkpoint.is_some() || args.resume {
            return Err(
                "--checkpoint and --resume are for image renders; a render job (--film) is rerun whole"
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
    let checkpoint = checkpoint_path(&output);
    let adaptive = args.target_error.is_some() || args.time_budget.is_some();
    if adaptive && (args.resume || args.checkpoint.is_some()) {
        return Err(
            "--checkpoint and --resume are for fixed-spp renders: not with --target-error or --time-budget (an interrupted adaptive render writes its partial image only)"
                .to_string(),
        );
    }
    if !args.resume && checkpoint.exists() {
        return Err(format!(
            "{}: the checkpoint of an unfinished render of this output is there: --resume continues it (delete it to start again)",
            checkpoint.display()
        ));
    }
    let encoding = args.encoding.encoding();
    encoding.check()?;
    let mut image_file = PendingFile::reserve(&output)?;
    // The checkpoint's name fits and its folder takes files: a signal or
    // the first interval can save the render.
    drop(PendingFile::reserve(&checkpoint)?);
    let mut sidecar_file = match is_hdr(&output) {
        true => Some(PendingFile::reserve(&sidecar_path(&output))?),
        false => None,
    };
    let scene = load_for_render(&args.scene, &args.sampling.scene)?;
    let outputs: Vec<&PendingFile> = std::iter::once(&image_file)
        .chain(sidecar_file.as_ref())
        .collect();
    refuse_inputs(&outputs, &scene.load.inputs(&args.scene))?;
    let settings = args.sampling.settings(&scene, args.spp, !args.quiet);
    check_writable(&output, settings.width as usize, settings.height as usize)?;
    if let Some(notice) = args.sampling.spp_notice(&settings, args.spp) {
        pathtracer::stderr_line!("{notice}");
    }
    let world_start = Instant::now();
    let scene = render_scene(scene, &settings);
    let world_seconds = world_start.elapsed().as_secs_f64();
    let rule = StoppingRule {
        target_error: args.target_error,
        time_budget: args.time_budget,
    };
    let header = JobHeader::new(
        &args.scene.display().to_string(),
        scene.description().load.source_hash,
        scene.world().triangle_count() as u64,
        &settings,
        args.sampling.scene.missing_assets.name(),
        Crop::full(settings.width, settings.height),
        0..settings.spp,
    );
    let checkpoints = Checkpoints {
        path: checkpoint,
        every: Some(args.checkpoint.unwrap_or(CHECKPOINT_SECONDS))
            .filter(|&seconds| seconds > 0.0)
            .map(Duration::from_secs_f64),
        header,
    };
    check_photon_options(args, &settings)?;
    let mut film = args.sampling.film(&settings)?;
    if args.resume {
        match checkpoints.read(args.sampling.scene.memory_budget())? {
            Some(partial) => film = partial,
            None => pathtracer::stderr_line!(
                "warning: {}: no checkpoint to resume: rendering from the first sample",
                checkpoints.path.display()
            ),
        }
    }
    // From here a first SIGINT or SIGTERM lets the samples in flight finish
    // and the partial image (and checkpoint) be written.
    let _graceful = interrupt::Graceful::start();
    // Photon mapping renders an image, not a film.
    let mut photon_image = None;
    let (stats, written) = if settings.integrator == Integrator::Sppm {
        let photons = args.sampling.photons.settings();
        let (image, stats) = photon_render::render(&scene, &settings, photons, true)?;
        photon_image = Some(image);
        (stats, CheckpointStats::default())
    } else if adaptive {
        let progress = progress_for(&film, settings.spp, rule);
        let renderer = Renderer::new(&scene, &settings, progress)?;
        let stats = render_adaptive(&renderer, rule, &mut film)?;
        (stats, CheckpointStats::default())
    } else {
        let samples = checkpoints.samples();
        let renderer = Renderer::new(&scene, &settings, Progress::new(samples.count(&film), None))?;
        render_resumable(&renderer, &mut film, &checkpoints)?
    };
    let held = match photon_image {
        Some(_) => stats.samples,
        None => film.samples(),
    };
    let mut image = photon_image.unwrap_or_else(|| film.to_image());
    if !is_hdr(&output) && args.encoding.encoding() == Encoding::default() {
        // The look's renderer's own curve before its writer (a square
        // root, a rounded gamma ...); `--gamma` and the rest replace it.
        settings.look.output.apply(&mut image);
    }
    if args.stats {
        print_phases(&scene, &settings, world_seconds, stats.seconds);
    }
    image_file.write(&encode_image(&output, &image, &encoding)?)?;
    let pixels = (settings.width as u64 * settings.height as u64).max(1);
    // What the image holds (a resumed render's earlier samples too).
    let reached = held as f64 / pixels as f64;
    let complete = stats.stopped.is_none();
    if let Some(sidecar) = &mut sidecar_file {
        let made = Made {
            spp: reached,
            samples: held,
            spp_asked: settings.spp,
            complete,
            seconds: Some(stats.seconds),
            parts: None,
        };
        let json = sidecar_json(&checkpoints.header, &made, &encoding);
        sidecar.write(json.as_bytes())?;
    }
    // The sidecar first, the image last: a new image always finds its own
    // sidecar beside it; a failure leaves both as they were.
    commit_together(sidecar_file.into_iter().chain([image_file]).collect())?;
    if complete {
        // The image is there: the checkpoint it continued has served.
        checkpoints.remove();
    }
    let (look, why) = args.sampling.look(scene.description());
    let checkpoint_note = match written.written {
        0 => String::new(),
        n => format!(", {n} checkpoints written in {:.2} s", written.seconds),
    };
    say!(
        "{}: look {} ({why}), {} integrator, {}x{}, {:.1} spp {}, render {:.2} s ({:.2} s in all), {:.3} M samples/s, {} NaN/Inf samples dropped, {} fireflies{}{checkpoint_note}",
        output.display(),
        look.name,
        settings.integrator.name(),
        settings.width,
        settings.height,
        reached,
        if complete {
            "spent"
        } else {
            "reached (interrupted)"
        },
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
    if let Some(hint) = linear_output_hint(&output, &encoding) {
        say!("{hint}");
    }
    if !complete && !adaptive {
        say!(
            "{}: the render so far; `render --resume` with the same arguments continues it",
            checkpoints.path.display()
        );
    }
    Ok(())
}

/// Refuses what photon mapping does not do, and its options without it.
fn check_photon_options(args: &RenderArgs, settings: &RenderSettings) -> Result<(), String> {
    if settings.integrator != Integrator::Sppm {
        if args.sampling.photons.given() {
            return Err(format!(
                "--photons-per-pass, --initial-radius and --alpha are options of --integrator sppm, not of the {} integrator",
                settings.integrator.name()
            ));
        }
        return Ok(());
    }
    if args.target_error.is_some() || args.time_budget.is_some() {
        return Err(
            "--target-error and --time-budget are not for --integrator sppm: photon mapping renders --spp passes, each pixel's error shrinking with its radius"
                .to_string(),
        );
    }
    if args.checkpoint.is_some() || args.resume {
        return Err(
            "--checkpoint and --resume are not for --integrator sppm: a photon-mapped pixel keeps a radius and photon count that checkpoints do not hold"
                .to_string(),
        );
    }
    Ok(())
}

/// `--stats`: the time of each phase, and the machinery a scene did not need.
fn print_phases(
    scene: &RenderScene,
    settings: &RenderSettings,
    world_seconds: f64,
    render_seconds: f64,
) {
    let load = &scene.description().load;
    let world = scene.world();
    let plan = scene.plan();
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
    say!(
        "light subpaths  {}",
        match (
            settings.integrator,
            settings.light_paths,
            scene.light_paths()
        ) {
            (Integrator::Original, _, _) => "off (original estimator)",
            (_, false, _) => "off (--no-light-paths)",
            _ if settings.look.one_sided_planes => "off (the look's planes are one-sided)",
            (_, true, false) => "off (no emitters, or no mirror or glass)",
            (_, true, true) => "on (caustics by light tracing and connections)",
        }
    );
    let split = match (settings.light_paths, scene.light_paths()) {
        _ if scene.media() || settings.integrator != Integrator::Path => {
            "off (path integrator without media only)".to_string()
        }
        (false, _) => "off (--no-light-paths)".to_string(),
        (true, true) => format!(
            "on ({} bounces from diffuse vertices seen through mirrors and glass)",
            split::SPLIT
        ),
        (true, false) => "off (as light subpaths, above)".to_string(),
    };
    say!("split bounces   {split}");
}
