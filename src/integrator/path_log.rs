//! What one path did, vertex by vertex, for `render --debug-sample x,y,i`
//! (pbrt-v4's `--debugstart`): the integrators report their vertices, the
//! lobes they scatter by and every term they add to the sample's radiance
//! to a [`PathLog`]. A render uses [`Silent`], whose calls compile to
//! nothing (the events are closures that are never called), so the image
//! and the speed are those of an integrator without a log; one re-traced
//! sample uses a [`PathRecord`].

use std::fmt;

use crate::bsdf::{BsdfFlags, LobeSet};
use crate::color::Color;
use crate::math::{Point3, Vec3};

/// Where an integrator reports what its path does.
pub trait PathLog {
    /// Records the event `event` makes (only called when the log keeps it).
    fn record(&mut self, event: impl FnOnce() -> PathEvent);
}

/// The log of a render: keeps nothing, costs nothing.
pub struct Silent;

impl PathLog for Silent {
    #[inline(always)]
    fn record(&mut self, _event: impl FnOnce() -> PathEvent) {}
}

/// The log of one re-traced sample: every event, in order.
#[derive(Clone, Debug, Default)]
pub struct PathRecord {
    pub events: Vec<PathEvent>,
}

impl PathLog for PathRecord {
    fn record(&mut self, event: impl FnOnce() -> PathEvent) {
        self.events.push(event());
    }
}

impl PathRecord {
    /// The sum of the terms the path added, in the order it added them:
    /// the sample's radiance.
    pub fn total(&self) -> Color {
        let mut total = Color::BLACK;
        for event in &self.events {
            if let PathEvent::Added { value, .. } = event {
                total += *value;
            }
        }
        total
    }
}

/// A term of a sample's radiance.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Term {
    /// Emission of the surface the ray found.
    Emission,
    /// What a ray that found nothing adds (the look's rule).
    Background,
    /// The PA1 point and directional lights (and spot lights) at a vertex.
    DirectLights,
    /// A light sample (next-event estimation), MIS-weighted.
    LightSample,
    /// The light sample of the last vertex, counted alone.
    LastLightSample,
    /// Emission the split bounce's probes found (see `split`).
    SplitChain,
    /// A connection to the light subpath's vertex (see `caustics`).
    Connection,
    /// The whole estimate of an integrator that records no vertices
    /// (ray casting, paths through media).
    Estimate,
}

/// One thing a path did.
#[derive(Clone, Debug)]
pub enum PathEvent {
    /// Hit `depth` of the path (1: the camera ray's) is on a surface of
    /// `material` at `point` (shading normal `normal`). The other events
    /// name the hit they happen at the same way (a ray that finds nothing:
    /// the hit it would have been).
    Hit {
        depth: u32,
        point: Point3,
        normal: Vec3,
        material: usize,
        /// The material's lobes and their weights.
        lobes: Box<LobeSet>,
    },
    /// The path added `value` (throughput included) to the sample.
    Added {
        depth: u32,
        term: Term,
        /// The MIS weight, where the term has one.
        mis_weight: Option<f64>,
        value: Color,
    },
    /// The BSDF at vertex `depth` sent the path on.
    Scattered {
        depth: u32,
        wi: Vec3,
        /// `f |cos| / pdf`, with the lobe choice.
        weight: Color,
        pdf: f64,
        /// The kind of the lobe it chose.
        flags: BsdfFlags,
        /// The throughput after this vertex.
        throughput: Color,
    },
    /// Russian roulette kept the path with this probability.
    Survived { depth: u32, probability: f64 },
    /// The path ended.
    Ended { depth: u32, why: &'static str },
}

impl fmt::Display for PathEvent {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            PathEvent::Hit {
                depth,
                point,
                normal,
                material,
                lobes,
            } => {
                write!(
                    f,
                    "hit {depth}: point ({}), normal ({}), material {material}, lobes:",
                    vector(point.x, point.y, point.z),
                    vector(normal.x, normal.y, normal.z)
                )?;
                if lobes.is_empty() {
                    write!(f, " none")?;
                }
                for (lobe, weight) in lobes.weighted() {
                    write!(f, "\n    {weight:.6} x {lobe:?}")?;
                }
                Ok(())
            }
            PathEvent::Added {
                depth,
                term,
                mis_weight,
                value,
            } => {
                write!(f, "  + {} at {depth}: {term:?}", color(value))?;
                if let Some(w) = mis_weight {
                    write!(f, " (MIS weight {w:.6})")?;
                }
                Ok(())
            }
            PathEvent::Scattered {
                depth,
                wi,
                weight,
                pdf,
                flags,
                throughput,
            } => write!(
                f,
                "  scattered at {depth}: {} wi ({}), weight {}, pdf {pdf:.6}, throughput {}",
                kinds(*flags),
                vector(wi.x, wi.y, wi.z),
                color(weight),
                color(throughput)
            ),
            PathEvent::Survived { depth, probability } => {
                write!(
                    f,
                    "  roulette at {depth}: survived, probability {probability:.6}"
                )
            }
            PathEvent::Ended { depth, why } => write!(f, "ended at {depth}: {why}"),
        }
    }
}

/// The names of the kinds in `flags`.
fn kinds(flags: BsdfFlags) -> String {
    let names = [
        (BsdfFlags::SPECULAR, "specular (delta)"),
        (BsdfFlags::DIFFUSE, "diffuse"),
        (BsdfFlags::GLOSSY, "glossy"),
        (BsdfFlags::REFLECTION, "reflection"),
        (BsdfFlags::TRANSMISSION, "transmission"),
        (BsdfFlags::NONRECIPROCAL, "non-reciprocal"),
    ];
    let named: Vec<&str> = names
        .iter()
        .filter(|(kind, _)| flags.contains(*kind))
        .map(|(_, name)| *name)
        .collect();
    named.join(" ")
}

fn vector(x: f64, y: f64, z: f64) -> String {
    format!("{x:.6}, {y:.6}, {z:.6}")
}

/// A colour with all the digits that tell two values apart.
pub fn color(c: &Color) -> String {
    format!("{:e} {:e} {:e}", c.r, c.g, c.b)
}
