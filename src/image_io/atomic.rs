//! Output files reserved before the work that fills them: a temporary sibling
//! is created at once (proving the folder writable and the name acceptable),
//! filled later, and renamed over the target (see `commit`).
//!
//! The temporary `.<name>.pathtracer-tmp-<pid>-<n>` lives in the target's
//! folder, so the rename stays on one file system and is atomic. Its name is
//! never shorter than the target's (`<name>` is cut, or padded with `_`, to
//! fit [`MAX_FILE_NAME_BYTES`]), so a target name the file system refuses is
//! refused when the temporary is created, and a 255-byte name works. A
//! symlink as output is followed: its target is replaced, the link stays. A
//! reserved file that is dropped uncommitted is removed; a signal removes it
//! too (`crate::interrupt`).

use std::ffi::OsString;
use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};

use crate::interrupt;
use crate::limits::{MAX_FILE_NAME_BYTES, MAX_SYMLINK_HOPS};

/// Distinguishes the temporary files of one process.
static NEXT_TEMPORARY: AtomicU64 = AtomicU64::new(0);

/// What every temporary name holds: the pattern docs/guide/limits.md gives for leftovers.
pub const TEMPORARY_MARK: &str = ".pathtracer-tmp-";

/// An output whose temporary file exists, to be written and then committed.
pub struct PendingFile {
    /// The path as the user gave it, for messages.
    shown: PathBuf,
    /// Where the bytes go: `shown` with symlinks followed.
    target: PathBuf,
    temporary: PathBuf,
    file: Option<File>,
    written: bool,
    /// Whether the temporary is still ours to remove.
    owned: bool,
}

impl PendingFile {
    /// Creates the temporary file of `path` (and the folder it goes in).
    pub fn reserve(path: &Path) -> Result<PendingFile, String> {
        let shown = path.display();
        let target = follow_links(path)?;
        let Some(file_name) = target.file_name() else {
            return Err(format!("{shown}: not a file path"));
        };
        if target.is_dir() {
            return Err(format!("{shown}: is a directory"));
        }
        refuse_special(path, &target)?;
        let directory = match target.parent() {
            Some(parent) if !parent.as_os_str().is_empty() => parent.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if directory.exists() && !directory.is_dir() {
            return Err(format!(
                "{shown}: cannot create folder {}: a file of that name is in the way",
                directory.display()
            ));
        }
        fs::create_dir_all(&directory)
            .map_err(|e| format!("{shown}: cannot create folder {}: {e}", directory.display()))?;
        let temporary = temporary_sibling(&directory, file_name);
        let file = create_registered(&temporary).map_err(|e| {
            let length = file_name.len();
            if length > MAX_FILE_NAME_BYTES {
                format!(
                    "{shown}: the file name is {length} bytes, more than the file system allows ({e})"
                )
            } else {
                format!(
                    "{shown}: cannot create a file in {}: {e}",
                    directory.display()
                )
            }
        })?;
        Ok(PendingFile {
            shown: path.to_path_buf(),
            target,
            temporary,
            file: Some(file),
            written: false,
            owned: true,
        })
    }

    /// The path as given.
    pub fn path(&self) -> &Path {
        &self.shown
    }

    /// The file that commit replaces (symlinks followed).
    pub fn target(&self) -> &Path {
        &self.target
    }

    pub(super) fn temporary(&self) -> &Path {
        &self.temporary
    }

    pub(super) fn is_written(&self) -> bool {
        self.written
    }

    /// Writes the whole content to the temporary file and flushes it to disk.
    pub fn write(&mut self, bytes: &[u8]) -> Result<(), String> {
        let Some(mut file) = self.file.take() else {
            return Err(format!("{}: written twice", self.shown.display()));
        };
        file.write_all(bytes)
            .and_then(|()| file.sync_all())
            .map_err(|e| format!("{}: cannot write: {e}", self.shown.display()))?;
        self.written = true;
        Ok(())
    }

    /// Renames the written temporary over the target.
    pub fn commit(self) -> Result<(), String> {
        super::commit::commit_together(vec![self])
    }

    /// The temporary is now the target (renamed): not ours to remove.
    pub(super) fn disown(&mut self, registry: &mut interrupt::Registry) {
        registry.unregister(&self.temporary);
        self.owned = false;
    }
}

impl Drop for PendingFile {
    fn drop(&mut self) {
        if self.owned {
            self.file = None;
            let mut registry = interrupt::lock();
            let _ = fs::remove_file(&self.temporary);
            registry.unregister(&self.temporary);
        }
    }
}

/// Writes `bytes` to `path` whole or not at all (reserve, write, commit).
pub fn write_file(path: &Path, bytes: &[u8]) -> Result<(), String> {
    let mut pending = PendingFile::reserve(path)?;
    pending.write(bytes)?;
    pending.commit()
}

/// Creates `path`, which must not exist, registered for removal on a signal
/// before it exists.
pub(super) fn create_registered(path: &Path) -> std::io::Result<File> {
    let mut registry = interrupt::lock();
    registry.register(path);
    let created = File::create_new(path);
    if created.is_err() {
        registry.unregister(path);
    }
    created
}

/// A fresh temporary name in `directory` for a file called `name`, at least
/// as long as `name` and, when `name` fits, at most [`MAX_FILE_NAME_BYTES`].
pub(super) fn temporary_sibling(directory: &Path, name: &std::ffi::OsStr) -> PathBuf {
    let suffix = format!(
        "{TEMPORARY_MARK}{}-{}",
        std::process::id(),
        NEXT_TEMPORARY.fetch_add(1, Ordering::Relaxed)
    );
    let natural = 1 + name.len() + suffix.len();
    let length = if natural <= MAX_FILE_NAME_BYTES {
        natural
    } else {
        MAX_FILE_NAME_BYTES.max(name.len())
    };
    let room = length.saturating_sub(1 + suffix.len());
    let text = name.to_string_lossy();
    let mut cut = room.min(text.len());
    while !text.is_char_boundary(cut) {
        cut -= 1;
    }
    let mut temporary = OsString::from(".");
    temporary.push(&text[..cut]);
    temporary.push("_".repeat(room - cut));
    temporary.push(&suffix);
    directory.join(temporary)
}

/// An error if `target` exists and is not a regular file: a named pipe, a
/// device or a socket would be replaced by the rename (or, written
/// directly, block or swallow the image), so it is refused.
fn refuse_special(path: &Path, target: &Path) -> Result<(), String> {
    match fs::metadata(target) {
        Ok(metadata) if !metadata.is_file() => Err(format!(
            "{}: is not a regular file (a named pipe, device or socket); refusing to replace it",
            path.display()
        )),
        _ => Ok(()),
    }
}

/// `path` with symlinks followed to the file they name (which may not exist
/// yet); a loop is an error.
fn follow_links(path: &Path) -> Result<PathBuf, String> {
    let mut current = path.to_path_buf();
    for _ in 0..MAX_SYMLINK_HOPS {
        let is_link = fs::symlink_metadata(&current).is_ok_and(|m| m.file_type().is_symlink());
        if !is_link {
            return Ok(current);
        }
        let link = fs::read_link(&current)
            .map_err(|e| format!("{}: cannot read the symlink: {e}", path.display()))?;
        current = match current.parent() {
            Some(parent) => parent.join(link),
            None => link,
        };
    }
    Err(format!(
        "{}: more than {MAX_SYMLINK_HOPS} symlinks in a row",
        path.display()
    ))
}
