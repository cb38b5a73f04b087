//! The board the renderer posts to and every connection reads from: the
//! latest frame of the film and the render's status, with a generation
//! number that rises on each post so that event streams wait for the next.
//!
//! Memory is bounded whatever the number of readers: the board holds one
//! frame, and a reader holds the frame it is sending (an `Arc`), never a
//! queue of them.

use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

use super::status::Status;

/// What was last posted.
#[derive(Clone, Default)]
pub struct Posted {
    /// Rises by one on every post.
    pub generation: u64,
    /// The film as [`super::frame`] encodes it (none before the first pass).
    pub frame: Option<Arc<Vec<u8>>>,
    pub status: Status,
}

/// Shared between the render loop and the server's connections.
#[derive(Default)]
pub struct Board {
    posted: Mutex<Posted>,
    changed: Condvar,
}

impl Board {
    fn lock(&self) -> MutexGuard<'_, Posted> {
        // A reader that panicked leaves the board as it was: plain data.
        self.posted.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Replaces the status, and the frame when one is given, and wakes
    /// every reader waiting for a change.
    pub fn post(&self, status: Status, frame: Option<Vec<u8>>) {
        let mut posted = self.lock();
        posted.generation += 1;
        posted.status = status;
        if let Some(frame) = frame {
            posted.frame = Some(Arc::new(frame));
        }
        drop(posted);
        self.changed.notify_all();
    }

    /// Changes the status in place (a new error or warning without a new
    /// frame) and wakes the readers.
    pub fn update(&self, change: impl FnOnce(&mut Status)) {
        let mut posted = self.lock();
        posted.generation += 1;
        change(&mut posted.status);
        drop(posted);
        self.changed.notify_all();
    }

    /// What is posted now.
    pub fn now(&self) -> Posted {
        self.lock().clone()
    }

    /// The first post after generation `seen`, or `None` after `timeout`
    /// without one.
    pub fn after(&self, seen: u64, timeout: Duration) -> Option<Posted> {
        let posted = self.lock();
        let (posted, _) = self
            .changed
            .wait_timeout_while(posted, timeout, |p| p.generation <= seen)
            .unwrap_or_else(|e| e.into_inner());
        (posted.generation > seen).then(|| posted.clone())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_waiting_reader_gets_the_next_post_and_only_the_latest_frame_is_kept() {
        let board = Arc::new(Board::default());
        let reader = {
            let board = board.clone();
            std::thread::spawn(move || board.after(0, Duration::from_secs(10)))
        };
        board.post(Status::default(), Some(vec![1]));
        let got = reader.join().expect("reader").expect("a post");
        assert!(got.generation >= 1);
        board.post(Status::default(), Some(vec![2]));
        board.update(|s| s.spp = 3.0);
        let now = board.now();
        assert_eq!(now.generation, 3);
        assert_eq!(now.frame.as_deref().map(|f| f.as_slice()), Some(&[2u8][..]));
        assert_eq!(now.status.spp, 3.0);
        assert!(board.after(3, Duration::from_millis(10)).is_none());
    }
}
