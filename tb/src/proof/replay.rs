//! Level 3 for PROOF (the OPP, shading and filter tops): a self-checking Verilog testbench generated from a
//! port list replays vectors recorded by a bench run (every cycle's inputs and the cycle model's
//! outputs) on the generated Verilog, under Icarus Verilog or Verilator. An output with a guard is
//! compared only in cycles where its guard (a valid bit) is expected high: data beside a low valid is
//! don't-care (and may be X in Verilog, from block RAM never written).

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::Command;

/// A port of the top: name in the Verilog (`upstream$data`), width, direction, guard.
#[derive(Clone, Debug)]
pub struct Port {
    pub name: &'static str,
    pub width: usize,
    pub input: bool,
    /// Compare this output only when the output named here is expected 1.
    pub guard: Option<&'static str>,
}

pub fn inp(name: &'static str, width: usize) -> Port {
    Port { name, width, input: true, guard: None }
}
pub fn out(name: &'static str, width: usize, guard: Option<&'static str>) -> Port {
    Port { name, width, input: false, guard }
}

fn ident(name: &str) -> String {
    name.replace('$', "_")
}

/// Records one hex column per port per cycle.
pub struct Recorder {
    out: BufWriter<File>,
    pub path: PathBuf,
    pub cycles: u64,
    ports: usize,
}

impl Recorder {
    pub fn create(path: PathBuf, ports: &[Port]) -> Result<Recorder, String> {
        let f = File::create(&path).map_err(|e| format!("cannot create {}: {e}", path.display()))?;
        Ok(Recorder { out: BufWriter::new(f), path, cycles: 0, ports: ports.len() })
    }
    /// One cycle: the values in port order, as hex strings.
    pub fn cycle(&mut self, values: &[String]) -> Result<(), String> {
        assert_eq!(values.len(), self.ports);
        writeln!(self.out, "{}", values.join(" ")).map_err(|e| format!("{}: {e}", self.path.display()))?;
        self.cycles += 1;
        Ok(())
    }
    pub fn finish(mut self) -> Result<(PathBuf, u64), String> {
        self.out.flush().map_err(|e| format!("{}: {e}", self.path.display()))?;
        Ok((self.path, self.cycles))
    }
}

/// The self-checking testbench: inputs change after the falling edge, outputs are compared just
/// before the rising edge; prints `REPLAY PASSED <cycles>` or the first mismatch.
pub fn testbench(top: &str, ports: &[Port], vectors: &Path, cycles: u64) -> String {
    let mut decl = String::new();
    let mut conn = vec![".clock(clock)".to_string()];
    let mut scan_fmt = Vec::new();
    let mut scan_args = Vec::new();
    let mut drive = String::new();
    let mut check = String::new();
    for p in ports {
        let id = ident(p.name);
        let w = p.width - 1;
        if p.input {
            decl += &format!("  reg [{w}:0] {id} = 0; reg [{w}:0] t_{id};\n");
            scan_args.push(format!("t_{id}"));
            drive += &format!("      {id} = t_{id};\n");
        } else {
            decl += &format!("  wire [{w}:0] {id}; reg [{w}:0] e_{id};\n");
            scan_args.push(format!("e_{id}"));
            let cond = match p.guard {
                Some(g) => format!("e_{} == 1 && {id} !== e_{id}", ident(g)),
                None => format!("{id} !== e_{id}"),
            };
            check += &format!(
                "      if ({cond}) begin $display(\"REPLAY FAILED at cycle %0d: {name} got %h expected %h\", cyc, {id}, e_{id}); $finish; end\n",
                name = p.name
            );
        }
        scan_fmt.push("%h");
        conn.push(format!(".{}({id})", p.name));
    }
    format!(
        r#"`timescale 1ns/1ps
module tb_{top};
  reg clock = 0;
{decl}  integer fd, r, cyc;
  {top} uut({conn});
  initial begin
    fd = $fopen("{vec}", "r");
    for (cyc = 0; cyc < {cycles}; cyc = cyc + 1) begin
      r = $fscanf(fd, "{fmt}\n", {args});
      if (r != {n}) begin $display("REPLAY FAILED: bad vector line %0d", cyc); $finish; end
{drive}      #4;
{check}      #1 clock = 1;
      #5 clock = 0;
    end
    $display("REPLAY PASSED %0d", {cycles});
    $finish;
  end
endmodule
"#,
        conn = conn.join(", "),
        vec = vectors.display(),
        fmt = scan_fmt.join(" "),
        args = scan_args.join(", "),
        n = ports.len(),
    )
}

/// Replay `vectors` on `verilog` (top module `top`) under `sim` ("iverilog" or "verilator").
pub fn replay(sim: &str, dir: &Path, top: &str, ports: &[Port], verilog: &str, vectors: &Path, cycles: u64) -> Result<String, String> {
    let dut = dir.join(format!("{top}.v"));
    let tbv = dir.join(format!("tb_{top}.v"));
    std::fs::write(&dut, verilog).map_err(|e| e.to_string())?;
    std::fs::write(&tbv, testbench(top, ports, vectors, cycles)).map_err(|e| e.to_string())?;
    let run = |c: &mut Command| -> Result<String, String> {
        let o = c.output().map_err(|e| format!("cannot run {c:?}: {e}"))?;
        let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), String::from_utf8_lossy(&o.stderr));
        if !o.status.success() {
            return Err(format!("{c:?} failed:\n{text}"));
        }
        Ok(text)
    };
    let out = match sim {
        "iverilog" => {
            let exe = dir.join(format!("tb_{top}.vvp"));
            run(Command::new("iverilog").args(["-g2012", "-o"]).arg(&exe).arg(&tbv).arg(&dut))?;
            run(Command::new("timeout").args(["600", "vvp", "-n"]).arg(&exe))?
        }
        "verilator" => {
            let mdir = dir.join("obj_dir");
            run(Command::new("verilator")
                .args(["--binary", "-O2", "-j", "2", "-Wno-fatal", "-Wno-WIDTH", "-Wno-DECLFILENAME", "-Wno-UNUSEDPARAM", "-Wno-STMTDLY", "-Wno-INITIALDLY"])
                .args(["--top-module", &format!("tb_{top}"), "-Mdir"])
                .arg(&mdir)
                .arg(&tbv)
                .arg(&dut))?;
            run(&mut Command::new(mdir.join(format!("Vtb_{top}"))))?
        }
        _ => return Err(format!("unknown simulator {sim}")),
    };
    match out.lines().find(|l| l.contains("REPLAY")) {
        Some(l) if l.contains("PASSED") => Ok(l.trim().to_string()),
        Some(_) => Err(out),
        None => Err(format!("no verdict from {sim}:\n{out}")),
    }
}
