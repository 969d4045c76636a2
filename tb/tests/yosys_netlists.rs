//! Yosys reads the generated Verilog as the simulators do: the netlist that `yosys prep` makes of each
//! top (the netlist the FPGA flow and the mutation cover start from: every top of `tb::mutation::TOPS`)
//! replays the same recorded vectors as the generated Verilog, every port in every cycle, under Icarus
//! (Verilator for `cs_tex`, and for `cs`'s 1024x1024 frame).
//!
//! Before `hdl::common::sized_localparams`, Yosys 0.23 read rust-hdl's `localparam signed k = 17'b111;`
//! as unsigned, and the netlist of `rc` clipped the boxes of triangles left of or above the screen
//! wrongly (the replay of the hand-made cases failed at cycle 3232).

use tb::common::{require_tools, workspace_target};
use tb::mutation::{target, yosys_netlist, TOPS};

#[test]
fn yosys_netlists_of_every_mutation_top_replay_as_the_generated_verilog_does() {
    if !require_tools("yosys_netlists_of_every_mutation_top_replay_as_the_generated_verilog_does", &["yosys", "iverilog", "vvp", "verilator"]) {
        return;
    }
    for top in TOPS {
        let dir = workspace_target().join("hdl").join("yosys_netlists").join(top);
        let _ = std::fs::remove_dir_all(&dir);
        let t = target(top, &dir).unwrap_or_else(|e| panic!("{top}: {e}"));
        t.replay(&t.verilog, &dir.join("generated")).unwrap_or_else(|e| panic!("{top}: the generated Verilog: {e}"));
        let netlist = yosys_netlist(&t, &dir).unwrap_or_else(|e| panic!("{top}: {e}"));
        t.replay(&netlist, &dir.join("netlist")).unwrap_or_else(|e| panic!("{top}: Yosys's netlist differs from the generated Verilog: {e}"));
        println!("{top}: Yosys's netlist replays {}", t.stimulus);
    }
}
