//! The profile curve of a `RevSurface`: its control points, their limit, and
//! the warnings for profiles that sweep no area or have a span that is a point.

use crate::geometry::{CurveKind, Profile};
use crate::limits::MAX_CONTROL_POINTS;
use crate::limits::shown;
use crate::scene::ast::{Block, ItemKind};
use crate::scene::build::Context;
use crate::scene::error::{Location, SceneError};

/// `BezierCurve { controls [x y z]* }` or `BsplineCurve { ... }`. `None`
/// (with a warning) for a profile that sweeps no area: all its controls at
/// one point, or all on the axis.
pub fn read_profile(
    context: &mut Context,
    curve: &Block,
    location: Location,
) -> Result<Option<Profile>, SceneError> {
    let kind = match curve.name.as_str() {
        "BezierCurve" => CurveKind::Bezier,
        "BsplineCurve" => CurveKind::Bspline,
        other => {
            return Err(context.error(
                location,
                format!("unknown profile curve '{}'", shown(other)),
            ));
        }
    };
    let mut controls = Vec::new();
    let mut locations = Vec::new();
    for item in &curve.items {
        match &item.kind {
            ItemKind::List(point) => match &point[..] {
                [x, y, ..] if x.is_finite() && y.is_finite() => {
                    if controls.len() == MAX_CONTROL_POINTS {
                        return Err(context.error(
                            item.location,
                            format!(
                                "{} has more than {MAX_CONTROL_POINTS} control points",
                                curve.name
                            ),
                        ));
                    }
                    controls.push([*x, *y]);
                    locations.push(item.location);
                }
                _ => {
                    return Err(
                        context.error(item.location, "a control point needs finite x and y".into())
                    );
                }
            },
            ItemKind::Word(w) if &**w == "controls" || &**w == "num_controls" => {}
            ItemKind::Number(_) => {}
            _ => context.skip_item(item, &curve.name)?,
        }
    }
    let needed = match kind {
        CurveKind::Bezier => 2,
        CurveKind::Bspline => 4,
    };
    if controls.len() < needed {
        return Err(context.error(
            location,
            format!("{} needs at least {needed} control points", curve.name),
        ));
    }
    let first = controls[0];
    if controls.iter().all(|c| *c == first) {
        context.warn(
            location,
            format!(
                "all control points of the {} are equal: the surface has no area and is left out",
                curve.name
            ),
        )?;
        return Ok(None);
    }
    if controls.iter().all(|c| c[0] == 0.0) {
        context.warn(
            location,
            format!(
                "the {} lies on the axis (x = 0): the surface has no area and is left out",
                curve.name
            ),
        )?;
        return Ok(None);
    }
    if kind == CurveKind::Bspline
        && let Some(start) = controls
            .windows(4)
            .position(|w| w.iter().all(|c| *c == w[0]))
    {
        context.warn(
            locations[start],
            format!(
                "control points {} to {} are equal: a span of the B-spline is a single point",
                start + 1,
                start + 4
            ),
        )?;
    }
    Ok(Some(Profile { kind, controls }))
}
