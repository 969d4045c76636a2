//! `idxrender vcd-diff A.vcd B.vcd`: compare two waveforms of the same top cycle by cycle.
//!
//! Each trace is sampled at every rising edge of its `clock`, with the values each signal held just
//! before that edge (the settled values of the cycle), so traces with different timing (RustHDL's
//! direct drive changes inputs with the falling edge, an Icarus or Verilator testbench a little
//! later) compare by cycle, not by time. Signals are matched by name below each file's top scope (the
//! shallowest scope holding a `clock`, or `--scope-a`/`--scope-b`):
//! * scope and name parts are joined with `$`, so RustHDL's port struct `cmd` holding `valid` is
//!   `cmd$valid`, as the generated Verilog names the port; Verilator's mangled `$` (`__024`) and
//!   escaped identifiers (`\name`) are undone;
//! * RustHDL writes a struct-valued port field by field (`cmd` / `data$kind`, `data$x0`, ...) where the
//!   Verilog has one vector `cmd$data`: the fields are concatenated, first field in the least
//!   significant bits, as rust-hdl packs a `LogicStruct`;
//! * when no name matches exactly, `$` and `_` are taken as the same separator.
//!
//! Without `--signals`, every port present in both traces is compared. A trace whose top scope has
//! sub-scopes (RustHDL's) shows which variables are ports: those of the top scope and of the
//! interface scopes below it (no sub-scopes, no clock: the port structs), not those of child blocks.
//! A flat trace (Icarus `$dumpvars(1, dut)`, Verilator) cannot tell ports from the top module's
//! nets, so with two flat traces every common name is compared. With `--signals`, exactly those.
//! A port of one trace missing from the other is a difference (for two flat traces, any name in one
//! only); real-valued signals are compared by their values. Exit status: 0 when equal, 1 with a
//! report of the first difference (cycle, time in each file, signal, both values) or of the missing
//! ports, 2 when a trace cannot be read, a named signal is missing, or neither trace has a rising edge
//! of the clock (nothing to compare).

use std::collections::{BTreeMap, HashMap, HashSet};
use std::fs::File;
use std::io::BufReader;
use std::path::{Path, PathBuf};
use vcd::{Command as VcdCmd, IdCode, ScopeItem, Value};

#[derive(clap::Args, Debug)]
pub struct VcdDiffArgs {
    /// First trace.
    pub a: PathBuf,
    /// Second trace.
    pub b: PathBuf,
    /// Compare only these signals (comma-separated names, e.g. `cmd$data,z_we`).
    #[arg(long, value_delimiter = ',')]
    pub signals: Vec<String>,
    /// Top scope of A as a dotted path (e.g. `tb_rc.dut`); default: the shallowest scope with a `clock`.
    #[arg(long)]
    pub scope_a: Option<String>,
    /// Top scope of B as a dotted path.
    #[arg(long)]
    pub scope_b: Option<String>,
    /// The clock's name in the top scopes.
    #[arg(long, default_value = "clock")]
    pub clock: String,
}

/// A variable below the top scope.
#[derive(Clone, Debug)]
struct Leaf {
    name: String,
    code: IdCode,
    width: usize,
    /// A top-level port as far as the trace shows: a variable of the top scope, or of an interface
    /// scope below it (a scope with neither sub-scopes nor a clock: RustHDL's port structs).
    port: bool,
}

/// A trace's header: its top scope and the variables under it, in declaration order.
struct Trace {
    path: PathBuf,
    scope: String,
    leaves: Vec<Leaf>,
    clock: IdCode,
    /// The top scope has sub-scopes (RustHDL: port structs and child blocks), so ports are known;
    /// a flat trace (Verilog `$dumpvars(1, dut)`, Verilator) does not tell ports from nets.
    structured: bool,
}

impl Trace {
    /// The variables that may be compared by default: the ports of a structured trace, else all.
    fn comparable(&self) -> Vec<Leaf> {
        self.leaves.iter().filter(|l| l.port || !self.structured).cloned().collect()
    }
}

fn demangle(s: &str) -> String {
    s.trim_start_matches('\\').replace("__024", "$")
}

fn collect(items: &[ScopeItem], prefix: &str, depth: usize, port: bool, clock: &str, out: &mut Vec<Leaf>) {
    for it in items {
        match it {
            ScopeItem::Var(v) => out.push(Leaf { name: format!("{prefix}{}", demangle(&v.reference)), code: v.code, width: v.size as usize, port }),
            ScopeItem::Scope(s) => {
                let interface = depth == 0
                    && !s.children.iter().any(|c| matches!(c, ScopeItem::Scope(_)) || matches!(c, ScopeItem::Var(v) if demangle(&v.reference) == clock));
                collect(&s.children, &format!("{prefix}{}$", demangle(&s.identifier)), depth + 1, port && interface, clock, out)
            }
        }
    }
}

/// Find the top scope: by dotted path, or the shallowest scope with a variable named `clock`.
fn find_top<'a>(items: &'a [ScopeItem], want: Option<&str>, clock: &str) -> Option<(String, &'a [ScopeItem])> {
    if let Some(path) = want {
        let mut cur = items;
        for part in path.split('.') {
            cur = cur.iter().find_map(|i| match i {
                ScopeItem::Scope(s) if demangle(&s.identifier) == part => Some(s.children.as_slice()),
                _ => None,
            })?;
        }
        return Some((path.to_string(), cur));
    }
    let mut level: Vec<(String, &[ScopeItem])> = vec![(String::new(), items)];
    while !level.is_empty() {
        for (name, children) in &level {
            if !name.is_empty() && children.iter().any(|c| matches!(c, ScopeItem::Var(v) if demangle(&v.reference) == clock)) {
                return Some((name.clone(), children));
            }
        }
        let mut next = Vec::new();
        for (name, children) in &level {
            for c in children.iter() {
                if let ScopeItem::Scope(s) = c {
                    let n = if name.is_empty() { demangle(&s.identifier) } else { format!("{name}.{}", demangle(&s.identifier)) };
                    next.push((n, s.children.as_slice()));
                }
            }
        }
        level = next;
    }
    None
}

fn open(path: &Path) -> Result<vcd::Parser<BufReader<File>>, String> {
    let f = File::open(path).map_err(|e| format!("cannot open {}: {e}", path.display()))?;
    Ok(vcd::Parser::new(BufReader::new(f)))
}

fn read_header(path: &Path, scope: Option<&str>, clock: &str) -> Result<(Trace, vcd::Parser<BufReader<File>>), String> {
    let mut p = open(path)?;
    let h = p.parse_header().map_err(|e| format!("{} is not a readable VCD: {e}", path.display()))?;
    let (scope, items) = find_top(&h.items, scope, clock).ok_or_else(|| match scope {
        Some(s) => format!("{}: no scope `{s}`", path.display()),
        None => format!("{}: no scope holds a signal named `{clock}` (name the top with --scope-a/--scope-b, the clock with --clock)", path.display()),
    })?;
    let mut leaves = Vec::new();
    collect(items, "", 0, true, clock, &mut leaves);
    let structured = items.iter().any(|i| matches!(i, ScopeItem::Scope(_)));
    let clock_leaf = leaves
        .iter()
        .find(|l| l.name == clock)
        .ok_or_else(|| format!("{}: the scope `{scope}` has no signal `{clock}`", path.display()))?;
    if clock_leaf.width != 1 {
        return Err(format!("{}: `{clock}` is {} bits wide, not a clock", path.display(), clock_leaf.width));
    }
    let clock = clock_leaf.code;
    Ok((Trace { path: path.to_path_buf(), scope, leaves, clock, structured }, p))
}

/// A sampled value: binary digits (MSB first, `x`/`z` allowed) or a string (RustHDL's enums).
#[derive(Clone, Debug, PartialEq, Eq)]
enum Val {
    Bits(String),
    Text(String),
}

fn bits_of(vs: &[Value], width: usize) -> String {
    let mut s: String = vs
        .iter()
        .map(|v| match v {
            Value::V0 => '0',
            Value::V1 => '1',
            Value::X => 'x',
            Value::Z => 'z',
        })
        .collect();
    if s.len() < width {
        // VCD left-extension: 0 for a leading 0 or 1, else the leading x/z.
        let fill = match s.chars().next() {
            Some('x') => 'x',
            Some('z') => 'z',
            _ => '0',
        };
        s = std::iter::repeat(fill).take(width - s.len()).chain(s.chars()).collect();
    } else if s.len() > width && width > 0 {
        s = s[s.len() - width..].to_string();
    }
    s
}

/// Per-cycle samples: the time of each rising edge, and per variable its value runs
/// (first cycle, value), a new run when the sampled value changes.
struct Samples {
    edges: Vec<u64>,
    runs: HashMap<IdCode, Vec<(usize, Val)>>,
}

fn sample(trace: &Trace, mut p: vcd::Parser<BufReader<File>>, wanted: &HashSet<IdCode>) -> Result<Samples, String> {
    let widths: HashMap<IdCode, usize> = trace.leaves.iter().map(|l| (l.code, l.width)).collect();
    let mut cur: HashMap<IdCode, Val> = HashMap::new();
    let mut batch: Vec<(IdCode, Val)> = Vec::new();
    let mut time = 0u64;
    let mut s = Samples { edges: Vec::new(), runs: HashMap::new() };
    let flush = |time: u64, batch: &mut Vec<(IdCode, Val)>, cur: &mut HashMap<IdCode, Val>, s: &mut Samples| {
        let new_clock = batch.iter().rev().find(|(c, _)| *c == trace.clock).map(|x| x.1.clone());
        let old_clock = cur.get(&trace.clock);
        let rising = matches!(new_clock, Some(Val::Bits(ref b)) if b == "1") && matches!(old_clock, Some(Val::Bits(b)) if b == "0" || b == "x");
        if rising {
            let cycle = s.edges.len();
            s.edges.push(time);
            for code in wanted {
                let v = cur.get(code).cloned().unwrap_or_else(|| Val::Bits("x".repeat(widths.get(code).copied().unwrap_or(1).max(1))));
                let runs = s.runs.entry(*code).or_default();
                if runs.last().map(|r| &r.1) != Some(&v) {
                    runs.push((cycle, v));
                }
            }
        }
        for (c, v) in batch.drain(..) {
            cur.insert(c, v);
        }
    };
    for cmd in p.by_ref() {
        let cmd = cmd.map_err(|e| format!("{}: unreadable after time {time}: {e}", trace.path.display()))?;
        match cmd {
            VcdCmd::Timestamp(t) => {
                flush(time, &mut batch, &mut cur, &mut s);
                time = t;
            }
            VcdCmd::ChangeScalar(c, v) if c == trace.clock || wanted.contains(&c) => batch.push((c, Val::Bits(bits_of(&[v], 1)))),
            VcdCmd::ChangeVector(c, v) if c == trace.clock || wanted.contains(&c) => {
                batch.push((c, Val::Bits(bits_of(&v, widths.get(&c).copied().unwrap_or(v.len())))))
            }
            VcdCmd::ChangeString(c, v) if wanted.contains(&c) => batch.push((c, Val::Text(v))),
            VcdCmd::ChangeReal(c, v) if wanted.contains(&c) => batch.push((c, Val::Text(v.to_string()))),
            _ => {}
        }
    }
    flush(time, &mut batch, &mut cur, &mut s);
    Ok(s)
}

/// A compared signal in one trace: one variable, or the fields of a struct (first field = LSBs).
#[derive(Clone, Debug)]
struct Sig {
    parts: Vec<Leaf>,
}

impl Sig {
    fn width(&self) -> usize {
        self.parts.iter().map(|l| l.width).sum()
    }
    fn value(&self, s: &Samples, cycle: usize) -> Val {
        let mut bits = String::new();
        for l in self.parts.iter().rev() {
            match at(s, l.code, cycle) {
                Val::Bits(b) => bits.push_str(&b),
                Val::Text(t) => return Val::Text(if self.parts.len() == 1 { t } else { format!("{}={t}", l.name) }),
            }
        }
        Val::Bits(bits)
    }
}

fn at(s: &Samples, code: IdCode, cycle: usize) -> Val {
    let runs = &s.runs[&code];
    let i = runs.partition_point(|r| r.0 <= cycle);
    runs[i.saturating_sub(1)].1.clone()
}

/// The signal called `name` in a trace: the variable itself, or the struct whose fields are
/// `name$...` (`loose`: `$` and `_` equivalent).
fn resolve(leaves: &[Leaf], name: &str, loose: bool) -> Option<Sig> {
    let norm = |s: &str| if loose { s.replace('$', "_") } else { s.to_string() };
    let n = norm(name);
    if let Some(l) = leaves.iter().find(|l| norm(&l.name) == n) {
        return Some(Sig { parts: vec![l.clone()] });
    }
    let prefix = format!("{n}{}", if loose { "_" } else { "$" });
    let parts: Vec<Leaf> = leaves.iter().filter(|l| norm(&l.name).starts_with(&prefix) && l.width > 0).cloned().collect();
    (!parts.is_empty()).then_some(Sig { parts })
}

fn show(v: &Val) -> String {
    match v {
        Val::Text(t) => format!("\"{t}\""),
        Val::Bits(b) if b.chars().all(|c| c == '0' || c == '1') && !b.is_empty() => {
            let digits = b.len().div_ceil(4);
            let padded: String = std::iter::repeat('0').take(digits * 4 - b.len()).chain(b.chars()).collect();
            let hex: String = padded.as_bytes().chunks(4).map(|c| char::from_digit(c.iter().fold(0, |a, &d| a * 2 + (d - b'0') as u32), 16).unwrap()).collect();
            format!("0x{hex}")
        }
        Val::Bits(b) => format!("'b{b}"),
    }
}

/// The outcome of a comparison.
pub struct Outcome {
    pub equal: bool,
    pub report: String,
}

/// Compare two traces; `Err` when a trace cannot be read or a named signal is missing.
pub fn compare(args: &VcdDiffArgs) -> Result<Outcome, String> {
    let (ta, pa) = read_header(&args.a, args.scope_a.as_deref(), &args.clock)?;
    let (tb, pb) = read_header(&args.b, args.scope_b.as_deref(), &args.clock)?;
    // The names to compare: those asked for, or every name of either trace that resolves in both.
    let mut pairs: BTreeMap<String, (Sig, Sig)> = BTreeMap::new();
    let mut notes = Vec::new();
    let mut missing: Vec<String> = Vec::new();
    let mut only_in: [Vec<(String, Sig)>; 2] = [Vec::new(), Vec::new()];
    if !args.signals.is_empty() {
        for name in &args.signals {
            let name = name.trim();
            let find = |t: &Trace| resolve(&t.leaves, name, false).or_else(|| resolve(&t.leaves, name, true));
            let sa = find(&ta).ok_or_else(|| format!("{} has no signal `{name}` in scope `{}`", ta.path.display(), ta.scope))?;
            let sb = find(&tb).ok_or_else(|| format!("{} has no signal `{name}` in scope `{}`", tb.path.display(), tb.scope))?;
            pairs.insert(name.to_string(), (sa, sb));
        }
    } else {
        // Candidate names: each variable, and each struct prefix (`cmd$data` of `cmd$data$kind`).
        let (la, lb) = (ta.comparable(), tb.comparable());
        let mut names: Vec<String> = Vec::new();
        let mut seen = HashSet::new();
        for l in la.iter().chain(lb.iter()) {
            let mut n = String::new();
            for (k, part) in l.name.split('$').enumerate() {
                if k > 0 {
                    n.push('$');
                }
                n.push_str(part);
                if seen.insert(n.clone()) {
                    names.push(n.clone());
                }
            }
        }
        // The variables already compared, per trace: the two traces' identifier codes are separate
        // name spaces (both start at `!`), so one set for both would confuse their variables.
        let (mut covered_a, mut covered_b): (HashSet<IdCode>, HashSet<IdCode>) = (HashSet::new(), HashSet::new());
        let (mut only_a, mut only_b) = (Vec::<(String, Sig)>::new(), Vec::<(String, Sig)>::new());
        let mut textual: Vec<String> = Vec::new();
        for n in &names {
            if n == &args.clock {
                continue;
            }
            let exact = (resolve(&la, n, false), resolve(&lb, n, false));
            let (sa, sb) = match exact {
                (Some(a), Some(b)) => (a, b),
                (a, b) => match (a.or_else(|| resolve(&la, n, true)), b.or_else(|| resolve(&lb, n, true))) {
                    (Some(a), Some(b)) => (a, b),
                    (Some(a), None) => {
                        if !a.parts.iter().all(|l| covered_a.contains(&l.code)) {
                            only_a.push((n.clone(), a));
                        }
                        continue;
                    }
                    (None, Some(b)) => {
                        if !b.parts.iter().all(|l| covered_b.contains(&l.code)) {
                            only_b.push((n.clone(), b));
                        }
                        continue;
                    }
                    (None, None) => continue,
                },
            };
            // Compare each variable once, at the level where both traces have a whole signal: a
            // struct in one trace against a vector in the other, or a variable against a variable.
            let single = sa.parts.len() == 1 && sb.parts.len() == 1;
            let composite = sa.parts.len() > 1 || sb.parts.len() > 1;
            if !(single || composite) || (sa.parts.iter().all(|l| covered_a.contains(&l.code)) && sb.parts.iter().all(|l| covered_b.contains(&l.code))) {
                continue;
            }
            if composite && sa.parts.len() > 1 && sb.parts.len() > 1 {
                // Both sides are split the same way: their fields are compared one by one.
                continue;
            }
            covered_a.extend(sa.parts.iter().map(|l| l.code));
            covered_b.extend(sb.parts.iter().map(|l| l.code));
            if sa.parts.iter().chain(sb.parts.iter()).any(|l| l.width == 0) {
                // RustHDL declares enum-valued signals 0 bits wide and writes their state names.
                textual.push(n.clone());
                continue;
            }
            pairs.insert(n.clone(), (sa, sb));
        }
        only_in = [only_a, only_b];
        if !textual.is_empty() {
            notes.push(format!("not compared (enum states written as text): {}", textual.join(", ")));
        }
    }
    if pairs.is_empty() {
        return Err(format!("{} and {} have no signal in common below `{}` / `{}`", ta.path.display(), tb.path.display(), ta.scope, tb.scope));
    }
    for (name, (sa, sb)) in &pairs {
        if sa.width() != sb.width() {
            return Ok(Outcome { equal: false, report: format!("signal {name} is {} bits wide in A and {} bits in B", sa.width(), sb.width()) });
        }
    }
    let mut want_a: HashSet<IdCode> = pairs.values().flat_map(|(a, _)| a.parts.iter().map(|l| l.code)).collect();
    let mut want_b: HashSet<IdCode> = pairs.values().flat_map(|(_, b)| b.parts.iter().map(|l| l.code)).collect();
    want_a.extend(only_in[0].iter().flat_map(|(_, s)| s.parts.iter().map(|l| l.code)));
    want_b.extend(only_in[1].iter().flat_map(|(_, s)| s.parts.iter().map(|l| l.code)));
    let sa = sample(&ta, pa, &want_a)?;
    let sb = sample(&tb, pb, &want_b)?;
    // A signal of one trace that the other lacks is a difference when the trace says it is a port and
    // the other trace should show ports too: two structured traces (RustHDL's), two flat ones (the same
    // kind of Verilog dump), or a structured trace's port that changes against a flat trace. What a
    // flat trace has beyond a structured one may be nets, and a structured trace's variable that never
    // changes may be a constant of the top: those are listed, not counted.
    let list = |v: &[&str]| {
        let mut s = v.iter().take(8).cloned().collect::<Vec<_>>().join(", ");
        if v.len() > 8 {
            s.push_str(&format!(", ... ({} more)", v.len() - 8));
        }
        s
    };
    for (k, (this, other, t, o, smp)) in [("A", "B", &ta, &tb, &sa), ("B", "A", &tb, &ta, &sb)].into_iter().enumerate() {
        let (mut counted, mut listed) = (Vec::new(), Vec::new());
        let names: Vec<&str> = only_in[k].iter().map(|(n, _)| n.as_str()).collect();
        for (name, sig) in &only_in[k] {
            // A struct's name stands for its fields, which are listed themselves.
            if names.iter().any(|m| m.len() > name.len() && m.starts_with(name.as_str()) && m.as_bytes()[name.len()] == b'$') {
                continue;
            }
            let changes = sig.parts.iter().any(|l| smp.runs.get(&l.code).is_some_and(|r| r.len() > 1));
            if t.structured == o.structured || (t.structured && changes) {
                counted.push(name.as_str());
            } else {
                listed.push(name.as_str());
            }
        }
        if !counted.is_empty() {
            missing.push(format!("{} of {this} missing from {other}: {}", if t.structured { "ports" } else { "signals" }, list(&counted)));
        }
        if !listed.is_empty() {
            notes.push(format!("not compared, only in {this} (nets or constants, not known to be ports): {}", list(&listed)));
        }
    }
    if sa.edges.is_empty() && sb.edges.is_empty() {
        return Err(format!(
            "neither {} nor {} has a rising edge of `{}`: no cycle to compare",
            ta.path.display(),
            tb.path.display(),
            args.clock
        ));
    }
    let cycles = sa.edges.len().min(sb.edges.len());
    // Per pair, the first cycle where the values differ (checked only where one of them changes).
    let mut first: Option<(usize, String, Val, Val)> = None;
    for (name, (a, b)) in &pairs {
        let mut at_cycles: Vec<usize> = a
            .parts
            .iter()
            .flat_map(|l| sa.runs.get(&l.code).into_iter().flatten().map(|r| r.0))
            .chain(b.parts.iter().flat_map(|l| sb.runs.get(&l.code).into_iter().flatten().map(|r| r.0)))
            .filter(|&c| c < cycles)
            .collect();
        at_cycles.sort_unstable();
        at_cycles.dedup();
        for c in at_cycles {
            if first.as_ref().is_some_and(|f| f.0 <= c) {
                break;
            }
            let (va, vb) = (a.value(&sa, c), b.value(&sb, c));
            if matches!(va, Val::Text(_)) != matches!(vb, Val::Text(_)) {
                notes.push(format!("not compared (text in one trace, bits in the other): {name}"));
                break;
            }
            if va != vb {
                first = Some((c, name.clone(), va, vb));
                break;
            }
        }
    }
    let names: Vec<&str> = pairs.keys().map(String::as_str).collect();
    let mut report = String::new();
    let equal = match &first {
        Some((c, name, va, vb)) => {
            report.push_str(&format!(
                "first difference at cycle {c} (rising edge at time {} in A, {} in B, in each file's time units): signal {name}: A = {}, B = {}\n",
                sa.edges[*c],
                sb.edges[*c],
                show(va),
                show(vb)
            ));
            false
        }
        None if sa.edges.len() != sb.edges.len() => {
            report.push_str(&format!(
                "the traces agree for {cycles} cycles, then {} ends: A has {} rising edges of {}, B has {}\n",
                if sa.edges.len() < sb.edges.len() { "A" } else { "B" },
                sa.edges.len(),
                args.clock,
                sb.edges.len()
            ));
            false
        }
        None if !missing.is_empty() => {
            report.push_str(&format!("the compared signals agree for {cycles} cycles, but {}\n", missing.join("; ")));
            false
        }
        None => {
            report.push_str(&format!("equal: {cycles} cycles, {} signals\n", pairs.len()));
            true
        }
    };
    report.push_str(&format!("A: {} (scope {})\nB: {} (scope {})\ncompared: {}\n", ta.path.display(), ta.scope, tb.path.display(), tb.scope, names.join(", ")));
    for n in notes {
        report.push_str(&n);
        report.push('\n');
    }
    Ok(Outcome { equal, report })
}

pub fn run(args: &VcdDiffArgs) -> Result<(), String> {
    match compare(args) {
        Ok(o) => {
            crate::say!("{}", o.report.trim_end());
            if !o.equal {
                std::process::exit(1);
            }
            Ok(())
        }
        Err(e) => {
            eprintln!("error: {e}");
            std::process::exit(2);
        }
    }
}
