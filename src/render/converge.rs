//! Error against time: a render continued at doubling sample counts, each
//! stage compared with a reference image.

use std::fmt::Write;

use crate::film::Film;
use crate::image_io::Image;
use crate::limits::MemoryBudget;
use crate::metrics::compare;
use std::time::Instant;

use crate::render::{Progress, RenderSettings, Renderer, Samples, Stop};
use crate::render_scene::RenderScene;

/// One stage of a convergence run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ConvergencePoint {
    pub spp: u32,
    /// Render time of all samples so far (comparisons not counted).
    pub seconds: f64,
    pub rmse: f64,
    pub rel_mse: f64,
    pub ssim: f64,
}

impl ConvergencePoint {
    /// The point of `image`, made of `spp` samples per pixel in `seconds`,
    /// against `reference` (both cut to `region` first when one is given).
    pub fn measure(
        image: &Image,
        reference: &Image,
        region: Option<[usize; 4]>,
        spp: u32,
        seconds: f64,
    ) -> Result<ConvergencePoint, String> {
        let comparison = match region {
            Some(region) => compare(&cut(image, region)?, &cut(reference, region)?)?,
            None => compare(image, reference)?,
        };
        Ok(ConvergencePoint {
            spp,
            seconds,
            rmse: comparison.rmse,
            rel_mse: comparison.rel_mse,
            ssim: comparison.ssim,
        })
    }
}

/// Renders 1, 2, 4, ... up to `max_spp` samples per pixel (each stage
/// continues the previous one) and compares every stage with `reference`;
/// `max_spp` 0 is an error (no stage, no curve).
pub fn converge(
    scene: &RenderScene,
    settings: &RenderSettings,
    reference: &Image,
    max_spp: u32,
    on_point: impl FnMut(&ConvergencePoint),
) -> Result<Vec<ConvergencePoint>, String> {
    converge_within(
        scene,
        settings,
        reference,
        max_spp,
        MemoryBudget::default(),
        None,
        on_point,
    )
}

/// [`converge`], once the image's size is checked against `budget`, the
/// error measured over `region` (see [`cut`]) when one is given.
pub fn converge_within(
    scene: &RenderScene,
    settings: &RenderSettings,
    reference: &Image,
    max_spp: u32,
    budget: MemoryBudget,
    region: Option<[usize; 4]>,
    mut on_point: impl FnMut(&ConvergencePoint),
) -> Result<Vec<ConvergencePoint>, String> {
    if max_spp == 0 {
        return Err("the largest sample count (--max-spp) must be at least 1".to_string());
    }
    let mut film = Film::within(
        settings.width.max(1) as usize,
        settings.height.max(1) as usize,
        budget,
    )?;
    let mut points = Vec::new();
    // One renderer for every stage; the time to start it (the worker
    // threads) counts in the first point.
    let built = Instant::now();
    let pixels = (film.width * film.height) as u64;
    let renderer = Renderer::new(
        scene,
        settings,
        Progress::new(pixels * max_spp as u64, None),
    )?;
    let mut seconds = built.elapsed().as_secs_f64();
    let mut done = 0;
    let mut next = 1;
    while done < max_spp {
        let target = next.min(max_spp);
        let samples = Samples::Range(done..target);
        seconds += renderer.render(&mut film, &samples, Stop::Never)?.seconds;
        done = target;
        let point = ConvergencePoint::measure(&film.to_image(), reference, region, done, seconds)?;
        on_point(&point);
        points.push(point);
        next = next.saturating_mul(2);
    }
    Ok(points)
}

/// The pixels of `image` in `[x0, y0, x1, y1)`.
pub fn cut(image: &Image, [x0, y0, x1, y1]: [usize; 4]) -> Result<Image, String> {
    if !(x0 < x1 && y0 < y1 && x1 <= image.width && y1 <= image.height) {
        return Err(format!(
            "the region {x0},{y0},{x1},{y1} is not inside the {}x{} image",
            image.width, image.height
        ));
    }
    let pixels = (y0..y1)
        .flat_map(|y| {
            image.pixels[y * image.width + x0..y * image.width + x1]
                .iter()
                .copied()
        })
        .collect();
    Ok(Image {
        width: x1 - x0,
        height: y1 - y0,
        pixels,
    })
}

pub const CSV_HEADER: &str = "spp,seconds,rmse,rel_mse,ssim";

pub fn to_csv(points: &[ConvergencePoint]) -> String {
    let mut csv = format!("{CSV_HEADER}\n");
    for p in points {
        let _ = writeln!(
            csv,
            "{},{:.6},{:.8e},{:.8e},{:.6}",
            p.spp, p.seconds, p.rmse, p.rel_mse, p.ssim
        );
    }
    csv
}

/// Reads the (seconds, column) pairs of a convergence CSV (ours or any file
/// with a header naming `seconds` and the column).
pub fn read_csv_series(text: &str, column: &str) -> Result<Vec<(f64, f64)>, String> {
    let mut lines = text.lines().filter(|l| !l.trim().is_empty());
    let header: Vec<&str> = lines
        .next()
        .ok_or("empty CSV file")?
        .split(',')
        .map(str::trim)
        .collect();
    let find = |name: &str| {
        header
            .iter()
            .position(|h| *h == name)
            .ok_or_else(|| format!("no '{name}' column in the CSV header"))
    };
    let (x, y) = (find("seconds")?, find(column)?);
    lines
        .enumerate()
        .map(|(i, line)| {
            let fields: Vec<&str> = line.split(',').map(str::trim).collect();
            let value = |k: usize| -> Result<f64, String> {
                fields
                    .get(k)
                    .and_then(|f| f.parse().ok())
                    .ok_or_else(|| format!("line {}: not a number in column {}", i + 2, k + 1))
            };
            Ok((value(x)?, value(y)?))
        })
        .collect()
}

/// When a curve of (seconds, error) first reaches `target`: interpolated on
/// log-log axes between the two points around it. `Reach::Extrapolated` when
/// the curve ends above the target (error taken as proportional to 1/time
/// from the last point, the Monte Carlo rate).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Reach {
    Measured(f64),
    Extrapolated(f64),
}

pub fn time_to_reach(points: &[(f64, f64)], target: f64) -> Option<Reach> {
    let usable: Vec<(f64, f64)> = points
        .iter()
        .copied()
        .filter(|(x, y)| x.is_finite() && y.is_finite() && *x > 0.0 && *y > 0.0)
        .collect();
    let first = usable.first()?;
    if first.1 <= target {
        return Some(Reach::Measured(first.0));
    }
    for pair in usable.windows(2) {
        let ((x0, y0), (x1, y1)) = (pair[0], pair[1]);
        if y1 <= target {
            let f = (target.ln() - y0.ln()) / (y1.ln() - y0.ln());
            return Some(Reach::Measured((x0.ln() + f * (x1.ln() - x0.ln())).exp()));
        }
    }
    let (x, y) = *usable.last()?;
    Some(Reach::Extrapolated(x * y / target))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn time_to_reach_interpolates_on_log_log_axes() {
        let curve = [(1.0, 1.0), (4.0, 0.25), (16.0, 0.0625)];
        match time_to_reach(&curve, 0.5) {
            Some(Reach::Measured(t)) => assert!((t - 2.0).abs() < 1e-12, "{t}"),
            other => panic!("{other:?}"),
        }
        assert_eq!(time_to_reach(&curve, 2.0), Some(Reach::Measured(1.0)));
        match time_to_reach(&curve, 0.01) {
            Some(Reach::Extrapolated(t)) => assert!((t - 100.0).abs() < 1e-9),
            other => panic!("{other:?}"),
        }
        assert_eq!(time_to_reach(&[], 1.0), None);
    }

    #[test]
    fn csv_round_trips() {
        let points = [
            ConvergencePoint {
                spp: 1,
                seconds: 0.5,
                rmse: 0.1,
                rel_mse: 0.02,
                ssim: 0.5,
            },
            ConvergencePoint {
                spp: 2,
                seconds: 1.0,
                rmse: 0.07,
                rel_mse: 0.01,
                ssim: 0.6,
            },
        ];
        let series = read_csv_series(&to_csv(&points), "rel_mse").unwrap();
        assert_eq!(series.len(), 2);
        assert!((series[1].0 - 1.0).abs() < 1e-9 && (series[1].1 - 0.01).abs() < 1e-12);
        assert!(read_csv_series("spp,rmse\n1,2\n", "rel_mse").is_err());
        assert!(read_csv_series("seconds,rel_mse\n1,x\n", "rel_mse").is_err());
    }
}
