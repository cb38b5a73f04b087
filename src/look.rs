//! Looks: the conventions by which a renderer turns a scene into pixels,
//! as data. A look is chosen per render (`--look NAME`); the rendering
//! follows its row.
//!
//! | look | what it is |
//! |---|---|
//! | `original` | the renderer this project ports (`docs/original-renderer.md`): Schlick's Fresnel term for glass |
//! | `physical` | the project's physically based rendering of the same scene: exact Fresnel equations |

use crate::bsdf::DielectricFresnel;

/// One look's conventions.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Look {
    pub name: &'static str,
    /// What dielectrics reflect.
    pub fresnel: DielectricFresnel,
}

impl Look {
    pub const ORIGINAL: Look = Look {
        name: "original",
        fresnel: DielectricFresnel::Schlick,
    };

    pub const PHYSICAL: Look = Look {
        name: "physical",
        fresnel: DielectricFresnel::Exact,
    };

    /// Every look, by name.
    pub const ALL: [Look; 2] = [Look::ORIGINAL, Look::PHYSICAL];

    pub fn from_name(name: &str) -> Option<Look> {
        Look::ALL.into_iter().find(|look| look.name == name)
    }
}

impl Default for Look {
    fn default() -> Self {
        Look::ORIGINAL
    }
}
