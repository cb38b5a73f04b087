//! One pixel sample re-traced alone (`render --debug-sample x,y,i`, the
//! idea of pbrt-v4's `--debugstart`): the same sampler seed, camera ray and
//! integrator as in a render, with a [`PathRecord`] that keeps the path's
//! vertices, lobes and terms. Its value is what that sample adds to the
//! pixel of a render with the same settings.

use std::fmt;

use crate::color::Color;
use crate::integrator::Splats;
use crate::integrator::path_log::{PathRecord, color};
use crate::render::{PixelSample, Progress, RenderSettings, Renderer};
use crate::render_scene::RenderScene;

/// What one pixel sample did.
#[derive(Clone, Debug)]
pub struct SampleTrace {
    pub x: usize,
    /// Row from the top of the image.
    pub row: usize,
    pub sample: u32,
    /// The radiance the sample adds to its pixel (before the film's clamp).
    pub value: Color,
    /// What its light subpath adds to other pixels: (x, row from the top, value).
    pub splats: Vec<(usize, usize, Color)>,
    pub record: PathRecord,
}

/// Re-traces sample `sample` of pixel (`x`, `row`) (row from the top) of a
/// render of `scene` with `settings`.
pub fn trace_sample(
    scene: &RenderScene,
    settings: &RenderSettings,
    x: usize,
    row: usize,
    sample: u32,
) -> Result<SampleTrace, String> {
    let (width, height) = (
        settings.width.max(1) as usize,
        settings.height.max(1) as usize,
    );
    if x >= width || row >= height {
        return Err(format!(
            "--debug-sample: pixel ({x}, {row}) is outside the {width}x{height} image"
        ));
    }
    let mut one_thread = settings.clone();
    one_thread.threads = Some(1);
    one_thread.progress = false;
    let renderer = Renderer::new(scene, &one_thread, Progress::new(1, None))?;
    let at = PixelSample {
        x,
        y: height - 1 - row,
        pixel_index: (row * width + x) as u64,
        sample,
    };
    let mut splats = Splats::default();
    let mut record = PathRecord::default();
    let value = renderer.trace_sample(at, &mut splats, &mut record);
    Ok(SampleTrace {
        x,
        row,
        sample,
        value,
        splats: splats
            .iter()
            .map(|&(sx, sy, v)| (sx, height - 1 - sy, v))
            .collect(),
        record,
    })
}

impl fmt::Display for SampleTrace {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        writeln!(
            f,
            "pixel ({}, {}) sample {} (row from the top)",
            self.x, self.row, self.sample
        )?;
        for event in &self.record.events {
            writeln!(f, "{event}")?;
        }
        for (x, row, value) in &self.splats {
            writeln!(
                f,
                "light subpath adds to pixel ({x}, {row}): {}",
                color(value)
            )?;
        }
        write!(f, "sample value: {}", color(&self.value))
    }
}
