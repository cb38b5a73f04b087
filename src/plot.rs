//! Error-against-time curves as SVG on log-log axes (no plotting dependency:
//! a few lines, circles and labels).

use std::fmt::Write;

/// One curve: a name and (x, y) points with x, y > 0.
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
}

const WIDTH: f64 = 720.0;
const HEIGHT: f64 = 480.0;
const LEFT: f64 = 80.0;
const RIGHT: f64 = 190.0;
const TOP: f64 = 40.0;
const BOTTOM: f64 = 60.0;
const COLORS: [&str; 6] = [
    "#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b",
];

/// Draws the series on log-log axes. Points with a non-positive or
/// non-finite coordinate are left out.
pub fn log_log_svg(title: &str, x_label: &str, y_label: &str, series: &[Series]) -> String {
    let points = || {
        series
            .iter()
            .flat_map(|s| s.points.iter())
            .filter(|(x, y)| usable(*x) && usable(*y))
    };
    let (mut x_min, mut x_max, mut y_min, mut y_max) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
    for &(x, y) in points() {
        x_min = x_min.min(x.log10());
        x_max = x_max.max(x.log10());
        y_min = y_min.min(y.log10());
        y_max = y_max.max(y.log10());
    }
    if x_min > x_max {
        (x_min, x_max, y_min, y_max) = (0.0, 1.0, 0.0, 1.0);
    }
    let (x_lo, x_hi) = (x_min.floor(), x_max.ceil().max(x_min.floor() + 1.0));
    let (y_lo, y_hi) = (y_min.floor(), y_max.ceil().max(y_min.floor() + 1.0));
    let plot_w = WIDTH - LEFT - RIGHT;
    let plot_h = HEIGHT - TOP - BOTTOM;
    let sx = |x: f64| LEFT + (x.log10() - x_lo) / (x_hi - x_lo) * plot_w;
    let sy = |y: f64| TOP + (y_hi - y.log10()) / (y_hi - y_lo) * plot_h;

    let mut svg = String::new();
    let _ = writeln!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{WIDTH}" height="{HEIGHT}" font-family="sans-serif" font-size="12">"#
    );
    let _ = writeln!(svg, r#"<rect width="100%" height="100%" fill="white"/>"#);
    let _ = writeln!(
        svg,
        r#"<text x="{}" y="22" text-anchor="middle" font-size="15">{}</text>"#,
        LEFT + plot_w / 2.0,
        escape(title)
    );
    for decade in (x_lo as i32)..=(x_hi as i32) {
        let x = sx(10f64.powi(decade));
        let _ = writeln!(
            svg,
            r##"<line x1="{x:.1}" y1="{TOP}" x2="{x:.1}" y2="{:.1}" stroke="#ddd"/><text x="{x:.1}" y="{:.1}" text-anchor="middle">1e{decade}</text>"##,
            TOP + plot_h,
            TOP + plot_h + 18.0
        );
    }
    for decade in (y_lo as i32)..=(y_hi as i32) {
        let y = sy(10f64.powi(decade));
        let _ = writeln!(
            svg,
            r##"<line x1="{LEFT}" y1="{y:.1}" x2="{:.1}" y2="{y:.1}" stroke="#ddd"/><text x="{:.1}" y="{:.1}" text-anchor="end">1e{decade}</text>"##,
            LEFT + plot_w,
            LEFT - 6.0,
            y + 4.0
        );
    }
    let _ = writeln!(
        svg,
        r#"<rect x="{LEFT}" y="{TOP}" width="{plot_w}" height="{plot_h}" fill="none" stroke="black"/>"#
    );
    let _ = writeln!(
        svg,
        r#"<text x="{:.1}" y="{:.1}" text-anchor="middle">{}</text>"#,
        LEFT + plot_w / 2.0,
        HEIGHT - 15.0,
        escape(x_label)
    );
    let _ = writeln!(
        svg,
        r#"<text x="18" y="{:.1}" text-anchor="middle" transform="rotate(-90 18 {:.1})">{}</text>"#,
        TOP + plot_h / 2.0,
        TOP + plot_h / 2.0,
        escape(y_label)
    );
    for (i, s) in series.iter().enumerate() {
        let color = COLORS[i % COLORS.len()];
        let pts: Vec<String> = s
            .points
            .iter()
            .filter(|(x, y)| usable(*x) && usable(*y))
            .map(|&(x, y)| format!("{:.1},{:.1}", sx(x), sy(y)))
            .collect();
        let _ = writeln!(
            svg,
            r#"<polyline points="{}" fill="none" stroke="{color}" stroke-width="2"/>"#,
            pts.join(" ")
        );
        for p in &pts {
            let (x, y) = p.split_once(',').unwrap_or(("0", "0"));
            let _ = writeln!(svg, r#"<circle cx="{x}" cy="{y}" r="3" fill="{color}"/>"#);
        }
        let ly = TOP + 10.0 + 20.0 * i as f64;
        let lx = LEFT + plot_w + 12.0;
        let _ = writeln!(
            svg,
            r#"<line x1="{lx}" y1="{ly}" x2="{}" y2="{ly}" stroke="{color}" stroke-width="2"/><text x="{}" y="{}">{}</text>"#,
            lx + 20.0,
            lx + 26.0,
            ly + 4.0,
            escape(&s.name)
        );
    }
    svg.push_str("</svg>\n");
    svg
}

/// Checks that every series has a point to draw (positive and finite on
/// both axes): an empty or all-NaN curve is an error, not an empty plot.
pub fn check_plottable(series: &[Series]) -> Result<(), String> {
    if series.is_empty() {
        return Err("no curves to plot".to_string());
    }
    for s in series {
        let drawn = s
            .points
            .iter()
            .filter(|(x, y)| usable(*x) && usable(*y))
            .count();
        if drawn == 0 {
            return Err(format!(
                "curve '{}' has no point to plot ({} rows, none with positive finite values on \
                 both axes)",
                s.name,
                s.points.len()
            ));
        }
    }
    Ok(())
}

fn usable(v: f64) -> bool {
    v.is_finite() && v > 0.0
}

fn escape(text: &str) -> String {
    text.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn points_land_inside_the_frame_and_bad_points_are_dropped() {
        let series = [Series {
            name: "a<b".into(),
            points: vec![
                (0.5, 1e-2),
                (2.0, 3e-3),
                (-1.0, 1.0),
                (8.0, f64::NAN),
                (30.0, 4e-4),
            ],
        }];
        let svg = log_log_svg("t", "seconds", "relMSE", &series);
        assert!(svg.contains("a&lt;b"));
        assert_eq!(svg.matches("<circle").count(), 3);
        for circle in svg.split("<circle").skip(1) {
            let value = |key: &str| -> f64 {
                let start = circle.find(key).unwrap() + key.len() + 2;
                let end = start + circle[start..].find('"').unwrap();
                circle[start..end].parse().unwrap()
            };
            let (x, y) = (value("cx"), value("cy"));
            assert!((LEFT..=WIDTH - RIGHT).contains(&x), "{x}");
            assert!((TOP..=HEIGHT - BOTTOM).contains(&y), "{y}");
        }
    }
}
