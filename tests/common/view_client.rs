//! Driving `pathtracer view` in tests: started on a free port against a
//! scene, its URL read from standard output, asked over raw HTTP, and
//! killed when the test ends (also when it fails).

use std::io::{BufRead, BufReader, Read, Write};
use std::net::TcpStream;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use super::binary;

/// A running `view` (killed on drop).
pub struct Viewer {
    pub child: Child,
    pub port: u16,
}

impl Drop for Viewer {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// An HTTP answer.
pub struct Answer {
    pub code: u16,
    pub head: String,
    pub body: Vec<u8>,
}

impl Answer {
    pub fn text(&self) -> String {
        String::from_utf8_lossy(&self.body).into_owned()
    }
}

impl Viewer {
    /// `pathtracer view SCENE --port 0 ARGS...` in `dir`, once it has
    /// printed its URL.
    pub fn start(dir: &Path, scene: &Path, args: &[&str]) -> Viewer {
        let mut child = Command::new(binary())
            .arg("view")
            .arg(scene)
            .args(["--port", "0"])
            .args(args)
            .current_dir(dir)
            .stdin(Stdio::null())
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
            .expect("the binary runs");
        let stdout = child.stdout.take().expect("stdout");
        let mut line = String::new();
        let _ = BufReader::new(stdout).read_line(&mut line);
        let port = line
            .split("http://127.0.0.1:")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .and_then(|port| port.parse().ok());
        let mut viewer = Viewer { child, port: 0 };
        match port {
            Some(port) => viewer.port = port,
            None => panic!(
                "no URL printed (got {line:?}; exit {:?})",
                viewer.child.try_wait()
            ),
        }
        viewer
    }

    /// `GET path` with the server's own `Host`.
    pub fn get(&self, path: &str) -> Answer {
        self.request(&format!(
            "GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{}\r\n\r\n",
            self.port
        ))
    }

    /// Sends `raw` and reads the answer to the end (the server closes).
    pub fn request(&self, raw: &str) -> Answer {
        let mut stream = TcpStream::connect(("127.0.0.1", self.port)).expect("connect");
        stream
            .set_read_timeout(Some(Duration::from_secs(20)))
            .expect("timeout");
        stream.write_all(raw.as_bytes()).expect("send");
        let mut bytes = Vec::new();
        stream.read_to_end(&mut bytes).expect("read the answer");
        let split = bytes
            .windows(4)
            .position(|w| w == b"\r\n\r\n")
            .expect("a response head");
        let head = String::from_utf8_lossy(&bytes[..split]).into_owned();
        let code = head
            .split(' ')
            .nth(1)
            .and_then(|c| c.parse().ok())
            .expect("a status code");
        Answer {
            code,
            head,
            body: bytes[split + 4..].to_vec(),
        }
    }

    /// Asks `path` until `done` holds for the answer, failing after `limit`.
    pub fn wait_for(&self, path: &str, limit: Duration, done: impl Fn(&Answer) -> bool) -> Answer {
        let started = Instant::now();
        loop {
            let answer = self.get(path);
            if done(&answer) {
                return answer;
            }
            assert!(
                started.elapsed() < limit,
                "{path}: still {} {} after {limit:?}",
                answer.code,
                answer.text().chars().take(300).collect::<String>()
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}
