//! Writing a frame's files: frame.png, index.bin, index.png, stats.json.

use golden::render::Frame;
use std::path::{Path, PathBuf};

/// Write `bytes` to `dir/name` through a temporary file and a rename, so that a reader (or a failed
/// run) never sees half a file.
pub fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<PathBuf, String> {
    let path = dir.join(name);
    let tmp = dir.join(format!(".{name}.tmp"));
    std::fs::write(&tmp, bytes).map_err(|e| format!("cannot write {}: {e}", tmp.display()))?;
    std::fs::rename(&tmp, &path).map_err(|e| format!("cannot write {}: {e}", path.display()))?;
    Ok(path)
}

pub fn png_bytes(width: u32, height: u32, rgb: &[u8]) -> Result<Vec<u8>, String> {
    let mut out = Vec::new();
    let enc = image::codecs::png::PngEncoder::new(&mut out);
    image::ImageEncoder::write_image(enc, rgb, width, height, image::ExtendedColorType::Rgb8).map_err(|e| format!("PNG encoding failed: {e}"))?;
    Ok(out)
}

/// The I-buffer as raw little-endian u32 per pixel, top row first.
pub fn index_bin(index: &[u32]) -> Vec<u8> {
    index.iter().flat_map(|i| i.to_le_bytes()).collect()
}

/// A false-colour view of an I-buffer: background black, each index a stable, well-spread hue.
pub fn index_false_colour(index: &[u32]) -> Vec<u8> {
    index
        .iter()
        .flat_map(|&i| {
            if i == 0 {
                [0, 0, 0]
            } else {
                // Multiplicative hash, then keep the colour away from black.
                let h = i.wrapping_mul(2654435761);
                [64 + (h >> 24) as u8 % 192, 64 + (h >> 16) as u8 % 192, 64 + (h >> 8) as u8 % 192]
            }
        })
        .collect()
}

/// Create `dir` and write the four files of a frame.
pub fn write_frame(dir: &Path, frame: &Frame, stats_json: &serde_json::Value) -> Result<Vec<PathBuf>, String> {
    std::fs::create_dir_all(dir).map_err(|e| format!("cannot create output directory {}: {e}", dir.display()))?;
    let (w, h) = (frame.screen.width, frame.screen.height);
    Ok(vec![
        write_atomic(dir, "frame.png", &png_bytes(w, h, &frame.rgb)?)?,
        write_atomic(dir, "index.bin", &index_bin(&frame.index))?,
        write_atomic(dir, "index.png", &png_bytes(w, h, &index_false_colour(&frame.index))?)?,
        write_atomic(dir, "stats.json", serde_json::to_string_pretty(stats_json).unwrap().as_bytes())?,
    ])
}
