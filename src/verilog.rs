//! `idxrender verilog`: write the generated Verilog of the RTL tops, for an FPGA flow.
//!
//! `--out DIR` receives one `<top>.v` per top (top module named after the top, submodules
//! `<top>$child`), `files.f` (the file list, one path per line, for yosys/Verilator/simulators) and a
//! `README.md` that documents, per top, its ports (name, direction, width, meaning), the memory
//! interface, the handshake and the clocking. Everything the README says about a top is read from its
//! generated Verilog (ports, clock edges, power-up values, internal memories) or from the `///` doc
//! comments of the RustHDL struct that defines the top (port meanings), so it cannot drift from the RTL.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

#[derive(clap::Args, Debug)]
pub struct VerilogArgs {
    /// The top to generate (one of `hdl::TOPS`); all of them when left out.
    #[arg(long)]
    pub block: Option<String>,
    /// Output directory: one `<block>.v` per top, `files.f` and `README.md`, replaced as a whole (a
    /// folder holding other files is refused).
    #[arg(long, default_value = "out/verilog")]
    pub out: PathBuf,
    /// Screen size WxH that the screen-sized tops (proof_filter2x2, rc, rc3, chipset, chipset3, chipset_tex) are
    /// generated for: their address widths and the 2x2 filter's line buffer follow it. The other
    /// tops do not depend on it.
    #[arg(long, default_value = "320x200")]
    pub size: String,
}

/// Direction of a top-level port.
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub enum Dir {
    In,
    Out,
}

impl Dir {
    pub fn as_str(self) -> &'static str {
        match self {
            Dir::In => "in",
            Dir::Out => "out",
        }
    }
}

/// A port of a top module as declared in the generated Verilog.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Port {
    pub name: String,
    pub dir: Dir,
    pub width: usize,
}

/// The names of the tops, in `hdl::TOPS` order, or the one `block` names (checked).
pub fn selected_tops(block: Option<&str>) -> Result<Vec<String>, String> {
    let all: Vec<String> = hdl::TOPS.iter().map(|t| t.0.to_string()).collect();
    if all.is_empty() {
        return Err("no RTL tops are defined yet".into());
    }
    match block {
        None => Ok(all),
        Some(b) if all.iter().any(|t| t == b) => Ok(vec![b.to_string()]),
        Some(b) => Err(format!("unknown block '{b}': known blocks are {}", all.join(", "))),
    }
}

/// The ports of module `top` in `verilog`, in declaration order (the `clock` included).
pub fn parse_ports(verilog: &str, top: &str) -> Result<Vec<Port>, String> {
    let head = format!("module {top}(");
    let start = verilog
        .lines()
        .position(|l| l.trim_start().starts_with(&head))
        .ok_or_else(|| format!("the Verilog has no module named `{top}`"))?;
    let mut ports = Vec::new();
    for line in verilog.lines().skip(start + 1) {
        let t = line.trim();
        if t.starts_with("endmodule") || t.starts_with("module ") {
            break;
        }
        let dir = if let Some(r) = t.strip_prefix("input ") {
            (Dir::In, r)
        } else if let Some(r) = t.strip_prefix("output ") {
            (Dir::Out, r)
        } else {
            continue;
        };
        // "wire  [189:0] cmd$data;" / "reg  z_re;"
        // "wire signed [39:0] tdbv_rd_a;": a signed port's width reads the same way.
        let rest = dir.1.trim_start_matches("wire").trim_start_matches("reg").trim();
        let rest = rest.strip_prefix("signed").unwrap_or(rest).trim().trim_end_matches(';').trim();
        let (width, name) = if let Some(r) = rest.strip_prefix('[') {
            let (range, name) = r.split_once(']').ok_or_else(|| format!("{top}: cannot read the port declaration `{t}`"))?;
            let (hi, lo) = range.split_once(':').ok_or_else(|| format!("{top}: cannot read the range of `{t}`"))?;
            let hi: usize = hi.trim().parse().map_err(|_| format!("{top}: cannot read the range of `{t}`"))?;
            let lo: usize = lo.trim().parse().map_err(|_| format!("{top}: cannot read the range of `{t}`"))?;
            (hi.abs_diff(lo) + 1, name.trim())
        } else {
            (1, rest)
        };
        if name.is_empty() || name.contains(char::is_whitespace) {
            return Err(format!("{top}: cannot read the port declaration `{t}`"));
        }
        ports.push(Port { name: name.to_string(), dir: dir.0, width });
    }
    if ports.is_empty() {
        return Err(format!("module `{top}` declares no ports"));
    }
    Ok(ports)
}

/// A field of a RustHDL block struct with its doc comment and the `// ...` group comment above it.
#[derive(Clone, Debug, Default)]
struct Field {
    name: String,
    ty: String,
    doc: String,
    group: String,
}

/// Every `pub struct` of the Rust sources under `dir` with its `pub` fields.
fn rust_structs(dir: &Path, out: &mut Vec<(String, Vec<Field>)>) {
    let Ok(rd) = std::fs::read_dir(dir) else { return };
    let mut entries: Vec<PathBuf> = rd.filter_map(|e| e.ok().map(|e| e.path())).collect();
    entries.sort();
    for p in entries {
        if p.is_dir() {
            rust_structs(&p, out);
        } else if p.extension().is_some_and(|e| e == "rs") {
            if let Ok(text) = std::fs::read_to_string(&p) {
                parse_structs(&text, out);
            }
        }
    }
}

fn parse_structs(text: &str, out: &mut Vec<(String, Vec<Field>)>) {
    let mut lines = text.lines();
    while let Some(l) = lines.next() {
        let t = l.trim();
        let Some(rest) = t.strip_prefix("pub struct ") else { continue };
        if !t.ends_with('{') {
            continue;
        }
        let name: String = rest.chars().take_while(|c| c.is_alphanumeric() || *c == '_').collect();
        let (mut fields, mut doc, mut group) = (Vec::new(), Vec::<String>::new(), String::new());
        for l in lines.by_ref() {
            let t = l.trim();
            if t == "}" {
                break;
            }
            if let Some(d) = t.strip_prefix("///") {
                doc.push(d.trim().to_string());
            } else if let Some(c) = t.strip_prefix("//") {
                group = c.trim().to_string();
                doc.clear();
            } else if let Some(f) = t.strip_prefix("pub ") {
                if let Some((fname, ty)) = f.split_once(':') {
                    fields.push(Field { name: fname.trim().to_string(), ty: ty.trim().trim_end_matches(',').to_string(), doc: doc.join(" "), group: group.clone() });
                }
                doc.clear();
            } else if !t.starts_with('#') && !t.is_empty() {
                doc.clear();
            }
        }
        out.push((name, fields));
    }
}

/// Meaning of each port of a top, from the doc comments of the RustHDL struct whose `pub` port fields
/// are exactly the ports' base names (`cmd$data` -> `cmd`). Returns the struct's name and, per port,
/// (group, meaning); `None` when the sources are not at hand or no struct matches.
fn port_docs(top: &str, ports: &[Port]) -> Option<(String, BTreeMap<String, (String, String)>)> {
    let src = Path::new(env!("CARGO_MANIFEST_DIR")).join("hdl").join("src");
    let mut structs = Vec::new();
    rust_structs(&src, &mut structs);
    let bases: std::collections::BTreeSet<&str> = ports.iter().map(|p| p.name.split('$').next().unwrap()).collect();
    let is_port = |f: &Field| f.ty.starts_with("Signal<In") || f.ty.starts_with("Signal<Out") || f.ty.starts_with("StreamIn<") || f.ty.starts_with("StreamOut<");
    let matches = |fields: &Vec<Field>| {
        let names: std::collections::BTreeSet<&str> = fields.iter().filter(|f| is_port(f)).map(|f| f.name.as_str()).collect();
        names == bases
    };
    // The struct named for a known top (several blocks can share a port list: PROOF's shading and
    // filter stages), else the only struct with exactly these ports.
    let candidates: Vec<(String, Vec<Field>)> = structs.into_iter().filter(|(_, f)| matches(f)).collect();
    let (sname, fields) = match known_struct(top) {
        Some(k) => candidates.into_iter().find(|(n, _)| n == k)?,
        None if candidates.len() == 1 => candidates.into_iter().next()?,
        None => return None,
    };
    let mut docs = BTreeMap::new();
    for p in ports {
        let (base, sub) = match p.name.split_once('$') {
            Some((b, s)) => (b, Some(s)),
            None => (p.name.as_str(), None),
        };
        let Some(i) = fields.iter().position(|f| f.name == base) else { continue };
        let f = &fields[i];
        let meaning = match sub {
            Some(s) => {
                let payload = f.ty.split_once('<').map(|x| x.1.trim_end_matches('>')).unwrap_or("");
                let what = if f.doc.is_empty() { format!("stream `{base}`") } else { format!("stream `{base}` ({})", f.doc.trim_end_matches('.')) };
                match s {
                    "data" => format!("{what}: the payload, a `{payload}`"),
                    "valid" => format!("{what}: `{base}$data` holds a payload"),
                    "ready" => format!("{what}: the receiver takes the payload"),
                    other => format!("{what}: `{other}`"),
                }
            }
            None if !f.doc.is_empty() => f.doc.clone(),
            None if base.ends_with("_tvalid") => "AXI4-Stream: `tdata` (with `tuser`, `tlast`) holds a beat".into(),
            None if base.ends_with("_tready") => "AXI4-Stream: the display takes the beat".into(),
            None => {
                // Documented together with the field above it (`z_re`, then `z_rd_addr`, `z_rd_data`).
                match fields[..i].iter().rev().find(|g| !g.doc.is_empty() && g.group == f.group) {
                    Some(g) => format!("with `{}`: {}", g.name, g.doc),
                    None => String::new(),
                }
            }
        };
        docs.insert(p.name.clone(), (f.group.clone(), meaning));
    }
    Some((sname, docs))
}

/// The RustHDL struct that defines a known top.
fn known_struct(top: &str) -> Option<&'static str> {
    Some(match top {
        "opp" => "Opp",
        "proof_shade" => "ShadingStage",
        "proof_filter" => "FilterStage",
        "proof_filter2x2" => "Filter2x2Stage",
        "rc" => "Rc",
        "rc3" => "Rc3",
        "colour_setup" => "ColourSetup",
        "cs" => "ColorShader",
        "chipset" => "Chipset",
        "chipset3" => "Chipset3",
        "cs_tex" => "ColorShaderTex",
        "chipset_tex" => "ChipsetTex",
        _ => return None,
    })
}

/// What the Verilog of a top says about its clocking and internal memories.
#[derive(Clone, Debug, Default)]
pub struct VerilogFacts {
    pub posedge_blocks: usize,
    pub negedge_blocks: usize,
    pub initial_values: usize,
    pub nonzero_initial_values: usize,
    /// Internal memory arrays: (words, bits per word).
    pub memories: Vec<(u64, u64)>,
    pub modules: usize,
}

pub fn verilog_facts(v: &str) -> VerilogFacts {
    let mut f = VerilogFacts::default();
    let mut lines = v.lines().peekable();
    while let Some(l) = lines.next() {
        let t = l.trim();
        f.posedge_blocks += t.matches("posedge").count();
        f.negedge_blocks += t.matches("negedge").count();
        f.modules += t.starts_with("module ") as usize;
        if t == "initial begin" {
            while let Some(n) = lines.peek() {
                let n = n.trim();
                if n == "end" {
                    break;
                }
                if let Some((_, val)) = n.split_once('=') {
                    f.initial_values += 1;
                    let digits = val.trim().trim_end_matches(';').rsplit(['h', 'b', 'd']).next().unwrap_or("");
                    if digits.chars().any(|c| c.is_ascii_alphanumeric() && c != '0') {
                        f.nonzero_initial_values += 1;
                    }
                }
                lines.next();
            }
        }
        // "(* no_rw_check *) reg [95:0] mem [0:255];"
        if let Some(i) = t.find("reg [") {
            let r = &t[i + 5..];
            if let (Some((w, rest)), true) = (r.split_once(']'), r.matches('[').count() == 1) {
                if let Some((_, range)) = rest.split_once('[') {
                    let range = range.trim_end_matches(';').trim_end_matches(']');
                    let num = |s: &str| s.trim().parse::<u64>().ok();
                    let width = w.split_once(':').and_then(|(h, l)| Some(num(h)?.abs_diff(num(l)?) + 1));
                    let words = range.split_once(':').and_then(|(a, b)| Some(num(a)?.abs_diff(num(b)?) + 1));
                    if let (Some(wd), Some(n)) = (width, words) {
                        f.memories.push((n, wd));
                    }
                }
            }
        }
    }
    f
}

/// The memory ports of each known top (outside the core, synchronous): what a user must attach.
fn memory_interface(top: &str, screen: (u32, u32)) -> String {
    let text = match top {
        "rc" => "Z-buffer (W*H words x 24 bits, address `y*W + x`): read port `z_re`/`z_rd_addr` -> `z_rd_data`, write port `z_we`/`z_wr_addr`/`z_wr_data`. I-buffer (W*H x 16): write port `i_we`/`i_wr_addr`/`i_wr_data`, and `i_rd_data`, the index read with `z_re`/`z_rd_addr` (a background index makes the depth read with it count as far: no Z clear pass).",
        "rc3" => "No Z-buffer. I-buffer (W*H x 16, address `y*W + x`): read port `i_re`/`i_rd_addr` -> `i_rd_data` one cycle later, write port `i_we`/`i_wr_addr`/`i_wr_data`. TdbV (2^16 records x 136 bits, address = triangle index, a depth plane: A 40 bits, B 40, C 56): read port `tdbv_re`/`tdbv_rd_addr` -> `tdbv_rd_a`/`_b`/`_c` one cycle later, write port `tdbv_we`/`tdbv_wr_addr`/`tdbv_wr_a`/`_b`/`_c`.",
        "cs" => "I-buffer (W*H x 16): read port `ibuf_read_enable`/`ibuf_read_address` -> `ibuf_read_data`, clear-behind write port `ibuf_write_*`. TdbS (2^16 x 424): read port `tdbs_read_enable`/`tdbs_read_address` -> `tdbs_read_data`. Z-buffer (W*H x 24): clear-behind write port `zbuf_write_*`.",
        "colour_setup" => "TdbS (2^16 words x 424 bits, address = triangle index): write port `tdbs_write_enable`/`tdbs_write_address`/`tdbs_write_data`.",
        "chipset" => "Z-buffer (W*H x 24, one bank, the RC's): `z_re`/`z_rd_addr` -> `z_rd_data`, `z_we`/`z_wr_addr`/`z_wr_data`. I-buffer (two banks of W*H x 16, address bit 20 = bank): draw side (the RC, bank `draw_bank`) `id_re`/`id_rd_addr` -> `id_rd_data` (read with the depth), `id_we`/`id_wr_addr`/`id_wr_data`; scan side (the CS, the other bank) `is_re`/`is_rd_addr` -> `is_rd_data`, `is_we`/`is_wr_addr`/`is_wr_data` (clear-behind). TdbS (two banks of 2^16 x 424, address bit 16 = bank): `t_we`/`t_wr_addr`/`t_wr_data` (colour setup, draw bank), `t_re`/`t_rd_addr` -> `t_rd_data` (the CS, scan bank). A scan start the CS takes swaps the banks.",
        "chipset3" => "No Z-buffer. TdbV (2^16 records x 136 bits, one bank, the RC's; address = triangle index, a depth plane: A 40 bits, B 40, C 56): `tdbv_re`/`tdbv_rd_addr` -> `tdbv_rd_a`/`_b`/`_c`, `tdbv_we`/`tdbv_wr_addr`/`tdbv_wr_a`/`_b`/`_c`. I-buffer (two banks of W*H x 16, address bit 20 = bank): draw side (the RC, bank `draw_bank`) `id_re`/`id_rd_addr` -> `id_rd_data` (the index whose plane gives the old depth), `id_we`/`id_wr_addr`/`id_wr_data`; scan side as `chipset`'s. TdbS as `chipset`'s. A scan start the CS takes swaps the banks of the I-buffer and TdbS; TdbV has one bank.",
        "cs_tex" => "As `cs`, and: TdbT (2^16 x 408, address = triangle index): read port `tdbt_read_enable`/`tdbt_read_address` -> `tdbt_read_data` (beside TdbS, textured frames only). Four texture banks (RGB888 words, `golden::texbank`'s layout: texel (x, y) of a level in bank (x & 1) | (y & 1) << 1 at word base + (y >> 1) * ceil(w / 2) + (x >> 1)): bank k read when bit k of `tex_rd` is set, at `tex_addrk` -> `tex_datak` one cycle later. The level table (each mipmap level's first word) is inside, written through `tex_base_*` while idle.",
        "chipset_tex" => "As `chipset`, and: TdbT (two banks of 2^16 x 408, address bit 16 = bank): `tt_we`/`tt_wr_addr`/`tt_wr_data` (texture setup, draw bank), `tt_re`/`tt_rd_addr` -> `tt_rd_data` (the CS, scan bank); a scan start swaps them with TdbS. Four texture banks (one set: the frame's texture, loaded by the host while no scan runs): bank k read when bit k of `tex_rd` is set, at `tex_addrk` -> `tex_datak` one cycle later.",
        "opp" => "No external memory: the object parameters are loaded through `load`/`load_op`/`load_params`; the FIFOs are inside.",
        "proof_shade" => "No external memory: the object table and the light parameters are inside (written through `cfg_*`).",
        "proof_filter" => "No external memory: the direction table and the filter's parameters are inside (written through `cfg_*`).",
        "proof_filter2x2" => "No external memory: the direction table and the filter's parameters are inside (written through `cfg_*`); the 2x2 box's line buffer (one 112-bit word per screen column) is inside too. The screen size is fixed at generation (320x200): the stream must be whole frames of that size in raster order.",
        _ => "See the port table (no memory-interface note is written for this top yet).",
    };
    hdl::for_screen(text, screen)
}

/// The README of the output directory for these tops (name, Verilog).
pub fn readme(tops: &[(String, String)], screen: (u32, u32)) -> Result<String, String> {
    let mut s = String::new();
    let _ = writeln!(s, "# Generated Verilog of the index-rendering chipset\n");
    let _ = writeln!(s, "Generated by `idxrender verilog` from the RustHDL sources (rust-hdl 0.46); do not edit. One file per top:");
    let _ = writeln!(s, "the top module has the top's name, its submodules are `<top>$<child>` (Verilog allows `$` inside identifiers).");
    let _ = writeln!(s, "`files.f` lists the files, relative to this directory, for tools: `verilator -F files.f` (relative to the list), or from this directory `iverilog -c files.f` / `read_verilog` each.\n");
    let _ = writeln!(s, "| top | file | description |\n|---|---|---|");
    for (t, _) in tops {
        let desc = hdl::top_description(t, screen).unwrap_or_default();
        let _ = writeln!(s, "| `{t}` | `{t}.v` | {desc} |");
    }
    let _ = writeln!(s, "\n## Conventions (all tops)\n");
    let all_zero = tops.iter().all(|(_, v)| verilog_facts(v).nonzero_initial_values == 0);
    let _ = writeln!(
        s,
        "* **Clock and reset.** One clock, the input `clock`; registers are written on its rising edge (`always @(posedge clock)`); there is no negative-edge logic and no reset port (each top's section gives the counts read from its Verilog). The power-up state is what rust-hdl generates: every register has an `initial` value{}, which an FPGA bitstream loads at configuration. An ASIC flow would need a reset added.",
        if all_zero { " and all of them are 0 in these tops (enum FSMs start in their first state)" } else { " (see each top for the non-zero ones)" }
    );
    let _ = writeln!(s, "* **Handshake.** Every stream port is a valid/ready triple around a payload (`name$data`, `name$valid`, `name$ready`), AXI-Stream style: a payload is transferred at a rising edge where `valid` and `ready` are both high, and a producer holds `data` and `valid` until then.");
    let _ = writeln!(s, "* **Memory interface.** The screen-size buffers (Z, I) and TdbS are outside the core: their ports are top-level ports, so the same RTL drives FPGA block RAM or external synchronous SRAM. Every memory port is synchronous: a read issued with its enable high at a rising edge returns the word in the next cycle (latency 1, the `*_rd_data`/`*_read_data` input is sampled at the following edge); a write happens at the rising edge where its enable is high; a read and a write of the same address at the same edge return the **old** word (read-before-write). Word sizes and address maps are in each top's section.");
    let _ = writeln!(s, "* **Video (cs, chipset).** AXI4-Stream video (Xilinx UG934): one pixel per beat, `tdata` RGB888 ordered R 23:16, B 15:8, G 7:0; `tvalid`/`tready` as above; `tuser` marks the first pixel of a frame (pixel (0,0)); `tlast` marks the last pixel of each line; pixels in raster order (left to right, top to bottom).");
    let _ = writeln!(s, "* **Port meanings** below come from the `///` comments of the RustHDL struct that defines each top; stream sub-ports (`$data`, `$valid`, `$ready`) are explained from the stream's comment.");
    for (t, v) in tops {
        let ports = parse_ports(v, t)?;
        let facts = verilog_facts(v);
        let docs = port_docs(t, &ports);
        let _ = writeln!(s, "\n## `{t}`\n");
        if let Some(d) = hdl::top_description(t, screen) {
            let _ = writeln!(s, "{d}.\n");
        }
        let (nin, nout) = (
            ports.iter().filter(|p| p.dir == Dir::In).map(|p| p.width).sum::<usize>(),
            ports.iter().filter(|p| p.dir == Dir::Out).map(|p| p.width).sum::<usize>(),
        );
        let _ = writeln!(s, "Module `{t}` in `{t}.v`: {} modules, {} ports ({nin} input bits, {nout} output bits).", facts.modules, ports.len());
        let _ = writeln!(s, "Memory interface: {}", memory_interface(t, screen));
        if facts.memories.is_empty() {
            let _ = writeln!(s, "Internal memories: none.");
        } else {
            let list: Vec<String> = facts.memories.iter().map(|(n, w)| format!("{n} x {w}")).collect();
            let _ = writeln!(s, "Internal memories (block RAM on an FPGA): {}.", list.join(", "));
        }
        let _ = writeln!(
            s,
            "Clocking (read from the Verilog): {} rising-edge blocks, {} falling-edge; {} registers with an initial value, {} of them non-zero.\n",
            facts.posedge_blocks, facts.negedge_blocks, facts.initial_values, facts.nonzero_initial_values
        );
        match &docs {
            Some((sname, _)) => {
                let _ = writeln!(s, "Ports (meanings from `hdl::...::{sname}`):\n");
            }
            None => {
                let _ = writeln!(s, "Ports (no meanings: the RustHDL sources are not next to this binary, or no single struct has exactly these ports):\n");
            }
        }
        let _ = writeln!(s, "| port | dir | width | group | meaning |\n|---|---|---|---|---|");
        for p in &ports {
            let (group, meaning) = if p.name == "clock" {
                (String::new(), "the clock; everything happens at its rising edge".to_string())
            } else {
                docs.as_ref().and_then(|d| d.1.get(&p.name).cloned()).unwrap_or_default()
            };
            let _ = writeln!(s, "| `{}` | {} | {} | {} | {} |", p.name, p.dir.as_str(), p.width, group, meaning.replace('|', "\\|"));
        }
    }
    Ok(s)
}

pub fn run(args: &VerilogArgs) -> Result<(), String> {
    let blocks = selected_tops(args.block.as_deref())?;
    let size = crate::args::parse_size(&args.size)?;
    let screen = (size.width, size.height);
    // The folder is one unit (crate::output::OutputDir): written staged, moved into --out at the end;
    // a failure leaves the previous folder whole, and no .v of an earlier run stays beside files.f.
    let ours = |n: &str| n == "files.f" || n == "README.md" || n.strip_suffix(".v").is_some_and(|t| hdl::TOPS.iter().any(|top| top.0 == t));
    let od = crate::output::OutputDir::begin_with(&args.out, &ours)?;
    let mut tops = Vec::new();
    let mut wrote = Vec::new();
    for b in blocks {
        let v = hdl::verilog_top_for(&b, screen)?;
        parse_ports(&v, &b)?;
        let path = crate::output::write_atomic(od.dir(), &format!("{b}.v"), v.as_bytes())?;
        wrote.push(format!("wrote {} ({} lines)", od.final_path(&path).display(), v.lines().count()));
        tops.push((b, v));
    }
    let list: String = tops.iter().map(|(b, _)| format!("{b}.v\n")).collect();
    let path = crate::output::write_atomic(od.dir(), "files.f", list.as_bytes())?;
    wrote.push(format!("wrote {}", od.final_path(&path).display()));
    let path = crate::output::write_atomic(od.dir(), "README.md", readme(&tops, screen)?.as_bytes())?;
    wrote.push(format!("wrote {}", od.final_path(&path).display()));
    od.commit()?;
    for w in wrote {
        crate::say!("{w}");
    }
    Ok(())
}
