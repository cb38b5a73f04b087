//! `pathtracer render SCENE --debug-sample x,y,i`: one pixel sample
//! re-traced alone, its path printed (see `pathtracer::render::debug_sample`).

use std::path::Path;

use pathtracer::render::debug_sample::trace_sample;

use super::{SamplingOptions, load_for_render, render_scene};

/// Which sample of which pixel: x, row from the top, sample index.
#[derive(Clone, Copy, Debug)]
pub struct Which {
    pub x: u32,
    pub row: u32,
    pub sample: u32,
}

/// `x,y,i`: three whole numbers.
pub fn parse(text: &str) -> Result<Which, String> {
    let numbers: Vec<u32> = text
        .split(',')
        .map(|part| part.trim().parse::<u32>())
        .collect::<Result<_, _>>()
        .map_err(|_| format!("'{text}': expected x,y,i (three whole numbers)"))?;
    match numbers[..] {
        [x, row, sample] => Ok(Which { x, row, sample }),
        _ => Err(format!("'{text}': expected x,y,i (three whole numbers)")),
    }
}

pub fn run(scene: &Path, which: Which, spp: u32, sampling: &SamplingOptions) -> Result<(), String> {
    let scene = load_for_render(scene, &sampling.scene)?;
    let settings = sampling.settings(&scene, spp, false);
    let scene = render_scene(scene, &settings);
    let trace = trace_sample(
        &scene,
        &settings,
        which.x as usize,
        which.row as usize,
        which.sample,
    )?;
    say!("{trace}");
    Ok(())
}
