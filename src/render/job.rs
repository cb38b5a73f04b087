//! Render jobs: what one part of a render is (a pixel region and a sample
//! range of one scene and settings), and how parts are checked before they
//! are merged (same scene and settings, no sample rendered twice, nothing
//! missing).

use std::fmt;
use std::ops::Range;

use crate::film::Film;
use crate::render::RenderSettings;

/// A rectangle of pixels, `x0 <= x < x1`, `y0 <= y < y1`, row 0 at the top
/// of the image.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Crop {
    pub x0: u32,
    pub y0: u32,
    pub x1: u32,
    pub y1: u32,
}

impl Crop {
    pub fn full(width: u32, height: u32) -> Crop {
        Crop {
            x0: 0,
            y0: 0,
            x1: width,
            y1: height,
        }
    }

    /// `x0,y0,x1,y1`.
    pub fn parse(text: &str) -> Result<Crop, String> {
        let numbers: Vec<u32> = text
            .split(',')
            .map(|n| n.trim().parse::<u32>())
            .collect::<Result<_, _>>()
            .map_err(|_| format!("--crop '{text}': expected x0,y0,x1,y1 (pixel bounds)"))?;
        match numbers[..] {
            [x0, y0, x1, y1] => Ok(Crop { x0, y0, x1, y1 }),
            _ => Err(format!(
                "--crop '{text}': expected four numbers x0,y0,x1,y1"
            )),
        }
    }

    /// Checks that the crop is a non-empty part of a `width` x `height` image.
    pub fn check(&self, width: u32, height: u32) -> Result<(), String> {
        if self.x0 >= self.x1 || self.y0 >= self.y1 || self.x1 > width || self.y1 > height {
            return Err(format!(
                "--crop {self}: not a non-empty region of the {width}x{height} image"
            ));
        }
        Ok(())
    }

    pub fn contains(&self, x: u32, y: u32) -> bool {
        (self.x0..self.x1).contains(&x) && (self.y0..self.y1).contains(&y)
    }

    /// Marks the pixels of `film` outside the crop as done, so that a render
    /// adds samples only inside it.
    pub fn restrict(&self, film: &mut Film) {
        let width = film.width;
        for (index, pixel) in film.pixels.iter_mut().enumerate() {
            if !self.contains((index % width) as u32, (index / width) as u32) {
                pixel.converged = true;
            }
        }
    }
}

impl fmt::Display for Crop {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{},{},{},{}", self.x0, self.y0, self.x1, self.y1)
    }
}

/// `A..B`: sample indices A to B - 1 of every pixel.
pub fn parse_samples(text: &str) -> Result<Range<u32>, String> {
    let bad = || format!("--samples '{text}': expected A..B, e.g. 0..64");
    let (start, end) = text.split_once("..").ok_or_else(bad)?;
    let start: u32 = start.trim().parse().map_err(|_| bad())?;
    let end: u32 = end.trim().parse().map_err(|_| bad())?;
    if start >= end {
        return Err(format!("--samples {text}: the range is empty"));
    }
    Ok(start..end)
}

/// What a film file says about the part it holds. Parts merge when every
/// field of [`JobHeader::identity`] is the same.
#[derive(Clone, Debug, PartialEq)]
pub struct JobHeader {
    /// The scene file as named on the command line (not compared).
    pub scene: String,
    /// FNV-1a of the scene file's bytes, in hex (assets are not hashed;
    /// their triangle count is compared).
    pub scene_hash: String,
    pub triangles: u64,
    pub seed: u64,
    pub look: String,
    pub integrator: String,
    pub sampler: String,
    pub max_depth: u32,
    /// `none` or the luminance.
    pub clamp: String,
    pub light_paths: bool,
    pub missing_assets: String,
    pub width: u32,
    pub height: u32,
    pub crop: Crop,
    pub samples: Range<u32>,
    /// The film is the checkpoint of a render that stopped part way: its
    /// pixels hold the first samples of `samples`, not all of them, each
    /// pixel as many as it got (`render --resume` continues it; `merge`
    /// refuses it).
    pub checkpoint: bool,
}

impl JobHeader {
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        scene: &str,
        scene_hash: u64,
        triangles: u64,
        settings: &RenderSettings,
        missing_assets: &str,
        crop: Crop,
        samples: Range<u32>,
    ) -> JobHeader {
        JobHeader {
            scene: scene.to_string(),
            scene_hash: format!("{scene_hash:016x}"),
            triangles,
            seed: settings.seed,
            look: settings.look.name.to_string(),
            integrator: settings.integrator.name().to_string(),
            sampler: settings.sampler.name().to_string(),
            max_depth: settings.max_depth,
            clamp: settings.clamp.map_or("none".to_string(), |c| c.to_string()),
            light_paths: settings.light_paths,
            missing_assets: missing_assets.to_string(),
            width: settings.width,
            height: settings.height,
            crop,
            samples,
            checkpoint: false,
        }
    }

    /// The fields that must agree for parts to merge, by name.
    pub fn identity(&self) -> [(&'static str, String); 12] {
        [
            ("scene_hash", self.scene_hash.clone()),
            ("triangles", self.triangles.to_string()),
            ("seed", self.seed.to_string()),
            ("look", self.look.clone()),
            ("integrator", self.integrator.clone()),
            ("sampler", self.sampler.clone()),
            ("max_depth", self.max_depth.to_string()),
            ("clamp", self.clamp.clone()),
            ("light_paths", self.light_paths.to_string()),
            ("missing_assets", self.missing_assets.clone()),
            ("width", self.width.to_string()),
            ("height", self.height.to_string()),
        ]
    }

    /// Every field as (name, text), the identity first: what a film file's
    /// header holds (`checkpoint` only when it is one).
    pub fn fields(&self) -> Vec<(&'static str, String)> {
        let mut fields = vec![("scene", self.scene.clone())];
        fields.extend(self.identity());
        fields.push(("crop", self.crop.to_string()));
        fields.push((
            "samples",
            format!("{}..{}", self.samples.start, self.samples.end),
        ));
        if self.checkpoint {
            fields.push(("checkpoint", "true".to_string()));
        }
        fields
    }

    /// The header from its fields; `field` looks one up by name.
    pub fn from_fields(field: impl Fn(&str) -> Option<String>) -> Result<JobHeader, String> {
        let text = |name: &str| field(name).ok_or_else(|| format!("no '{name}' attribute"));
        let number = |name: &str| -> Result<u64, String> {
            let value = text(name)?;
            value
                .parse()
                .map_err(|_| format!("attribute '{name}' is '{value}', not a number"))
        };
        let small = |name: &str| -> Result<u32, String> {
            u32::try_from(number(name)?).map_err(|_| format!("attribute '{name}' is too large"))
        };
        Ok(JobHeader {
            scene: text("scene")?,
            scene_hash: text("scene_hash")?,
            triangles: number("triangles")?,
            seed: number("seed")?,
            look: text("look")?,
            integrator: text("integrator")?,
            sampler: text("sampler")?,
            max_depth: small("max_depth")?,
            clamp: text("clamp")?,
            light_paths: text("light_paths")? == "true",
            missing_assets: text("missing_assets")?,
            width: small("width")?,
            height: small("height")?,
            crop: Crop::parse(&text("crop")?)?,
            samples: parse_samples(&text("samples")?)?,
            checkpoint: field("checkpoint").is_some_and(|value| value == "true"),
        })
    }
}

/// The first field of [`JobHeader::identity`] in which `header` differs
/// from `expected`: its name, its value in `header` and in `expected`.
pub fn first_difference(
    header: &JobHeader,
    expected: &JobHeader,
) -> Option<(&'static str, String, String)> {
    header
        .identity()
        .into_iter()
        .zip(expected.identity())
        .find(|((_, found), (_, wanted))| found != wanted)
        .map(|((name, found), (_, wanted))| (name, found, wanted))
}

/// A part to merge: its file name and header.
pub struct Part<'a> {
    pub name: &'a str,
    pub header: &'a JobHeader,
}

/// Checks that `parts` are of one scene and settings (naming the field that
/// differs) and that no pixel gets a sample index twice. Returns the sample
/// ranges missing per region (`x0,y0,x1,y1: samples A..B`) below the largest
/// sample index of any part: empty when the parts cover the whole image.
pub fn check_parts(parts: &[Part]) -> Result<Vec<String>, String> {
    let first = parts.first().ok_or("no film parts to merge")?;
    for part in &parts[1..] {
        if let Some((name, found, expected)) = first_difference(part.header, first.header) {
            return Err(format!(
                "{}: {name} is {found}, but {} has {expected}: not a part of the same render",
                part.name, first.name
            ));
        }
    }
    let (width, height) = (first.header.width, first.header.height);
    for part in parts {
        part.header
            .crop
            .check(width, height)
            .map_err(|e| format!("{}: {e}", part.name))?;
    }
    let total = parts
        .iter()
        .map(|p| p.header.samples.end)
        .max()
        .unwrap_or(0);
    // The image cut at every crop edge: within a cell, every pixel is in
    // the same parts.
    let edges = |of: fn(&Crop) -> [u32; 2], size: u32| {
        let mut edges: Vec<u32> = parts.iter().flat_map(|p| of(&p.header.crop)).collect();
        edges.extend([0, size]);
        edges.sort_unstable();
        edges.dedup();
        edges
    };
    let xs = edges(|c| [c.x0, c.x1], width);
    let ys = edges(|c| [c.y0, c.y1], height);
    let mut missing = Vec::new();
    for rows in ys.windows(2) {
        for columns in xs.windows(2) {
            let cell = Crop {
                x0: columns[0],
                y0: rows[0],
                x1: columns[1],
                y1: rows[1],
            };
            let mut covering: Vec<&Part> = parts
                .iter()
                .filter(|p| p.header.crop.contains(cell.x0, cell.y0))
                .collect();
            covering.sort_by_key(|p| p.header.samples.start);
            let mut next = 0;
            let mut previous: Option<&Part> = None;
            for part in covering {
                let range = &part.header.samples;
                if range.start < next
                    && let Some(other) = previous
                {
                    return Err(format!(
                        "{} and {} overlap: both hold samples {}..{} of pixels {cell}",
                        other.name,
                        part.name,
                        range.start,
                        next.min(range.end)
                    ));
                }
                if range.start > next {
                    missing.push(format!("{cell}: samples {next}..{}", range.start));
                }
                if range.end > next {
                    next = range.end;
                    previous = Some(part);
                }
            }
            if next < total {
                missing.push(format!("{cell}: samples {next}..{total}"));
            }
        }
    }
    Ok(missing)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn header(crop: &str, samples: &str) -> JobHeader {
        JobHeader::from_fields(|name| {
            Some(match name {
                "width" => "10".to_string(),
                "height" => "8".to_string(),
                "crop" => crop.to_string(),
                "samples" => samples.to_string(),
                _ => "0".to_string(),
            })
        })
        .unwrap()
    }

    fn check(parts: &[(&str, &str)]) -> Result<Vec<String>, String> {
        let headers: Vec<JobHeader> = parts.iter().map(|(c, s)| header(c, s)).collect();
        let names: Vec<String> = (0..parts.len()).map(|i| format!("p{i}")).collect();
        let parts: Vec<Part> = names
            .iter()
            .zip(&headers)
            .map(|(name, header)| Part { name, header })
            .collect();
        check_parts(&parts)
    }

    #[test]
    fn tiles_and_ranges_that_cover_everything_leave_nothing_missing() {
        let parts = [
            ("0,0,10,8", "8..16"),
            ("0,0,4,8", "0..8"),
            ("4,0,10,3", "0..8"),
            ("4,3,10,8", "0..2"),
            ("4,3,10,8", "2..8"),
        ];
        assert_eq!(check(&parts), Ok(vec![]));
    }

    #[test]
    fn gaps_are_listed_by_region_and_range() {
        let missing = check(&[("0,0,10,8", "0..4"), ("0,0,5,8", "6..9")]).unwrap();
        assert_eq!(missing, ["0,0,5,8: samples 4..6", "5,0,10,8: samples 4..9"]);
    }

    #[test]
    fn overlaps_name_both_parts_and_the_shared_samples() {
        let error = check(&[("2,2,3,3", "1..3"), ("0,0,10,8", "0..10")]).unwrap_err();
        assert!(
            error.starts_with("p1 and p0 overlap: both hold samples 1..3 of pixels 2,2,3,3"),
            "{error}"
        );
        let error = check(&[("0,0,10,8", "0..10"), ("9,7,10,8", "9..12")]).unwrap_err();
        assert!(
            error.contains("both hold samples 9..10 of pixels 9,7,10,8"),
            "{error}"
        );
    }

    #[test]
    fn job_arguments_are_parsed_or_refused() {
        assert_eq!(parse_samples("16..40"), Ok(16..40));
        assert!(parse_samples("4..4").is_err() && parse_samples("4").is_err());
        assert_eq!(
            Crop::parse("1,2,3,4").map(|c| c.to_string()),
            Ok("1,2,3,4".into())
        );
        assert!(Crop::parse("1,2,3").is_err() && Crop::parse("a,b,c,d").is_err());
        assert!(Crop::full(4, 4).check(4, 4).is_ok());
        assert!(Crop::parse("2,0,2,4").unwrap().check(4, 4).is_err());
    }
}
