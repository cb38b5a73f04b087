//! Caustics: light that reaches a diffuse surface through mirrors and glass,
//! found from the light's side.
//!
//! A path tracer finds a caustic only when a diffuse bounce (or the camera
//! ray) happens to aim, through the specular objects, at a small light: rare
//! samples of great weight, the fireflies that dominate the error of the
//! course scenes (a glass ball and a mirror ball under a small light). So
//! each camera sample also traces one light subpath (`light_path`): from a
//! point of an emitter, through mirror and glass vertices only, to the first
//! vertex where the diffuse lobe is chosen, `y`. Then (`connect`)
//!
//! - `y` is connected to the camera (light tracing): its radiance is splatted
//!   onto the pixels around its film position;
//! - every diffuse vertex `x` of the camera path connects to `y` with a
//!   shadow ray.
//!
//! A path `camera [... x] y S1 .. Sm light` (`x`, `y` diffuse, `S` specular)
//! then has two strategies: the path tracer's (the bounce from `y` finds the
//! light) and the connection. They are combined by the power heuristic with
//! the ratio of their densities, which after the shared vertices and the
//! specular chain cancel (the chain's geometry is reciprocal, and both
//! directions at its ends are drawn from known densities) is
//!
//! `r = p_path / p_connection = edge * s_y / e`,
//!
//! where `edge` is the path tracer's density, in area at `y`, of the step
//! that found `y`: `(cos_x / pi) (cos_y / d^2)` from a diffuse `x`, or
//! `f_pixel(p) J(y) / (W H)` from the camera (the pixel filter's density at
//! the film position, the film area per area at `y`, and the number of
//! pixels, since light tracing spends one subpath per camera sample on the
//! whole image); `s_y` is the shading-normal correction of `y` for the
//! chain's direction and `e` the emission density of the light point
//! (`emitters::emission`; directions leave it by the cosine). Both strategies compute `r`
//! from the path alone, so the two weights sum to one for every path they
//! share; paths a connection cannot make (a light that is not sampled, a
//! point outside the sampled cap, a specular `x`) keep weight 1 in the path
//! tracer. Path lengths are the original's: a connection at scattering
//! vertex `k` makes a path with `k + 1 + m` scattering vertices, at most
//! `max_depth`.

mod connect;
mod light_path;
pub(crate) mod track;

use crate::math::Vec3;
use crate::render_scene::RenderScene;
use crate::world::WorldHit;

pub use connect::{camera_edge, connect, edge_density};
pub use light_path::{CausticVertex, trace};

/// The emission density (see the module documentation) of the light point
/// of `hit` for light leaving it in unit `direction`. Directions are
/// cosine-distributed, so it is the density of the point.
pub fn emission_density(scene: &RenderScene, time: f64, hit: &WorldHit, direction: &Vec3) -> f64 {
    scene
        .emitters()
        .emission_point_density(&scene.camera_center(), time, hit, direction)
}

/// `r = p_path / p_connection` (see the module documentation).
fn density_ratio(edge: f64, shading_ratio: f64, emission_density: f64) -> f64 {
    edge * shading_ratio / emission_density
}

/// The connection's MIS weight for a path with density ratio terms as in
/// [`density_ratio`].
fn connection_weight(edge: f64, shading_ratio: f64, emission_density: f64) -> f64 {
    let r2 = density_ratio(edge, shading_ratio, emission_density).powi(2);
    if r2.is_finite() {
        1.0 / (1.0 + r2)
    } else {
        0.0
    }
}

/// The path tracer's MIS weight for a path `... y S1 .. Sm light` that it
/// found by the bounce from `y`: `edge` of the step that found `y` (see the
/// module documentation), `shading_ratio` of `y` for the bounce's
/// direction, and the light point's emission density (0 when light subpaths
/// never start there: weight 1).
pub fn path_weight(edge: f64, shading_ratio: f64, emission_density: f64) -> f64 {
    if emission_density <= 0.0 {
        return 1.0;
    }
    let r2 = density_ratio(edge, shading_ratio, emission_density).powi(2);
    if r2.is_finite() { r2 / (1.0 + r2) } else { 1.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_two_weights_of_a_path_sum_to_one() {
        for (edge, ratio, density) in [(1e-3, 1.0, 0.02), (5.0, 0.8, 1e-4), (1e-9, 1.2, 3.0)] {
            let sum = path_weight(edge, ratio, density) + connection_weight(edge, ratio, density);
            assert!((sum - 1.0).abs() < 1e-12, "{sum}");
        }
        assert_eq!(path_weight(1.0, 1.0, 0.0), 1.0);
    }
}
