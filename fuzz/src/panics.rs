//! Panics as libFuzzer crashes, except those the library catches on purpose.
//!
//! libfuzzer-sys installs a panic hook that aborts at once, before any
//! unwinding. The library catches the panics of one dependency itself (the
//! OBJ reader, `tobj`, in `scene::build::obj`) and turns them into errors, so
//! under that hook a handled panic would look like a crash. [`install`]
//! replaces the hook by one that only prints the message (and a backtrace
//! with `RUST_BACKTRACE=1`); [`crash_on_panic`] aborts when a panic reaches
//! the fuzz target, which is every panic the library does not handle.

use std::panic::{AssertUnwindSafe, catch_unwind};

/// Replaces libfuzzer-sys's aborting panic hook by the printing default.
pub fn install() {
    let _ = std::panic::take_hook();
    std::panic::set_hook(Box::new(|info| {
        let message = info
            .payload()
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| info.payload().downcast_ref::<String>().cloned())
            .unwrap_or_default();
        let place = info
            .location()
            .map(|l| format!("{}:{}:{}", l.file(), l.line(), l.column()))
            .unwrap_or_default();
        eprintln!("panicked at {place}: {message}");
        if std::env::var_os("RUST_BACKTRACE").is_some() {
            eprintln!("{}", std::backtrace::Backtrace::force_capture());
        }
    }));
}

/// Runs `work`; a panic that escapes it aborts the process (a libFuzzer crash).
pub fn crash_on_panic<T>(work: impl FnOnce() -> T) -> T {
    match catch_unwind(AssertUnwindSafe(work)) {
        Ok(value) => value,
        Err(_) => std::process::abort(),
    }
}
