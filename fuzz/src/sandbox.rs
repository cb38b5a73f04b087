//! The one folder a fuzzed input may read files from, and the screening of
//! inputs whose file names could point anywhere else.
//!
//! Scene files resolve relative names against `--base`, the scene's folder
//! and the working directory (`scene::build::paths`); OBJ files name their
//! `.mtl` libraries and those their images. A fuzz target makes all three
//! folders the sandbox (it changes the working directory into it), fills it
//! with the few small assets it wants reachable, and skips inputs that could
//! name a file outside: an absolute path, a `..` next to a `/`, a backslash.

use std::path::{Path, PathBuf};

/// A fresh folder below the temporary directory, for one fuzzing process.
pub struct Sandbox {
    pub folder: PathBuf,
}

impl Sandbox {
    /// Creates the folder (emptied first) and makes it the working directory,
    /// after removing the folders of this target's processes that have ended
    /// (libFuzzer's `-fork` starts one process per job). The fuzzer must be
    /// started by an absolute path: `-fork` restarts it by its `argv[0]`.
    pub fn enter(target: &str) -> Sandbox {
        let prefix = format!("pathtracer-fuzz-{target}-");
        remove_ended(&prefix);
        let folder = std::env::temp_dir().join(format!("{prefix}{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&folder);
        if let Err(error) = std::fs::create_dir_all(&folder) {
            eprintln!("cannot create {}: {error}", folder.display());
            std::process::exit(2);
        }
        if let Err(error) = std::env::set_current_dir(&folder) {
            eprintln!("cannot enter {}: {error}", folder.display());
            std::process::exit(2);
        }
        Sandbox { folder }
    }

    /// Copies `source` (relative to the repository) to `name` in the sandbox;
    /// a missing source is left out with a note.
    pub fn copy_asset(&self, source: &str, name: &str) {
        let from = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("..")
            .join(source);
        let to = self.folder.join(name);
        if let Some(parent) = to.parent() {
            let _ = std::fs::create_dir_all(parent);
        }
        if std::fs::copy(&from, &to).is_err() {
            eprintln!("note: {} not copied into the sandbox", from.display());
        }
    }

    /// Writes `bytes` to `name` in the sandbox; false when that fails.
    pub fn write(&self, name: &str, bytes: &[u8]) -> bool {
        std::fs::write(self.folder.join(name), bytes).is_ok()
    }

    /// The path of `name` in the sandbox.
    pub fn path(&self, name: &str) -> PathBuf {
        self.folder.join(name)
    }
}

/// Removes the sandboxes named `prefix<pid>` whose process is gone.
fn remove_ended(prefix: &str) {
    let Ok(entries) = std::fs::read_dir(std::env::temp_dir()) else {
        return;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(pid) = name.strip_prefix(prefix) else {
            continue;
        };
        if pid.parse::<u32>().is_ok() && !Path::new("/proc").join(pid).exists() {
            let _ = std::fs::remove_dir_all(entry.path());
        }
    }
}

/// True when every `/` in `bytes` follows a byte that can end a relative
/// path component (letters, digits, `_`, `-`, `.`), no `..` touches a `/`
/// and there is no backslash: whatever the parser reads as a file name then
/// stays inside the folder it is resolved against (a lone `..` is a folder,
/// which no reader opens).
pub fn names_stay_inside(bytes: &[u8]) -> bool {
    let parent = |three: &[u8]| three == b"../" || three == b"/..";
    if bytes.windows(3).any(parent) || bytes.contains(&b'\\') {
        return false;
    }
    bytes.iter().enumerate().all(|(index, &byte)| {
        byte != b'/'
            || index
                .checked_sub(1)
                .and_then(|before| bytes.get(before))
                .is_some_and(|&b| b.is_ascii_alphanumeric() || matches!(b, b'_' | b'-' | b'.'))
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_names_pass_and_escapes_do_not() {
        assert!(names_stay_inside(b"obj_file mesh/torus.obj"));
        assert!(!names_stay_inside(b"obj_file /etc/passwd"));
        assert!(!names_stay_inside(b"texture \"/dev/zero\""));
        assert!(!names_stay_inside(b"obj_file mesh/../../x"));
        assert!(!names_stay_inside(b"obj_file a\\b"));
        assert!(!names_stay_inside(b"/x"));
        assert!(!names_stay_inside(b"texture ../x"));
        assert!(names_stay_inside(b"# and so on... texture .."));
    }
}
