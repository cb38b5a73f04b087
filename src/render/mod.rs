//! The only parallel code: rows of the film rendered by rayon, every pixel
//! sample with its own generator seeded from (pixel, sample index, seed).

pub mod adaptive;
pub mod checkpoint;
pub mod converge;
pub mod debug_sample;
pub mod film_file;
pub mod job;
pub mod photon_passes;
mod photon_tasks;
pub mod ppm_rounds;

use std::ops::Range;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use rayon::prelude::*;

use crate::film::{Film, PixelSum, SplatSums};
use crate::image_io::Image;
use crate::integrator::path_log::{PathLog, Silent};
use crate::integrator::{CameraSample, Integrator, Splats};
use crate::interrupt;
use crate::limits::MemoryBudget;
use crate::look::Look;
pub use crate::progress::{PROGRESS_LOG_SECONDS, Progress};
use crate::render_scene::{RenderScene, SceneSettings};
use crate::sampler::{Sampler, SamplerKind};
use crate::spectral::Dispersion;

#[derive(Clone, Debug)]
pub struct RenderSettings {
    pub width: u32,
    pub height: u32,
    /// Samples per pixel in total, spread over the 2x2 sub-pixels.
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
    /// Whether the path integrator uses its strategies for caustics where
    /// the scene has any: light subpaths (light tracing and connections)
    /// and split bounces (see [`crate::integrator::split`]).
    pub light_paths: bool,
    /// The conventions of the rendering.
    pub look: Look,
    /// Indices per RGB channel for every refractive material
    /// (`--dispersion`; `None`: the scene's own).
    pub dispersion: Option<Dispersion>,
}

impl RenderSettings {
    /// The settings that decide the render-time scene (see
    /// [`RenderScene::build`]).
    pub fn scene(&self) -> SceneSettings {
        SceneSettings {
            look: self.look,
            width: self.width,
            height: self.height,
            max_depth: self.max_depth,
            light_paths: self.light_paths,
            dispersion: self.dispersion,
        }
    }
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
    /// Why the render stopped before all its samples, if it did.
    pub stopped: Option<Stopped>,
}

impl RenderStats {
    pub fn samples_per_second(&self) -> f64 {
        self.samples as f64 / self.seconds.max(1e-9)
    }

    /// Adds the figures of a later call of the same render (its seconds,
    /// samples and why it stopped).
    pub fn add(&mut self, later: &RenderStats) {
        self.seconds += later.seconds;
        self.samples += later.samples;
        self.dropped += later.dropped;
        self.fireflies += later.fireflies;
        self.stopped = later.stopped;
    }
}

/// Renders `scene` into a linear image, within the default memory budget.
pub fn render(
    scene: &RenderScene,
    settings: &RenderSettings,
) -> Result<(Image, RenderStats), String> {
    render_within(scene, settings, MemoryBudget::default())
}

/// [`render`], once the image's size is checked against `budget` (before
/// the film is allocated).
pub fn render_within(
    scene: &RenderScene,
    settings: &RenderSettings,
    budget: MemoryBudget,
) -> Result<(Image, RenderStats), String> {
    let mut film = Film::within(
        settings.width.max(1) as usize,
        settings.height.max(1) as usize,
        budget,
    )?;
    let stats = render_into(scene, settings, &mut film, 0..settings.spp)?;
    Ok((film.to_image(), stats))
}

/// Adds the pixel samples with indices in `samples` to the pixels of `film`
/// that have not converged, with a [`Renderer`] made for this one call.
/// Sample `i` of a pixel is the same whichever call renders it, so
/// rendering 0..4 and then 4..8 gives the image of rendering 0..8.
pub fn render_into(
    scene: &RenderScene,
    settings: &RenderSettings,
    film: &mut Film,
    samples: Range<u32>,
) -> Result<RenderStats, String> {
    let samples = Samples::Range(samples);
    let progress = Progress::new(samples.count(film), None);
    let renderer = Renderer::new(scene, settings, progress)?;
    renderer.render(film, &samples, Stop::Never)
}

/// Which samples of each pixel a call adds.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Samples {
    /// The same indices for every pixel that has not converged.
    Range(Range<u32>),
    /// Each pixel from the first index it has not taken yet (`first` plus
    /// its kept and dropped samples: every sample counts in exactly one)
    /// up to `end`: what continues a render that stopped part way, in the
    /// same process or from a checkpoint.
    Continue { first: u32, end: u32 },
}

impl Samples {
    /// The indices `pixel` takes.
    pub fn of(&self, pixel: &PixelSum) -> Range<u32> {
        match self {
            Samples::Range(range) => range.clone(),
            Samples::Continue { first, end } => {
                let taken = pixel.samples.saturating_add(pixel.dropped);
                first.saturating_add(taken).min(*end)..*end
            }
        }
    }

    /// The pixel samples a call will trace into `film`.
    pub fn count(&self, film: &Film) -> u64 {
        film.pixels
            .iter()
            .filter(|p| !p.converged)
            .map(|p| self.of(p).len() as u64)
            .sum()
    }
}

/// When a call may stop before all its samples are traced. Either way the
/// film holds whole samples only, and [`Samples::Continue`] takes up from
/// where each pixel stopped.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stop {
    Never,
    /// On SIGINT or SIGTERM ([`interrupt::interrupted`]), between two
    /// samples; and at the deadline, if there is one, between two pixels.
    Interrupted {
        deadline: Option<Instant>,
    },
}

/// Why a call stopped early.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stopped {
    /// By this signal (2: SIGINT, 15: SIGTERM).
    Signal(i32),
    Deadline,
}

/// What a render needs besides the scene and the film, made once and
/// reused by every call of one render (adaptive passes, converge stages,
/// the slices between checkpoints): the worker threads and the progress.
pub struct Renderer<'a> {
    settings: &'a RenderSettings,
    scene: &'a RenderScene,
    pool: rayon::ThreadPool,
    progress: Progress,
}

impl<'a> Renderer<'a> {
    /// A renderer of `scene` into films of `settings`' size; `progress`
    /// counts the work of all its calls. `scene` must have been built for
    /// `settings`.
    pub fn new(
        scene: &'a RenderScene,
        settings: &'a RenderSettings,
        progress: Progress,
    ) -> Result<Renderer<'a>, String> {
        if *scene.settings() != settings.scene() {
            return Err(format!(
                "the render-time scene was built for {:?}, not for {:?}",
                scene.settings(),
                settings.scene()
            ));
        }
        if settings.integrator == Integrator::Sppm {
            return Err(
                "--integrator sppm renders whole photon passes, not pixel samples: `render` runs it, this command does not"
                    .to_string(),
            );
        }
        let pool = worker_pool(settings.threads)?;
        Ok(Renderer {
            settings,
            scene,
            pool,
            progress,
        })
    }

    /// The work counted over every call.
    pub fn progress(&self) -> &Progress {
        &self.progress
    }

    pub fn settings(&self) -> &RenderSettings {
        self.settings
    }

    /// Adds `samples` to the pixels of `film` that have not converged,
    /// unless `stop` says to stop first.
    pub fn render(
        &self,
        film: &mut Film,
        samples: &Samples,
        stop: Stop,
    ) -> Result<RenderStats, String> {
        let settings = self.settings;
        let (width, height) = (film.width, film.height);
        let expected = (settings.width.max(1), settings.height.max(1));
        if (width, height) != (expected.0 as usize, expected.1 as usize) {
            return Err(format!(
                "a {width}x{height} film for a {}x{} render",
                expected.0, expected.1
            ));
        }
        // Light tracing's sums, only where light subpaths run.
        let splat_sums = SplatSums::try_new(if self.scene.light_paths() {
            width * height
        } else {
            0
        })?;
        let before = (film.samples(), film.dropped(), film.fireflies());
        let start = Instant::now();
        let stopping = AtomicBool::new(false);
        let interruptible = matches!(stop, Stop::Interrupted { .. });
        let deadline = match stop {
            Stop::Interrupted { deadline } => deadline,
            Stop::Never => None,
        };
        let stop_before_sample = || interruptible && interrupt::interrupted().is_some();
        let stop_before_pixel = || {
            stopping.load(Ordering::Relaxed)
                || stop_before_sample()
                || deadline.is_some_and(|d| Instant::now() >= d)
        };
        self.progress
            .while_running(settings.progress, settings.progress_every, || {
                self.pool.install(|| {
                    film.pixels
                        .par_chunks_mut(width)
                        .enumerate()
                        .for_each(|(row, pixels)| {
                            let y = height - 1 - row;
                            let mut light_paths = 0u64;
                            let mut traced = 0u64;
                            'pixels: for (x, pixel) in pixels.iter_mut().enumerate() {
                                if pixel.converged {
                                    continue;
                                }
                                if stop_before_pixel() {
                                    stopping.store(true, Ordering::Relaxed);
                                    break;
                                }
                                let pixel_index = (row * width + x) as u64;
                                for sample in samples.of(pixel) {
                                    if stop_before_sample() {
                                        stopping.store(true, Ordering::Relaxed);
                                        break 'pixels;
                                    }
                                    let at = PixelSample {
                                        x,
                                        y,
                                        pixel_index,
                                        sample,
                                    };
                                    let mut splats = Splats::default();
                                    let value = self.trace_sample(at, &mut splats, &mut Silent);
                                    pixel.add(value, settings.clamp);
                                    for &(sx, sy, splat) in splats.iter() {
                                        splat_sums.add((height - 1 - sy) * width + sx, splat);
                                    }
                                    light_paths += splats.light_paths as u64;
                                    traced += 1;
                                }
                            }
                            splat_sums.add_light_paths(light_paths);
                            self.progress.add(traced);
                        });
                });
            });
        splat_sums.add_to(film);
        let stopped = stopping
            .load(Ordering::Relaxed)
            .then(|| match interrupt::interrupted() {
                Some(signal) => Stopped::Signal(signal),
                None => Stopped::Deadline,
            });
        Ok(RenderStats {
            seconds: start.elapsed().as_secs_f64(),
            samples: film.samples() - before.0,
            dropped: film.dropped() - before.1,
            fireflies: film.fireflies() - before.2,
            stopped,
        })
    }

    /// One camera sample: a position under the 2x2 sub-pixels' tent filter
    /// (see `subpixel`), lens and time only where the scene needs them.
    pub(crate) fn trace_sample(
        &self,
        at: PixelSample,
        splats: &mut Splats,
        log: &mut impl PathLog,
    ) -> crate::color::Color {
        let settings = self.settings;
        let mut sampler = Sampler::new(
            settings.sampler,
            at.pixel_index,
            at.sample as u64,
            settings.seed,
        );
        let (ray, lens) = self.scene.camera_ray(at.x, at.y, &mut sampler);
        let sample = CameraSample {
            pixel_x: at.x,
            pixel_y: at.y,
            lens,
        };
        settings
            .integrator
            .radiance_logged(self.scene, ray, &sample, &mut sampler, splats, log)
    }
}

/// Which sample of which pixel is traced.
#[derive(Clone, Copy)]
pub(crate) struct PixelSample {
    pub x: usize,
    /// Row from the bottom of the image.
    pub y: usize,
    /// Row from the top times the width, plus `x` (what seeds the sampler).
    pub pixel_index: u64,
    pub sample: u32,
}

/// The worker threads of a render: `threads` of them (at least one), or
/// rayon's default (one per core) when not given.
pub fn worker_pool(threads: Option<usize>) -> Result<rayon::ThreadPool, String> {
    let mut builder = rayon::ThreadPoolBuilder::new();
    if let Some(threads) = threads {
        builder = builder.num_threads(threads.max(1));
    }
    builder
        .build()
        .map_err(|e| format!("cannot start worker threads: {e}"))
}
