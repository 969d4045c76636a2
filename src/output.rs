//! Writing a run's files: frame.png, index.bin, index.png, stats.json, and the rest.
//!
//! A run's files are a unit ([`OutputDir`]): they are written into a hidden folder beside `--out` and
//! moved into place together when the last one is written, so `--out` holds either the previous run's
//! complete result or this run's, never a mix, never a half-written file, and no file of an earlier run
//! that this run does not write (an RTL run's `cycles.json` after a golden run).

use golden::render::Frame;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

/// The files a run of this program writes into `--out`: a folder holding only these (or nothing) may
/// be replaced by a new run's.
pub const KNOWN_OUTPUTS: &[&str] = &[
    "frame.png", "index.bin", "index.png", "stats.json", "cycles.json", "chipset.v", "frame.vcd", "coverage.png", "shade.vcd", "filter.vcd",
];

/// Files written so far by this process (for the fault injection of `IDXRENDER_FAIL_AFTER_WRITES`).
static WRITES: AtomicUsize = AtomicUsize::new(0);

/// Write `bytes` to `dir/name` through a temporary file and a rename, so that a reader (or a failed
/// run) never sees half a file.
///
/// Fault injection for the tests: with `IDXRENDER_FAIL_AFTER_WRITES=N`, the write after the N-th of
/// the process stops halfway and fails, as a full disk would.
pub fn write_atomic(dir: &Path, name: &str, bytes: &[u8]) -> Result<PathBuf, String> {
    Ok(write_set(dir, &[(name, bytes)])?.remove(0))
}

/// Write several files that belong together (a report's .md and .json) beside other files: every
/// file is written in full under a temporary name first, and only then are they renamed into place,
/// so a failed write (a full disk, a file-size limit) leaves the previous set whole, never a new .md
/// beside an old .json.
pub fn write_set(dir: &Path, files: &[(&str, &[u8])]) -> Result<Vec<PathBuf>, String> {
    let tmp = |name: &str| dir.join(format!(".{name}.tmp"));
    let clean = || {
        for (name, _) in files {
            let _ = std::fs::remove_file(tmp(name));
        }
    };
    for (name, bytes) in files {
        let n = WRITES.fetch_add(1, Ordering::Relaxed);
        let fail = std::env::var("IDXRENDER_FAIL_AFTER_WRITES").ok().and_then(|v| v.parse::<usize>().ok()).is_some_and(|k| n >= k);
        let r = if fail {
            let _ = std::fs::write(tmp(name), &bytes[..bytes.len() / 2]);
            Err(format!("cannot write {}: injected fault after {n} files (IDXRENDER_FAIL_AFTER_WRITES)", tmp(name).display()))
        } else {
            std::fs::write(tmp(name), bytes).map_err(|e| format!("cannot write {}: {e}", tmp(name).display()))
        };
        if let Err(e) = r {
            clean();
            return Err(e);
        }
    }
    let mut paths = Vec::new();
    for (name, _) in files {
        let path = dir.join(name);
        std::fs::rename(tmp(name), &path).map_err(|e| {
            clean();
            format!("cannot write {}: {e}", path.display())
        })?;
        paths.push(path);
    }
    Ok(paths)
}

/// The output folder of one run, staged: write into [`OutputDir::dir`], then [`OutputDir::commit`].
/// Dropped without a commit (an error on the way), it removes what it staged and `--out` is as it was.
pub struct OutputDir {
    out: PathBuf,
    stage: PathBuf,
    parent: PathBuf,
    name: String,
    committed: bool,
}

impl OutputDir {
    /// Check `out` (a folder holding nothing but this program's outputs, or nothing, or not there yet)
    /// and make the staging folder beside it.
    pub fn begin(out: &Path) -> Result<OutputDir, String> {
        OutputDir::begin_with(out, &|n| KNOWN_OUTPUTS.contains(&n))
    }

    /// [`OutputDir::begin`] for a command whose files are those `is_ours` accepts (`verilog`,
    /// `analyze`): a folder holding anything else is refused, never replaced.
    pub fn begin_with(out: &Path, is_ours: &dyn Fn(&str) -> bool) -> Result<OutputDir, String> {
        let name = out.file_name().map(|n| n.to_string_lossy().into_owned()).ok_or_else(|| format!("--out {}: not a folder name", out.display()))?;
        let parent = match out.parent() {
            Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
            _ => PathBuf::from("."),
        };
        if out.exists() {
            if !out.is_dir() {
                return Err(format!("--out {}: exists and is not a folder", out.display()));
            }
            let entries = std::fs::read_dir(out).map_err(|e| format!("--out {}: cannot read it: {e}", out.display()))?;
            let mut foreign: Vec<String> = entries
                .filter_map(|e| e.ok())
                .map(|e| e.file_name().to_string_lossy().into_owned())
                .filter(|n| !is_ours(n.as_str()) && !(n.starts_with('.') && n.ends_with(".tmp")))
                .collect();
            if !foreign.is_empty() {
                foreign.sort();
                return Err(format!(
                    "--out {}: holds files this program does not write ({}); a run replaces the whole folder, so give a new or empty one",
                    out.display(),
                    foreign.join(", ")
                ));
            }
        }
        std::fs::create_dir_all(&parent).map_err(|e| format!("--out {}: cannot create {}: {e}", out.display(), parent.display()))?;
        let stage = parent.join(format!(".{name}.new-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&stage);
        std::fs::create_dir(&stage).map_err(|e| format!("--out {}: cannot create {}: {e}", out.display(), stage.display()))?;
        Ok(OutputDir { out: out.to_path_buf(), stage, parent, name, committed: false })
    }

    /// Where this run's files go until the commit.
    pub fn dir(&self) -> &Path {
        &self.stage
    }

    /// The path a staged file will have in `--out`.
    pub fn final_path(&self, staged: &Path) -> PathBuf {
        staged.strip_prefix(&self.stage).map(|rel| self.out.join(rel)).unwrap_or_else(|_| staged.to_path_buf())
    }

    /// Put the staged folder in the place of `--out` (the previous one is removed after).
    pub fn commit(mut self) -> Result<(), String> {
        let old = self.parent.join(format!(".{}.old-{}", self.name, std::process::id()));
        let had_old = self.out.exists();
        if had_old {
            let _ = std::fs::remove_dir_all(&old);
            std::fs::rename(&self.out, &old).map_err(|e| format!("cannot replace {}: {e}", self.out.display()))?;
        }
        if let Err(e) = std::fs::rename(&self.stage, &self.out) {
            if had_old {
                let _ = std::fs::rename(&old, &self.out);
            }
            return Err(format!("cannot move the new files into {}: {e}", self.out.display()));
        }
        self.committed = true;
        if had_old {
            let _ = std::fs::remove_dir_all(&old);
        }
        Ok(())
    }
}

impl Drop for OutputDir {
    fn drop(&mut self) {
        if !self.committed {
            let _ = std::fs::remove_dir_all(&self.stage);
        }
    }
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

/// Write the four files of a frame into `dir`.
pub fn write_frame(dir: &Path, frame: &Frame, stats_json: &serde_json::Value) -> Result<Vec<PathBuf>, String> {
    let (w, h) = (frame.screen.width, frame.screen.height);
    Ok(vec![
        write_atomic(dir, "frame.png", &png_bytes(w, h, &frame.rgb)?)?,
        write_atomic(dir, "index.bin", &index_bin(&frame.index))?,
        write_atomic(dir, "index.png", &png_bytes(w, h, &index_false_colour(&frame.index))?)?,
        write_atomic(dir, "stats.json", serde_json::to_string_pretty(stats_json).unwrap().as_bytes())?,
    ])
}

#[cfg(test)]
mod tests {
    use super::write_set;

    /// A report's .md and .json (bench, fpga-report) go in together: when the second cannot be
    /// written, the first keeps its earlier content and no temporary file is left.
    #[test]
    fn a_set_whose_second_file_cannot_be_written_leaves_the_first_as_it_was() {
        let dir = std::env::temp_dir().join(format!("idxrender-write-set-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        std::fs::write(dir.join("r.md"), b"earlier").unwrap();
        // The second file's temporary name is taken by a folder, so its write fails.
        std::fs::create_dir(dir.join(".r.json.tmp")).unwrap();
        let e = write_set(&dir, &[("r.md", b"new md"), ("r.json", b"{}")]).unwrap_err();
        assert!(e.contains(".r.json.tmp"), "{e}");
        assert_eq!(std::fs::read(dir.join("r.md")).unwrap(), b"earlier");
        assert!(!dir.join(".r.md.tmp").exists() && !dir.join("r.json").exists());
        std::fs::remove_dir(dir.join(".r.json.tmp")).unwrap();
        let paths = write_set(&dir, &[("r.md", b"new md"), ("r.json", b"{}")]).unwrap();
        assert_eq!(paths, [dir.join("r.md"), dir.join("r.json")]);
        assert_eq!(std::fs::read(dir.join("r.md")).unwrap(), b"new md");
        let _ = std::fs::remove_dir_all(&dir);
    }
}
