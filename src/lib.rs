//! pathtracer: a physically based renderer for the scene files of the Tsinghua
//! computer-graphics course (the "PA" grammar and its coursework dialects).
//!
//! Data flows one way:
//! scene text -> syntax tree -> built [`scene::model::Scene`] ->
//! [`render_scene::RenderScene`] (built once by `RenderScene::build`: the
//! world, render materials, emitters, camera) -> camera rays ->
//! [`integrator`] samples -> [`film`] -> [`image_io`] file. [`render::render`] is the only parallel code;
//! [`metrics`] compares images (RMSE, relative MSE, PSNR, SSIM, FLIP, the
//! look-alike criterion); [`pairs`] measures our renders of reference pairs.

#![forbid(unsafe_code)]
// A failed `eprintln!` panics: messages go through `stderr_line!` (console.rs).
#![deny(clippy::print_stderr)]
// Library code returns errors for bad input; tests may unwrap.
#![cfg_attr(
    not(test),
    deny(
        clippy::unwrap_used,
        clippy::expect_used,
        clippy::panic,
        clippy::unreachable,
        clippy::todo,
        clippy::unimplemented
    )
)]

pub mod accel;
pub mod adaptive;
pub mod allocation;
pub mod bsdf;
pub mod camera;
pub mod checkpoint;
pub mod color;
pub mod console;
pub mod converge;
pub mod debug_sample;
pub mod emitters;
pub mod film;
pub mod film_file;
pub mod fixed_sum;
pub mod geometry;
pub mod image_io;
pub mod integrator;
pub mod interrupt;
pub mod limits;
pub mod look;
pub mod math;
pub mod medium;
pub mod metrics;
pub mod pairs;
pub mod photon_render;
pub mod plot;
pub mod preview;
pub mod progress;
pub mod render;
pub mod render_job;
pub mod render_scene;
pub mod rng;
pub mod sampler;
pub mod scene;
pub mod shading;
pub mod side_files;
pub mod spectral;
pub mod subpixel;
pub mod texture;
pub mod trig;
pub mod world;

// The few names a program that renders needs (the rest stay in their modules).
pub use color::Color;
pub use debug_sample::{SampleTrace, trace_sample};
pub use film::Film;
pub use image_io::Image;
pub use integrator::Integrator;
pub use look::Look;
pub use render::{RenderSettings, RenderStats, Renderer, render};
pub use render_scene::{RenderScene, SceneSettings};
pub use sampler::SamplerKind;
pub use scene::model::Scene;
pub use scene::{LoadOptions, load_scene};
