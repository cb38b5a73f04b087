//! Adaptive sampling: render in passes until each pixel's relative error or
//! the whole render's time budget is reached.
//!
//! Every pass continues the sample sequence of the pixels that are still
//! active, so an adaptive image is the fixed-spp image of each pixel's own
//! sample count: deterministic for a seed, whatever the thread count.

use std::time::Instant;

use crate::film::Film;
use crate::render::{Progress, RenderStats, Renderer, Samples, Stop};

/// When to stop sampling. `RenderSettings::spp` is the most any pixel gets.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct StoppingRule {
    /// Stop a pixel once the standard error of its mean luminance (the largest
    /// in its 3x3 neighbourhood) is at most `target * mean + ABSOLUTE_FLOOR`:
    /// a relative error, with a floor so that black pixels stop too.
    pub target_error: Option<f64>,
    /// Stop the render before this many seconds of rendering are exceeded.
    pub time_budget: Option<f64>,
}

/// The absolute part of the per-pixel error target (in luminance).
pub const ABSOLUTE_FLOOR: f64 = 1e-3;

/// Stops the pixels whose error is within target. A pixel's error is the
/// largest standard error in its 3x3 neighbourhood: a rare light path that a
/// pixel has not met yet has usually shown up in a neighbour, so that pixel
/// does not stop on a falsely zero variance.
fn mark_converged(film: &mut Film, target: f64) {
    let (width, height) = (film.width, film.height);
    let errors: Vec<f64> = film.pixels.iter().map(|p| p.standard_error()).collect();
    for y in 0..height {
        for x in 0..width {
            let pixel = &mut film.pixels[y * width + x];
            if pixel.converged || pixel.samples < MIN_SAMPLES {
                continue;
            }
            let mut error: f64 = 0.0;
            for ny in y.saturating_sub(1)..(y + 2).min(height) {
                for nx in x.saturating_sub(1)..(x + 2).min(width) {
                    error = error.max(errors[ny * width + nx]);
                }
            }
            let mean = pixel.mean().luminance().max(0.0);
            pixel.converged = error <= target * mean + ABSOLUTE_FLOOR;
        }
    }
}

/// Samples every pixel takes before its error is trusted.
pub const MIN_SAMPLES: u32 = 16;

/// The progress of an adaptive render of `film` at most `max_spp` per
/// pixel, for its [`Renderer`]: the most it can take, within the budget.
pub fn progress_for(film: &Film, max_spp: u32, rule: StoppingRule) -> Progress {
    let pixels = film.pixels.iter().filter(|p| !p.converged).count() as u64;
    Progress::new(pixels * max_spp as u64, rule.time_budget)
}

/// Renders into `film` following `rule`, up to the renderer's spp per
/// pixel; returns the totals of all passes. SIGINT or SIGTERM stops it
/// between two samples (then `stopped` says so).
pub fn render_adaptive(
    renderer: &Renderer,
    rule: StoppingRule,
    film: &mut Film,
) -> Result<RenderStats, String> {
    let started = Instant::now();
    let max_spp = renderer.settings().spp.max(1);
    let mut total = RenderStats::default();
    let mut done = 0u32;
    let mut pass = MIN_SAMPLES.min(max_spp);
    let mut seconds_per_pixel_sample: Option<f64> = None;
    while done < max_spp {
        let active = film.pixels.iter().filter(|p| !p.converged).count();
        // One overall estimate: what the pixels still active can take.
        renderer
            .progress()
            .plan_remaining(active as u64 * (max_spp - done) as u64);
        if active == 0 {
            break;
        }
        pass = pass.min(max_spp - done);
        if let (Some(budget), Some(cost)) = (rule.time_budget, seconds_per_pixel_sample) {
            let left = budget - started.elapsed().as_secs_f64();
            let affordable = (left / (cost * active as f64)).floor();
            if affordable < 1.0 {
                break;
            }
            pass = pass.min(affordable as u32);
        }
        let samples = Samples::Range(done..done + pass);
        let stats = renderer.render(film, &samples, Stop::Interrupted { deadline: None })?;
        seconds_per_pixel_sample = Some(stats.seconds / (active as f64 * pass as f64));
        total.add(&stats);
        if stats.stopped.is_some() {
            break;
        }
        done += pass;
        if let Some(target) = rule.target_error {
            mark_converged(film, target);
        }
        // Doubling passes: the total grows geometrically, so the checks cost
        // a logarithmic number of passes.
        pass = done;
    }
    total.seconds = started.elapsed().as_secs_f64();
    Ok(total)
}
