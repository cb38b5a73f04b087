//! SIGINT, SIGTERM, SIGHUP and SIGQUIT: a flag that long loops can read, and
//! the registry of temporary files to remove before the process exits.
//!
//! [`install`] starts a thread that waits for any of [`STOP_SIGNALS`]
//! (SIGHUP and SIGQUIT, a closed terminal or Ctrl-\, are treated as
//! SIGTERM). By default it sets the flag, removes every registered temporary
//! file and exits with 128 plus the signal number (130 for SIGINT, 143 for
//! SIGTERM, 129 for SIGHUP, 131 for SIGQUIT). While a
//! [`Graceful`] guard is held (a render that can stop between samples and
//! write what it has), the first signal only sets the flag that
//! [`interrupted`] reads; the command finishes its outputs and `main` exits
//! with 128 plus the signal. A second signal exits at once, as by default.
//!
//! The registry is one lock: code that must not be cut in the middle (the
//! renames that put several outputs in place together) holds it through
//! [`lock`], and a signal arriving meanwhile is handled once it is released.
//! SIGKILL cannot be caught; it leaves the temporaries behind, named as
//! `crate::image_io` says (`.<name>.pathtracer-tmp-<pid>-<n>`).

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, AtomicI32, Ordering};
use std::sync::{Mutex, MutexGuard};

/// The signal received, or 0.
static SIGNAL: AtomicI32 = AtomicI32::new(0);

/// Whether the first signal only sets [`SIGNAL`] (see [`Graceful`]).
static GRACEFUL: AtomicBool = AtomicBool::new(false);

/// Temporary files that exist (or are about to) and must not outlive the process.
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// The signal that interrupted the process (SIGINT is 2, SIGTERM 15), if any.
pub fn interrupted() -> Option<i32> {
    match SIGNAL.load(Ordering::SeqCst) {
        0 => None,
        signal => Some(signal),
    }
}

/// While held, the first stopping signal (SIGINT, SIGTERM, SIGHUP, SIGQUIT) asks the process to finish (the
/// samples in flight, the partial outputs) instead of ending it.
pub struct Graceful(());

impl Graceful {
    pub fn start() -> Graceful {
        GRACEFUL.store(true, Ordering::SeqCst);
        Graceful(())
    }
}

impl Drop for Graceful {
    fn drop(&mut self) {
        GRACEFUL.store(false, Ordering::SeqCst);
    }
}

/// The registry of temporary files, held: no signal is handled until it is
/// dropped.
pub struct Registry {
    temporaries: MutexGuard<'static, Vec<PathBuf>>,
}

/// Holds the registry (waiting for a signal being handled, which exits).
pub fn lock() -> Registry {
    Registry {
        // A panic while the list was held leaves it usable: it is only paths.
        temporaries: TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner()),
    }
}

impl Registry {
    /// Records `path` for removal on a signal; call it before creating the file.
    pub fn register(&mut self, path: &Path) {
        self.temporaries.push(path.to_path_buf());
    }

    /// Forgets `path` (removed, or renamed into place).
    pub fn unregister(&mut self, path: &Path) {
        if let Some(index) = self.temporaries.iter().rposition(|p| p == path) {
            self.temporaries.swap_remove(index);
        }
    }

    /// Removes every registered file (those that do not exist are skipped).
    fn remove_all(&mut self) {
        for path in self.temporaries.drain(..) {
            let _ = std::fs::remove_file(&path);
        }
    }
}

/// The signals that stop a run as described above: SIGINT, SIGTERM, SIGHUP
/// and SIGQUIT.
#[cfg(unix)]
pub const STOP_SIGNALS: [i32; 4] = [
    signal_hook::consts::SIGINT,
    signal_hook::consts::SIGTERM,
    signal_hook::consts::SIGHUP,
    signal_hook::consts::SIGQUIT,
];

/// Starts the thread that handles [`STOP_SIGNALS`] (once per process).
pub fn install() -> Result<(), String> {
    #[cfg(unix)]
    {
        let mut signals = signal_hook::iterator::Signals::new(STOP_SIGNALS)
            .map_err(|e| format!("cannot handle SIGINT, SIGTERM, SIGHUP and SIGQUIT: {e}"))?;
        std::thread::Builder::new()
            .name("interrupt".to_string())
            .spawn(move || {
                for signal in signals.forever() {
                    let first = SIGNAL.load(Ordering::SeqCst) == 0;
                    if first && GRACEFUL.load(Ordering::SeqCst) {
                        SIGNAL.store(signal, Ordering::SeqCst);
                        crate::stderr_line!(
                            "\ninterrupted by signal {signal}: finishing the samples in flight and writing what is done (again to stop at once)"
                        );
                    } else {
                        finish(signal);
                    }
                }
            })
            .map_err(|e| format!("cannot start the signal thread: {e}"))?;
    }
    Ok(())
}

/// Sets the flag, removes the temporaries and exits with `128 + signal`.
fn finish(signal: i32) -> ! {
    SIGNAL.store(signal, Ordering::SeqCst);
    let mut registry = lock();
    registry.remove_all();
    crate::stderr_line!("interrupted by signal {signal}: temporary files removed");
    // The registry stays held: no new temporary can appear before the exit.
    std::process::exit(128 + signal)
}
