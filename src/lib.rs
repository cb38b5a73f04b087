//! pathtracer: a physically based renderer for the scene files of the Tsinghua
//! computer-graphics course (the "PA" grammar and its coursework dialects).
//!
//! Data flows one way:
//! scene text -> syntax tree -> built [`scene::model::Scene`] -> [`world::World`]
//! -> camera rays -> integrator samples -> film -> image file.

pub mod accel;
pub mod color;
pub mod geometry;
pub mod image_io;
pub mod math;
pub mod rng;
pub mod scene;
pub mod texture;
pub mod world;
