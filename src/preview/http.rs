//! The little HTTP/1.1 the preview needs: one request per connection, read
//! with a size and time limit and parsed by `httparse`; responses written
//! whole, with `Connection: close`.

use std::io::{Read, Write};
use std::net::TcpStream;

/// The most a request head may take (its line and headers).
pub const MAX_HEAD_BYTES: usize = 8 * 1024;

/// The most headers a request may have.
const MAX_HEADERS: usize = 32;

/// What the server looks at in a request.
#[derive(Debug, PartialEq, Eq)]
pub struct Request {
    pub method: String,
    /// The request target without its query (`/film?frame=3` is `/film`).
    pub path: String,
    /// What follows the `?` of the target (empty without one).
    pub query: String,
    pub host: Option<String>,
    pub origin: Option<String>,
    /// Whether the request announced a body (refused: no route takes one).
    pub has_body: bool,
}

/// Why a request is answered with an error before it is routed.
#[derive(Debug, PartialEq, Eq)]
pub enum Refusal {
    /// Not HTTP, or a head beyond [`MAX_HEAD_BYTES`] or [`MAX_HEADERS`].
    Malformed,
    /// The connection closed or timed out before a whole head.
    Incomplete,
}

/// Reads one request head from `stream` (which has its read timeout set).
pub fn read_request(stream: &mut TcpStream) -> Result<Request, Refusal> {
    let mut head = [0u8; MAX_HEAD_BYTES];
    let mut filled = 0;
    loop {
        let read = stream
            .read(&mut head[filled..])
            .map_err(|_| Refusal::Incomplete)?;
        if read == 0 {
            return Err(Refusal::Incomplete);
        }
        filled += read;
        match parse(&head[..filled]) {
            Ok(Some(request)) => return Ok(request),
            Ok(None) if filled < head.len() => continue,
            _ => return Err(Refusal::Malformed),
        }
    }
}

/// The request in `bytes`, `None` while its head is incomplete.
pub fn parse(bytes: &[u8]) -> Result<Option<Request>, Refusal> {
    let mut headers = [httparse::EMPTY_HEADER; MAX_HEADERS];
    let mut request = httparse::Request::new(&mut headers);
    match request.parse(bytes) {
        Ok(httparse::Status::Complete(_)) => {}
        Ok(httparse::Status::Partial) => return Ok(None),
        Err(_) => return Err(Refusal::Malformed),
    }
    let header = |name: &str| {
        request
            .headers
            .iter()
            .find(|h| h.name.eq_ignore_ascii_case(name))
            .map(|h| String::from_utf8_lossy(h.value).trim().to_string())
    };
    let target = request.path.unwrap_or("");
    let target = target.split('#').next().unwrap_or("");
    let (path, query) = target.split_once('?').unwrap_or((target, ""));
    let length = header("content-length").filter(|l| l != "0");
    Ok(Some(Request {
        method: request.method.unwrap_or("").to_string(),
        path: path.to_string(),
        query: query.to_string(),
        host: header("host"),
        origin: header("origin"),
        has_body: length.is_some() || header("transfer-encoding").is_some(),
    }))
}

/// Headers every response carries: nothing cached, nothing sniffed, no
/// content from elsewhere.
const COMMON_HEADERS: &str = "Cache-Control: no-store\r\n\
     X-Content-Type-Options: nosniff\r\n\
     Referrer-Policy: no-referrer\r\n\
     Content-Security-Policy: default-src 'self'; img-src 'self' blob: data:; frame-ancestors 'none'\r\n\
     Connection: close\r\n";

/// Writes a whole response (status line, headers, body).
pub fn respond(
    stream: &mut TcpStream,
    status: &str,
    content_type: &str,
    body: &[u8],
) -> std::io::Result<()> {
    let head = format!(
        "HTTP/1.1 {status}\r\nContent-Type: {content_type}\r\nContent-Length: {}\r\n{COMMON_HEADERS}\r\n",
        body.len()
    );
    stream.write_all(head.as_bytes())?;
    stream.write_all(body)?;
    stream.flush()
}

/// A plain-text error response.
pub fn refuse(stream: &mut TcpStream, status: &str, why: &str) -> std::io::Result<()> {
    respond(
        stream,
        status,
        "text/plain; charset=utf-8",
        format!("{status}: {why}\n").as_bytes(),
    )
}

/// The head of an event stream; events follow as [`event`] writes them.
pub fn start_events(stream: &mut TcpStream) -> std::io::Result<()> {
    let head =
        format!("HTTP/1.1 200 OK\r\nContent-Type: text/event-stream\r\n{COMMON_HEADERS}\r\n");
    stream.write_all(head.as_bytes())?;
    stream.flush()
}

/// One server-sent event whose data is `json` (one line).
pub fn event(stream: &mut TcpStream, json: &str) -> std::io::Result<()> {
    stream.write_all(format!("data: {json}\n\n").as_bytes())?;
    stream.flush()
}

/// A comment line that keeps an idle event stream open (and finds a
/// closed one).
pub fn keep_alive(stream: &mut TcpStream) -> std::io::Result<()> {
    stream.write_all(b": still here\n\n")?;
    stream.flush()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_request_gives_its_method_path_without_query_and_host() {
        let request = parse(b"GET /film?frame=3 HTTP/1.1\r\nHost: 127.0.0.1:8000\r\n\r\n")
            .expect("parsed")
            .expect("complete");
        assert_eq!(request.method, "GET");
        assert_eq!(request.path, "/film");
        assert_eq!(request.query, "frame=3");
        assert_eq!(request.host.as_deref(), Some("127.0.0.1:8000"));
        assert!(!request.has_body);
    }

    #[test]
    fn partial_heads_wait_and_garbage_is_malformed() {
        assert_eq!(parse(b"GET / HTTP/1.1\r\nHost: x"), Ok(None));
        assert_eq!(parse(b"\x00\x01 nonsense\r\n\r\n"), Err(Refusal::Malformed));
        let with_body = parse(b"POST /save HTTP/1.1\r\nHost: h\r\nContent-Length: 5\r\n\r\n")
            .expect("parsed")
            .expect("complete");
        assert!(with_body.has_body);
    }
}
