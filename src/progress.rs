//! Progress of a whole render on standard error, across all the calls that
//! make it up (adaptive passes, converge stages, the slices between
//! checkpoints): one estimate of the work done and left, not one per call.
//!
//! The work is counted in pixel samples. Workers add what they traced; the
//! caller says how much is planned (and updates it when, as in adaptive
//! sampling, the plan shrinks) and, for a time budget, when the render must
//! end. A reporter thread, running while pixels are rendered, prints a line
//! rewritten in place on a terminal, otherwise (batch logs) a whole line
//! every few seconds.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// Seconds between progress lines when standard error is not a terminal.
pub const PROGRESS_LOG_SECONDS: f64 = 5.0;

/// The counters of one render's progress.
#[derive(Debug)]
pub struct Progress {
    start: Instant,
    /// Pixel samples traced since `start`.
    done: AtomicU64,
    /// Pixel samples planned since `start` (at least `done`).
    planned: AtomicU64,
    /// Seconds the whole render may take, if it has a budget.
    budget: Option<f64>,
}

impl Progress {
    pub fn new(planned: u64, budget: Option<f64>) -> Progress {
        Progress {
            start: Instant::now(),
            done: AtomicU64::new(0),
            planned: AtomicU64::new(planned),
            budget,
        }
    }

    /// Counts `samples` more pixel samples traced.
    pub fn add(&self, samples: u64) {
        self.done.fetch_add(samples, Ordering::Relaxed);
    }

    /// The pixel samples traced so far.
    pub fn done(&self) -> u64 {
        self.done.load(Ordering::Relaxed)
    }

    /// Sets the pixel samples still to trace (the plan of an adaptive
    /// render shrinks as pixels converge).
    pub fn plan_remaining(&self, remaining: u64) {
        self.planned
            .store(self.done() + remaining, Ordering::Relaxed);
    }

    /// The line printed now: percent, samples/s, elapsed, remaining.
    pub fn line(&self) -> String {
        let elapsed = self.start.elapsed().as_secs_f64();
        let done = self.done() as f64;
        let planned = (self.planned.load(Ordering::Relaxed) as f64)
            .max(done)
            .max(1.0);
        let mut fraction = done / planned;
        let rate = done / elapsed.max(1e-9);
        let mut left = (done > 0.0).then(|| (planned - done) / rate);
        if let Some(budget) = self.budget {
            fraction = fraction.max(elapsed / budget.max(1e-9)).min(1.0);
            let by_budget = (budget - elapsed).max(0.0);
            left = Some(left.map_or(by_budget, |l| l.min(by_budget)));
        }
        let left = match left {
            Some(seconds) => format!("{seconds:.0} s left"),
            None => "estimating".to_string(),
        };
        format!(
            "rendering {:5.1}%  {:.2} M samples/s  {elapsed:.0} s elapsed  {left}",
            fraction * 100.0,
            rate / 1e6
        )
    }

    /// Prints [`Progress::line`] until `finished`: four times a second in
    /// place on a terminal, otherwise every `every` seconds as a new line
    /// (the thread is unparked to finish at once).
    pub fn report(&self, terminal: bool, every: f64, finished: &AtomicBool) {
        let tick = if terminal {
            Duration::from_millis(250)
        } else {
            Duration::from_secs_f64(every)
        };
        let mut printed = false;
        loop {
            std::thread::park_timeout(tick);
            let over = finished.load(Ordering::Relaxed);
            if over && !(terminal && printed) {
                return;
            }
            let line = self.line();
            if terminal {
                crate::stderr_text!("\r{line}    ");
                printed = true;
                if over {
                    crate::stderr_line!();
                    return;
                }
            } else {
                crate::stderr_line!("{line}");
            }
        }
    }

    /// Runs `work` on this thread; when `show` is set, a reporter thread
    /// prints this progress meanwhile (every `every` seconds to a log,
    /// [`PROGRESS_LOG_SECONDS`] when not given; a live line on a terminal)
    /// and ends with it.
    pub fn while_running<T>(&self, show: bool, every: Option<f64>, work: impl FnOnce() -> T) -> T {
        let finished = AtomicBool::new(false);
        std::thread::scope(|scope| {
            let reporter = show.then(|| {
                scope.spawn(|| {
                    let every = every.unwrap_or(PROGRESS_LOG_SECONDS);
                    self.report(std::io::stderr().is_terminal(), every, &finished)
                })
            });
            let result = work();
            finished.store(true, Ordering::Relaxed);
            if let Some(reporter) = reporter {
                reporter.thread().unpark();
            }
            result
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_estimate_spans_every_call_and_follows_the_plan() {
        let progress = Progress::new(1000, None);
        assert!(
            progress.line().contains("estimating"),
            "{}",
            progress.line()
        );
        progress.add(250);
        assert!(
            progress.line().starts_with("rendering  25.0%"),
            "{}",
            progress.line()
        );
        progress.add(250);
        assert!(
            progress.line().starts_with("rendering  50.0%"),
            "{}",
            progress.line()
        );
        // Half the remaining pixels converged: 250 of the 500 left.
        progress.plan_remaining(250);
        assert!(
            progress.line().starts_with("rendering  66.7%"),
            "{}",
            progress.line()
        );
    }

    #[test]
    fn a_time_budget_bounds_what_is_left() {
        let progress = Progress::new(1_000_000_000, Some(3600.0));
        progress.add(1);
        std::thread::sleep(Duration::from_millis(20));
        let line = progress.line();
        let left: f64 = line
            .split("elapsed  ")
            .nth(1)
            .and_then(|rest| rest.split(' ').next())
            .and_then(|s| s.parse().ok())
            .expect("a number of seconds left");
        assert!(left <= 3600.0, "{line}");
    }
}
