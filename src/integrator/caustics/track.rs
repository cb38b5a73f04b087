//! The path tracer's side of a caustic connection (see the module above):
//! the last Lambert vertex `y` a path found by a bounce from a Lambert
//! vertex `x` (or by the camera ray), the density of the step that found
//! it, and the mirror and glass vertices since, from which the emission
//! the path finds is weighted against light tracing and the connections.

use crate::math::{Point3, Ray, Vec3};
use crate::render_scene::RenderScene;
use crate::shading::Shading;

use crate::integrator::CameraSample;

/// The path tracer's side of a caustic connection: the last Lambert vertex
/// `y` that a bounce from a Lambert vertex `x` found, and the specular
/// vertices since.
#[derive(Clone, Copy)]
pub(crate) struct CausticTrack {
    /// The path tracer's density of the step that found `y`.
    pub edge: Edge,
    /// Shading-normal correction of `y` for the direction it was left in.
    pub shading_ratio: f64,
    /// Mirror and glass vertices after `y`.
    pub chain: u32,
}

/// The `edge` of a caustic track (see `caustics`).
#[derive(Clone, Copy)]
pub(crate) enum Edge {
    /// `(cos_x / pi) (cos_y / d^2)` of a bounce from a Lambert `x`.
    Bounce(f64),
    /// The camera ray found `y` (at `point`, geometric `normal` facing the
    /// camera): computed when needed, which is rarely.
    Camera { point: Point3, normal: Vec3 },
}

impl Edge {
    pub fn density(&self, scene: &RenderScene, sample: &CameraSample) -> Option<f64> {
        match *self {
            Edge::Bounce(density) => Some(density),
            Edge::Camera { point, normal } => super::camera_edge(scene, sample, &point, &normal),
        }
    }
}

/// The caustic track of a diffuse vertex `at` (as `y`) reached by `ray` from
/// the diffuse vertex at `from_point` (as `x`, the ray's direction of
/// density `from_pdf` there) and left in `direction`; `None` where
/// a caustic connection could not make the path.
pub(crate) fn caustic_track(
    from_point: &Point3,
    from_pdf: f64,
    at: &Shading,
    ray: &Ray,
    direction: &Vec3,
) -> Option<CausticTrack> {
    let distance_squared = (from_point - at.point).norm_squared();
    let edge = super::edge_density(
        from_pdf,
        at.geometric.dot(&-ray.direction),
        distance_squared,
    )?;
    Some(CausticTrack {
        edge: Edge::Bounce(edge),
        shading_ratio: shading_ratio(at, direction)?,
        chain: 0,
    })
}

/// The caustic track of the camera ray's first vertex `at` (as `y`), left
/// in `direction`; `None` where light tracing could not make the path.
pub(crate) fn camera_track(at: &Shading, direction: &Vec3) -> Option<CausticTrack> {
    Some(CausticTrack {
        edge: Edge::Camera {
            point: at.point,
            normal: at.geometric,
        },
        shading_ratio: shading_ratio(at, direction)?,
        chain: 0,
    })
}

/// `cos_shading / cos_geometric` of a direction leaving `at` on the side of
/// its oriented normals; `None` on the other side.
fn shading_ratio(at: &Shading, direction: &Vec3) -> Option<f64> {
    let geometric = at.geometric.dot(direction);
    let ratio = at.normal.dot(direction) / geometric;
    (geometric > 0.0 && ratio > 0.0 && ratio.is_finite()).then_some(ratio)
}

pub(crate) fn count_chain_vertex(track: &mut Option<CausticTrack>) {
    if let Some(track) = track {
        track.chain += 1;
    }
}
