//! Which look a scene file gets when `--look` does not say: the renderer
//! whose fingerprint the file carries ([`table::FINGERPRINTS`]), or
//! `original` when it carries none. Detection is by evidence only: the
//! dialect the file is written in and words that only that renderer's files
//! use; the render summary and `check` name what was found.

mod table;

use crate::look::Look;
use crate::scene::model::{Dialect, Scene};
pub use table::FINGERPRINTS;

/// What a file must contain, besides its dialect, to carry a fingerprint.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Evidence {
    /// Nothing more: only this renderer's files are written in the dialect
    /// (or the renderer is the dialect's default, see its row).
    Dialect,
    /// At least one of these words, anywhere in the file.
    AnyWord(&'static [&'static str]),
    /// The file lies in a clone of the renderer's repository: a folder on
    /// its path is named `owner+repository` (the layout of
    /// `../shared/reference/coursework/`) or, where the name is the
    /// renderer's alone (`repository_alone`), `repository`. For renderers
    /// whose files are another's, word for word.
    Folder {
        owner: &'static str,
        repository: &'static str,
        repository_alone: bool,
    },
}

/// One renderer's fingerprint: a row of [`FINGERPRINTS`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fingerprint {
    /// The dialects the file may be read in (one of them).
    pub dialects: &'static [Dialect],
    pub evidence: Evidence,
    /// The look the file then renders in.
    pub look: Look,
    /// Whose renderer it is, as `check` and the render summary say it.
    pub says: &'static str,
}

impl Fingerprint {
    /// What of this fingerprint `scene` carries (the dialect's name and the
    /// word found), or `None` when it does not carry it.
    pub fn found_in(&self, scene: &Scene) -> Option<String> {
        if !self.dialects.contains(&scene.dialect) {
            return None;
        }
        let dialect = format!("{} dialect", scene.dialect.name());
        match self.evidence {
            Evidence::Dialect => Some(dialect),
            Evidence::AnyWord(words) => words
                .iter()
                .find(|word| scene.has_word(word))
                .map(|word| format!("{dialect} with '{word}'")),
            Evidence::Folder {
                owner,
                repository,
                repository_alone,
            } => {
                let joined = format!("{owner}+{repository}");
                scene
                    .source
                    .ancestors()
                    .skip(1)
                    .filter_map(|folder| folder.file_name()?.to_str())
                    .any(|name| name == joined || (repository_alone && name == repository))
                    .then(|| format!("{dialect} in a folder of {owner}/{repository}"))
            }
        }
    }
}

/// The look of the renderer that wrote `scene`, and why: the fingerprint
/// found and whose it is.
pub fn detect(scene: &Scene) -> (Look, String) {
    for fingerprint in FINGERPRINTS {
        if let Some(found) = fingerprint.found_in(scene) {
            return (fingerprint.look, format!("{found}: {}", fingerprint.says));
        }
    }
    let why = match scene.dialect {
        Dialect::Canonical => "canonical dialect: no coursework renderer's fingerprint".to_string(),
        other => format!("{} dialect: no look of its own yet", other.name()),
    };
    (Look::ORIGINAL, why)
}
