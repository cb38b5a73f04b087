//! Watching the files a scene reads by polling their modification time and
//! length: the scene file, and every mesh, `.mtl`, texture and descriptor of
//! its last good build. Polling needs no thread, follows editors that save
//! by renaming a new file into place, and costs a `stat` per file per poll
//! (see docs/guide/view.md for the figures).

use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

/// How often the files are looked at while nothing else is to be done.
pub const POLL: Duration = Duration::from_millis(100);

/// How long the files must stay unchanged before a changed scene is read:
/// an editor that writes in steps is not read half way.
pub const SETTLE: Duration = Duration::from_millis(60);

/// One file's modification time and length (`None`: it cannot be read).
type Stamp = Option<(SystemTime, u64)>;

fn stamp(path: &Path) -> Stamp {
    let metadata = std::fs::metadata(path).ok()?;
    Some((metadata.modified().ok()?, metadata.len()))
}

/// The watched files and their stamps when last [`Watch::mark`]ed.
pub struct Watch {
    files: Vec<PathBuf>,
    stamps: Vec<Stamp>,
}

impl Watch {
    /// Watches `files`, as they are now.
    pub fn new(files: Vec<PathBuf>) -> Watch {
        let stamps = files.iter().map(|f| stamp(f)).collect();
        Watch { files, stamps }
    }

    pub fn files(&self) -> &[PathBuf] {
        &self.files
    }

    /// Whether any file differs from its stamp.
    pub fn changed(&self) -> bool {
        self.files
            .iter()
            .zip(&self.stamps)
            .any(|(file, old)| stamp(file) != *old)
    }

    /// Takes the stamps now, once they have stayed the same for
    /// [`SETTLE`].
    pub fn mark(&mut self) {
        loop {
            let before: Vec<Stamp> = self.files.iter().map(|f| stamp(f)).collect();
            std::thread::sleep(SETTLE);
            let after: Vec<Stamp> = self.files.iter().map(|f| stamp(f)).collect();
            if before == after {
                self.stamps = after;
                return;
            }
        }
    }

    /// Watches `files` from now on, keeping the stamps of those already
    /// watched (a change since the last mark is still a change).
    pub fn watch(&mut self, files: Vec<PathBuf>) {
        let stamps = files
            .iter()
            .map(|file| match self.files.iter().position(|f| f == file) {
                Some(known) => self.stamps[known],
                None => stamp(file),
            })
            .collect();
        self.files = files;
        self.stamps = stamps;
    }

    /// Waits until a file changes.
    pub fn wait(&self) {
        while !self.changed() {
            std::thread::sleep(POLL);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_rewrite_a_new_length_a_removal_and_a_new_file_are_changes() {
        let dir = std::env::temp_dir().join(format!("pathtracer-watch-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("dir");
        let (a, b) = (dir.join("a.txt"), dir.join("b.txt"));
        std::fs::write(&a, "one").expect("write");
        let mut watch = Watch::new(vec![a.clone(), b.clone()]);
        assert!(!watch.changed());
        std::fs::write(&a, "one more").expect("write");
        assert!(watch.changed());
        watch.mark();
        assert!(!watch.changed());
        std::fs::write(&b, "new").expect("write");
        assert!(watch.changed(), "a file that appears");
        watch.mark();
        std::fs::remove_file(&a).expect("remove");
        assert!(watch.changed(), "a file that goes");
        watch.mark();
        // Watching another list keeps the stamps of files already watched.
        std::fs::write(&b, "newer").expect("write");
        watch.watch(vec![b.clone()]);
        assert!(watch.changed());
        let _ = std::fs::remove_dir_all(&dir);
    }
}
