//! `fpga-report`'s endpoint budget: how many timing endpoints of a placed and routed top arrive too
//! late for a clock, and in which blocks, from nextpnr's JSON report (`--report FILE
//! --detailed-timing-report`).
//!
//! nextpnr's log names one critical path per clock. A top that misses its clock by much has thousands
//! of late endpoints, and removing the worst path rarely moves Fmax: the next path is only a little
//! shorter, and placement moves each path by several nanoseconds from one run to the next
//! (docs/clock.md). The count of late endpoints per block says how much work is left and
//! where, and it moves when a change removes a whole class of paths even while the worst one stays.
//!
//! An endpoint is a cell input that ends a timing path (a flip-flop's data, clock enable or reset
//! input, a DSP's registered input). Its *arrival* is the latest time, after the launching clock edge,
//! at which its value settles: nextpnr's `detailed_net_timings` give it per sink (`delay`, a
//! [min, max] pair in ns; the max is taken). The endpoint's own setup time is not in it, so the counts
//! are a lower bound for a clock of that period (setup is about 0.1-0.2 ns on the ECP5).
//!
//! Blocks are named by the instance path below the wrapper's `core.` with RustHDL's register wrapper
//! (`….q`) and yosys's cell suffixes (`_TRELLIS_FF_Q_3`, `$…`) removed: `core.front.setup.s7.q_TRELLIS_FF_Q_33`
//! is register `front.setup.s7` of block `front.setup`. Endpoints outside `core.` are the wrapper's
//! (its output register behind the top's outputs) and are counted as `(wrapper)`.

use std::collections::BTreeMap;

/// One endpoint's latest arrival.
#[derive(Clone, Debug, PartialEq)]
pub struct Endpoint {
    /// nextpnr's cell name.
    pub cell: String,
    pub port: String,
    /// ns after the launching edge.
    pub arrival: f64,
}

/// The late endpoints of one block.
#[derive(Clone, Debug, PartialEq)]
pub struct BlockBudget {
    pub block: String,
    /// Endpoints later than each budget (same order as [`Budget::periods`]).
    pub late: Vec<usize>,
    /// The block's latest endpoint: its register and arrival.
    pub worst_register: String,
    pub worst_arrival: f64,
}

/// A top's endpoints against a list of clock periods.
#[derive(Clone, Debug, PartialEq)]
pub struct Budget {
    /// Clock periods in ns, from the budgets' MHz.
    pub periods: Vec<f64>,
    pub endpoints: usize,
    /// Endpoints later than each period.
    pub late: Vec<usize>,
    /// Sum of (arrival - period) over the endpoints later than the first period, ns.
    pub over_ns: f64,
    /// Blocks with an endpoint later than the last (longest) period first, most late endpoints first.
    pub blocks: Vec<BlockBudget>,
}

/// The endpoints of a nextpnr JSON report on the design's clock (`clock` or `$glbnet$clock…`), each
/// with its latest arrival over the nets that reach it. Fails when the report has no
/// `detailed_net_timings` (nextpnr ran without `--detailed-timing-report`).
pub fn endpoints(report: &serde_json::Value) -> Result<Vec<Endpoint>, String> {
    let nets = report
        .get("detailed_net_timings")
        .and_then(|v| v.as_array())
        .ok_or("nextpnr's report has no detailed_net_timings (run it with --detailed-timing-report)")?;
    let mut latest: BTreeMap<(String, String), f64> = BTreeMap::new();
    for net in nets {
        let Some(eps) = net.get("endpoints").and_then(|v| v.as_array()) else { continue };
        for e in eps {
            let event = e.get("event").and_then(|v| v.as_str()).unwrap_or("");
            if !event.contains("clock") {
                continue;
            }
            let (Some(cell), Some(port)) = (e.get("cell").and_then(|v| v.as_str()), e.get("port").and_then(|v| v.as_str())) else { continue };
            let arrival = match e.get("delay") {
                Some(serde_json::Value::Array(a)) => a.iter().filter_map(|x| x.as_f64()).fold(f64::NAN, f64::max),
                Some(v) => v.as_f64().unwrap_or(f64::NAN),
                None => f64::NAN,
            };
            if !arrival.is_finite() {
                continue;
            }
            let slot = latest.entry((cell.to_string(), port.to_string())).or_insert(f64::NEG_INFINITY);
            *slot = slot.max(arrival);
        }
    }
    if latest.is_empty() {
        return Err("nextpnr's report names no endpoint on the design's clock".into());
    }
    Ok(latest.into_iter().map(|((cell, port), arrival)| Endpoint { cell, port, arrival }).collect())
}

/// The register a cell belongs to: its instance path below `core.`, without yosys's suffixes and
/// RustHDL's `q` wrapper; `None` for the wrapper's own cells.
pub fn register_of(cell: &str) -> Option<String> {
    let path = cell.strip_prefix("core.")?;
    let mut parts: Vec<&str> = path.split('.').collect();
    let last = parts.pop().unwrap_or("");
    let cut = [ "_TRELLIS", "$", "_CCU2C", "_LUT4", "_MULT18X18D", "_PFUMX", "_L6MUX21", "_DP16KD"]
        .iter()
        .filter_map(|s| last.find(s))
        .min()
        .unwrap_or(last.len());
    let base = &last[..cut];
    if !base.is_empty() && base != "q" {
        parts.push(base);
    }
    Some(if parts.is_empty() { "(top)".to_string() } else { parts.join(".") })
}

/// The block a register is in (its parent instance), `(top)` for the core's own registers.
pub fn block_of(register: &str) -> String {
    match register.rsplit_once('.') {
        Some((b, _)) => b.to_string(),
        None => "(top)".to_string(),
    }
}

/// Count the endpoints later than each budget (MHz), per block.
pub fn budget(eps: &[Endpoint], budgets_mhz: &[f64]) -> Budget {
    let periods: Vec<f64> = budgets_mhz.iter().map(|f| 1000.0 / f).collect();
    let late = periods.iter().map(|p| eps.iter().filter(|e| e.arrival > *p).count()).collect();
    let first = periods.iter().cloned().fold(f64::INFINITY, f64::min);
    let over_ns = eps.iter().filter(|e| e.arrival > first).map(|e| e.arrival - first).sum();
    let mut blocks: BTreeMap<String, BlockBudget> = BTreeMap::new();
    for e in eps.iter().filter(|e| e.arrival > first) {
        let (block, reg) = match register_of(&e.cell) {
            Some(r) => (block_of(&r), r),
            None => ("(wrapper)".to_string(), e.cell.clone()),
        };
        let b = blocks.entry(block.clone()).or_insert(BlockBudget { block, late: vec![0; periods.len()], worst_register: String::new(), worst_arrival: f64::NEG_INFINITY });
        for (k, p) in periods.iter().enumerate() {
            b.late[k] += (e.arrival > *p) as usize;
        }
        if e.arrival > b.worst_arrival {
            b.worst_arrival = e.arrival;
            b.worst_register = format!("{}.{}", reg, e.port);
        }
    }
    let mut blocks: Vec<BlockBudget> = blocks.into_values().collect();
    let key = |b: &BlockBudget| b.late.iter().rev().cloned().collect::<Vec<_>>();
    blocks.sort_by(|a, b| key(b).cmp(&key(a)).then(b.worst_arrival.total_cmp(&a.worst_arrival)));
    Budget { periods, endpoints: eps.len(), late, over_ns, blocks }
}

/// The budget as Markdown: one summary line and a table of the `rows` blocks with the most late
/// endpoints.
pub fn markdown(name: &str, b: &Budget, budgets_mhz: &[f64], rows: usize) -> String {
    use std::fmt::Write as _;
    let mut s = String::new();
    let late: Vec<String> = b
        .late
        .iter()
        .zip(b.periods.iter().zip(budgets_mhz))
        .map(|(n, (p, f))| format!("**{n}** later than {p:.2} ns ({f} MHz)"))
        .collect();
    let _ = writeln!(s, "{name}: of {} endpoints, {}; {:.0} ns over the first budget in all.\n", b.endpoints, late.join(", "), b.over_ns);
    if b.blocks.is_empty() {
        return s;
    }
    let heads: Vec<String> = budgets_mhz.iter().map(|f| format!("late for {f} MHz")).collect();
    let _ = writeln!(s, "| block | {} | latest arrival (ns) | at |", heads.join(" | "));
    let _ = writeln!(s, "|---|{}---|---|", "---|".repeat(heads.len()));
    for bl in b.blocks.iter().take(rows) {
        let n: Vec<String> = bl.late.iter().map(|x| x.to_string()).collect();
        let _ = writeln!(s, "| `{}` | {} | {:.2} | `{}` |", bl.block, n.join(" | "), bl.worst_arrival, bl.worst_register);
    }
    if b.blocks.len() > rows {
        let _ = writeln!(s, "\n({} more blocks with late endpoints.)", b.blocks.len() - rows);
    }
    s.push('\n');
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cut of a real nextpnr-ecp5 report (the `rc` top), with one endpoint reached by two nets and
    /// one on the wrapper.
    const REPORT: &str = r#"{"detailed_net_timings": [
      {"driver": "core.front.setup.mul_q.hh_CCU2C_S0$CCU2_COMB1", "endpoints": [
         {"cell": "core.front.setup.q_prod.q_TRELLIS_FF_Q", "delay": [6.8, 16.297], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "DI"},
         {"cell": "core.front.traversal.e2.q_TRELLIS_FF_Q_24", "delay": [2.0, 9.0], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "CE"}],
       "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "net": "n1", "port": "F"},
      {"driver": "core.front.traversal.walk_end_LUT4_Z", "endpoints": [
         {"cell": "core.front.traversal.e2.q_TRELLIS_FF_Q_24", "delay": [3.0, 13.35], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "CE"},
         {"cell": "core.front.setup.mul_d1.pp0_0_TRELLIS_FF_Q_1", "delay": [1.0, 11.0], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "M"},
         {"cell": "core.z_test.f0.q_TRELLIS_FF_Q_65", "delay": [1.0, 4.0], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "M"},
         {"cell": "fpga_so_TRELLIS_FF_Q_2", "delay": [1.0, 10.5], "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "port": "DI"},
         {"cell": "fpga_so_pin", "delay": [1.0, 30.0], "event": "<async>", "port": "I"}],
       "event": "posedge $glbnet$clock$TRELLIS_IO_IN", "net": "n2", "port": "Z"}
    ]}"#;

    #[test]
    fn an_endpoint_reached_by_two_nets_counts_once_at_its_latest_arrival_and_async_sinks_are_left_out() {
        let r: serde_json::Value = serde_json::from_str(REPORT).unwrap();
        let eps = endpoints(&r).unwrap();
        assert_eq!(eps.len(), 5);
        let e2 = eps.iter().find(|e| e.cell.contains("e2")).unwrap();
        assert_eq!(e2.arrival, 13.35);
        assert!(!eps.iter().any(|e| e.cell == "fpga_so_pin"));
    }

    #[test]
    fn registers_and_blocks_are_named_from_the_instance_path_without_cell_suffixes() {
        assert_eq!(register_of("core.front.setup.s7.q_TRELLIS_FF_Q_33").as_deref(), Some("front.setup.s7"));
        assert_eq!(register_of("core.front.setup.mul_d1.pp0_0_TRELLIS_FF_Q_1").as_deref(), Some("front.setup.mul_d1.pp0_0"));
        assert_eq!(register_of("core.front.setup.mul_q.hh_MULT18X18D_P0").as_deref(), Some("front.setup.mul_q.hh"));
        assert_eq!(register_of("core.state$q_TRELLIS_FF_Q").as_deref(), Some("state"));
        assert_eq!(register_of("fpga_so_TRELLIS_FF_Q_2"), None);
        assert_eq!(block_of("front.setup.s7"), "front.setup");
        assert_eq!(block_of("state"), "(top)");
    }

    #[test]
    fn endpoints_are_counted_against_every_budget_per_block_latest_first() {
        let r: serde_json::Value = serde_json::from_str(REPORT).unwrap();
        let b = budget(&endpoints(&r).unwrap(), &[100.0, 80.0]);
        assert_eq!(b.periods, vec![10.0, 12.5]);
        // Late for 10 ns: q_prod 16.297, e2 13.35, mul_d1 11.0, the wrapper's 10.5; for 12.5 ns the first two.
        assert_eq!(b.late, vec![4, 2]);
        assert!((b.over_ns - (6.297 + 3.35 + 1.0 + 0.5)).abs() < 1e-9);
        let names: Vec<&str> = b.blocks.iter().map(|x| x.block.as_str()).collect();
        // Ordered by endpoints late for 80 MHz, then for 100 MHz, then by the latest arrival; a leaf
        // block (the multiplier `mul_d1`) is a block of its own.
        assert_eq!(names, vec!["front.setup", "front.traversal", "front.setup.mul_d1", "(wrapper)"]);
        assert_eq!(b.blocks[0].late, vec![1, 1]);
        assert_eq!(b.blocks[2].late, vec![1, 0]);
        assert_eq!(b.blocks[0].worst_register, "front.setup.q_prod.DI");
        assert_eq!(b.blocks[3].worst_register, "fpga_so_TRELLIS_FF_Q_2.DI");
        let md = markdown("`rc` on ecp5-45k", &b, &[100.0, 80.0], 3);
        assert!(md.contains("**4** later than 10.00 ns (100 MHz), **2** later than 12.50 ns (80 MHz)"), "{md}");
        assert!(md.contains("| `front.setup` | 1 | 1 | 16.30 | `front.setup.q_prod.DI` |"), "{md}");
        assert!(md.contains("(1 more blocks"), "{md}");
    }

    #[test]
    fn a_report_without_detailed_timings_is_an_error_that_says_which_flag_is_missing() {
        let r: serde_json::Value = serde_json::from_str(r#"{"fmax": {}}"#).unwrap();
        let e = endpoints(&r).unwrap_err();
        assert!(e.contains("--detailed-timing-report"), "{e}");
    }
}
