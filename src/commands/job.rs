//! `pathtracer render SCENE --film PART.exr [--samples A..B] [--crop
//! x0,y0,x1,y1]`: one part of a render, written as a film for `merge`.

use std::ops::Range;
use std::path::{Path, PathBuf};

use clap::Args;

use pathtracer::image_io::{PendingFile, check_writable, refuse_inputs};
use pathtracer::render::film_file::encode_film;
use pathtracer::render::job::{Crop, JobHeader, parse_samples};
use pathtracer::render::render_into;

use super::{SamplingOptions, load_for_render, render_scene};

/// The options that make `render` a render job.
#[derive(Args)]
pub struct JobOptions {
    /// Write the raw sums of the render (a film, .exr) instead of an image,
    /// for `pathtracer merge`.
    #[arg(long)]
    pub film: Option<PathBuf>,
    /// With --film: the sample indices A..B (B excluded) of every pixel
    /// (default 0..SPP).
    #[arg(long, value_parser = parse_samples)]
    pub samples: Option<Range<u32>>,
    /// With --film: render only the pixels x0 <= x < x1, y0 <= y < y1 (row 0
    /// at the top).
    #[arg(long, value_parser = Crop::parse)]
    pub crop: Option<Crop>,
}

impl JobOptions {
    /// Refuses the job options of a render that writes an image.
    pub fn check_without_film(&self) -> Result<(), String> {
        if self.samples.is_some() || self.crop.is_some() {
            return Err("--samples and --crop need --film PART.exr (a render job)".to_string());
        }
        Ok(())
    }
}

/// Renders the samples and pixels of `job` into its film file.
pub fn run(
    scene_path: &Path,
    part: &Path,
    spp: u32,
    job: &JobOptions,
    sampling: &SamplingOptions,
    quiet: bool,
) -> Result<(), String> {
    let samples = job.samples.clone().unwrap_or(0..spp);
    check_writable(part, 1, 1)?;
    if !part
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("exr"))
    {
        return Err(format!("{}: a film is an .exr file", part.display()));
    }
    // As for an image: the film's temporary exists before the scene is
    // read, and a film that would replace one of the render's inputs is
    // refused.
    let mut part_file = PendingFile::reserve(part)?;
    let scene = load_for_render(scene_path, &sampling.scene)?;
    refuse_inputs(&[&part_file], &scene.load.inputs(scene_path))?;
    let settings = sampling.settings(&scene, samples.end, !quiet);
    if settings.integrator == pathtracer::integrator::Integrator::Sppm {
        return Err(
            "render jobs (--film) are not for --integrator sppm: every pass of photon mapping needs the whole image's visible points"
                .to_string(),
        );
    }
    let crop = job
        .crop
        .unwrap_or(Crop::full(settings.width, settings.height));
    crop.check(settings.width, settings.height)?;
    check_writable(part, settings.width as usize, settings.height as usize)?;
    let scene = render_scene(scene, &settings);
    let mut film = sampling.film(&settings)?;
    crop.restrict(&mut film);
    let stats = render_into(&scene, &settings, &mut film, samples.clone())?;
    let header = JobHeader::new(
        &scene_path.display().to_string(),
        scene.description().load.source_hash,
        scene.world().triangle_count() as u64,
        &settings,
        sampling.scene.missing_assets.name(),
        crop,
        samples.clone(),
    );
    part_file.write(&encode_film(part, &film, &header)?)?;
    part_file.commit()?;
    say!(
        "{}: film of samples {}..{} of pixels {crop} ({}x{} image), {} samples, {} light subpaths, render {:.2} s, {} NaN/Inf samples dropped, {} fireflies, {} saturated",
        part.display(),
        samples.start,
        samples.end,
        settings.width,
        settings.height,
        stats.samples,
        film.light_paths,
        stats.seconds,
        stats.dropped,
        stats.fireflies,
        film.saturated(),
    );
    Ok(())
}
