//! `view --against IMAGE`: the user's image measured against ours as the
//! render converges: the look-alike criterion and FLIP of
//! [`crate::pairs::measure`] (ours as the PNG writer stores it, theirs
//! box-resampled to our size), the FLIP heat map, and theirs at our size
//! for the page to show beside ours.
//!
//! One thread measures the latest image on the board, at most every
//! [`MIN_INTERVAL`] and never more than a third of the time (a measure of a
//! large image takes a while), so the render keeps the cores.

use std::sync::Arc;
use std::time::{Duration, Instant};

use crate::image_io::DisplayImage;
use crate::pairs::measure::{Measurement, measure};

use super::board::Board;
use super::status::string;

/// The least time between two measures.
pub const MIN_INTERVAL: Duration = Duration::from_millis(500);

/// What the page shows of a comparison.
#[derive(Clone, Debug)]
pub struct Compared {
    /// The figures as JSON (see [`figures_json`]).
    pub json: String,
    /// Theirs at our size, and the FLIP map in magma, as display frames.
    pub theirs: Arc<Vec<u8>>,
    pub heat: Arc<Vec<u8>>,
}

/// A display frame: `PTVD`, width, height and frame number as u32
/// (little-endian), then the bytes of each pixel (red, green, blue), row 0
/// at the top.
pub fn display_frame(image: &DisplayImage, number: u64) -> Vec<u8> {
    let mut bytes = Vec::with_capacity(16 + image.pixels.len() * 3);
    bytes.extend_from_slice(b"PTVD");
    bytes.extend_from_slice(&(image.width as u32).to_le_bytes());
    bytes.extend_from_slice(&(image.height as u32).to_le_bytes());
    bytes.extend_from_slice(&(number as u32).to_le_bytes());
    for pixel in &image.pixels {
        bytes.extend_from_slice(pixel);
    }
    bytes
}

/// The figures of a measure of frame `frame` at `spp` samples per pixel.
pub fn figures_json(
    name: &str,
    measured: &Measurement,
    frame: u64,
    spp: f64,
    seconds: f64,
) -> String {
    let l = &measured.lookalike;
    format!(
        "{{\"image\": {}, \"frame\": {frame}, \"spp\": {}, \"same\": {}, \"mean\": {:.3}, \"p95\": {:.3}, \
         \"flip\": {:.5}, \"aspect_differs\": {}, \"width\": {}, \"height\": {}, \"seconds\": {:.3}}}",
        string(name),
        if spp.is_finite() { spp } else { 0.0 },
        l.same,
        l.mean,
        l.p95,
        measured.flip,
        l.aspect_differs,
        measured.ours.width,
        measured.ours.height,
        seconds
    )
}

/// Starts the thread that measures each new image on `board` against
/// `theirs` (named `name` on the page).
pub fn start(board: Arc<Board>, theirs: DisplayImage, name: String) -> Result<(), String> {
    std::thread::Builder::new()
        .name("preview-compare".to_string())
        .spawn(move || {
            let mut seen = 0;
            let mut measured_frame = 0;
            loop {
                let Some(posted) = board.after(seen, Duration::from_secs(3600)) else {
                    continue;
                };
                seen = posted.generation;
                let (Some(image), frame) = (posted.image, posted.status.frame) else {
                    continue;
                };
                if frame == measured_frame {
                    continue;
                }
                measured_frame = frame;
                let started = Instant::now();
                let compared = measure(&image, &theirs).map(|measured| {
                    let seconds = started.elapsed().as_secs_f64();
                    Compared {
                        json: figures_json(&name, &measured, frame, posted.status.spp, seconds),
                        theirs: Arc::new(display_frame(&measured.theirs, frame)),
                        heat: Arc::new(display_frame(&measured.error_map, frame)),
                    }
                });
                let took = started.elapsed();
                match compared {
                    Ok(compared) => board.set_compared(compared),
                    Err(why) => board.set_compared(Compared {
                        json: format!(
                            "{{\"image\": {}, \"error\": {}}}",
                            string(&name),
                            string(&why)
                        ),
                        theirs: Arc::new(Vec::new()),
                        heat: Arc::new(Vec::new()),
                    }),
                }
                std::thread::sleep(MIN_INTERVAL.max(took * 2));
            }
        })
        .map(|_| ())
        .map_err(|e| format!("cannot start the comparing thread: {e}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_display_frame_holds_its_size_number_and_bytes() {
        let image = DisplayImage {
            width: 2,
            height: 1,
            pixels: vec![[1, 2, 3], [250, 251, 252]],
        };
        let frame = display_frame(&image, 9);
        assert_eq!(&frame[..4], b"PTVD");
        assert_eq!(frame[4..16], [2, 0, 0, 0, 1, 0, 0, 0, 9, 0, 0, 0]);
        assert_eq!(frame[16..], [1, 2, 3, 250, 251, 252]);
    }
}
