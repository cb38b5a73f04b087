//! Which estimator renders an image: each look's own (see `Look`), or the
//! one `--integrator` chooses. The estimators themselves are in
//! `crate::integrator`.

/// An estimator of the radiance along camera rays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Integrator {
    /// The original renderer's estimator: path tracing by BSDF sampling
    /// alone, one lobe chosen per vertex (see docs/original-renderer.md);
    /// the estimator of looks whose conventions next-event estimation
    /// cannot reproduce (rays that re-hit the surface they leave).
    Original,
    /// Path tracing with next-event estimation and multiple importance
    /// sampling at diffuse vertices: the original's expected image with
    /// less noise (see `integrator::path`).
    #[default]
    Path,
    /// The course framework's ray casting: at the first hit, for every point
    /// and directional light, `kd max(0, n.l) + ks max(0, v.r)^shininess`,
    /// no shadows, nothing else (the PA1 look's).
    RayCast,
    /// Whitted-style ray tracing with shadow rays: Phong per light where a
    /// shadow ray reaches it (the background colour where none does), the
    /// mirror and refracted rays by the material's fixed weights (jefflyy's;
    /// see `integrator::whitted`).
    Whitted,
    /// Whitted-style ray tracing without shadow rays, the mirror ray by
    /// Schlick's weight times `specularColor` and the refracted ray by the
    /// rest, at index 1 (emily-jia's; see `integrator::whitted`).
    WhittedUnshadowed,
    /// CaveSpiderLZJ's path tracer (the `cav` look), with its hit normals
    /// as its code leaves them: a triangle's winding normal, a transformed
    /// shape's normal not normalised, mirror rays not normalised (see
    /// `integrator::cav`).
    Cav,
    /// 1rubbishyuan's recursive estimator with its ad-hoc factors (direct
    /// light x1500, the diffuse bounce x1000, both over the depth, clamps
    /// per term, death with probability 0.2 at every call, never
    /// reweighted; see `integrator::rub`).
    Rub,
    /// Stochastic progressive photon mapping (see `integrator::sppm`):
    /// passes of visible points and photons, rendered by `sppm::render`.
    Sppm,
}

impl Integrator {
    pub const ALL: [Integrator; 8] = [
        Integrator::Path,
        Integrator::Original,
        Integrator::RayCast,
        Integrator::Sppm,
        Integrator::Whitted,
        Integrator::WhittedUnshadowed,
        Integrator::Rub,
        Integrator::Cav,
    ];

    /// Whether it draws no random numbers: one camera ray through a fixed
    /// point of each pixel gives the whole image.
    pub fn is_deterministic(self) -> bool {
        matches!(
            self,
            Integrator::RayCast | Integrator::Whitted | Integrator::WhittedUnshadowed
        )
    }

    /// The command-line name.
    pub fn name(self) -> &'static str {
        match self {
            Integrator::Original => "original",
            Integrator::Path => "path",
            Integrator::RayCast => "raycast",
            Integrator::Whitted => "whitted",
            Integrator::WhittedUnshadowed => "whitted-unshadowed",
            Integrator::Rub => "rub",
            Integrator::Cav => "cav",
            Integrator::Sppm => "sppm",
        }
    }

    /// Parses a command-line name, as returned by [`Integrator::name`].
    pub fn from_name(name: &str) -> Option<Integrator> {
        Integrator::ALL.into_iter().find(|i| i.name() == name)
    }
}
