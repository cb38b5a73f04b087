//! What is measured of one pair: our render as the PNG writer stores it,
//! theirs box-resampled to our size for the page, the look-alike criterion
//! (on the full-size images: it resamples them itself), and the FLIP map of
//! ours against the resampled theirs.

use crate::image_io::{DisplayImage, Image};
use crate::metrics::flip::{DEFAULT_PIXELS_PER_DEGREE, flip};
use crate::metrics::lookalike::{Lookalike, lookalike};
use crate::metrics::resample::box_resize;

/// The figures and pictures of one rendered pair.
#[derive(Clone, Debug)]
pub struct Measurement {
    pub lookalike: Lookalike,
    /// Mean FLIP (67 pixels per degree) of ours against theirs at our size.
    pub flip: f64,
    /// Our render: the bytes `render -o x.png` writes.
    pub ours: DisplayImage,
    /// Theirs, box-resampled to our size and rounded to bytes.
    pub theirs: DisplayImage,
    /// The FLIP map in magma.
    pub error_map: DisplayImage,
}

/// Measures our linear render against their image as read from its file.
pub fn measure(ours: &Image, theirs: &DisplayImage) -> Result<Measurement, String> {
    let ours = DisplayImage::from_image(ours);
    let lookalike = lookalike(&ours, theirs)?;
    let theirs_small = box_resize(theirs, ours.width, ours.height).to_display();
    let map = flip(&ours, &theirs_small, DEFAULT_PIXELS_PER_DEGREE)?;
    Ok(Measurement {
        lookalike,
        flip: map.mean(),
        error_map: map.to_magma(),
        ours,
        theirs: theirs_small,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    #[test]
    fn a_render_of_their_picture_at_a_fifth_of_the_size_looks_the_same() {
        let theirs = DisplayImage {
            width: 100,
            height: 50,
            pixels: (0..100 * 50)
                .map(|i| {
                    if (i % 100) < 50 {
                        [200, 40, 40]
                    } else {
                        [20, 20, 160]
                    }
                })
                .collect(),
        };
        let ours = Image {
            width: 20,
            height: 10,
            pixels: (0..200)
                .map(|i| {
                    if (i % 20) < 10 {
                        Color::new(200.0, 40.0, 40.0) / 255.0
                    } else {
                        Color::new(20.0, 20.0, 160.0) / 255.0
                    }
                })
                .collect(),
        };
        let measured = measure(&ours, &theirs).unwrap();
        assert!(measured.lookalike.same, "{}", measured.lookalike);
        assert_eq!(measured.theirs, measured.ours);
        assert_eq!(measured.flip, 0.0);
        assert_eq!(
            (measured.error_map.width, measured.error_map.height),
            (20, 10)
        );
    }
}
