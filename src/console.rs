//! Lines for standard error that never panic: a closed or full stderr
//! (`2>/dev/full`, a closed terminal) loses the message, never the run.
//!
//! `eprintln!` panics when the write fails ("failed printing to stderr"),
//! which would turn a warning into exit 101 with the outputs' temporaries
//! left behind; `clippy::print_stderr` (denied in lib.rs and main.rs)
//! forbids it, and every message goes through
//! [`stderr_line!`](crate::stderr_line) or [`stderr_text!`](crate::stderr_text).

/// `eprintln!` that ignores a failed write.
#[macro_export]
macro_rules! stderr_line {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = writeln!(std::io::stderr(), $($arg)*);
    }};
}

/// `eprint!` that ignores a failed write.
#[macro_export]
macro_rules! stderr_text {
    ($($arg:tt)*) => {{
        use std::io::Write as _;
        let _ = write!(std::io::stderr(), $($arg)*);
    }};
}
