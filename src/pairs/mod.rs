//! Reference pairs: a scene file and the image another renderer wrote for
//! it, one per line of a pairs file (`shared/reference/pairs.tsv`), and what
//! `pathtracer lookalike` measures of our render of each (`measure`) and
//! writes about them all (`report`).
//!
//! A pairs file has tab-separated columns `folder`, `base`, `scene`,
//! `render`, `pixels` (`WxH`, the render's size) and `ok` or `doubt` (how
//! sure the pairing is); `scene` and `render` are relative to the folder,
//! and the scene's relative paths resolve against `folder/base`, all below
//! the directory that holds the pairs file. Blank lines and lines starting
//! with `#` (the header) are skipped.

pub mod measure;
pub mod report;

use std::path::{Path, PathBuf};

use crate::limits::{MAX_TABLE_BYTES, read_text_within};

/// How sure the pairing of a scene and a render is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Confidence {
    /// The render was made from this scene file as it is.
    Ok,
    /// Something is in doubt (see the folder's `renders/PAIRS.md`).
    Doubt,
}

impl Confidence {
    pub fn name(&self) -> &'static str {
        match self {
            Confidence::Ok => "ok",
            Confidence::Doubt => "doubt",
        }
    }
}

/// One line of a pairs file.
#[derive(Clone, Debug, PartialEq)]
pub struct Pair {
    pub folder: String,
    pub base: String,
    pub scene: String,
    pub render: String,
    /// The render's width and height.
    pub pixels: (usize, usize),
    pub confidence: Confidence,
}

impl Pair {
    /// The scene file, below `root` (the pairs file's directory).
    pub fn scene_path(&self, root: &Path) -> PathBuf {
        root.join(&self.folder).join(&self.scene)
    }

    /// The directory the scene's relative paths resolve against.
    pub fn base_path(&self, root: &Path) -> PathBuf {
        root.join(&self.folder).join(&self.base)
    }

    /// The other renderer's image.
    pub fn render_path(&self, root: &Path) -> PathBuf {
        root.join(&self.folder).join(&self.render)
    }

    /// Whether the render was made with its renderer's `dispersion`
    /// command-line flag: its name ends in `__pt_dispersion` (only
    /// yuzc19's renderer has such a flag; its `renders/PAIRS.md`).
    pub fn command_line_dispersion(&self) -> bool {
        Path::new(&self.render)
            .file_stem()
            .is_some_and(|stem| stem.to_string_lossy().ends_with("__pt_dispersion"))
    }

    /// A file-name-safe name for the pair's images: the folder and the
    /// render's name without extension, characters other than ASCII letters,
    /// digits, `.`, `_` and `-` replaced by `-`, e.g.
    /// `coursework-Achazwl-CG_homework__scene01_basic`.
    pub fn slug(&self) -> String {
        let stem = Path::new(&self.render)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_else(|| self.render.clone());
        let safe = |text: &str| -> String {
            text.chars()
                .map(|c| {
                    if c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-') {
                        c
                    } else {
                        '-'
                    }
                })
                .collect()
        };
        format!("{}__{}", safe(&self.folder), safe(&stem))
    }
}

/// Reads a pairs file; a malformed line is an error naming its line.
pub fn read_pairs(path: &Path) -> Result<Vec<Pair>, String> {
    let text = read_text_within(path, MAX_TABLE_BYTES, "limits::MAX_TABLE_BYTES")
        .map_err(|e| format!("cannot read the pairs: {e}"))?;
    parse_pairs(&text).map_err(|(line, message)| format!("{}:{line}: {message}", path.display()))
}

/// Parses the text of a pairs file; errors carry their 1-based line.
pub fn parse_pairs(text: &str) -> Result<Vec<Pair>, (usize, String)> {
    let mut pairs = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line_number = index + 1;
        let line = line.trim_end_matches('\r');
        if line.trim().is_empty() || line.starts_with('#') {
            continue;
        }
        let columns: Vec<&str> = line.split('\t').map(str::trim).collect();
        let [folder, base, scene, render, pixels, confidence] = columns[..] else {
            return Err((
                line_number,
                format!("expected 6 tab-separated columns, found {}", columns.len()),
            ));
        };
        let pixels = parse_size(pixels).ok_or_else(|| {
            (
                line_number,
                format!("pixels '{pixels}' is not WIDTHxHEIGHT"),
            )
        })?;
        let confidence = match confidence {
            "ok" => Confidence::Ok,
            "doubt" => Confidence::Doubt,
            other => {
                return Err((
                    line_number,
                    format!("expected 'ok' or 'doubt', found '{other}'"),
                ));
            }
        };
        pairs.push(Pair {
            folder: folder.to_string(),
            base: base.to_string(),
            scene: scene.to_string(),
            render: render.to_string(),
            pixels,
            confidence,
        });
    }
    Ok(pairs)
}

/// `WxH` with both at least 1.
fn parse_size(text: &str) -> Option<(usize, usize)> {
    let (width, height) = text.split_once('x')?;
    let (width, height) = (width.parse().ok()?, height.parse().ok()?);
    (width > 0 && height > 0).then_some((width, height))
}

/// The size we render a pair at: `width` wide, and as tall as the render's
/// aspect ratio makes it (`round(width h / w)` of the render's `w x h`, at
/// least 1).
///
/// The scene's camera gives the same height whenever its size has the
/// render's aspect, which is the usual case. Where the two differ, the
/// render is the evidence of the framing its renderer produced (its size may
/// have come from a command line, or the file may have been edited since);
/// rendering at the scene's aspect would make the comparison stretch one
/// image to the other's shape and measure that instead of the look. The
/// camera's field of view keeps its own axis either way.
pub fn render_size(render_pixels: (usize, usize), width: usize) -> (usize, usize) {
    let (w, h) = render_pixels;
    let height = ((width * h) as f64 / w.max(1) as f64).round().max(1.0) as usize;
    (width.max(1), height)
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEADER: &str = "# folder\tbase\tscene\trender\tpixels\tok|doubt\n";

    #[test]
    fn reads_the_columns_and_skips_the_header_and_blank_lines() {
        let text = format!(
            "{HEADER}\nrepo/a\tcode\tcode/t/x.txt\trenders/x__pt.png\t640x480\tdoubt\r\ncam\t.\tt/y.txt\tr/y.png\t256x256\tok\n"
        );
        let pairs = parse_pairs(&text).unwrap();
        assert_eq!(pairs.len(), 2);
        assert_eq!(pairs[0].pixels, (640, 480));
        assert_eq!(pairs[0].confidence, Confidence::Doubt);
        assert_eq!(pairs[1].confidence, Confidence::Ok);
        let root = Path::new("/r");
        assert_eq!(
            pairs[0].scene_path(root),
            Path::new("/r/repo/a/code/t/x.txt")
        );
        assert_eq!(pairs[0].base_path(root), Path::new("/r/repo/a/code"));
        assert_eq!(
            pairs[0].render_path(root),
            Path::new("/r/repo/a/renders/x__pt.png")
        );
        assert_eq!(pairs[0].slug(), "repo-a__x__pt");
        assert!(!pairs[0].command_line_dispersion());
        let flagged = Pair {
            render: "renders/dispersion__pt_dispersion.png".into(),
            ..pairs[0].clone()
        };
        assert!(flagged.command_line_dispersion());
    }

    #[test]
    fn malformed_lines_name_their_line() {
        for (line, message) in [
            ("a\tb\tc\td\t10x10", "6 tab-separated columns"),
            ("a\tb\tc\td\t10by10\tok", "not WIDTHxHEIGHT"),
            ("a\tb\tc\td\t0x10\tok", "not WIDTHxHEIGHT"),
            ("a\tb\tc\td\t10x10\tmaybe", "'ok' or 'doubt'"),
        ] {
            let (number, error) = parse_pairs(&format!("{HEADER}{line}\n")).unwrap_err();
            assert_eq!(number, 2, "{line}");
            assert!(error.contains(message), "{line}: {error}");
        }
    }

    #[test]
    fn the_render_size_keeps_the_references_aspect() {
        assert_eq!(render_size((1024, 768), 160), (160, 120));
        assert_eq!(render_size((256, 256), 160), (160, 160));
        assert_eq!(render_size((640, 481), 160), (160, 120));
        assert_eq!(render_size((4000, 10), 160), (160, 1));
    }
}
