//! The renderer's limits on input size and work, in one place (docs/guide/limits.md).
//!
//! Each limit keeps a hostile or careless input from exhausting memory or time:
//! beyond it the input is refused with a located error before any large
//! allocation or long computation starts. Film memory has a budget the user can
//! raise with `--max-memory`; the others are fixed.

use std::io::Read;
use std::path::Path;

mod shown;
pub use shown::{printable, shown, shown_path};

/// Default budget for the memory an image's film and output buffers may take,
/// in bytes (4 GiB); `--max-memory` raises or lowers it.
pub const DEFAULT_MEMORY_BUDGET: u64 = 4 << 30;

/// Largest image width or height, in pixels.
pub const MAX_IMAGE_SIDE: u32 = 65_536;

/// Largest scene file (and texture descriptor `.txt`, which is parsed like
/// one), in bytes (64 MiB). The largest scene of the course is a few
/// kilobytes and a hand-written or generated scene of a million objects
/// stays well under it (meshes go in OBJ files), while it keeps
/// `check /dev/zero` or a huge file from being read into memory whole.
pub const MAX_SCENE_BYTES: u64 = 64 << 20;

/// Largest table a command reads: a `plot` curve (CSV) or a `lookalike`
/// pairs file (TSV), in bytes (16 MiB). A curve of `converge` is a few
/// hundred bytes and the pairs file of the whole corpus a few kilobytes.
pub const MAX_TABLE_BYTES: u64 = 16 << 20;

/// Reads a text file through [`read_within`]: a regular file of at most
/// `max_bytes`, in UTF-8.
pub fn read_text_within(path: &Path, max_bytes: u64, limit_name: &str) -> Result<String, String> {
    let bytes = read_within(path, max_bytes, limit_name)?;
    String::from_utf8(bytes).map_err(|e| {
        format!(
            "'{}': not UTF-8 text (byte {})",
            shown_path(path),
            e.utf8_error().valid_up_to()
        )
    })
}

/// Largest mesh (OBJ) file, in bytes.
pub const MAX_MESH_BYTES: u64 = 1 << 30;

/// Largest texture image file, in bytes.
pub const MAX_TEXTURE_BYTES: u64 = 512 << 20;

/// Most a compared image's long side may exceed its short side, as a
/// factor: the look-alike criterion resamples both images to 32 columns and
/// the reference's aspect ratio, so a 1x65535 reference would take a grid
/// of 32x2,097,120. Panoramas stay far below it.
pub const MAX_ASPECT_RATIO: usize = 64;

/// Warnings of one kind kept (and printed) for one scene file; the others
/// are counted in one more warning (`scene::build::warning_tally`).
pub const MAX_WARNINGS_PER_KIND: usize = 5;

/// Most control points of one Bezier or B-spline curve.
pub const MAX_CONTROL_POINTS: usize = 4_096;

/// Most triangles of the `cav` look's tessellations of surfaces of
/// revolution in one scene (its rule: 1,600 a control point, about 190
/// bytes each with their BVH, so 8 million take 1.5 GB; one curve of
/// [`MAX_CONTROL_POINTS`] fits). Surfaces beyond it are built exact, with a
/// warning.
pub const MAX_CAV_TESSELLATION_TRIANGLES: usize = 8_000_000;

/// Distinct field and block names of a scene file kept for look detection
/// (`scene::build::distinct_words`); real files use fewer than 100.
pub const MAX_KEPT_WORDS: usize = 1_024;

/// Deepest nesting of groups and transforms in a scene file.
pub const MAX_NESTING: usize = 256;

/// Largest `--max-depth` (scattering vertices of a path): far beyond any
/// useful image, and short enough that a path always ends.
pub const MAX_PATH_DEPTH: u32 = 10_000;

/// Longest token shown whole in a message; longer ones are cut with an ellipsis.
pub const MAX_SHOWN_TOKEN: usize = 40;

/// Longest path shown whole in a message, in characters; longer ones keep
/// their start and end (where the folder and the file's name are) with an
/// ellipsis between, so a path of thousands of bytes does not bury the
/// reason. Far above the length of any real project's paths.
pub const MAX_SHOWN_PATH: usize = 200;

/// Largest radiance a sample or a pixel may carry, per channel: half of
/// `f32::MAX`, so that a pixel's mean (at most this) plus light tracing's
/// saturated fixed-point sums still fits the f32 of a PFM or EXR file.
/// Larger (and non-finite) values are dropped and counted.
pub const MAX_RADIANCE: f64 = f32::MAX as f64 / 2.0;

/// Whether every channel of a radiance value is finite and within
/// [`MAX_RADIANCE`].
pub fn is_usable_radiance(channels: [f64; 3]) -> bool {
    channels
        .iter()
        .all(|c| c.is_finite() && c.abs() <= MAX_RADIANCE)
}

/// Bytes per pixel of an image's render at its peak, which is when a film
/// file is written (a checkpoint or a render job's part): the film's sums,
/// squares and counts ([`PIXEL_SUM_BYTES`]) and light
/// tracing's sums (3 x 8 bytes), plus [`FILM_FILE_BYTES_PER_PIXEL`]. The
/// other phases take less: a pass adds an atomic copy of the light sums
/// (24 bytes), writing an image the linear image and its largest encoding
/// (24 + 36 bytes). Measured: a film job of 2048x1536 peaks at 290 bytes
/// per pixel above the process's own 8 MB.
pub const BYTES_PER_PIXEL: u64 = PIXEL_SUM_BYTES + 24 + FILM_FILE_BYTES_PER_PIXEL;

/// Size of one pixel's [`PixelSum`](crate::film::PixelSum), in bytes; the
/// film checks it at compile time, so the figure cannot drift from the type.
pub const PIXEL_SUM_BYTES: u64 = 96;

/// Bytes per pixel of encoding a film file (`film_file`): 26 channels of
/// 32-bit words (sums, squares, counts, splats), the preview image and its
/// three f32 channels, and about a quarter more that the `exr` crate holds
/// while it compresses.
pub const FILM_FILE_BYTES_PER_PIXEL: u64 =
    26 * 4 + std::mem::size_of::<crate::color::Color>() as u64 + 3 * 4 + 32;

/// What an image may take in memory (`--max-memory`; default
/// [`DEFAULT_MEMORY_BUDGET`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct MemoryBudget {
    pub bytes: u64,
}

impl Default for MemoryBudget {
    fn default() -> MemoryBudget {
        MemoryBudget {
            bytes: DEFAULT_MEMORY_BUDGET,
        }
    }
}

impl MemoryBudget {
    /// Memory a `width` x `height` render needs (see [`BYTES_PER_PIXEL`]).
    pub fn image_bytes(width: u64, height: u64) -> u64 {
        width.saturating_mul(height).saturating_mul(BYTES_PER_PIXEL)
    }

    /// Checks, before anything is allocated, that a `width` x `height`
    /// image is within [`MAX_IMAGE_SIDE`] and the budget; the message says
    /// what is needed, the budget, and how to raise it.
    pub fn check_image(&self, width: u64, height: u64) -> Result<(), String> {
        for (side, value) in [("width", width), ("height", height)] {
            if value == 0 || value > MAX_IMAGE_SIDE as u64 {
                return Err(format!(
                    "image {side} {value} is outside 1 to {MAX_IMAGE_SIDE} pixels"
                ));
            }
        }
        let needed = MemoryBudget::image_bytes(width, height);
        if needed > self.bytes {
            let gibibytes = needed.div_ceil(1 << 30);
            return Err(format!(
                "a {width}x{height} image needs {} of memory ({BYTES_PER_PIXEL} bytes per pixel), \
                 more than the budget of {}; raise it with --max-memory {gibibytes}G",
                show_bytes(needed),
                show_bytes(self.bytes)
            ));
        }
        Ok(())
    }

    /// Checks that decoding a `width` x `height` image of `bytes_per_texel`
    /// bytes per texel stays within the budget (decompression bombs: a small
    /// file that claims a huge image).
    pub fn check_texture(
        &self,
        width: u64,
        height: u64,
        bytes_per_texel: u64,
    ) -> Result<(), String> {
        let needed = width.saturating_mul(height).saturating_mul(bytes_per_texel);
        if needed > self.bytes {
            return Err(format!(
                "its header claims {width}x{height} texels, which need {} to decode, more than \
                 the memory budget of {}; raise it with --max-memory {}G",
                show_bytes(needed),
                show_bytes(self.bytes),
                needed.div_ceil(1 << 30)
            ));
        }
        Ok(())
    }

    /// Reads a size: bytes, or a number with a binary unit `K`, `M`, `G`,
    /// `T` (optionally followed by `B` or `iB`): `8G`, `512M`, `1.5G`.
    pub fn parse(text: &str) -> Result<MemoryBudget, String> {
        let trimmed = text.trim();
        let split = trimmed
            .find(|c: char| !(c.is_ascii_digit() || c == '.'))
            .unwrap_or(trimmed.len());
        let (number, unit) = trimmed.split_at(split);
        let unit = unit.trim().to_ascii_uppercase();
        let unit = unit
            .strip_suffix("IB")
            .or_else(|| unit.strip_suffix('B'))
            .unwrap_or(&unit);
        let scale: u64 = match unit {
            "" => 1,
            "K" => 1 << 10,
            "M" => 1 << 20,
            "G" => 1 << 30,
            "T" => 1 << 40,
            _ => {
                return Err(format!(
                    "memory size '{text}' has an unknown unit (bytes, or K, M, G, T: 8G, 512M)"
                ));
            }
        };
        let value: f64 = number
            .parse()
            .map_err(|_| format!("memory size '{text}' is not a number of bytes (8G, 512M)"))?;
        let bytes = value * scale as f64;
        if !(bytes >= 1.0 && bytes < u64::MAX as f64) {
            return Err(format!(
                "memory size '{text}' is out of range (1 byte to 16 EiB)"
            ));
        }
        Ok(MemoryBudget {
            bytes: bytes as u64,
        })
    }
}

/// Reads a whole file that must be a regular file of at most `max_bytes`
/// (`limit_name` names the limit in messages), checked by its metadata
/// before anything is read: a directory, a device such as `/dev/zero`, a
/// pipe or an oversized file is refused at once, never read forever.
pub fn read_within(path: &Path, max_bytes: u64, limit_name: &str) -> Result<Vec<u8>, String> {
    let shown = shown_path(path);
    let metadata = std::fs::metadata(path).map_err(|e| format!("'{shown}': {e}"))?;
    if metadata.is_dir() {
        return Err(format!("'{shown}' is a directory, not a file"));
    }
    if !metadata.is_file() {
        return Err(format!(
            "'{shown}' is not a regular file (a device, pipe or socket)"
        ));
    }
    let too_large = |size: u64| {
        format!(
            "'{shown}' is {} ({size} bytes), more than the limit of {} ({limit_name})",
            show_bytes(size),
            show_bytes(max_bytes)
        )
    };
    if metadata.len() > max_bytes {
        return Err(too_large(metadata.len()));
    }
    let file = std::fs::File::open(path).map_err(|e| format!("cannot open '{shown}': {e}"))?;
    let mut bytes = Vec::with_capacity(metadata.len() as usize);
    // `take` also bounds a file that grows while it is read.
    file.take(max_bytes + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read '{shown}': {e}"))?;
    if bytes.len() as u64 > max_bytes {
        return Err(too_large(bytes.len() as u64));
    }
    Ok(bytes)
}

/// A byte count for messages: `41.9 GiB`, `512.0 MiB`, `300 bytes`.
pub fn show_bytes(bytes: u64) -> String {
    const UNITS: [(&str, u64); 4] = [
        ("TiB", 1 << 40),
        ("GiB", 1 << 30),
        ("MiB", 1 << 20),
        ("KiB", 1 << 10),
    ];
    for (name, size) in UNITS {
        if bytes >= size {
            return format!("{:.1} {name}", bytes as f64 / size as f64);
        }
    }
    format!("{bytes} bytes")
}

/// Longest name of one file or folder, in bytes (Linux's NAME_MAX): a
/// temporary's name is cut to fit it.
pub const MAX_FILE_NAME_BYTES: usize = 255;

/// Most symlinks followed from an output path to the file it names.
pub const MAX_SYMLINK_HOPS: usize = 40;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_with_binary_units() {
        let bytes = |text| MemoryBudget::parse(text).map(|b| b.bytes);
        assert_eq!(bytes("8G"), Ok(8 << 30));
        assert_eq!(bytes("512M"), Ok(512 << 20));
        assert_eq!(bytes("512MiB"), Ok(512 << 20));
        assert_eq!(bytes("1.5g"), Ok(3 << 29));
        assert_eq!(bytes("1000"), Ok(1000));
        for bad in ["", "0", "-1G", "8X", "G", "1e30T"] {
            assert!(bytes(bad).is_err(), "accepted {bad:?}");
        }
    }

    #[test]
    fn the_budget_refuses_big_images_and_says_how_to_raise_it() {
        let budget = MemoryBudget::default();
        assert!(budget.check_image(1920, 1080).is_ok());
        let error = budget.check_image(16384, 16384).unwrap_err();
        assert!(
            error.contains("--max-memory") && error.contains("4.0 GiB"),
            "{error}"
        );
        let raised = MemoryBudget { bytes: 96 << 30 };
        assert!(raised.check_image(16384, 16384).is_ok());
        assert!(raised.check_image(MAX_IMAGE_SIDE as u64 + 1, 1).is_err());
    }
}
