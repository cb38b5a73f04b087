//! What `pathtracer lookalike` writes about all pairs: `index.html` (one row
//! per pair with ours, theirs and the error map), `lookalike.csv` (the same
//! figures) and the summary line.

use std::fmt::Write as _;

use super::{Confidence, Pair};
use crate::metrics::lookalike::{LOOKALIKE_WIDTH, MEAN_LIMIT, P95_LIMIT};

/// The figures of a pair that rendered and compared.
#[derive(Clone, Debug, PartialEq)]
pub struct Figures {
    pub mean: f64,
    pub p95: f64,
    pub same: bool,
    pub flip: f64,
    pub aspect_differs: bool,
    /// Our render's size.
    pub width: usize,
    pub height: usize,
}

/// One pair's row.
#[derive(Clone, Debug, PartialEq)]
pub struct Row {
    pub pair: Pair,
    /// The name of the pairs file the pair comes from.
    pub source: String,
    /// File-name-safe name; the images are `images/<slug>.{ours,theirs,diff}.png`.
    pub slug: String,
    /// The scene's detected dialect and the look it was rendered in, once
    /// it has loaded.
    pub dialect: Option<String>,
    pub look: Option<String>,
    /// Loading, building and rendering, in seconds.
    pub seconds: f64,
    /// Whether `images/<slug>.theirs.png` was written.
    pub has_theirs: bool,
    /// The figures, or why there are none (a scene that did not load...).
    pub outcome: Result<Figures, String>,
}

impl Row {
    fn verdict(&self) -> &'static str {
        match &self.outcome {
            Ok(figures) if figures.same => "same",
            Ok(_) => "different",
            Err(_) => "failed",
        }
    }

    fn looks_the_same(&self) -> bool {
        matches!(&self.outcome, Ok(figures) if figures.same)
    }
}

/// How the run was made, for the page's heading.
#[derive(Clone, Debug)]
pub struct RunDescription {
    pub pairs_file: String,
    pub width: usize,
    pub spp: u32,
    /// The render settings' other names (integrator, sampler, look...).
    pub settings: String,
}

/// `N of M ok pairs look the same`, and the doubtful pairs' count when
/// there are any, and how many failed; with pairs of several files, that
/// for each file, `pairs.tsv: ...; oracle-pairs.tsv: ...`.
pub fn summary(rows: &[Row]) -> String {
    let mut sources: Vec<&str> = Vec::new();
    for row in rows {
        if !sources.contains(&row.source.as_str()) {
            sources.push(&row.source);
        }
    }
    if sources.len() < 2 {
        return summary_of(rows);
    }
    let parts: Vec<String> = sources
        .iter()
        .map(|source| {
            let of: Vec<Row> = rows
                .iter()
                .filter(|r| r.source == *source)
                .cloned()
                .collect();
            format!("{source}: {}", summary_of(&of))
        })
        .collect();
    parts.join("; ")
}

fn summary_of(rows: &[Row]) -> String {
    let count = |confidence: Confidence| {
        let of: Vec<&Row> = rows
            .iter()
            .filter(|r| r.pair.confidence == confidence)
            .collect();
        (of.iter().filter(|r| r.looks_the_same()).count(), of.len())
    };
    let (same, ok) = count(Confidence::Ok);
    let mut line = format!("{same} of {ok} ok pairs look the same");
    let (same_doubt, doubt) = count(Confidence::Doubt);
    if doubt > 0 {
        let _ = write!(line, ", {same_doubt} of {doubt} doubtful pairs");
    }
    let failed = rows.iter().filter(|r| r.outcome.is_err()).count();
    if failed > 0 {
        let _ = write!(line, " ({failed} failed)");
    }
    line
}

/// The CSV file: a header line, then one line per row.
pub fn csv(rows: &[Row]) -> String {
    let mut text = String::from(
        "name,folder,scene,render,confidence,dialect,look,width,height,reference_pixels,seconds,mean,p95,verdict,flip,aspect_differs,error,pairs_file\n",
    );
    for row in rows {
        let pair = &row.pair;
        let (figures, error) = match &row.outcome {
            Ok(f) => (
                [
                    f.width.to_string(),
                    f.height.to_string(),
                    format!("{:.3}", f.mean),
                    format!("{:.3}", f.p95),
                ],
                String::new(),
            ),
            Err(e) => (Default::default(), e.clone()),
        };
        let [width, height, mean, p95] = figures;
        let (flip, aspect) = match &row.outcome {
            Ok(f) => (format!("{:.5}", f.flip), f.aspect_differs.to_string()),
            Err(_) => (String::new(), String::new()),
        };
        let fields = [
            row.slug.clone(),
            pair.folder.clone(),
            pair.scene.clone(),
            pair.render.clone(),
            pair.confidence.name().to_string(),
            row.dialect.clone().unwrap_or_default(),
            row.look.clone().unwrap_or_default(),
            width,
            height,
            format!("{}x{}", pair.pixels.0, pair.pixels.1),
            format!("{:.2}", row.seconds),
            mean,
            p95,
            row.verdict().to_string(),
            flip,
            aspect,
            error,
            row.source.clone(),
        ];
        let quoted: Vec<String> = fields.iter().map(|f| csv_field(f)).collect();
        text.push_str(&quoted.join(","));
        text.push('\n');
    }
    text
}

/// A CSV field, quoted (with doubled quotes) when it holds a comma, quote or line break.
fn csv_field(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// Text made safe inside HTML elements and attribute values.
fn escape(text: &str) -> String {
    let mut safe = String::with_capacity(text.len());
    for c in text.chars() {
        match c {
            '&' => safe.push_str("&amp;"),
            '<' => safe.push_str("&lt;"),
            '>' => safe.push_str("&gt;"),
            '"' => safe.push_str("&quot;"),
            '\'' => safe.push_str("&#39;"),
            _ => safe.push(c),
        }
    }
    safe
}

/// The page: the summary, how the run was made, the criterion, and a table
/// with one row per pair.
pub fn html(rows: &[Row], run: &RunDescription) -> String {
    let mut page = String::new();
    let _ = write!(
        page,
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>Look-alike: {}</title>\n\
         <style>\nbody {{ font-family: sans-serif; margin: 1.5em; }}\ntable {{ border-collapse: collapse; }}\n\
         td, th {{ border: 1px solid #ccc; padding: 4px 8px; vertical-align: top; text-align: left; }}\n\
         td.same {{ background: #dfd; }} td.different {{ background: #fdd; }} td.failed {{ background: #eee; }}\n\
         img {{ display: block; }}\n.error {{ max-width: 30em; font-family: monospace; white-space: pre-wrap; }}\n</style>\n</head>\n<body>\n",
        escape(&summary(rows))
    );
    let _ = write!(
        page,
        "<h1>{}</h1>\n<p>Pairs from <code>{}</code>, rendered {} px wide at {} spp ({}). \
         Look the same: both images box-resampled to {LOOKALIKE_WIDTH} px wide at the reference's aspect, \
         mean absolute 8-bit channel difference &le; {MEAN_LIMIT} and 95th percentile of the per-pixel largest \
         channel difference &le; {P95_LIMIT}. The error map is FLIP (67 pixels per degree) of ours against theirs \
         resampled to our size, in magma (black: none, yellow: most).</p>\n",
        escape(&summary(rows)),
        escape(&run.pairs_file),
        run.width,
        run.spp,
        escape(&run.settings)
    );
    page.push_str(&by_renderer(rows));
    page.push_str(
        "<table>\n<tr><th>pair</th><th>ours</th><th>theirs</th><th>error map</th><th>mean</th><th>p95</th>\
         <th>verdict</th><th>FLIP</th><th>seconds</th><th>dialect</th><th>look</th></tr>\n",
    );
    // Grouped by renderer (folder), in the files' order within each.
    let mut grouped: Vec<&Row> = rows.iter().collect();
    grouped.sort_by(|a, b| a.pair.folder.cmp(&b.pair.folder));
    for row in grouped {
        let pair = &row.pair;
        let image = |kind: &str| {
            format!(
                "<img src=\"images/{}.{kind}.png\" alt=\"{kind}\">",
                escape(&row.slug)
            )
        };
        let _ = write!(
            page,
            "<tr><td>{}<br><code>{}</code><br><code>{}</code><br>{} ({}x{})</td>",
            escape(&pair.folder),
            escape(&pair.scene),
            escape(&pair.render),
            pair.confidence.name(),
            pair.pixels.0,
            pair.pixels.1
        );
        let theirs = if row.has_theirs {
            image("theirs")
        } else {
            String::new()
        };
        match &row.outcome {
            Ok(f) => {
                let aspect = if f.aspect_differs {
                    "<br>aspect ratios differ"
                } else {
                    ""
                };
                let _ = write!(
                    page,
                    "<td>{}</td><td>{theirs}</td><td>{}</td><td>{:.1}</td><td>{:.1}</td><td class=\"{}\">{}{aspect}</td><td>{:.4}</td>",
                    image("ours"),
                    image("diff"),
                    f.mean,
                    f.p95,
                    row.verdict(),
                    row.verdict(),
                    f.flip
                );
            }
            Err(error) => {
                let _ = write!(
                    page,
                    "<td class=\"error\">{}</td><td>{theirs}</td><td></td><td></td><td></td><td class=\"failed\">failed</td><td></td>",
                    escape(error)
                );
            }
        }
        let _ = writeln!(
            page,
            "<td>{:.1}</td><td>{}</td><td>{}</td></tr>",
            row.seconds,
            escape(row.dialect.as_deref().unwrap_or("")),
            escape(row.look.as_deref().unwrap_or(""))
        );
    }
    page.push_str("</table>\n</body>\n</html>\n");
    page
}

/// A table of each renderer (folder) and pairs file: how many of its `ok`
/// pairs look the same, and the looks they were rendered in.
fn by_renderer(rows: &[Row]) -> String {
    let mut keys: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r.pair.folder.as_str(), r.source.as_str()))
        .collect();
    keys.sort();
    keys.dedup();
    let mut table = String::from(
        "<table>\n<tr><th>renderer (folder)</th><th>pairs file</th><th>ok pairs the same</th><th>looks</th></tr>\n",
    );
    for (folder, source) in keys {
        let of: Vec<&Row> = rows
            .iter()
            .filter(|r| r.pair.folder == folder && r.source == source)
            .filter(|r| r.pair.confidence == Confidence::Ok)
            .collect();
        let same = of.iter().filter(|r| r.looks_the_same()).count();
        let mut looks: Vec<&str> = of.iter().filter_map(|r| r.look.as_deref()).collect();
        looks.sort();
        looks.dedup();
        let _ = writeln!(
            table,
            "<tr><td>{}</td><td>{}</td><td>{same} of {}</td><td>{}</td></tr>",
            escape(folder),
            escape(source),
            of.len(),
            escape(&looks.join(", "))
        );
    }
    table.push_str("</table>\n<p></p>\n");
    table
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(confidence: Confidence, outcome: Result<Figures, String>) -> Row {
        Row {
            source: "pairs.tsv".to_string(),
            pair: Pair {
                folder: "repo/a+b".to_string(),
                base: ".".to_string(),
                scene: "t/x.txt".to_string(),
                render: "r/x.png".to_string(),
                pixels: (200, 100),
                confidence,
            },
            slug: "repo-a-b__x".to_string(),
            dialect: Some("pa1".to_string()),
            look: Some("pa1".to_string()),
            seconds: 1.25,
            has_theirs: true,
            outcome,
        }
    }

    fn figures(same: bool) -> Figures {
        Figures {
            mean: if same { 1.0 } else { 9.0 },
            p95: 3.0,
            same,
            flip: 0.1,
            aspect_differs: false,
            width: 160,
            height: 80,
        }
    }

    #[test]
    fn the_summary_counts_ok_pairs_doubtful_ones_and_failures() {
        let rows = [
            row(Confidence::Ok, Ok(figures(true))),
            row(Confidence::Ok, Ok(figures(false))),
            row(Confidence::Ok, Err("texture missing".to_string())),
        ];
        assert_eq!(summary(&rows), "1 of 3 ok pairs look the same (1 failed)");
        let mut with_doubt = rows.to_vec();
        with_doubt.push(row(Confidence::Doubt, Ok(figures(true))));
        assert_eq!(
            summary(&with_doubt),
            "1 of 3 ok pairs look the same, 1 of 1 doubtful pairs (1 failed)"
        );
    }

    #[test]
    fn pairs_of_several_files_are_summed_up_file_by_file() {
        let mut oracle = row(Confidence::Ok, Ok(figures(false)));
        oracle.source = "oracle-pairs.tsv".to_string();
        let rows = [row(Confidence::Ok, Ok(figures(true))), oracle];
        assert_eq!(
            summary(&rows),
            "pairs.tsv: 1 of 1 ok pairs look the same; oracle-pairs.tsv: 0 of 1 ok pairs look the same"
        );
    }

    #[test]
    fn csv_has_one_line_per_row_with_every_column_and_quotes_what_needs_it() {
        let rows = [
            row(Confidence::Ok, Ok(figures(true))),
            row(Confidence::Doubt, Err("x.txt:3:4: \"a\", b".to_string())),
        ];
        let text = csv(&rows);
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 3);
        let columns = lines[0].split(',').count();
        assert_eq!(lines[1].split(',').count(), columns);
        assert!(lines[1].contains(",160,80,200x100,1.25,1.000,3.000,same,0.10000,false,"));
        assert!(
            lines[2].ends_with(",failed,,,\"x.txt:3:4: \"\"a\"\", b\",pairs.tsv"),
            "{}",
            lines[2]
        );
    }

    #[test]
    fn the_page_has_a_row_per_pair_and_escapes_text() {
        let rows = [
            row(Confidence::Ok, Ok(figures(false))),
            row(Confidence::Ok, Err("<missing> & gone".to_string())),
        ];
        let run = RunDescription {
            pairs_file: "pairs.tsv".to_string(),
            width: 160,
            spp: 64,
            settings: "path".to_string(),
        };
        let page = html(&rows, &run);
        // One row per pair, and one for the renderer in the table by renderer.
        assert_eq!(page.matches("<tr><td>repo/a+b<br>").count(), 2);
        assert!(page.contains("<tr><td>repo/a+b</td><td>pairs.tsv</td><td>0 of 2</td>"));
        assert!(page.contains("images/repo-a-b__x.ours.png"));
        assert!(page.contains("images/repo-a-b__x.diff.png"));
        assert!(page.contains("&lt;missing&gt; &amp; gone"));
        assert!(!page.contains("<missing>"));
        assert!(page.contains("0 of 2 ok pairs look the same (1 failed)"));
    }
}
