//! The rounds of yao-jz's progressive photon mapping (the `yao` look;
//! its sums and branches are `integrator::ppm`): each round's camera pass
//! and photon pass over the pixels and photons in parallel, the radius
//! schedule, progress and the stop on a signal.

use std::time::Instant;

use rayon::prelude::*;

use crate::color::Color;
use crate::image_io::Image;
use crate::integrator::ppm::{
    MIN_ROUNDS, PhotonPass, RADIUS_DECAY, SAMPLES_PER_ROUND, ViewPoint, camera_branch,
    uniform_sphere,
};
use crate::integrator::sppm::PhotonSettings;
use crate::integrator::sppm::grid::{GridPoint, PointGrid};
use crate::integrator::sppm::pixel::Gathered;
use crate::interrupt;
use crate::math::{Point3, Ray};
use crate::progress::Progress;
use crate::render_scene::RenderScene;
use crate::sampler::Sampler;
use crate::scene::model::Light;

use super::photon_tasks::trace_photons;
use super::{RenderSettings, RenderStats, Stopped};

/// Salt of the photons' seeds.
const PHOTON_SALT: u64 = 0x5A0_1A2D_9E37_11C5;

/// Renders `scene` by yao-jz's PPM: `settings.spp` camera rays per pixel
/// in rounds of [`SAMPLES_PER_ROUND`] (at least [`MIN_ROUNDS`]), the
/// photons per round, the first radius and the brightness from the look
/// (`photon_settings` overrides the first two). With `stop_on_signal`,
/// SIGINT or SIGTERM ends it after the round in flight.
pub fn render(
    scene: &RenderScene,
    settings: &RenderSettings,
    photon_settings: PhotonSettings,
    stop_on_signal: bool,
) -> Result<(Image, RenderStats), String> {
    let start = Instant::now();
    let look = scene
        .look()
        .photons
        .ok_or("yao's PPM needs a photon-mapping look")?;
    let photon_settings = photon_settings.with_look(scene.look());
    photon_settings.check()?;
    let (width, height) = (
        settings.width.max(1) as usize,
        settings.height.max(1) as usize,
    );
    let count = width * height;
    let photons = photon_settings.photons(count as u64);
    let mut radius = photon_settings
        .initial_radius
        .unwrap_or(look.initial_radius);
    let rounds = settings.spp.div_ceil(SAMPLES_PER_ROUND).max(MIN_ROUNDS);
    let mut camera_energy = 1.0 / (rounds as f64).ln();
    let photon_energy = look.power / photons as f64;
    let lights: Vec<(Point3, Color)> = scene
        .lights()
        .iter()
        .filter_map(|light| match light {
            Light::Point { position, color } => Some((*position, *color)),
            _ => None,
        })
        .collect();
    let per_light = if lights.is_empty() {
        0
    } else {
        photons / lights.len() as u64
    };
    let traced = per_light * lights.len() as u64;
    let gathered = Gathered::try_new(count)?;
    let mut board = vec![Color::BLACK; count];
    let pool = super::worker_pool(settings.threads)?;
    let camera_rays = count as u64 * SAMPLES_PER_ROUND as u64;
    let progress = Progress::new(rounds as u64 * (camera_rays + traced), None);
    let mut grid = PointGrid::default();
    let mut stopped = None;
    let mut done = 0;
    progress.while_running(
        settings.progress,
        settings.progress_every,
        || -> Result<(), String> {
            for round in 0..rounds {
                if stop_on_signal && let Some(signal) = interrupt::interrupted() {
                    stopped = Some(Stopped::Signal(signal));
                    break;
                }
                // 1. Camera pass, row by row from the top.
                let rows: Vec<(Vec<Color>, Vec<ViewPoint>)> = pool.install(|| {
                    (0..height)
                        .into_par_iter()
                        .map(|row| {
                            let y = height - 1 - row;
                            let mut seen = vec![Color::BLACK; width];
                            let mut points = Vec::new();
                            for (x, seen) in seen.iter_mut().enumerate() {
                                let pixel = (row * width + x) as u32;
                                for s in 0..SAMPLES_PER_ROUND {
                                    let sample = (round * SAMPLES_PER_ROUND + s) as u64;
                                    let mut sampler = Sampler::new(
                                        settings.sampler,
                                        pixel as u64,
                                        sample,
                                        settings.seed,
                                    );
                                    let [u, v] = sampler.next_2d();
                                    let lens = if scene.plan().lens {
                                        sampler.next_2d()
                                    } else {
                                        [0.5, 0.5]
                                    };
                                    let time = if scene.plan().time {
                                        sampler.next_f64()
                                    } else {
                                        0.0
                                    };
                                    let ray = scene.camera().ray(
                                        x as f64 + u - 0.5,
                                        y as f64 + v - 0.5,
                                        lens,
                                        time,
                                    );
                                    camera_branch(
                                        scene,
                                        &ray,
                                        camera_energy,
                                        0,
                                        pixel,
                                        seen,
                                        &mut points,
                                    );
                                }
                            }
                            progress.add(width as u64 * SAMPLES_PER_ROUND as u64);
                            (seen, points)
                        })
                        .collect()
                });
                let mut seen = Vec::with_capacity(count);
                let mut points = Vec::new();
                for (row_seen, row_points) in rows {
                    seen.extend(row_seen);
                    points.extend(row_points);
                }
                if points.len() > u32::MAX as usize {
                    return Err(format!(
                        "{} view points: too many for one round",
                        points.len()
                    ));
                }
                // 2. The grid of view points, all of the round's radius.
                let grid_points: Vec<GridPoint> = points
                    .iter()
                    .enumerate()
                    .map(|(index, view)| GridPoint {
                        index: index as u32,
                        point: view.point,
                        radius,
                    })
                    .collect();
                grid.rebuild(&grid_points);
                // 3. Photon pass.
                let pass = PhotonPass {
                    scene,
                    grid: &grid,
                    points: &points,
                    radius,
                    gathered: &gathered,
                };
                trace_photons(
                    &pool,
                    settings,
                    round as u64,
                    PHOTON_SALT,
                    traced,
                    &progress,
                    |i, sampler| {
                        let (position, color) = lights[(i / per_light) as usize];
                        let direction = uniform_sphere(sampler.next_2d());
                        let ray = Ray::new(position, direction, 0.0);
                        pass.trace(&ray, color, 0, photon_energy, 0, sampler);
                    },
                );
                // 4. Each pixel adds the round over its camera rays so far.
                let rays_so_far = ((round + 1) * SAMPLES_PER_ROUND) as f64;
                for (index, value) in board.iter_mut().enumerate() {
                    let (_, photons) = gathered.take(index);
                    *value += (seen[index] + photons) / rays_so_far;
                }
                radius *= RADIUS_DECAY;
                camera_energy /= RADIUS_DECAY;
                done += 1;
            }
            Ok(())
        },
    )?;
    let stats = RenderStats {
        seconds: start.elapsed().as_secs_f64(),
        samples: done as u64 * camera_rays,
        dropped: 0,
        fireflies: 0,
        stopped,
    };
    Ok((
        Image {
            width,
            height,
            pixels: board,
        },
        stats,
    ))
}
