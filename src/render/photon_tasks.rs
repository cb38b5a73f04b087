//! The photon pass's parallel loop, shared by SPPM's passes and yao-jz's
//! PPM rounds: photons in tasks of [`PHOTONS_PER_TASK`], each photon with a
//! sampler of its own (deterministic for any thread count), progress after
//! each task.

use rayon::prelude::*;

use crate::progress::Progress;
use crate::sampler::Sampler;

use super::RenderSettings;

/// Photons one task traces (the unit of a photon pass's parallel work).
const PHOTONS_PER_TASK: u64 = 1024;

/// Traces photons `0..count` of pass `pass` on `pool`: `trace(i, sampler)`
/// for photon `i`, whose sampler draws from (`pass`, `i`, the seed ^
/// `salt`).
pub fn trace_photons(
    pool: &rayon::ThreadPool,
    settings: &RenderSettings,
    pass: u64,
    salt: u64,
    count: u64,
    progress: &Progress,
    trace: impl Fn(u64, &mut Sampler) + Sync,
) {
    let tasks = count.div_ceil(PHOTONS_PER_TASK);
    pool.install(|| {
        (0..tasks).into_par_iter().for_each(|task| {
            let first = task * PHOTONS_PER_TASK;
            let end = (first + PHOTONS_PER_TASK).min(count);
            for i in first..end {
                let mut sampler = Sampler::new(settings.sampler, pass, i, settings.seed ^ salt);
                trace(i, &mut sampler);
            }
            progress.add(end - first);
        });
    });
}
