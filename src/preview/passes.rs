//! Progressive rendering: the film accumulates pass after pass, each pass
//! the next sample indices of every pixel, so that the image at N samples
//! per pixel is the image `render --spp N` makes. Passes grow to about
//! [`PASS_SECONDS`] so that the page sees a new picture a few times a
//! second whatever the scene costs.

use std::time::Instant;

use crate::film::Film;
use crate::render::{Renderer, Samples, Stop};

use super::board::Board;
use super::status::Status;

/// The time one pass aims for.
pub const PASS_SECONDS: f64 = 0.25;

/// The least time between two frames posted (the last one is always posted).
pub const POST_SECONDS: f64 = 0.1;

/// How a run of passes ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Ended {
    /// Every pixel has the samples asked for.
    Done,
    /// `stop` asked for it between two passes.
    Stopped,
}

/// Renders passes into `film` until it has `spp` samples per pixel (the
/// renderer's own sample count is not used) or `stop` returns true,
/// posting the film and `status` (with the progress filled in, and the
/// frame number one more each time) on `board`.
pub fn render_passes(
    renderer: &Renderer,
    film: &mut Film,
    spp: u32,
    board: &Board,
    status: &mut Status,
    stop: &dyn Fn() -> bool,
) -> Result<Ended, String> {
    let started = Instant::now();
    let pixels = (film.width * film.height).max(1) as f64;
    let (mut next, mut per_pass, mut samples, mut seconds) = (0u32, 1u32, 0u64, 0.0f64);
    let mut last_post: Option<Instant> = None;
    status.spp_target = spp;
    while next < spp {
        if stop() {
            return Ok(Ended::Stopped);
        }
        let end = next.saturating_add(per_pass).min(spp);
        let stats = renderer.render(film, &Samples::Range(next..end), Stop::Never)?;
        let taken = (end - next) as f64;
        next = end;
        samples += stats.samples;
        seconds += stats.seconds;
        // The next pass: about PASS_SECONDS at this pass's speed, at most
        // twice as many samples (a first pass can be slow to start).
        let per_sample = (stats.seconds / taken).max(1e-6);
        per_pass = ((PASS_SECONDS / per_sample) as u32).clamp(1, per_pass.saturating_mul(2));
        let due = last_post.is_none_or(|at| at.elapsed().as_secs_f64() >= POST_SECONDS);
        if due || next == spp {
            status.spp = film.samples() as f64 / pixels;
            status.seconds = started.elapsed().as_secs_f64();
            status.samples_per_second = samples as f64 / seconds.max(1e-9);
            status.frame += 1;
            status.done = next == spp;
            board.post(status.clone(), Some(film.to_image()));
            last_post = Some(Instant::now());
        }
    }
    Ok(Ended::Done)
}
