//! What the server answers: a fixed set of routes matched by their whole
//! path (no part of a request ever names a file), and the `Host` check that
//! keeps other sites' pages out (DNS rebinding).

/// Everything the server serves.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Route {
    /// The page (`/`).
    Page,
    Script,
    Style,
    /// Server-sent events: the status, once now and again on every change.
    Events,
    /// The latest frame of the film (see [`super::frame`]).
    Film,
    /// The status as JSON, once.
    Status,
    /// POST: write the image to the output file.
    Save,
    /// `--against`'s image at our size, and the FLIP map (display frames,
    /// see [`super::compare::display_frame`]).
    Against,
    Heat,
}

impl Route {
    /// The route of a GET of `path`, if there is one.
    pub fn of(path: &str) -> Option<Route> {
        Some(match path {
            "/" | "/index.html" => Route::Page,
            "/view.js" => Route::Script,
            "/view.css" => Route::Style,
            "/events" => Route::Events,
            "/film" => Route::Film,
            "/status" => Route::Status,
            "/save" => Route::Save,
            "/against" => Route::Against,
            "/heat" => Route::Heat,
            _ => return None,
        })
    }

    /// The one method the route answers.
    pub fn method(self) -> &'static str {
        match self {
            Route::Save => "POST",
            _ => "GET",
        }
    }
}

/// Whether a request's `Origin` is this server's page: what a page of
/// another site cannot send, so it cannot make this server write a file.
pub fn origin_allowed(origin: Option<&str>, port: u16) -> bool {
    origin
        .and_then(|o| o.strip_prefix("http://"))
        .is_some_and(|host| host_allowed(Some(host), port))
}

/// Whether a request's `Host` names this server: the loopback address or
/// `localhost`, with the port it listens on. A page of another site that
/// made its name resolve to 127.0.0.1 sends its own name, and is refused.
pub fn host_allowed(host: Option<&str>, port: u16) -> bool {
    let Some(host) = host else {
        return false;
    };
    let Some((name, given_port)) = host.rsplit_once(':') else {
        return false;
    };
    given_port.parse::<u16>() == Ok(port)
        && (name == "127.0.0.1" || name.eq_ignore_ascii_case("localhost"))
}

/// The page's files, compiled into the binary.
pub const PAGE: &str = include_str!("page/index.html");
pub const SCRIPT: &str = include_str!("page/view.js");
pub const STYLE: &str = include_str!("page/view.css");

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_the_pages_own_paths_are_routes() {
        assert_eq!(Route::of("/"), Some(Route::Page));
        assert_eq!(Route::of("/film"), Some(Route::Film));
        for path in [
            "/../../etc/passwd",
            "/etc/passwd",
            "//film",
            "/film/",
            "/%2e%2e/%2e%2e/etc/passwd",
            "/view.js/../../Cargo.toml",
            "",
        ] {
            assert_eq!(Route::of(path), None, "{path}");
        }
    }

    #[test]
    fn only_loopback_names_with_our_port_are_allowed_hosts() {
        assert!(host_allowed(Some("127.0.0.1:8123"), 8123));
        assert!(host_allowed(Some("localhost:8123"), 8123));
        assert!(host_allowed(Some("LocalHost:8123"), 8123));
        for host in [
            "evil.example:8123",
            "127.0.0.1:8124",
            "127.0.0.1",
            "localhost",
            "127.0.0.1.evil.example:8123",
            "127.0.0.2:8123",
            "",
        ] {
            assert!(!host_allowed(Some(host), 8123), "{host}");
        }
        assert!(!host_allowed(None, 8123));
        assert!(origin_allowed(Some("http://127.0.0.1:8123"), 8123));
        assert!(origin_allowed(Some("http://localhost:8123"), 8123));
        for origin in [
            "https://evil.example",
            "null",
            "http://127.0.0.1:8124",
            "127.0.0.1:8123",
        ] {
            assert!(!origin_allowed(Some(origin), 8123), "{origin}");
        }
        assert!(!origin_allowed(None, 8123));
    }
}
