//! The only parallel code: rows of the film rendered by rayon, every pixel
//! sample with its own generator seeded from (pixel, sample index, seed).

use std::io::IsTerminal;
use std::ops::Range;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use rayon::prelude::*;

use crate::camera::Camera;
use crate::film::{Film, SplatSums};
use crate::image_io::Image;
use crate::integrator::{CameraSample, Integrator, SceneView, Splats};
use crate::limits::MemoryBudget;
use crate::look::{Look, PixelSampling};
use crate::sampler::{Sampler, SamplerKind};
use crate::scene::model::{Object, Scene};
use crate::subpixel::film_position;
use crate::world::World;

#[derive(Clone, Debug)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel in total, spread over the 2x2 sub-pixels in turn.
    pub spp: u32,
    pub seed: u64,
    /// Worker threads; `None`: one per core.
    pub threads: Option<usize>,
    pub integrator: Integrator,
    /// Scattering vertices before a path ends (the original: 5).
    pub max_depth: u32,
    /// Where sample values come from (independent random or Sobol').
    pub sampler: SamplerKind,
    /// Report progress on standard error: a line rewritten in place on a
    /// terminal, otherwise (batch logs) one line every
    /// [`PROGRESS_LOG_SECONDS`].
    pub progress: bool,
    /// Seconds between progress lines when standard error is not a
    /// terminal (`None`: [`PROGRESS_LOG_SECONDS`]).
    pub progress_every: Option<f64>,
    /// Scale samples down to this luminance (biased; `None`: off).
    pub clamp: Option<f64>,
    /// Whether the path integrator traces light subpaths for caustics where
    /// the scene has any (light tracing and connections).
    pub light_paths: bool,
    /// The conventions of the rendering.
    pub look: Look,
}

/// What a render did.
#[derive(Clone, Debug, Default)]
pub struct RenderStats {
    pub seconds: f64,
    /// Samples that contributed to the image.
    pub samples: u64,
    /// NaN or infinite samples that were dropped.
    pub dropped: u64,
    /// Samples above the firefly bound (see `film::FIREFLY_FACTOR`).
    pub fireflies: u64,
}

impl RenderStats {
    pub fn samples_per_second(&self) -> f64 {
        self.samples as f64 / self.seconds.max(1e-9)
    }
}

/// Renders `scene` (whose geometry is `world`) into a linear image, within
/// the default memory budget.
pub fn render(
    scene: &Scene,
    world: &World,
    settings: &RenderSettings,
) -> Result<(Image, RenderStats), String> {
    render_within(scene, world, settings, MemoryBudget::default())
}

/// [`render`], once the image's size is checked against `budget` (before
/// the film is allocated).
pub fn render_within(
    scene: &Scene,
    world: &World,
    settings: &RenderSettings,
    budget: MemoryBudget,
) -> Result<(Image, RenderStats), String> {
    let mut film = Film::within(
        settings.width.max(1) as usize,
        settings.height.max(1) as usize,
        budget,
    )?;
    let stats = render_into(scene, world, settings, &mut film, 0..settings.spp)?;
    Ok((film.to_image(), stats))
}

/// Adds the pixel samples with indices in `samples` to the pixels of `film`
/// that have not converged. Sample `i` of a
/// pixel is the same whichever call renders it, so rendering 0..4 and then
/// 4..8 gives the image of rendering 0..8.
pub fn render_into(
    scene: &Scene,
    world: &World,
    settings: &RenderSettings,
    film: &mut Film,
    samples: Range<u32>,
) -> Result<RenderStats, String> {
    let width = film.width;
    let height = film.height;
    let camera = Camera::new(
        &settings.look.camera(&scene.camera),
        width as u32,
        height as u32,
    );
    let mut view = SceneView::with_look(scene, world, settings.look);
    view.max_depth = settings.max_depth;
    view.camera = Some(camera.clone());
    view.light_paths &= settings.light_paths;
    // Light tracing's sums, only where light subpaths run.
    let splat_sums = SplatSums::new(if view.light_paths { width * height } else { 0 });
    let plan = SamplingPlan::for_scene(scene);
    let before = (film.samples(), film.dropped(), film.fireflies());
    let rows_done = AtomicUsize::new(0);
    let start = Instant::now();
    let mut builder = rayon::ThreadPoolBuilder::new();
    if let Some(threads) = settings.threads {
        builder = builder.num_threads(threads.max(1));
    }
    let pool = builder
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))?;
    let terminal = std::io::stderr().is_terminal();
    let samples_per_row = (width * samples.len()) as f64;
    let finished = std::sync::atomic::AtomicBool::new(false);
    std::thread::scope(|scope| {
        let reporter = settings.progress.then(|| {
            scope.spawn(|| {
                let every = settings.progress_every.unwrap_or(PROGRESS_LOG_SECONDS);
                report_progress(
                    &rows_done,
                    height,
                    samples_per_row,
                    start,
                    terminal,
                    every,
                    &finished,
                )
            })
        });
        pool.install(|| {
            film.pixels
                .par_chunks_mut(width)
                .enumerate()
                .for_each(|(row, pixels)| {
                    let y = height - 1 - row;
                    let mut light_paths = 0u64;
                    for (x, pixel) in pixels.iter_mut().enumerate() {
                        if pixel.converged {
                            continue;
                        }
                        let pixel_index = (row * width + x) as u64;
                        for sample in samples.clone() {
                            let context = PixelSample {
                                x,
                                y,
                                pixel_index,
                                sample,
                            };
                            let mut splats = Splats::default();
                            let value =
                                trace_sample(&view, &camera, plan, settings, context, &mut splats);
                            pixel.add(value, settings.clamp);
                            for &(sx, sy, splat) in splats.iter() {
                                splat_sums.add((height - 1 - sy) * width + sx, splat);
                            }
                            light_paths += splats.light_paths as u64;
                        }
                    }
                    splat_sums.add_light_paths(light_paths);
                    rows_done.fetch_add(1, Ordering::Relaxed);
                });
        });
        finished.store(true, Ordering::Relaxed);
        if let Some(reporter) = reporter {
            reporter.thread().unpark();
        }
    });
    splat_sums.add_to(film);
    Ok(RenderStats {
        seconds: start.elapsed().as_secs_f64(),
        samples: film.samples() - before.0,
        dropped: film.dropped() - before.1,
        fireflies: film.fireflies() - before.2,
    })
}

/// Which sample of which pixel is traced.
#[derive(Clone, Copy)]
struct PixelSample {
    x: usize,
    /// Row from the bottom of the image.
    y: usize,
    pixel_index: u64,
    sample: u32,
}

/// One camera sample: sub-pixel `sample mod 4` of the 2x2 grid with the tent
/// filter, lens and time only where the scene needs them.
fn trace_sample(
    view: &SceneView,
    camera: &Camera,
    plan: SamplingPlan,
    settings: &RenderSettings,
    at: PixelSample,
    splats: &mut Splats,
) -> crate::color::Color {
    let mut sampler = Sampler::new(
        settings.sampler,
        at.pixel_index,
        at.sample as u64,
        settings.seed,
    );
    let (film_x, film_y) = match settings.look.pixels {
        PixelSampling::Tent => film_position(at.x, at.y, at.sample % 4, sampler.next_2d()),
        PixelSampling::Centre => (at.x as f64 + 0.5, at.y as f64 + 0.5),
    };
    let lens = if plan.lens {
        sampler.next_2d()
    } else {
        [0.5, 0.5]
    };
    let time = if plan.time { sampler.next_f64() } else { 0.0 };
    let ray = camera.ray(film_x, film_y, lens, time);
    let sample = CameraSample {
        pixel_x: at.x,
        pixel_y: at.y,
        lens,
    };
    settings
        .integrator
        .radiance(view, ray, &sample, &mut sampler, splats)
}

/// Which sample dimensions a scene needs: a scene pays only for what it uses.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SamplingPlan {
    /// Lens samples (depth of field).
    pub lens: bool,
    /// Shutter-time samples (moving spheres).
    pub time: bool,
}

impl SamplingPlan {
    pub fn for_scene(scene: &Scene) -> SamplingPlan {
        SamplingPlan {
            lens: scene.camera.lens_radius >= crate::camera::MIN_LENS_RADIUS,
            time: has_motion(&scene.root),
        }
    }
}

fn has_motion(root: &Object) -> bool {
    let mut moving = false;
    root.for_each_leaf(&mut |leaf| {
        if let Object::Sphere { motion, .. } = leaf {
            moving |= motion.norm_squared() > 0.0;
        }
    });
    moving
}

/// Seconds between progress lines when standard error is not a terminal.
pub const PROGRESS_LOG_SECONDS: f64 = 5.0;

/// Reports the rows done until `finished`: on a terminal, one line
/// rewritten four times a second; otherwise a line every
/// [`PROGRESS_LOG_SECONDS`] (percent, samples/s, elapsed, remaining), so
/// that a batch log grows by a line, not by carriage returns.
fn report_progress(
    rows_done: &AtomicUsize,
    rows: usize,
    samples_per_row: f64,
    start: Instant,
    terminal: bool,
    every: f64,
    finished: &std::sync::atomic::AtomicBool,
) {
    let tick = if terminal {
        Duration::from_millis(250)
    } else {
        Duration::from_secs_f64(every)
    };
    let mut printed = false;
    loop {
        std::thread::park_timeout(tick);
        let done = rows_done.load(Ordering::Relaxed);
        let over = finished.load(Ordering::Relaxed);
        if over && !(terminal && printed) {
            return;
        }
        let elapsed = start.elapsed().as_secs_f64();
        let fraction = done as f64 / rows.max(1) as f64;
        let left = if done > 0 {
            format!("{:.0} s left", elapsed / fraction - elapsed)
        } else {
            "estimating".to_string()
        };
        let rate = done as f64 * samples_per_row / elapsed.max(1e-9) / 1e6;
        let line = format!(
            "rendering {:5.1}%  {rate:.2} M samples/s  {elapsed:.0} s elapsed  {left}",
            fraction * 100.0
        );
        if terminal {
            eprint!("\r{line}    ");
            printed = true;
            if over {
                eprintln!();
                return;
            }
        } else {
            eprintln!("{line}");
        }
    }
}
