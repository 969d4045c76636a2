// Formal harness of the `rc` top (the Rasterizer Controller, `idxrender verilog --block rc`;
// RustHDL source hdl/src/rc/mod.rs). Run by `bash scripts/formal.sh rc`; see docs/verification.md.
// The Z-test's forwarding is checked on its module (rc_z_test.sv); this harness checks the top's
// streams and memory ports. Triangles are arbitrary; the Z and I read data are arbitrary.
//
// Assumed: cmd valid held until ready and data stable while stalled; no clearing frame command (a
// clear takes width x height = 64,000 cycles); no command kind 3; triangle indices not 0 (the
// background index).
// Asserted: result valid held until ready and data stable while stalled; one result per triangle
// or end-of-frame command, in command order (the n-th result, n solver-chosen, has the n-th such
// command's index, or eof for an end-of-frame command); Z and I written together at one address; every memory address and data
// output 0 while its enable is low. Reach points: a stalled result; a triangle's result with its
// `visible` flag set (set-up, traversed and Z-tested); an end-of-frame result.
//
// RcCommand: kind 1:0 (0 frame, 1 triangle, 2 end of frame), clear 2, index 18:3, then culling and
// the vertices. RcResult: eof 0, index 16:1, culled 17, zero_area 18, visible 19.
module rc_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire [213:0] cmd_data,
    input wire cmd_valid,
    input wire result_ready,
    input wire [23:0] z_rd_data,
    input wire [15:0] i_rd_data
);
    wire cmd_ready, result_valid, z_re, z_we, i_we;
    wire [19:0] result_data, z_rd_addr, z_wr_addr, i_wr_addr;
    wire [23:0] z_wr_data;
    wire [15:0] i_wr_data;
    rc dut (
        .clock(clock), .cmd$data(cmd_data), .cmd$valid(cmd_valid), .cmd$ready(cmd_ready),
        .result$data(result_data), .result$valid(result_valid), .result$ready(result_ready),
        .z_re(z_re), .z_rd_addr(z_rd_addr), .z_we(z_we), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data),
        .z_rd_data(z_rd_data), .i_we(i_we), .i_wr_addr(i_wr_addr), .i_wr_data(i_wr_data),
        .i_rd_data(i_rd_data)
    );

    `define RC_ORDER (REACH < 0)
    `include "stream.vh"
    `include "rc_protocol.vh"
    always @(*) begin
        if (REACH < 0) assert (z_we == i_we && (!z_we || z_wr_addr == i_wr_addr));
        if (!z_re) if (REACH < 0) assert (z_rd_addr == 20'd0);
        if (!z_we) if (REACH < 0) assert (z_wr_addr == 20'd0 && z_wr_data == 24'd0);
        if (!i_we) if (REACH < 0) assert (i_wr_addr == 20'd0 && i_wr_data == 16'd0);
    end
endmodule
