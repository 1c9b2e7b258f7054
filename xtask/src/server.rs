//! The local static file server of `cargo xtask serve` and the browser
//! tests: HTTP by `tiny_http`, GET and HEAD of the files under one folder
//! (a path that would leave it is refused), each with its MIME type, not
//! sniffed; the precompressed `file.br` or `file.gz` to a browser that
//! accepts Brotli or gzip (Brotli first: smaller);
//! cacheable by revalidation (an ETag of the file's size and time, 304 when
//! the browser has it).

use std::path::{Path, PathBuf};

use tiny_http::{Header, Method, Request, Response, Server};

use crate::Result;

/// A server on 127.0.0.1:`port` (0: any free port).
pub fn bind(port: u16) -> Result<Server> {
    Server::http(("127.0.0.1", port)).map_err(|e| format!("cannot listen on 127.0.0.1:{port}: {e}"))
}

/// The port `server` listens on.
pub fn port(server: &Server) -> Result<u16> {
    server.server_addr().to_ip().map(|a| a.port()).ok_or_else(|| "the server has no IP address".to_string())
}

/// Serves the files under `dir` until the process ends, each request on a
/// thread of its own (a slow reader of the wasm holds up no other).
pub fn serve_forever(server: Server, dir: PathBuf) {
    let dir = std::sync::Arc::new(dir);
    for request in server.incoming_requests() {
        let dir = std::sync::Arc::clone(&dir);
        std::thread::spawn(move || respond(request, &dir));
    }
}

/// Answers one request for a file under `dir`.
fn respond(request: Request, dir: &Path) {
    let head = *request.method() == Method::Head;
    let file = match request.method() {
        Method::Get | Method::Head => resolve(dir, request.url()),
        _ => {
            let _ = request.respond(Response::from_string("method not allowed\n").with_status_code(405));
            return;
        }
    };
    let header = |name: &'static str| {
        request.headers().iter().find(|h| h.field.equiv(name)).map(|h| h.value.as_str().to_string())
    };
    let accepted = header("Accept-Encoding").unwrap_or_default();
    let etag = file.as_ref().and_then(|f| etag(f));
    if etag.is_some() && header("If-None-Match") == etag {
        let mut response = Response::empty(304);
        if let Some(h) = etag.as_ref().and_then(|e| Header::from_bytes("ETag", e.as_str()).ok()) {
            response.add_header(h);
        }
        let _ = request.respond(response);
        return;
    }
    let packed = file.as_ref().and_then(|f| {
        [("br", ".br"), ("gzip", ".gz")].into_iter().filter(|(name, _)| accepts(&accepted, name)).find_map(
            |(name, suffix)| {
                let mut p = f.clone().into_os_string();
                p.push(suffix);
                std::fs::read(p).ok().map(|b| (name, b))
            },
        )
    });
    let (body, encoded) = match packed {
        Some((name, b)) => (Some(b), Some(name)),
        None => (file.as_ref().and_then(|f| std::fs::read(f).ok()), None),
    };
    let (status, mime, body) = match (&file, body) {
        (Some(f), Some(body)) => (200, mime(f), body),
        _ => (404, "text/plain", b"not found\n".to_vec()),
    };
    let len = body.len();
    let mut response = Response::from_data(if head { Vec::new() } else { body }).with_status_code(status);
    let mut headers = vec![
        ("Content-Type", mime.to_string()),
        ("Cache-Control", "no-cache".into()),
        ("X-Content-Type-Options", "nosniff".into()),
        ("Vary", "Accept-Encoding".into()),
    ];
    if let Some(name) = encoded {
        headers.push(("Content-Encoding", name.into()));
    }
    if let Some(e) = etag.filter(|_| status == 200) {
        headers.push(("ETag", e));
    }
    for (k, v) in headers {
        if let Ok(h) = Header::from_bytes(k, v.as_str()) {
            response.add_header(h);
        }
    }
    if head && let Ok(h) = Header::from_bytes("Content-Length", len.to_string()) {
        response.add_header(h);
    }
    let _ = request.respond(response);
}

/// Whether an `Accept-Encoding` value takes the coding `name` (listed, and
/// not with `q=0`; RFC 9110 §12.5.3).
fn accepts(value: &str, name: &str) -> bool {
    value.split(',').any(|item| {
        let mut parts = item.split(';').map(str::trim);
        let coding = parts.next().unwrap_or("");
        let refused = parts.any(|p| p.strip_prefix("q=").and_then(|q| q.parse::<f64>().ok()) == Some(0.0));
        coding.eq_ignore_ascii_case(name) && !refused
    })
}

/// A file's ETag: its size and modification time.
fn etag(file: &Path) -> Option<String> {
    let m = std::fs::metadata(file).ok()?;
    let t = m.modified().ok()?.duration_since(std::time::UNIX_EPOCH).ok()?.as_millis();
    Some(format!("\"{}-{t}\"", m.len()))
}

/// The file a request path names under `dir`, if it is inside it.
pub fn resolve(dir: &Path, target: &str) -> Option<PathBuf> {
    let path = target.split(['?', '#']).next().unwrap_or("/");
    let decoded = percent_encoding::percent_decode_str(path).decode_utf8().ok()?;
    let mut file = dir.to_path_buf();
    for part in decoded.split('/').filter(|p| !p.is_empty()) {
        if part == ".." || part == "." || part.contains('\\') {
            return None;
        }
        file.push(part);
    }
    if decoded.ends_with('/') || file == dir {
        file.push("index.html");
    }
    Some(file)
}

/// The MIME type of a file by its extension.
pub fn mime(path: &Path) -> &'static str {
    match path.extension().and_then(|e| e.to_str()).unwrap_or("") {
        "html" => "text/html; charset=utf-8",
        "js" | "mjs" => "text/javascript; charset=utf-8",
        "css" => "text/css; charset=utf-8",
        "wasm" => "application/wasm",
        "json" | "map" => "application/json; charset=utf-8",
        "svg" => "image/svg+xml",
        "png" => "image/png",
        "ico" => "image/x-icon",
        "nc" | "ngc" | "txt" | "md" => "text/plain; charset=utf-8",
        _ => "application/octet-stream",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn paths_resolve_inside_the_site_only() {
        let d = Path::new("/site");
        assert_eq!(resolve(d, "/"), Some(PathBuf::from("/site/index.html")));
        assert_eq!(resolve(d, "/?x=1#frag"), Some(PathBuf::from("/site/index.html")));
        assert_eq!(resolve(d, "/examples/o1006.nc"), Some(PathBuf::from("/site/examples/o1006.nc")));
        assert_eq!(resolve(d, "/a%20b.js"), Some(PathBuf::from("/site/a b.js")));
        assert_eq!(resolve(d, "/../etc/passwd"), None);
        assert_eq!(resolve(d, "/%2e%2e/etc/passwd"), None);
        assert_eq!(resolve(d, "/%ff"), None, "not UTF-8");
    }

    #[test]
    fn accept_encoding_is_read_by_coding_and_weight() {
        assert!(accepts("gzip, deflate, br, zstd", "br"));
        assert!(accepts("gzip, deflate, br, zstd", "gzip"));
        assert!(accepts("GZIP;q=0.5", "gzip"));
        assert!(!accepts("br;q=0, gzip", "br"), "q=0 refuses it");
        assert!(!accepts("brotli, xgzip", "br") && !accepts("brotli, xgzip", "gzip"), "whole codings only");
        assert!(!accepts("", "gzip") && !accepts("identity", "gzip"));
    }

    #[test]
    fn mime_types() {
        assert_eq!(mime(Path::new("a/screwcut_bg.wasm")), "application/wasm");
        assert_eq!(mime(Path::new("app.js")), "text/javascript; charset=utf-8");
        assert_eq!(mime(Path::new("index.html")), "text/html; charset=utf-8");
        assert_eq!(mime(Path::new("examples/index.json")), "application/json; charset=utf-8");
        assert_eq!(mime(Path::new("LICENSE")), "application/octet-stream");
        assert_eq!(mime(Path::new("element/README.md")), "text/plain; charset=utf-8");
    }

    /// A real request: a file, a missing one, and a way out of the folder.
    #[test]
    fn it_serves_files_and_nothing_outside() {
        let dir = std::env::temp_dir().join(format!("screwcut-server-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("index.html"), "<!doctype html>hi").unwrap();
        let server = bind(0).unwrap();
        let port = port(&server).unwrap();
        let d = dir.clone();
        std::thread::spawn(move || serve_forever(server, d));
        let get = |path: &str| {
            use std::io::{Read, Write};
            let mut s = std::net::TcpStream::connect(("127.0.0.1", port)).unwrap();
            write!(s, "GET {path} HTTP/1.0\r\nHost: x\r\n\r\n").unwrap();
            let mut out = String::new();
            s.read_to_string(&mut out).unwrap();
            out
        };
        let ok = get("/");
        assert!(ok.starts_with("HTTP/1.0 200") || ok.starts_with("HTTP/1.1 200"), "{ok}");
        assert!(ok.contains("text/html") && ok.ends_with("<!doctype html>hi"), "{ok}");
        assert!(get("/nothing.js").contains(" 404 "));
        assert!(get("/../../etc/passwd").contains(" 404 "));
        let _ = std::fs::remove_dir_all(&dir);
    }
}
