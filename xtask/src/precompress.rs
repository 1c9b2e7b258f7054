//! The site precompressed, as a static host serves it: beside every text
//! and wasm file over 1 KiB its gzip (`file.gz`, level 9) and its Brotli
//! (`file.br`, quality 11, RFC 7932), which the local server sends to a
//! browser that accepts them (and a host such as nginx's `gzip_static` /
//! `brotli_static` or a CDN does the same).

use std::io::Write;
use std::path::Path;

use crate::Result;

/// The extensions compressed.
const COMPRESSED: [&str; 6] = ["html", "js", "css", "wasm", "json", "svg"];

/// Writes `f.gz` and `f.br` beside each file of `dir` (and its folders) worth compressing.
pub fn precompress(dir: &Path) -> Result {
    for entry in std::fs::read_dir(dir).map_err(|e| format!("{}: {e}", dir.display()))? {
        let path = entry.map_err(|e| e.to_string())?.path();
        if path.is_dir() {
            precompress(&path)?;
            continue;
        }
        let ext = path.extension().and_then(|e| e.to_str()).unwrap_or("");
        if !COMPRESSED.contains(&ext) {
            continue;
        }
        let data = std::fs::read(&path).map_err(|e| format!("{}: {e}", path.display()))?;
        if data.len() < 1024 {
            continue;
        }
        for (suffix, packed) in [(".gz", gzip(&data)?), (".br", brotli(&data)?)] {
            let mut out = path.clone().into_os_string();
            out.push(suffix);
            std::fs::write(&out, packed).map_err(|e| format!("{}: {e}", Path::new(&out).display()))?;
        }
    }
    Ok(())
}

/// `data` gzipped at level 9.
pub fn gzip(data: &[u8]) -> Result<Vec<u8>> {
    let mut e = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::best());
    e.write_all(data).map_err(|e| e.to_string())?;
    e.finish().map_err(|e| e.to_string())
}

/// `data` in Brotli at quality 11 with a 4 MiB window (`lgwin` 22).
pub fn brotli(data: &[u8]) -> Result<Vec<u8>> {
    let params = brotli::enc::BrotliEncoderParams { quality: 11, lgwin: 22, ..Default::default() };
    let mut out = Vec::new();
    brotli::BrotliCompress(&mut &data[..], &mut out, &params).map_err(|e| e.to_string())?;
    Ok(out)
}

/// The gzipped size of `file` (its `.gz` beside it), bytes.
pub fn gz_size(file: &Path) -> u64 {
    packed_size(file, ".gz")
}

/// The Brotli size of `file` (its `.br` beside it), bytes.
pub fn br_size(file: &Path) -> u64 {
    packed_size(file, ".br")
}

/// The size of `file` + `suffix`, bytes (0 when missing).
fn packed_size(file: &Path, suffix: &str) -> u64 {
    let mut packed = file.as_os_str().to_owned();
    packed.push(suffix);
    std::fs::metadata(packed).map(|m| m.len()).unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Read;

    #[test]
    fn each_worthy_file_gets_its_gzip_beside_it() {
        let dir = std::env::temp_dir().join(format!("screwcut-gz-{}", std::process::id()));
        std::fs::create_dir_all(dir.join("sub")).unwrap();
        let text = "G32 Z13 F2\n".repeat(500);
        std::fs::write(dir.join("a.js"), &text).unwrap();
        std::fs::write(dir.join("sub").join("b.wasm"), text.as_bytes()).unwrap();
        std::fs::write(dir.join("small.css"), "a{}").unwrap();
        std::fs::write(dir.join("p.png"), text.as_bytes()).unwrap();
        precompress(&dir).unwrap();
        let mut back = String::new();
        flate2::read::GzDecoder::new(std::fs::File::open(dir.join("a.js.gz")).unwrap())
            .read_to_string(&mut back)
            .unwrap();
        assert_eq!(back, text);
        let mut unbr = Vec::new();
        brotli::BrotliDecompress(&mut std::fs::File::open(dir.join("a.js.br")).unwrap(), &mut unbr).unwrap();
        assert_eq!(unbr, text.as_bytes());
        assert!(br_size(&dir.join("a.js")) > 0 && br_size(&dir.join("a.js")) <= gz_size(&dir.join("a.js")));
        assert!(dir.join("sub").join("b.wasm.gz").exists());
        assert!(dir.join("sub").join("b.wasm.br").exists());
        assert!(!dir.join("small.css.gz").exists() && !dir.join("p.png.gz").exists());
        assert!(!dir.join("small.css.br").exists() && !dir.join("p.png.br").exists());
        assert!(gz_size(&dir.join("a.js")) < 200);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
