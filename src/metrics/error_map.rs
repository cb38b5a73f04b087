//! Per-pixel error maps with values in [0, 1], and their pictures in the
//! magma colour map (matplotlib's perceptually uniform map from black
//! through purple and orange to light yellow, the one FLIP's own tool draws
//! its maps in; the 256-entry table is the one the `nv-flip` crate ships).

use crate::image_io::{DisplayImage, Image};

/// One error value per pixel, row 0 at the top; 0 is no error, 1 the most.
#[derive(Clone, Debug, PartialEq)]
pub struct ErrorMap {
    pub width: usize,
    pub height: usize,
    pub values: Vec<f64>,
}

impl ErrorMap {
    /// The mean over all pixels (0 for an empty map).
    pub fn mean(&self) -> f64 {
        if self.values.is_empty() {
            return 0.0;
        }
        self.values.iter().sum::<f64>() / self.values.len() as f64
    }

    /// Per pixel, the largest absolute difference of the three channels,
    /// clamped to [0, 1] (so 1 is at least a full display range; a NaN in
    /// either image counts as 1). The error map where FLIP does not apply
    /// (linear images). The images must have the same size.
    pub fn largest_channel_difference(test: &Image, reference: &Image) -> Result<ErrorMap, String> {
        if (test.width, test.height) != (reference.width, reference.height)
            || test.pixels.len() != reference.pixels.len()
        {
            return Err(format!(
                "image sizes differ: {}x{} against a {}x{} reference",
                test.width, test.height, reference.width, reference.height
            ));
        }
        let values = test
            .pixels
            .iter()
            .zip(&reference.pixels)
            .map(|(a, b)| {
                let largest = (a.r - b.r)
                    .abs()
                    .max((a.g - b.g).abs())
                    .max((a.b - b.b).abs());
                let any_nan = [a.r, a.g, a.b, b.r, b.g, b.b].iter().any(|v| v.is_nan());
                if any_nan { 1.0 } else { largest.min(1.0) }
            })
            .collect();
        Ok(ErrorMap {
            width: test.width,
            height: test.height,
            values,
        })
    }

    /// The map in magma: value `v` is entry `round(255 v)` of the table.
    pub fn to_magma(&self) -> DisplayImage {
        let table = nv_flip::magma_lut().to_vec();
        let pixels = self
            .values
            .iter()
            .map(|&v| {
                let v = if v.is_nan() { 1.0 } else { v.clamp(0.0, 1.0) };
                let index = 3 * (v * 255.0).round() as usize;
                match table.get(index..index + 3) {
                    Some(&[r, g, b]) => [r, g, b],
                    _ => [255, 255, 255],
                }
            })
            .collect();
        DisplayImage {
            width: self.width,
            height: self.height,
            pixels,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::color::Color;

    fn image(pixels: Vec<Color>) -> Image {
        Image {
            width: pixels.len(),
            height: 1,
            pixels,
        }
    }

    #[test]
    fn largest_channel_difference_takes_the_worst_channel_and_clamps() {
        let test = image(vec![
            Color::new(0.5, 0.5, 0.5),
            Color::new(0.1, 0.9, 0.3),
            Color::new(5.0, 0.0, 0.0),
            Color::new(f64::NAN, 0.0, 0.0),
        ]);
        let reference = image(vec![
            Color::gray(0.5),
            Color::new(0.2, 0.5, 0.3),
            Color::BLACK,
            Color::BLACK,
        ]);
        let map = ErrorMap::largest_channel_difference(&test, &reference).unwrap();
        assert_eq!(map.values[0], 0.0);
        assert!((map.values[1] - 0.4).abs() < 1e-12);
        assert_eq!(&map.values[2..], &[1.0, 1.0]);
        let wider = image(vec![Color::BLACK; 5]);
        assert!(ErrorMap::largest_channel_difference(&wider, &reference).is_err());
    }

    #[test]
    fn magma_runs_from_black_to_light_yellow_getting_brighter() {
        let map = ErrorMap {
            width: 256,
            height: 1,
            values: (0..256).map(|i| i as f64 / 255.0).collect(),
        };
        let picture = map.to_magma();
        let brightness = |p: [u8; 3]| p[0] as u32 + p[1] as u32 + p[2] as u32;
        assert!(
            brightness(picture.pixels[0]) < 30,
            "{:?}",
            picture.pixels[0]
        );
        let top = picture.pixels[255];
        assert!(
            top[0] > 240 && top[1] > 240 && top[2] > 150 && top[2] < top[1],
            "{top:?}"
        );
        // Perceptually ordered: brightness never falls along the map.
        for pair in picture.pixels.windows(2) {
            assert!(brightness(pair[1]) + 2 >= brightness(pair[0]), "{pair:?}");
        }
    }
}
