//! rust-hdl writes one Verilog module per instance (`opp$ops$0`, `opp$ops$1`, ... each with its own
//! copies of every child), so an OPP of N object processors is N copies of the same text: some 32
//! modules and 30 KB per OP. Tools then parse, elaborate and (Verilator) compile every copy. This pass
//! keeps one module of each distinct body and points every instance at it, bottom-up until nothing
//! changes: two modules merge when their text is equal after each child's type is replaced by the
//! child's kept name. The design is the same netlist; only module names of merged copies change (an
//! instance of `opp$ops$7` becomes an instance of `opp$ops$0`). Instance names, ports and signals are
//! untouched, so hierarchical paths in a simulation stay as they were.

use std::collections::HashMap;

/// A module of rust-hdl's output: its name and its lines from `module` to `endmodule`.
struct Module {
    name: String,
    lines: Vec<String>,
}

/// One piece of the file: text between modules, or a module by index.
enum Piece {
    Text(String),
    Module(usize),
}

/// `module NAME(...` → NAME.
fn header_name(line: &str) -> Option<&str> {
    let rest = line.strip_prefix("module ")?;
    let end = rest.find('(')?;
    Some(rest[..end].trim())
}

/// An instance line `    TYPE INST(` → (TYPE, byte offset of TYPE in the line), when TYPE is a module.
fn instance_type<'a>(line: &'a str, modules: &HashMap<String, usize>) -> Option<(&'a str, usize)> {
    let t = line.trim_start();
    let at = line.len() - t.len();
    let mut words = t.split(' ');
    let ty = words.next()?;
    let inst = words.next()?;
    if words.next().is_some() || !inst.ends_with('(') || !modules.contains_key(ty) {
        return None;
    }
    Some((ty, at))
}

/// The Verilog `v` with modules of identical bodies merged (see the module comment). Text it does not
/// recognise as a module is kept as it is.
pub fn merge_identical_modules(v: &str) -> String {
    let mut modules: Vec<Module> = Vec::new();
    let mut pieces: Vec<Piece> = Vec::new();
    let mut open: Option<Module> = None;
    for line in v.lines() {
        if let Some(m) = open.as_mut() {
            m.lines.push(line.to_string());
            if line.trim_start().starts_with("endmodule") {
                pieces.push(Piece::Module(modules.len()));
                modules.push(open.take().unwrap());
            }
        } else if let Some(name) = header_name(line) {
            open = Some(Module { name: name.to_string(), lines: vec![line.to_string()] });
        } else {
            pieces.push(Piece::Text(line.to_string()));
        }
    }
    if let Some(m) = open {
        // An unterminated module: leave the whole text alone.
        let _ = m;
        return v.to_string();
    }
    let index: HashMap<String, usize> = modules.iter().enumerate().map(|(i, m)| (m.name.clone(), i)).collect();
    let mut canon: Vec<usize> = (0..modules.len()).collect();
    // An instance line with the child's type replaced by the child's kept name.
    let retyped = |line: &str, canon: &[usize]| -> Option<String> {
        let (ty, at) = instance_type(line, &index)?;
        Some(format!("{}{}{}", &line[..at], modules[canon[index[ty]]].name, &line[at + ty.len()..]))
    };
    // The body of module i with its own name blanked and each child's type replaced by its kept name.
    let key = |i: usize, canon: &[usize]| -> String {
        let m = &modules[i];
        let mut k = String::new();
        for line in &m.lines {
            k.push_str(&retyped(line, canon).unwrap_or_else(|| line.replace(m.name.as_str(), "\u{0}")));
            k.push('\n');
        }
        k
    };
    loop {
        let mut first: HashMap<String, usize> = HashMap::new();
        let mut next = canon.clone();
        for i in 0..modules.len() {
            let k = key(i, &canon);
            next[i] = *first.entry(k).or_insert(i);
        }
        if next == canon {
            break;
        }
        canon = next;
    }
    let mut out = String::with_capacity(v.len());
    for p in &pieces {
        match p {
            Piece::Text(t) => {
                out.push_str(t);
                out.push('\n');
            }
            Piece::Module(i) if canon[*i] == *i => {
                for line in &modules[*i].lines {
                    match retyped(line, &canon) {
                        Some(l) => out.push_str(&l),
                        None => out.push_str(line),
                    }
                    out.push('\n');
                }
            }
            Piece::Module(_) => {}
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::merge_identical_modules;

    const TWO_COPIES: &str = "\
module top(a,q);
    top$u$0 u$0(
        .d(a)
    );
    top$u$1 u$1(
        .d(a)
    );
endmodule // top

module top$u$0(d);
    top$u$0$r r(
        .d(d)
    );
endmodule // top$u$0

module top$u$0$r(d);
    input wire [3:0] d;
endmodule // top$u$0$r

module top$u$1(d);
    top$u$1$r r(
        .d(d)
    );
endmodule // top$u$1

module top$u$1$r(d);
    input wire [3:0] d;
endmodule // top$u$1$r
";

    #[test]
    fn copies_of_one_module_and_their_children_become_one_module() {
        let m = merge_identical_modules(TWO_COPIES);
        assert_eq!(m.matches("\nmodule ").count() + m.starts_with("module ") as usize, 3, "{m}");
        assert!(m.contains("    top$u$0 u$1(\n"), "{m}");
        assert!(!m.contains("top$u$1"), "{m}");
    }

    #[test]
    fn modules_that_differ_are_kept_apart() {
        let v = TWO_COPIES.replacen("input wire [3:0] d;\nendmodule // top$u$1$r", "input wire [4:0] d;\nendmodule // top$u$1$r", 1);
        let m = merge_identical_modules(&v);
        assert!(m.contains("module top$u$1(d);"), "{m}");
        assert!(m.contains("module top$u$1$r(d);"), "{m}");
    }
}
