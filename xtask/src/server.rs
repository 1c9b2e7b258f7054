//! The local static file server of `cargo xtask serve`, `cargo xtask book`
//! and the browser tests: tower-http's `ServeDir` over hyper (HTTP/1.1,
//! every connection a task of its own, however many the browser opens at
//! once and keeps alive). GET and HEAD of the files under one folder (a
//! path that would leave it is a 404), each with its MIME type and not
//! sniffed; the precompressed `file.br` or `file.gz` to a browser that
//! accepts Brotli or gzip (Brotli first: smaller); cacheable by
//! revalidation (`ETag` and `Last-Modified`, 304 when the browser has
//! the file).

use std::convert::Infallible;
use std::path::{Path, PathBuf};

use http::header::HeaderValue;
use http::{Request, Response};
use tower::ServiceExt;
use tower_http::services::ServeDir;

use crate::Result;

/// A listening socket on 127.0.0.1, not yet serving.
pub struct Server {
    listener: std::net::TcpListener,
}

/// A server on 127.0.0.1:`port` (0: any free port).
pub fn bind(port: u16) -> Result<Server> {
    let listener = std::net::TcpListener::bind(("127.0.0.1", port))
        .map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))?;
    Ok(Server { listener })
}

/// The port `server` listens on.
pub fn port(server: &Server) -> Result<u16> {
    server.listener.local_addr().map(|a| a.port()).map_err(|e| format!("the server has no address: {e}"))
}

/// Serves the files under `dir` until the process ends (or says why it
/// cannot).
pub fn serve_forever(server: Server, dir: PathBuf) {
    if let Err(e) = run(server, dir) {
        eprintln!("xtask: the file server stopped: {e}");
    }
}

/// The server's runtime: two worker threads, each connection a task.
fn run(server: Server, dir: PathBuf) -> Result {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_io()
        .build()
        .map_err(|e| format!("cannot start the server's runtime: {e}"))?;
    runtime.block_on(async move {
        server.listener.set_nonblocking(true).map_err(|e| e.to_string())?;
        let listener = tokio::net::TcpListener::from_std(server.listener).map_err(|e| e.to_string())?;
        let files = ServeDir::new(dir).precompressed_br().precompressed_gzip();
        loop {
            let stream = match listener.accept().await {
                Ok((stream, _)) => stream,
                Err(e) => {
                    eprintln!("xtask: the file server could not accept a connection: {e}");
                    continue;
                }
            };
            let files = files.clone();
            let service = hyper::service::service_fn(move |request| answer(files.clone(), request));
            tokio::spawn(async move {
                let io = hyper_util::rt::TokioIo::new(stream);
                // A connection the browser drops mid-answer is not the server's error.
                let _ = hyper::server::conn::http1::Builder::new().serve_connection(io, service).await;
            });
        }
    })
}

/// Answers one request from `files`, with the headers the site is served with.
async fn answer(
    files: ServeDir,
    request: Request<hyper::body::Incoming>,
) -> std::result::Result<Response<tower_http::services::fs::ServeFileSystemResponseBody>, Infallible> {
    let mut path = request.uri().path().to_string();
    if path.ends_with('/') {
        path.push_str("index.html");
    }
    let mut response = files.oneshot(request).await?;
    let ok = response.status().is_success();
    let headers = response.headers_mut();
    if ok && let Some(mime) = mime(Path::new(&path)) {
        headers.insert(http::header::CONTENT_TYPE, HeaderValue::from_static(mime));
    }
    headers.insert(http::header::CACHE_CONTROL, HeaderValue::from_static("no-cache"));
    headers.insert(http::header::X_CONTENT_TYPE_OPTIONS, HeaderValue::from_static("nosniff"));
    if !headers.contains_key(http::header::VARY) {
        headers.insert(http::header::VARY, HeaderValue::from_static("accept-encoding"));
    }
    Ok(response)
}

/// The MIME type of the site's files by extension, with the charset of the
/// text ones (a G-code file shown as text, not downloaded); `None` leaves
/// `ServeDir`'s guess.
pub fn mime(path: &Path) -> Option<&'static str> {
    Some(match path.extension().and_then(|e| e.to_str()).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "wasm" => "application/wasm",
        "json" | "map" => "application/json; charset=utf-8",
        "svg" => "image/svg+xml",
        "nc" | "ngc" | "txt" | "md" => "text/plain; charset=utf-8",
        _ => return None,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::{Read, Write};

    /// A site of three files in a folder of its own, served on a free port.
    fn site(name: &str) -> (PathBuf, u16) {
        let dir = std::env::temp_dir().join(format!("screwcut-server-{name}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(dir.join("examples")).unwrap();
        std::fs::write(dir.join("index.html"), "<!doctype html>hi").unwrap();
        std::fs::write(dir.join("examples").join("o1.nc"), "G00 X58 Z70\n").unwrap();
        std::fs::write(dir.join("app.js"), "plain").unwrap();
        std::fs::write(dir.join("app.js.gz"), "gzip!").unwrap();
        std::fs::write(dir.join("app.js.br"), "br!").unwrap();
        let server = bind(0).unwrap();
        let port = port(&server).unwrap();
        let d = dir.clone();
        std::thread::spawn(move || serve_forever(server, d));
        (dir, port)
    }

    /// One request on a connection of its own: the status line, the
    /// headers (names in lower case) and the body.
    fn get(port: u16, path: &str, headers: &str) -> (String, String, String) {
        let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
        write!(s, "GET {path} HTTP/1.1\r\nHost: x\r\nConnection: close\r\n{headers}\r\n").unwrap();
        let mut out = String::new();
        s.read_to_string(&mut out).unwrap();
        let (head, body) = out.split_once("\r\n\r\n").unwrap();
        let (status, fields) = head.split_once("\r\n").unwrap_or((head, ""));
        let fields = fields.lines().map(|l| match l.split_once(": ") {
            Some((name, value)) => format!("{}: {value}\n", name.to_lowercase()),
            None => format!("{l}\n"),
        });
        (status.to_string(), fields.collect(), body.to_string())
    }

    #[test]
    fn it_serves_files_and_nothing_outside() {
        let (dir, port) = site("files");
        let (status, headers, body) = get(port, "/", "");
        assert!(status.contains(" 200 "), "{status}");
        assert!(headers.contains("content-type: text/html; charset=utf-8") && body == "<!doctype html>hi", "{headers}");
        assert!(headers.contains("cache-control: no-cache") && headers.contains("x-content-type-options: nosniff"));
        let (_, headers, body) = get(port, "/examples/o1.nc", "");
        assert!(headers.contains("content-type: text/plain; charset=utf-8") && body == "G00 X58 Z70\n", "{headers}");
        assert!(get(port, "/nothing.js", "").0.contains(" 404 "));
        assert!(get(port, "/../../etc/passwd", "").0.contains(" 404 "));
        assert!(get(port, "/%2e%2e/%2e%2e/etc/passwd", "").0.contains(" 404 "));
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn brotli_first_then_gzip_then_the_file() {
        let (dir, port) = site("codings");
        let (_, headers, body) = get(port, "/app.js", "Accept-Encoding: gzip, deflate, br, zstd\r\n");
        assert!(headers.contains("content-encoding: br") && body == "br!", "{headers}");
        assert!(headers.contains("vary: accept-encoding"), "{headers}");
        let (_, headers, body) = get(port, "/app.js", "Accept-Encoding: br;q=0, gzip\r\n");
        assert!(headers.contains("content-encoding: gzip") && body == "gzip!", "{headers}");
        let (_, headers, body) = get(port, "/app.js", "");
        assert!(!headers.contains("content-encoding") && body == "plain", "{headers}");
        assert!(headers.contains("content-type: text/javascript; charset=utf-8"), "{headers}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn asked_again_with_its_tag_or_date_a_file_is_not_sent() {
        let (dir, port) = site("revalidate");
        let (_, headers, _) = get(port, "/app.js", "");
        let date = headers.lines().find_map(|l| l.strip_prefix("last-modified: ")).unwrap().to_string();
        let (status, _, body) = get(port, "/app.js", &format!("If-Modified-Since: {date}\r\n"));
        assert!(status.contains(" 304 ") && body.is_empty(), "{status}");
        let tag = headers.lines().find_map(|l| l.strip_prefix("etag: ")).unwrap().to_string();
        let (status, _, body) = get(port, "/app.js", &format!("If-None-Match: {tag}\r\n"));
        assert!(status.contains(" 304 ") && body.is_empty(), "{status}");
        let _ = std::fs::remove_dir_all(&dir);
    }

    /// A browser opens several connections at once and keeps them open:
    /// every one is answered (a pool of four threads, one per kept
    /// connection, left the fifth and later unanswered until one closed).
    #[test]
    fn many_connections_opened_at_once_are_all_answered() {
        let (dir, port) = site("many");
        let mut kept = Vec::new();
        for _ in 0..20 {
            let barrier = std::sync::Arc::new(std::sync::Barrier::new(8));
            let opened: Vec<_> = (0..8)
                .map(|_| {
                    let barrier = barrier.clone();
                    std::thread::spawn(move || {
                        barrier.wait();
                        let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
                        s.set_read_timeout(Some(std::time::Duration::from_secs(5))).unwrap();
                        write!(s, "GET / HTTP/1.1\r\nHost: x\r\n\r\n").unwrap();
                        let mut buf = [0u8; 12];
                        let answered = s.read_exact(&mut buf).is_ok() && buf.starts_with(b"HTTP/1.1 200");
                        (answered, s)
                    })
                })
                .collect();
            for o in opened {
                let (answered, s) = o.join().unwrap();
                assert!(answered, "a kept-alive connection got no answer within 5 s");
                kept.push(s);
            }
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
}
