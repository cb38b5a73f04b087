//! Stochastic progressive photon mapping (Hachisuka and Jensen 2009):
//! passes of
//!
//! 1. a camera pass: each pixel's camera ray, through mirrors and glass, to
//!    a visible point where a continuous lobe is chosen (`visible_point`),
//!    adding the light found on the way and one light sample there;
//! 2. a hashed grid of the visible points, rebuilt per pass (`grid`);
//! 3. a photon pass: photons from the emitters, scattered by the BSDF
//!    contract (`photon`), each gathered by the visible points within their
//!    pixel's radius, as `f(wo, wi)` times its power (`pixel::Gathered`);
//! 4. each pixel's radius and flux update (`pixel`).
//!
//! The image converges to the path integrator's (the same paths, the same
//! depth limit), and it finds caustics seen through glass that the path
//! integrator hardly does. Deterministic for any thread count: pixel `p`'s
//! camera ray of pass `k` draws its numbers from (`p`, `k`, seed), photon
//! `i` of pass `k` from (`k`, `i`, seed), and gathered flux is summed in
//! fixed point. The render driver, with the parallel loops of a pass, is
//! `photon_passes` in `src/render/`.
//!
//! Not here (the render command says so): checkpoints and resuming, render
//! jobs, adaptive stopping, media, dispersion (one index), Cambrian's
//! wavelengths, light from emitters that light sampling cannot pick
//! (planes, surfaces of revolution), which is seen directly only.

pub mod grid;
pub mod options;
pub mod photon;
pub mod pixel;
pub mod visible_point;

pub use options::PhotonSettings;
