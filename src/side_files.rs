//! Names of the files written beside an output: its checkpoint
//! (`IMAGE.checkpoint.exr`) and its sidecar (`IMAGE.json`).
//!
//! The name is the output's name plus a suffix when that fits a file name
//! ([`MAX_FILE_NAME_BYTES`]); otherwise the output's name is cut and the
//! FNV-1a hash of the whole name (16 hex digits) stands before the suffix,
//! so a name always fits and two long outputs in one folder still have
//! side files of their own. The name depends on the output's path alone:
//! `render --resume` finds the checkpoint a stopped render wrote.

use std::ffi::OsString;
use std::path::{Path, PathBuf};

use crate::limits::MAX_FILE_NAME_BYTES;

/// `output` with `suffix` added to its file name, cut as above to fit.
pub fn side_file_path(output: &Path, suffix: &str) -> PathBuf {
    let name = output.file_name().unwrap_or_default();
    let mut natural = name.to_os_string();
    natural.push(suffix);
    if natural.len() <= MAX_FILE_NAME_BYTES {
        return output.with_file_name(natural);
    }
    let hash = crate::scene::fnv1a(name.as_encoded_bytes());
    let mark = format!("-{hash:016x}{suffix}");
    let text = name.to_string_lossy();
    let mut cut = MAX_FILE_NAME_BYTES
        .saturating_sub(mark.len())
        .min(text.len());
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let mut short = OsString::from(&text[..cut]);
    short.push(mark);
    output.with_file_name(short)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn short_names_get_the_suffix_and_long_ones_a_hash_that_fits() {
        let short = side_file_path(Path::new("out/a.exr"), ".json");
        assert_eq!(short, Path::new("out/a.exr.json"));
        for length in [240, 241, 250, 255] {
            let long = format!("{}.png", "é".repeat((length - 4) / 2)) + &"x".repeat(length % 2);
            let side = side_file_path(&Path::new("out").join(&long), ".checkpoint.exr");
            let name = side.file_name().unwrap().to_str().unwrap();
            assert!(
                name.len() <= MAX_FILE_NAME_BYTES,
                "{length}: {}",
                name.len()
            );
            assert!(name.ends_with(".checkpoint.exr"), "{name}");
            assert_eq!(side.parent(), Some(Path::new("out")));
        }
        let one = side_file_path(Path::new(&"a".repeat(250)), ".json");
        let other = side_file_path(Path::new(&format!("{}b", "a".repeat(249))), ".json");
        assert_ne!(one, other);
    }
}
