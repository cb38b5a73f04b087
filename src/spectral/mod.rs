//! Spectral transport where a scene needs it: a path is RGB until it
//! meets a dispersive dielectric, where it is split to one wavelength (or
//! one RGB channel) and stays so (hero-wavelength style: one random choice
//! per path, weighted so that the expectation over the choice is the
//! spectral image). Scenes without a dispersive material never draw a
//! wavelength and render exactly as before.
//!
//! - [`Dispersion`]: how an index depends on the wavelength (Cauchy's
//!   coefficients, or one index per channel).
//! - [`PathSpectrum`]: a path's state (`Rgb`, `Channel`, `Wavelength`), the
//!   split, and how a colour multiplies into a split path.
//! - [`basis`]: colours as spectra and the sensor that reads them back.

pub mod basis;
pub mod cambrian;

#[cfg(test)]
mod tests;

use crate::color::Color;

pub use basis::{LAMBDA_MAX, LAMBDA_MIN};

/// A representative wavelength of each RGB channel (nm), for a Cauchy
/// index seen by a path split to one channel.
const CHANNEL_NM: [f64; 3] = [610.0, 550.0, 465.0];

/// How a dielectric's index of refraction depends on the wavelength.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Dispersion {
    /// Cauchy's equation `n(λ) = a + b / λ²` with `λ` in micrometres
    /// (Cambrian's `cauchy A B`: `A + B·10⁶ / λ²` with `λ` in nm).
    Cauchy { a: f64, b: f64 },
    /// One index per RGB channel (yuzc19's `dispersion` flag: 1.6473,
    /// 1.6527, 1.6726).
    Channels([f64; 3]),
}

impl Dispersion {
    /// yuzc19's indices for R, G and B.
    pub const YUZC19: Dispersion = Dispersion::Channels([1.6473, 1.6527, 1.6726]);

    /// Cauchy's index at `nm` nanometres.
    pub fn cauchy(a: f64, b: f64, nm: f64) -> f64 {
        let micrometres = nm * 1e-3;
        a + b / (micrometres * micrometres)
    }

    /// The index a path in state `spectrum` sees (an RGB path: the index at
    /// the middle of the spectrum, which no split path uses).
    pub fn ior(&self, spectrum: &PathSpectrum) -> f64 {
        match (*self, *spectrum) {
            (Dispersion::Cauchy { a, b }, PathSpectrum::Wavelength { nm, .. }) => {
                Dispersion::cauchy(a, b, nm)
            }
            (Dispersion::Cauchy { a, b }, PathSpectrum::Channel(k)) => {
                Dispersion::cauchy(a, b, CHANNEL_NM[k])
            }
            (Dispersion::Cauchy { a, b }, PathSpectrum::Tinted { nm }) => {
                Dispersion::cauchy(a, b, nm)
            }
            (Dispersion::Channels(n), PathSpectrum::Tinted { nm }) => {
                // The channel Cambrian's colour of that wavelength leans to.
                let w = cambrian::weight(nm);
                n[if w.r >= w.g && w.r >= w.b {
                    0
                } else if w.g >= w.b {
                    1
                } else {
                    2
                }]
            }
            (Dispersion::Cauchy { a, b }, PathSpectrum::Rgb) => {
                Dispersion::cauchy(a, b, CHANNEL_NM[1])
            }
            (Dispersion::Channels(n), PathSpectrum::Channel(k)) => n[k],
            (Dispersion::Channels(n), PathSpectrum::Wavelength { basis, .. }) => {
                // The channel whose basis function dominates there.
                let mut k = 0;
                for j in 1..3 {
                    if basis[j] > basis[k] {
                        k = j;
                    }
                }
                n[k]
            }
            (Dispersion::Channels(n), PathSpectrum::Rgb) => n[1],
        }
    }
}

/// What a path carries besides its throughput: all of RGB, or (after a
/// dispersive interface) one channel or one wavelength.
#[derive(Clone, Copy, Debug, PartialEq, Default)]
pub enum PathSpectrum {
    /// Every channel: colours multiply channel by channel.
    #[default]
    Rgb,
    /// One RGB channel, chosen uniformly; the throughput is zero in the
    /// others, so colours still multiply channel by channel.
    Channel(usize),
    /// One wavelength `nm`, drawn uniformly over [`LAMBDA_MIN`],
    /// [`LAMBDA_MAX`]: a colour multiplies as its spectrum there,
    /// `basis · c`; the throughput is an RGB triple (the sensor's weight).
    Wavelength {
        nm: f64,
        basis: [f64; 3],
        /// `c̃(λ) / p(λ)`: what light seen directly (not through the
        /// throughput) is worth on the film.
        sensor: Color,
    },
    /// Cambrian's look: one wavelength `nm` for the whole camera sample,
    /// the throughput started at its RGB weight ([`cambrian`]); colours
    /// multiply channel by channel, as Cambrian's do.
    Tinted { nm: f64 },
}

impl PathSpectrum {
    pub fn is_rgb(&self) -> bool {
        matches!(self, PathSpectrum::Rgb)
    }

    /// Splits an RGB path at an interface of `dispersion`, `u` in [0, 1)
    /// choosing the channel or wavelength, and turns `throughput` into the
    /// split path's; a path already split keeps its choice. The expectation
    /// over `u` of what the split path brings is the RGB value of the
    /// spectral transport (`∫ c̃ s_β s_rest dλ`).
    pub fn split(&mut self, dispersion: &Dispersion, u: f64, throughput: &mut Color) {
        if !self.is_rgb() {
            return;
        }
        match dispersion {
            Dispersion::Channels(_) => {
                let k = ((u * 3.0) as usize).min(2);
                let t = *throughput;
                *throughput = match k {
                    0 => Color::new(3.0 * t.r, 0.0, 0.0),
                    1 => Color::new(0.0, 3.0 * t.g, 0.0),
                    _ => Color::new(0.0, 0.0, 3.0 * t.b),
                };
                *self = PathSpectrum::Channel(k);
            }
            Dispersion::Cauchy { .. } => {
                let nm = LAMBDA_MIN + u * (LAMBDA_MAX - LAMBDA_MIN);
                let basis = basis::basis(nm);
                let sensor = basis::sensor(nm) * (LAMBDA_MAX - LAMBDA_MIN);
                *throughput = sensor * basis::spectrum_at(&basis, *throughput);
                *self = PathSpectrum::Wavelength { nm, basis, sensor };
            }
        }
    }

    /// Colour `c` as a factor of the path (a BSDF weight, an emission, a
    /// light sample): itself on RGB and channel paths, its spectrum's
    /// value (as a grey) on a wavelength path.
    #[inline]
    pub fn factor(&self, c: Color) -> Color {
        match self {
            PathSpectrum::Wavelength { basis, .. } => Color::gray(basis::spectrum_at(basis, c)),
            _ => c,
        }
    }

    /// Light `c` seen without the throughput (a look's unweighted
    /// background): what the split path's choice makes of it.
    pub fn seen(&self, c: Color) -> Color {
        match self {
            PathSpectrum::Rgb => c,
            PathSpectrum::Channel(0) => Color::new(3.0 * c.r, 0.0, 0.0),
            PathSpectrum::Channel(1) => Color::new(0.0, 3.0 * c.g, 0.0),
            PathSpectrum::Channel(_) => Color::new(0.0, 0.0, 3.0 * c.b),
            PathSpectrum::Wavelength { basis, sensor, .. } => {
                *sensor * basis::spectrum_at(basis, c)
            }
            PathSpectrum::Tinted { nm } => c * cambrian::weight(*nm),
        }
    }

    /// A camera sample in Cambrian's look with dispersion: its wavelength
    /// from uniform numbers `u` and `v`, and the throughput it starts with.
    pub fn cambrian(u: f64, v: f64) -> (PathSpectrum, Color) {
        let nm = cambrian::wavelength(u, v);
        (PathSpectrum::Tinted { nm }, cambrian::weight(nm))
    }

    /// Whether `throughput` can bring nothing more (on a wavelength path
    /// the sensor's weight may be negative in a channel).
    #[inline]
    pub fn is_dark(&self, throughput: &Color) -> bool {
        match self {
            PathSpectrum::Wavelength { .. } => {
                throughput.r == 0.0 && throughput.g == 0.0 && throughput.b == 0.0
            }
            _ => throughput.is_black(),
        }
    }

    /// The size of `throughput` that Russian roulette compares with 1.
    #[inline]
    pub fn roulette_level(&self, throughput: &Color) -> f64 {
        match self {
            PathSpectrum::Wavelength { .. } => throughput.map(f64::abs).max_component(),
            _ => throughput.max_component(),
        }
    }
}
