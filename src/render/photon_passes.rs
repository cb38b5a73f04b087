//! The render driver of stochastic progressive photon mapping (see
//! `integrator::sppm` for the method): the passes, each with its parallel
//! loops (camera rays by rows, photons by `photon_tasks::trace_photons`,
//! the pixels' update), progress, and stopping between passes on a signal.
//! The only parallel code besides `render`.

use std::time::Instant;

use rayon::prelude::*;

use crate::image_io::Image;
use crate::interrupt;
use crate::look::PhotonMethod;
use crate::math::Aabb;
use crate::progress::Progress;
use crate::render::converge::ConvergencePoint;
use crate::render::photon_tasks::trace_photons;
use crate::render::{RenderSettings, RenderStats, Stopped};
use crate::render_scene::RenderScene;
use crate::rng::mix64;
use crate::sampler::Sampler;

use crate::integrator::sppm::grid::{GridPoint, PointGrid};
use crate::integrator::sppm::pixel::{Gathered, PixelState};
use crate::integrator::sppm::{PhotonSettings, options, photon, visible_point};

/// Salt of the photons' seeds (apart from the camera rays').
const PHOTON_SALT: u64 = 0x9807_0DA5_5E5D_1CE5;

/// A photon-mapped render in progress.
pub struct PhotonMapper<'a> {
    scene: &'a RenderScene,
    settings: &'a RenderSettings,
    photon_settings: PhotonSettings,
    photons: u64,
    pool: rayon::ThreadPool,
    /// Row-major from the top, as the image.
    pixels: Vec<PixelState<'a>>,
    gathered: Gathered,
    grid: PointGrid,
    grid_points: Vec<GridPoint>,
    passes: u32,
    dropped: u64,
    /// The radius every pixel started with.
    first_radius: f64,
}

impl<'a> PhotonMapper<'a> {
    pub fn new(
        scene: &'a RenderScene,
        settings: &'a RenderSettings,
        photon_settings: PhotonSettings,
    ) -> Result<PhotonMapper<'a>, String> {
        if is_yao(scene) {
            return Err(
                "the yao look's PPM renders whole images (`render`, `lookalike`): not pass by pass"
                    .to_string(),
            );
        }
        let photon_settings = photon_settings.with_look(scene.look());
        photon_settings.check()?;
        if *scene.settings() != settings.scene() {
            return Err("the render-time scene was built for other settings".to_string());
        }
        let (width, height) = (
            settings.width.max(1) as usize,
            settings.height.max(1) as usize,
        );
        let count = width * height;
        let mut pixels = Vec::new();
        if pixels.try_reserve_exact(count).is_err() {
            return Err(format!(
                "cannot allocate the photon-mapping state of {width}x{height} pixels"
            ));
        }
        pixels.resize(
            count,
            PixelState::new(photon_settings.initial_radius.unwrap_or(0.0)),
        );
        let pool = super::worker_pool(settings.threads)?;
        Ok(PhotonMapper {
            scene,
            settings,
            photons: photon_settings.photons(count as u64),
            photon_settings,
            pool,
            pixels,
            gathered: Gathered::try_new(count)?,
            grid: PointGrid::default(),
            grid_points: Vec::new(),
            passes: 0,
            dropped: 0,
            first_radius: photon_settings.initial_radius.unwrap_or(0.0),
        })
    }

    /// Photons per pass.
    pub fn photons_per_pass(&self) -> u64 {
        self.photons
    }

    pub fn passes(&self) -> u32 {
        self.passes
    }

    /// Work units of one pass for [`Progress`]: camera rays and photons.
    pub fn work_per_pass(&self) -> u64 {
        self.pixels.len() as u64 + self.photons
    }

    /// The radius every pixel started with (the rule's is known after the
    /// first pass; 0 before).
    pub fn initial_radius(&self) -> f64 {
        self.first_radius
    }

    /// Runs one pass, counting its work in `progress`.
    pub fn pass(&mut self, progress: &Progress) {
        let scene = self.scene;
        let settings = self.settings;
        let pass = self.passes;
        let width = settings.width.max(1) as usize;
        let height = self.pixels.len() / width;
        let time = if scene.plan().time {
            (mix64(settings.seed ^ mix64(pass as u64 ^ PHOTON_SALT)) >> 11) as f64
                * (1.0 / (1u64 << 53) as f64)
        } else {
            0.0
        };
        let pool = &self.pool;
        // 1. Camera pass.
        let dropped: u64 = pool.install(|| {
            self.pixels
                .par_chunks_mut(width)
                .enumerate()
                .map(|(row, pixels)| {
                    let y = height - 1 - row;
                    let mut dropped = 0;
                    for (x, pixel) in pixels.iter_mut().enumerate() {
                        let index = (row * width + x) as u64;
                        let mut sampler =
                            Sampler::new(settings.sampler, index, pass as u64, settings.seed);
                        let (mut ray, _) = scene.camera_ray(x, y, &mut sampler);
                        ray.time = if scene.plan().time { time } else { ray.time };
                        let path = visible_point::trace(scene, ray, &mut sampler);
                        if path.direct.is_finite() {
                            pixel.direct += path.direct;
                        } else {
                            dropped += 1;
                        }
                        pixel.visible = path.visible;
                    }
                    progress.add(pixels.len() as u64);
                    dropped
                })
                .sum()
        });
        self.dropped += dropped;
        if pass == 0 && self.photon_settings.initial_radius.is_none() {
            self.first_radius = rule_radius(&self.pixels);
            for pixel in &mut self.pixels {
                pixel.radius = self.first_radius;
            }
        }
        // 2. The grid of visible points.
        self.grid_points.clear();
        self.grid_points
            .extend(self.pixels.iter().enumerate().filter_map(|(i, p)| {
                p.visible.map(|v| GridPoint {
                    index: i as u32,
                    point: v.point,
                    radius: p.radius,
                })
            }));
        self.grid.rebuild(&self.grid_points);
        // 3. Photon pass.
        let grid = &self.grid;
        let pixels = &self.pixels;
        let gathered = &self.gathered;
        let max_depth = scene.max_depth();
        trace_photons(
            pool,
            settings,
            pass as u64,
            PHOTON_SALT,
            self.photons,
            progress,
            |_, sampler| {
                photon::trace(scene, sampler, time, &mut |hit| {
                    grid.candidates(&hit.point, |index| {
                        let pixel = &pixels[index as usize];
                        let Some(visible) = &pixel.visible else {
                            return;
                        };
                        if visible.depth + 1 + hit.bounces > max_depth
                            || (visible.point - hit.point).norm_squared()
                                > pixel.radius * pixel.radius
                        {
                            return;
                        }
                        let value = visible.reflectance(&hit.wi) * hit.power;
                        if value.is_finite() {
                            gathered.add(index as usize, value);
                        }
                    });
                });
            },
        );
        // 4. Radius and flux update.
        let alpha = self.photon_settings.alpha;
        let unit = scene.emitters().photon_power_unit();
        let gathered = &self.gathered;
        pool.install(|| {
            self.pixels
                .par_iter_mut()
                .enumerate()
                .for_each(|(index, pixel)| {
                    let (count, flux) = gathered.take(index);
                    pixel.update(count, flux * unit, alpha);
                    pixel.visible = None;
                });
        });
        self.passes += 1;
    }

    /// The image after the passes so far (linear radiance).
    pub fn image(&self) -> Image {
        let width = self.settings.width.max(1) as usize;
        Image {
            width,
            height: self.pixels.len() / width,
            pixels: self
                .pixels
                .iter()
                .map(|p| p.radiance(self.passes, self.photons))
                .collect(),
        }
    }
}

/// Whether `scene`'s look renders by yao-jz's PPM (`integrator::ppm`).
fn is_yao(scene: &RenderScene) -> bool {
    scene
        .look()
        .photons
        .is_some_and(|look| look.method == PhotonMethod::Yao)
}

/// The default initial radius ([`options::RADIUS_DIVISOR`]): from the box
/// of the first pass's visible points (1 when there are none).
fn rule_radius(pixels: &[PixelState]) -> f64 {
    let mut bounds = Aabb::empty();
    for visible in pixels.iter().filter_map(|p| p.visible.as_ref()) {
        bounds = bounds.include_point(visible.point);
    }
    let diagonal = if bounds.is_empty() {
        0.0
    } else {
        bounds.extent().norm()
    };
    if diagonal > 0.0 && diagonal.is_finite() {
        diagonal / options::RADIUS_DIVISOR
    } else {
        1.0
    }
}

/// Renders `settings.spp` passes of `scene` by photon mapping; with
/// `stop_on_signal`, SIGINT or SIGTERM ends it after the pass in flight.
pub fn render(
    scene: &RenderScene,
    settings: &RenderSettings,
    photon_settings: PhotonSettings,
    stop_on_signal: bool,
) -> Result<(Image, RenderStats), String> {
    if is_yao(scene) {
        return super::ppm_rounds::render(scene, settings, photon_settings, stop_on_signal);
    }
    let start = Instant::now();
    let mut mapper = PhotonMapper::new(scene, settings, photon_settings)?;
    let passes = settings.spp.max(1);
    let progress = Progress::new(passes as u64 * mapper.work_per_pass(), None);
    let mut stopped = None;
    progress.while_running(settings.progress, settings.progress_every, || {
        for _ in 0..passes {
            if stop_on_signal && let Some(signal) = interrupt::interrupted() {
                stopped = Some(Stopped::Signal(signal));
                break;
            }
            mapper.pass(&progress);
        }
    });
    let pixels = mapper.pixels.len() as u64;
    let stats = RenderStats {
        seconds: start.elapsed().as_secs_f64(),
        samples: mapper.passes as u64 * pixels - mapper.dropped,
        dropped: mapper.dropped,
        fireflies: 0,
        stopped,
    };
    Ok((mapper.image(), stats))
}

/// Error against time of photon mapping: passes 1, 2, 4, ... up to
/// `max_passes`, each stage's image compared with `reference` (cut to
/// `region` first when one is given: `[x0, y0, x1, y1)`, rows from the top).
pub fn converge(
    scene: &RenderScene,
    settings: &RenderSettings,
    photon_settings: PhotonSettings,
    reference: &Image,
    max_passes: u32,
    region: Option<[usize; 4]>,
    mut on_point: impl FnMut(&ConvergencePoint),
) -> Result<Vec<ConvergencePoint>, String> {
    if max_passes == 0 {
        return Err("the largest pass count (--max-spp) must be at least 1".to_string());
    }
    let start = Instant::now();
    let mut mapper = PhotonMapper::new(scene, settings, photon_settings)?;
    let progress = Progress::new(max_passes as u64 * mapper.work_per_pass(), None);
    let mut seconds = start.elapsed().as_secs_f64();
    let mut points = Vec::new();
    let mut next = 1;
    while mapper.passes < max_passes {
        let stage = Instant::now();
        while mapper.passes < next.min(max_passes) {
            mapper.pass(&progress);
        }
        seconds += stage.elapsed().as_secs_f64();
        let point =
            ConvergencePoint::measure(&mapper.image(), reference, region, mapper.passes, seconds)?;
        on_point(&point);
        points.push(point);
        next = next.saturating_mul(2);
    }
    Ok(points)
}
