//! `idxrender verilog --out DIR`: every top of `hdl::TOPS` in its own file with its own module name,
//! `files.f` listing them, a README documenting every port, and Verilator's `-Wall` lint accepting
//! each file with the project's named waivers.

use std::path::{Path, PathBuf};
use std::process::Command;
use tb::common::require_tools;

fn bin() -> Command {
    Command::new(env!("CARGO_BIN_EXE_idxrender"))
}

fn scratch(name: &str) -> PathBuf {
    let d = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("target").join("test-cli").join(name);
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// (name, direction, width) of the ports of `module top(` in a Verilog text, read independently of
/// the CLI's own parser.
fn ports_of(v: &str, top: &str) -> Vec<(String, String, usize)> {
    let start = v.find(&format!("\nmodule {top}(")).unwrap_or_else(|| panic!("no module {top}"));
    let body = &v[start + 1..];
    let body = &body[..body.find("endmodule").unwrap()];
    body.lines()
        .filter_map(|l| {
            let t = l.trim();
            let dir = if t.starts_with("input ") { "in" } else if t.starts_with("output ") { "out" } else { return None };
            let decl = t.trim_end_matches(';');
            let name = decl.split_whitespace().last().unwrap().to_string();
            let width = match (decl.find('['), decl.find(':'), decl.find(']')) {
                (Some(a), Some(c), Some(b)) => decl[a + 1..c].trim().parse::<usize>().unwrap() - decl[c + 1..b].trim().parse::<usize>().unwrap() + 1,
                _ => 1,
            };
            Some((name, dir.to_string(), width))
        })
        .collect()
}

fn generate(dir: &Path) {
    let o = bin().args(["verilog", "--out"]).arg(dir).output().unwrap();
    assert!(o.status.success(), "verilog failed:\n{}", String::from_utf8_lossy(&o.stderr));
}

#[test]
fn verilog_out_writes_every_top_with_its_module_name_and_a_file_list() {
    let dir = scratch("verilog_all");
    generate(&dir);
    let list = std::fs::read_to_string(dir.join("files.f")).expect("files.f");
    let listed: Vec<&str> = list.lines().collect();
    let tops: Vec<&str> = hdl::TOPS.iter().map(|t| t.0).collect();
    assert_eq!(listed, tops.iter().map(|t| format!("{t}.v")).collect::<Vec<_>>(), "files.f does not list exactly the tops");
    for top in &tops {
        let v = std::fs::read_to_string(dir.join(format!("{top}.v"))).unwrap_or_else(|e| panic!("{top}.v: {e}"));
        assert!(v.contains(&format!("\nmodule {top}(")), "{top}.v has no module {top}");
        assert!(!v.contains("\nmodule top("), "{top}.v still has a module named top");
        // Every other module is a submodule of this top, so the files can be read together.
        for m in v.lines().filter_map(|l| l.strip_prefix("module ")) {
            let name = m.split('(').next().unwrap();
            assert!(name == *top || name.starts_with(&format!("{top}$")), "{top}.v: module {name} is not named after the top");
        }
    }
}

#[test]
fn verilog_readme_documents_every_port_of_every_top() {
    let dir = scratch("verilog_readme");
    generate(&dir);
    let readme = std::fs::read_to_string(dir.join("README.md")).expect("README.md");
    for needle in ["rising edge", "no reset port", "latency 1", "old", "valid", "ready", "AXI4-Stream", "tuser", "tlast", "files.f"] {
        assert!(readme.contains(needle), "README does not mention `{needle}`");
    }
    for (top, _) in hdl::TOPS {
        let v = std::fs::read_to_string(dir.join(format!("{top}.v"))).unwrap();
        let section = readme.split(&format!("\n## `{top}`\n")).nth(1).unwrap_or_else(|| panic!("README has no section for {top}"));
        let section = section.split("\n## ").next().unwrap();
        let ports = ports_of(&v, top);
        assert!(ports.len() > 2, "{top}: too few ports read");
        let mut undocumented = Vec::new();
        for (name, dir, width) in &ports {
            let row = format!("| `{name}` | {dir} | {width} |");
            let line = section.lines().find(|l| l.starts_with(&row)).unwrap_or_else(|| panic!("README {top}: no row `{row}`"));
            let meaning = line.rsplit('|').nth(1).unwrap().trim();
            if meaning.is_empty() {
                undocumented.push(name.clone());
            }
        }
        assert!(undocumented.is_empty(), "README {top}: ports without a meaning: {undocumented:?}");
    }
}

#[test]
fn verilog_of_every_top_passes_verilator_lint_all_with_named_waivers() {
    if !require_tools("verilog_of_every_top_passes_verilator_lint_all_with_named_waivers", &["verilator"]) {
        return;
    }
    let dir = scratch("verilog_lint");
    generate(&dir);
    // Each top with its waivers from the project's one list (`tb::lint::LINT_WAIVERS`).
    for (top, _) in hdl::TOPS {
        let text = std::fs::read_to_string(dir.join(format!("{top}.v"))).unwrap();
        tb::lint::lint(&text, top, &dir.join("lint")).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn verilog_rejects_an_unknown_block_naming_the_known_ones() {
    let dir = scratch("verilog_unknown");
    let o = bin().args(["verilog", "--block", "nosuch", "--out"]).arg(&dir).output().unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("unknown block 'nosuch'") && err.contains("rc"), "{err}");
}

/// `verilog --size WxH` sizes exactly the tops of `hdl::SCREEN_TOPS` (the formal harness of the 2x2
/// filter uses a 4x3 build): their Verilog and README text follow the size, every other top is the
/// same file as the default build; a size a top cannot take is refused naming the top's limit, and
/// writes nothing.
#[test]
fn verilog_size_resizes_only_the_screen_sized_tops_and_refuses_sizes_they_cannot_take() {
    let small = scratch("verilog_size_4x3");
    let o = bin().args(["verilog", "--size", "4x3", "--out"]).arg(&small).output().unwrap();
    assert!(o.status.success(), "verilog --size 4x3 failed:\n{}", String::from_utf8_lossy(&o.stderr));
    let default = scratch("verilog_size_default");
    generate(&default);
    for (top, _) in hdl::TOPS {
        let a = std::fs::read(small.join(format!("{top}.v"))).unwrap();
        let b = std::fs::read(default.join(format!("{top}.v"))).unwrap();
        assert_eq!(a != b, hdl::SCREEN_TOPS.contains(top), "{top}: resized = {}, but SCREEN_TOPS says otherwise", a != b);
    }
    let readme = std::fs::read_to_string(small.join("README.md")).unwrap();
    assert!(!readme.contains("320x200") && !readme.contains("320-column"), "the 4x3 README still names the default screen");
    assert!(readme.contains("for a 4x3 screen") && readme.contains("4-column line buffer"), "{readme}");
    // The 2x2 filter's line buffer: one 112-bit word per column.
    assert!(readme.contains("Internal memories (block RAM on an FPGA): 4 x 112,"), "{readme}");

    let refused = scratch("verilog_size_1x3");
    let o = bin().args(["verilog", "--block", "proof_filter2x2", "--size", "1x3", "--out"]).arg(&refused).output().unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("1x3 screen") && err.contains("width must be 2..=1024"), "{err}");
    assert_eq!(std::fs::read_dir(&refused).unwrap().count(), 0, "a refused size wrote into {}", refused.display());
    let o = bin().args(["verilog", "--size", "320by200", "--out"]).arg(&refused).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("--size '320by200' is not WxH"), "{}", String::from_utf8_lossy(&o.stderr));
}

/// `verilog --out` is one unit (issue 18): a run for one block replaces a folder of every block whole
/// (no stale .v beside a files.f that no longer lists it); a write that fails halfway leaves the
/// previous folder complete; a folder with files verilog does not write is refused.
#[test]
fn verilog_out_is_replaced_whole_never_mixed_and_foreign_folders_are_refused() {
    let dir = scratch("verilog_unit");
    generate(&dir);
    let all: Vec<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    assert!(all.len() > 3);
    // A failed run: the third file stops halfway.
    let o = bin().args(["verilog", "--block", "rc", "--out"]).arg(&dir).env("IDXRENDER_FAIL_AFTER_WRITES", "1").output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("injected fault"), "{}", String::from_utf8_lossy(&o.stderr));
    let mut after: Vec<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    let mut before = all.clone();
    before.sort();
    after.sort();
    assert_eq!(after, before, "a failed run changed --out");
    let parent = dir.parent().unwrap();
    assert!(!std::fs::read_dir(parent).unwrap().any(|e| e.unwrap().file_name().to_string_lossy().starts_with(".verilog_unit.")), "staging left behind");
    // A good run for one block: exactly its files.
    let o = bin().args(["verilog", "--block", "rc", "--out"]).arg(&dir).output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let mut now: Vec<String> = std::fs::read_dir(&dir).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into_owned()).collect();
    now.sort();
    assert_eq!(now, ["README.md", "files.f", "rc.v"]);
    // A folder with a file of someone else's.
    std::fs::write(dir.join("my_wrapper.sv"), b"module w; endmodule").unwrap();
    let o = bin().args(["verilog", "--block", "rc", "--out"]).arg(&dir).output().unwrap();
    assert!(!o.status.success());
    assert!(String::from_utf8_lossy(&o.stderr).contains("my_wrapper.sv"), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(dir.join("my_wrapper.sv").exists() && dir.join("rc.v").exists());
}
