//! Shared pieces of the cargo-fuzz targets: the sandbox folder that is the
//! only place a fuzzed input may name files in, panics reported as crashes
//! (and only the ones the library does not catch itself), and the tiny render
//! every surviving scene gets.

pub mod panics;
pub mod sandbox;
pub mod tiny_render;
