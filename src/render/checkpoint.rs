//! Checkpoints: a render's film written now and then while it runs, and
//! when SIGINT or SIGTERM stops it, so that `render --resume` continues it.
//!
//! A checkpoint is a film file (`film_file`) beside the output,
//! `<output>.checkpoint.exr`, whose header says `checkpoint`: each pixel
//! holds its first samples, as many as it got. Resuming renders each pixel
//! from its next sample index ([`Samples::Continue`]); since sample `i` of
//! a pixel is the same whichever call renders it and the film's sums do not
//! depend on the order of the additions, an interrupted and resumed render
//! gives the bytes of an uninterrupted one. The file is replaced atomically
//! at every write, so a render killed at any moment (even by SIGKILL) loses
//! at most the samples since the last write.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use crate::film::Film;
use crate::image_io::write_atomically;
use crate::limits::MemoryBudget;
use crate::render::film_file::{encode_film, read_film_within};
use crate::render::job::{JobHeader, first_difference};
use crate::render::{RenderStats, Renderer, Samples, Stop, Stopped};
use crate::side_files::side_file_path;

/// Seconds between checkpoints by default. Writing the film of a 1024x768
/// render takes a fraction of a second (the render summary prints it), a small part of
/// this interval; a render killed loses at most this much work.
pub const CHECKPOINT_SECONDS: f64 = 60.0;

/// `<output>.checkpoint.exr`, cut to a name that fits (see
/// [`side_file_path`]).
pub fn checkpoint_path(output: &Path) -> PathBuf {
    side_file_path(output, ".checkpoint.exr")
}

/// Where and how often one render writes its checkpoints.
pub struct Checkpoints {
    pub path: PathBuf,
    /// Time between writes while rendering (`None`: only when stopped by a
    /// signal).
    pub every: Option<Duration>,
    /// The render's header (samples `0..spp`), written with `checkpoint` set.
    pub header: JobHeader,
}

/// What checkpoints cost a render.
#[derive(Clone, Copy, Debug, Default)]
pub struct CheckpointStats {
    pub written: u32,
    /// Seconds spent encoding and writing them.
    pub seconds: f64,
}

impl Checkpoints {
    /// What the render still takes: every pixel from its next sample up to
    /// the header's sample count.
    pub fn samples(&self) -> Samples {
        Samples::Continue {
            first: 0,
            end: self.header.samples.end,
        }
    }

    /// Writes `film` as the checkpoint (replacing the previous one at once).
    pub fn write(&self, film: &Film, stats: &mut CheckpointStats) -> Result<(), String> {
        let start = Instant::now();
        let header = JobHeader {
            checkpoint: true,
            ..self.header.clone()
        };
        write_atomically(&self.path, &encode_film(&self.path, film, &header)?)?;
        stats.written += 1;
        stats.seconds += start.elapsed().as_secs_f64();
        Ok(())
    }

    /// The film of the checkpoint, if the file exists: refused unless it is
    /// a checkpoint of this very render (same scene bytes and settings) and
    /// no pixel has more samples than this render asks for. A pipe or a
    /// device in its place is refused, and so is a film beyond `budget`.
    pub fn read(&self, budget: MemoryBudget) -> Result<Option<Film>, String> {
        if std::fs::symlink_metadata(&self.path).is_err() {
            return Ok(None);
        }
        let shown = self.path.display();
        let (film, header) = read_film_within(&self.path, budget)?;
        if !header.checkpoint {
            return Err(format!("{shown}: a film of a render job, not a checkpoint"));
        }
        if let Some((name, found, wanted)) = first_difference(&header, &self.header) {
            return Err(format!(
                "{shown}: a checkpoint of another render ({name} is {found}, this render's is {wanted})"
            ));
        }
        let end = self.header.samples.end;
        if let Some(pixel) = film
            .pixels
            .iter()
            .find(|p| p.samples.saturating_add(p.dropped) > end)
        {
            return Err(format!(
                "{shown}: a pixel already has {} samples, more than --spp {end}",
                pixel.samples.saturating_add(pixel.dropped)
            ));
        }
        Ok(Some(film))
    }

    /// Removes the checkpoint of a render that finished (its image is
    /// written); a failure is only worth a warning.
    pub fn remove(&self) {
        match std::fs::remove_file(&self.path) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {}
            Err(e) => crate::stderr_line!(
                "warning: {}: cannot remove the checkpoint of the finished render: {e}",
                self.path.display()
            ),
        }
    }
}

/// Renders every pixel of `film` up to the header's sample count, from
/// where each pixel is, writing a checkpoint at every interval and when a
/// signal stops the render (then `stopped` says so).
pub fn render_resumable(
    renderer: &Renderer,
    film: &mut Film,
    checkpoints: &Checkpoints,
) -> Result<(RenderStats, CheckpointStats), String> {
    let samples = checkpoints.samples();
    let mut total = RenderStats::default();
    let mut written = CheckpointStats::default();
    loop {
        let deadline = checkpoints.every.map(|every| Instant::now() + every);
        let stats = renderer.render(film, &samples, Stop::Interrupted { deadline })?;
        total.add(&stats);
        match stats.stopped {
            None => return Ok((total, written)),
            Some(Stopped::Deadline) => checkpoints.write(film, &mut written)?,
            Some(Stopped::Signal(_)) => {
                checkpoints.write(film, &mut written)?;
                return Ok((total, written));
            }
        }
    }
}
