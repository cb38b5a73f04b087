//! Where a surface's colour comes from: images used as colour textures and
//! normal maps (here: nearest-texel lookup, clamped, wrapped, tiled, or
//! afb's rows-down wrap, and the placeholder of a missing texture), rub's
//! procedural checker (`checker`), and afb's rules that read an image at
//! the world hit point (`uv_rule`).

pub mod checker;
pub mod uv_rule;

use crate::color::Color;

/// A decoded image in linear [0, 1] values (no gamma conversion, as the original).
#[derive(Clone, Debug, PartialEq)]
pub struct Texture {
    pub width: usize,
    pub height: usize,
    /// Row-major, row 0 at the top of the image.
    pub texels: Vec<[f32; 3]>,
}

/// The colours of [`Texture::placeholder`]: magenta and mid grey.
pub const PLACEHOLDER_COLORS: [[f32; 3]; 2] = [[1.0, 0.0, 1.0], [0.5, 0.5, 0.5]];

impl Texture {
    /// What a missing colour texture becomes with `--missing-assets
    /// placeholder`: 8x8 texels alternating magenta (texel (0, 0), the top
    /// left, and every texel whose column plus row is even) and mid grey, so
    /// that a surface shows 8x8 squares across its uv range (a tiled plane
    /// one square per texel).
    pub fn placeholder() -> Texture {
        const SIZE: usize = 8;
        let texels = (0..SIZE * SIZE)
            .map(|k| PLACEHOLDER_COLORS[(k / SIZE + k % SIZE) % 2])
            .collect();
        Texture {
            width: SIZE,
            height: SIZE,
            texels,
        }
    }

    /// The image upside down: a renderer that reads row `v h` (v = 0 at the
    /// top, yuzc19's) sees through [`Texture::lookup`] what it saw.
    pub fn flip_rows(&mut self) {
        let width = self.width;
        for row in 0..self.height / 2 {
            let mirror = self.height - 1 - row;
            let (top, bottom) = self.texels.split_at_mut(mirror * width);
            top[row * width..(row + 1) * width].swap_with_slice(&mut bottom[..width]);
        }
    }

    /// Nearest texel at (u, v) in [0, 1], v = 0 at the bottom (the original's
    /// `i = floor(u*W)`, `j = floor((1-v)*H)`, clamped).
    pub fn lookup(&self, u: f64, v: f64) -> Color {
        let i = clamp_index(u * self.width as f64, self.width);
        let j = clamp_index((1.0 - v) * self.height as f64, self.height);
        self.texel(i, j)
    }

    /// [`Texture::lookup`] with wrap-around instead of clamping (u = 1 is
    /// u = 0 again), for height maps read one texel to either side.
    pub fn lookup_wrapped(&self, u: f64, v: f64) -> Color {
        let i = wrap_index(u * self.width as f64, self.width);
        let j = wrap_index((1.0 - v) * self.height as f64, self.height);
        self.texel(i, j)
    }

    /// Nearest texel with wrap-around, for tiled textures (coordinates in texels).
    pub fn lookup_tiled(&self, x: f64, y: f64) -> Color {
        let i = wrap_index(x, self.width);
        let j = wrap_index(-y, self.height);
        self.texel(i, j)
    }

    /// The texel `(trunc(a w), trunc(b h))`, each index wrapped into the
    /// image as afb's double modulo `((i % w) + w) % w` does, row 0 at the
    /// top of the image (b counts down, no vertical flip).
    pub fn lookup_rows_down(&self, a: f64, b: f64) -> Color {
        let i = truncate_wrap(a * self.width as f64, self.width);
        let j = truncate_wrap(b * self.height as f64, self.height);
        self.texel(i, j)
    }

    fn texel(&self, i: usize, j: usize) -> Color {
        match self.texels.get(j * self.width + i) {
            Some(t) => Color::new(t[0] as f64, t[1] as f64, t[2] as f64),
            None => Color::BLACK,
        }
    }
}

fn clamp_index(x: f64, size: usize) -> usize {
    if size == 0 || x.is_nan() || x < 0.0 {
        return 0;
    }
    (x as usize).min(size - 1)
}

fn wrap_index(x: f64, size: usize) -> usize {
    if size == 0 || !x.is_finite() {
        return 0;
    }
    let i = x.floor().rem_euclid(size as f64) as usize;
    i.min(size - 1)
}

/// `x` truncated towards zero, then wrapped into `0..size` (Euclidean
/// remainder); 0 for what is not finite.
fn truncate_wrap(x: f64, size: usize) -> usize {
    if size == 0 || !x.is_finite() {
        return 0;
    }
    let i = x.trunc().rem_euclid(size as f64) as usize;
    i.min(size - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn checker() -> Texture {
        // 2x2: top row red, green; bottom row blue, white.
        Texture {
            width: 2,
            height: 2,
            texels: vec![[1., 0., 0.], [0., 1., 0.], [0., 0., 1.], [1., 1., 1.]],
        }
    }

    #[test]
    fn flipped_rows_read_top_down() {
        let mut texture = Texture {
            width: 2,
            height: 3,
            texels: (0..6).map(|k| [k as f32, 0.0, 0.0]).collect(),
        };
        texture.flip_rows();
        let column: Vec<f32> = texture.texels.iter().step_by(2).map(|t| t[0]).collect();
        assert_eq!(column, [4.0, 2.0, 0.0]);
        // v = 0.1 now reads the image's top row, as row = v h does.
        assert_eq!(texture.lookup(0.9, 0.1).r, 1.0);
        let mut square = checker();
        square.flip_rows();
        assert_eq!(square.lookup(0.25, 0.25).b, 0.0);
        assert_eq!(square.lookup(0.25, 0.25).r, 1.0);
    }

    #[test]
    fn lookup_has_v_up() {
        let t = checker();
        assert_eq!(t.lookup(0.1, 0.9), Color::new(1., 0., 0.));
        assert_eq!(t.lookup(0.9, 0.1), Color::new(1., 1., 1.));
        assert_eq!(t.lookup(-5.0, 7.0), Color::new(1., 0., 0.));
        assert_eq!(t.lookup(f64::NAN, 0.5), t.lookup(0.0, 0.5));
    }

    #[test]
    fn wrapped_lookup_agrees_inside_and_wraps_outside() {
        let t = checker();
        for (u, v) in [(0.1, 0.9), (0.9, 0.1), (0.6, 0.3)] {
            assert_eq!(t.lookup_wrapped(u, v), t.lookup(u, v));
            assert_eq!(t.lookup_wrapped(u + 1.0, v - 3.0), t.lookup(u, v));
        }
    }

    #[test]
    fn placeholder_is_an_8x8_magenta_and_grey_checker() {
        let t = Texture::placeholder();
        assert_eq!((t.width, t.height, t.texels.len()), (8, 8, 64));
        let magenta = Color::new(1.0, 0.0, 1.0);
        let grey = Color::gray(0.5);
        // Neighbours along either axis differ, diagonal ones agree.
        for j in 0..8 {
            for i in 0..8 {
                let expected = if (i + j) % 2 == 0 { magenta } else { grey };
                assert_eq!(t.texel(i, j), expected, "texel ({i}, {j})");
            }
        }
        assert_eq!(t.lookup(0.01, 0.99), magenta);
        assert_eq!(t.lookup(0.14, 0.99), grey);
    }

    #[test]
    fn rows_down_lookup_truncates_then_wraps_like_a_double_modulo() {
        let t = checker();
        // Row 0 is the top: red, green; row 1: blue, white.
        assert_eq!(t.lookup_rows_down(0.1, 0.1), Color::new(1., 0., 0.));
        assert_eq!(t.lookup_rows_down(0.9, 0.9), Color::new(1., 1., 1.));
        assert_eq!(t.lookup_rows_down(1.6, 0.2), Color::new(0., 1., 0.));
        // trunc(-0.4 * 2) = 0, not -1: truncation, not floor.
        assert_eq!(t.lookup_rows_down(-0.4, 0.2), Color::new(1., 0., 0.));
        // trunc(-0.6 * 2) = -1, and ((-1 % 2) + 2) % 2 = 1.
        assert_eq!(t.lookup_rows_down(-0.6, -0.6), Color::new(1., 1., 1.));
        assert_eq!(
            t.lookup_rows_down(f64::NAN, 1e300),
            t.lookup_rows_down(0.0, 0.0)
        );
    }

    #[test]
    fn tiled_lookup_wraps() {
        let t = checker();
        assert_eq!(t.lookup_tiled(0.5, -0.5), t.lookup_tiled(2.5, -2.5));
        assert_eq!(t.lookup_tiled(-1.5, 0.5), t.lookup_tiled(0.5, 0.5));
    }
}
