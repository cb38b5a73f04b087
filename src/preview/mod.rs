//! `pathtracer view`'s live preview: the film rendered in passes
//! ([`passes`]) and posted on a [`board::Board`], which a small web server
//! on 127.0.0.1 ([`server`]) serves to a page compiled into the binary
//! (`page/`): the page applies exposure, tone curve and gamma to the linear
//! film ([`frame`]) and hears of each new pass by server-sent events.
//!
//! Safe by construction: only the routes of [`routes::Route`] are served
//! (no request names a file), a `Host` other than this server's loopback
//! address and port is refused, and memory stays bounded however many
//! connections come ([`server::MAX_CONNECTIONS`], one frame held).

pub mod board;
pub mod compare;
pub mod frame;
pub mod http;
pub mod passes;
pub mod routes;
pub mod save;
pub mod server;
pub mod status;
pub mod tev;
pub mod watch;
