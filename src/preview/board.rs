//! The board the renderer posts to and every connection reads from: the
//! latest frame of the film and the render's status, with a generation
//! number that rises on each post so that event streams wait for the next.
//!
//! Memory is bounded whatever the number of readers: the board holds one
//! image and its frame, and a reader holds the one it is sending (an
//! `Arc`), never a queue of them.

use std::path::PathBuf;
use std::sync::{Arc, Condvar, Mutex, MutexGuard};
use std::time::Duration;

use crate::image_io::Image;

use super::compare::Compared;
use super::frame;
use super::status::Status;

/// What was last posted.
#[derive(Clone, Default)]
pub struct Posted {
    /// Rises by one on every post.
    pub generation: u64,
    /// The film as [`super::frame`] encodes it (none before the first pass).
    pub frame: Option<Arc<Vec<u8>>>,
    /// The same film as an image, for the save button.
    pub image: Option<Arc<Image>>,
    pub status: Status,
    /// The last measure against `--against`'s image.
    pub compared: Option<Arc<Compared>>,
}

impl Posted {
    /// What an event says: the status, with the comparison's figures as
    /// `against` (null without one).
    pub fn to_json(&self) -> String {
        let status = self.status.to_json();
        let against = self.compared.as_ref().map_or("null", |c| c.json.as_str());
        format!("{}, \"against\": {against}}}", &status[..status.len() - 1])
    }
}

/// Shared between the render loop and the server's connections.
#[derive(Default)]
pub struct Board {
    posted: Mutex<Posted>,
    changed: Condvar,
    /// The files the scene reads, which a save may not replace.
    inputs: Mutex<Vec<PathBuf>>,
}

impl Board {
    fn lock(&self) -> MutexGuard<'_, Posted> {
        // A reader that panicked leaves the board as it was: plain data.
        self.posted.lock().unwrap_or_else(|e| e.into_inner())
    }

    /// Replaces the status, and the image (and its frame, numbered
    /// `status.frame`) when one is given, and wakes every reader waiting
    /// for a change.
    pub fn post(&self, status: Status, image: Option<Image>) {
        let frame = image
            .as_ref()
            .map(|i| Arc::new(frame::encode(i, status.frame)));
        let mut posted = self.lock();
        posted.generation += 1;
        posted.status = status;
        if let Some(image) = image {
            posted.image = Some(Arc::new(image));
            posted.frame = frame;
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

    /// Replaces the comparison and wakes the readers.
    pub fn set_compared(&self, compared: Compared) {
        let mut posted = self.lock();
        posted.generation += 1;
        posted.compared = Some(Arc::new(compared));
        drop(posted);
        self.changed.notify_all();
    }

    /// The files the scene reads now.
    pub fn set_inputs(&self, files: &[PathBuf]) {
        *self.inputs.lock().unwrap_or_else(|e| e.into_inner()) = files.to_vec();
    }

    pub fn inputs(&self) -> Vec<PathBuf> {
        self.inputs
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
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
        let image = |value: f64| Image {
            width: 1,
            height: 1,
            pixels: vec![crate::color::Color::new(value, value, value)],
        };
        board.post(Status::default(), Some(image(1.0)));
        let got = reader.join().expect("reader").expect("a post");
        assert!(got.generation >= 1);
        board.post(Status::default(), Some(image(2.0)));
        board.update(|s| s.spp = 3.0);
        let now = board.now();
        assert_eq!(now.generation, 3);
        assert_eq!(now.image.as_deref(), Some(&image(2.0)));
        let frame = now.frame.expect("a frame");
        assert_eq!(frame.len(), frame::HEADER_BYTES + 6);
        // 2.0 as a half float.
        assert_eq!(
            frame[frame::HEADER_BYTES..frame::HEADER_BYTES + 2],
            [0x00, 0x40]
        );
        assert_eq!(now.status.spp, 3.0);
        assert!(board.after(3, Duration::from_millis(10)).is_none());
    }
}
