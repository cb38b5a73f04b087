//! The preview's web server: a listener on 127.0.0.1 only, one thread per
//! connection up to [`MAX_CONNECTIONS`] (more are answered 503 at once),
//! each reading one request with a time limit and answering it from the
//! [`Board`].

use std::net::{Ipv4Addr, SocketAddr, TcpListener, TcpStream};
use std::path::PathBuf;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use super::board::Board;
use super::http::{self, Refusal, Request};
use super::routes::{self, Route};
use super::save;

/// Connections served at once (each event stream holds one).
pub const MAX_CONNECTIONS: usize = 32;

/// How long a client may take to send its request head.
const READ_TIMEOUT: Duration = Duration::from_secs(5);

/// How long one write may wait for a client that does not read.
const WRITE_TIMEOUT: Duration = Duration::from_secs(10);

/// How often an idle event stream says it is still there.
const KEEP_ALIVE: Duration = Duration::from_secs(5);

/// What the server serves: the board, and where the save button writes.
pub struct Served {
    pub board: Arc<Board>,
    pub output: PathBuf,
}

/// Starts serving on 127.0.0.1:`port` (0: a free port) and returns the
/// address it listens on. The server runs until the process ends.
pub fn start(port: u16, served: Served) -> Result<SocketAddr, String> {
    let listener = TcpListener::bind((Ipv4Addr::LOCALHOST, port))
        .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
    let address = listener
        .local_addr()
        .map_err(|e| format!("cannot read the listening address: {e}"))?;
    let active = Arc::new(AtomicUsize::new(0));
    let served = Arc::new(served);
    std::thread::Builder::new()
        .name("preview-accept".to_string())
        .spawn(move || {
            for stream in listener.incoming().flatten() {
                admit(stream, &served, &active, address.port());
            }
        })
        .map_err(|e| format!("cannot start the server thread: {e}"))?;
    Ok(address)
}

/// Serves `stream` on a thread of its own, or refuses it when
/// [`MAX_CONNECTIONS`] are being served.
fn admit(mut stream: TcpStream, served: &Arc<Served>, active: &Arc<AtomicUsize>, port: u16) {
    let _ = stream.set_read_timeout(Some(READ_TIMEOUT));
    let _ = stream.set_write_timeout(Some(WRITE_TIMEOUT));
    if active.fetch_add(1, Ordering::SeqCst) >= MAX_CONNECTIONS {
        active.fetch_sub(1, Ordering::SeqCst);
        let _ = http::refuse(
            &mut stream,
            "503 Service Unavailable",
            "too many connections",
        );
        return;
    }
    let (served, counted) = (served.clone(), active.clone());
    let spawned = std::thread::Builder::new()
        .name("preview-connection".to_string())
        .stack_size(256 * 1024)
        .spawn(move || {
            serve(stream, &served, port);
            counted.fetch_sub(1, Ordering::SeqCst);
        });
    if spawned.is_err() {
        active.fetch_sub(1, Ordering::SeqCst);
    }
}

/// Reads one request and answers it (write errors end the connection).
fn serve(mut stream: TcpStream, served: &Served, port: u16) {
    let request = match http::read_request(&mut stream) {
        Ok(request) => request,
        Err(Refusal::Malformed) => {
            let _ = http::refuse(&mut stream, "400 Bad Request", "not a request");
            return;
        }
        Err(Refusal::Incomplete) => return,
    };
    let _ = answer(&mut stream, &request, served, port);
}

fn answer(
    stream: &mut TcpStream,
    request: &Request,
    served: &Served,
    port: u16,
) -> std::io::Result<()> {
    let board = &served.board;
    if !routes::host_allowed(request.host.as_deref(), port) {
        return http::refuse(
            stream,
            "403 Forbidden",
            "the Host must be 127.0.0.1 or localhost with this server's port",
        );
    }
    if request.has_body {
        return http::refuse(stream, "413 Content Too Large", "no route takes a body");
    }
    let Some(route) = Route::of(&request.path) else {
        return http::refuse(stream, "404 Not Found", "no such page");
    };
    if request.method != route.method() {
        return http::refuse(stream, "405 Method Not Allowed", route.method());
    }
    match route {
        Route::Page => http::respond(
            stream,
            "200 OK",
            "text/html; charset=utf-8",
            routes::PAGE.as_bytes(),
        ),
        Route::Script => http::respond(
            stream,
            "200 OK",
            "text/javascript; charset=utf-8",
            routes::SCRIPT.as_bytes(),
        ),
        Route::Style => http::respond(
            stream,
            "200 OK",
            "text/css; charset=utf-8",
            routes::STYLE.as_bytes(),
        ),
        Route::Status => {
            let json = board.now().to_json();
            http::respond(stream, "200 OK", "application/json", json.as_bytes())
        }
        Route::Film => match board.now().frame {
            Some(frame) => http::respond(stream, "200 OK", "application/octet-stream", &frame),
            None => http::refuse(stream, "503 Service Unavailable", "no pass rendered yet"),
        },
        Route::Events => stream_events(stream, board),
        Route::Save => save_image(stream, request, served, port),
        Route::Against | Route::Heat => {
            let frame = board.now().compared.map(|c| match route {
                Route::Against => c.theirs.clone(),
                _ => c.heat.clone(),
            });
            match frame {
                Some(frame) if !frame.is_empty() => {
                    http::respond(stream, "200 OK", "application/octet-stream", &frame)
                }
                _ => http::refuse(stream, "404 Not Found", "no --against image measured"),
            }
        }
    }
}

/// Writes the image on the board to the output file, for the page only.
fn save_image(
    stream: &mut TcpStream,
    request: &Request,
    served: &Served,
    port: u16,
) -> std::io::Result<()> {
    if !routes::origin_allowed(request.origin.as_deref(), port) {
        return http::refuse(
            stream,
            "403 Forbidden",
            "saving is for this server's page only",
        );
    }
    let encoding = match save::encoding_of(&request.query) {
        Ok(encoding) => encoding,
        Err(why) => return http::refuse(stream, "400 Bad Request", &why),
    };
    let Some(image) = served.board.now().image else {
        return http::refuse(stream, "503 Service Unavailable", "no pass rendered yet");
    };
    let output = &served.output;
    match save::save(&image, output, &encoding, &served.board.inputs()) {
        Ok(()) => {
            let json = format!(
                "{{\"saved\": {}}}",
                super::status::string(&output.display().to_string())
            );
            http::respond(stream, "200 OK", "application/json", json.as_bytes())
        }
        Err(why) => http::refuse(stream, "500 Internal Server Error", &why),
    }
}

/// Sends the status now and after every post, until the client goes.
fn stream_events(stream: &mut TcpStream, board: &Board) -> std::io::Result<()> {
    http::start_events(stream)?;
    let now = board.now();
    http::event(stream, &now.to_json())?;
    let mut seen = now.generation;
    loop {
        match board.after(seen, KEEP_ALIVE) {
            Some(posted) => {
                seen = posted.generation;
                http::event(stream, &posted.to_json())?;
            }
            None => http::keep_alive(stream)?,
        }
    }
}
