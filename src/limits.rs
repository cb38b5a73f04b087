//! The renderer's limits on input size and work, in one place (README, "Limits").
//!
//! Each limit keeps a hostile or careless input from exhausting memory or time:
//! beyond it the input is refused with a located error before any large
//! allocation or long computation starts. Film memory has a budget the user can
//! raise with `--max-memory`; the others are fixed.

/// Default budget for the memory an image's film and output buffers may take,
/// in bytes (4 GiB); `--max-memory` raises or lowers it.
pub const DEFAULT_MEMORY_BUDGET: u64 = 4 << 30;

/// Largest image width or height, in pixels.
pub const MAX_IMAGE_SIDE: u32 = 65_536;

/// Largest mesh (OBJ) file, in bytes.
pub const MAX_MESH_BYTES: u64 = 1 << 30;

/// Largest texture image file, in bytes.
pub const MAX_TEXTURE_BYTES: u64 = 512 << 20;

/// Most control points of one Bezier or B-spline curve.
pub const MAX_CONTROL_POINTS: usize = 4_096;

/// Deepest nesting of groups and transforms in a scene file.
pub const MAX_NESTING: usize = 256;

/// Largest `--max-depth` (path vertices): far beyond any useful image.
pub const MAX_PATH_DEPTH: u32 = 10_000;

/// Longest token shown whole in a message; longer ones are cut with an ellipsis.
pub const MAX_SHOWN_TOKEN: usize = 40;

/// Longest file name (one path component) in bytes: NAME_MAX of Linux file
/// systems. Temporary names are cut to fit it; longer output names are refused.
pub const MAX_FILE_NAME_BYTES: usize = 255;

/// Most symlinks followed from an output path to the file it names.
pub const MAX_SYMLINK_HOPS: usize = 40;
