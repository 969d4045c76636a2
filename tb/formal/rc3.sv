// Formal harness of the `rc3` top (the Type III Rasterizer Controller, `idxrender verilog --block
// rc3`; RustHDL source hdl/src/rc/rc3.rs). Run by `bash scripts/formal.sh rc3`; see
// docs/verification.md. It checks the top's streams and memory ports, as rc.sv does for `rc`.
// Triangles are arbitrary; the I-buffer and TdbV read data are arbitrary.
//
// Assumed: cmd valid held until ready and data stable while stalled; no clearing frame command (a
// clear takes width x height = 64,000 cycles); no command kind 3; triangle indices not 0 (the
// background index).
// Asserted: result valid held until ready and data stable while stalled; one result per triangle
// or end-of-frame command, in command order (the n-th result, n solver-chosen, has the n-th such
// command's index, or eof for an end-of-frame command); every index written to the I-buffer, and
// every TdbV address written, is the index of a triangle command taken before (checked for one
// solver-chosen index); every memory address and data output 0 while its enable is low. Reach
// points: a stalled result; a triangle's result with its `visible` flag set (set-up, traversed and
// depth-tested against TdbV); an end-of-frame result; a TdbV write; an I-buffer write.
//
// RcCommand: kind 1:0 (0 frame, 1 triangle, 2 end of frame), clear 2, index 18:3, then culling and
// the vertices. RcResult: eof 0, index 16:1, culled 17, zero_area 18, visible 19.
module rc3_formal #(
    parameter integer REACH = -1,     // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDEX_ONLY = 0  // 1: only the assertions on the indices written to the I-buffer
                                      // and TdbV (a smaller cone: bmc reaches the first TdbV write)
) (
    input wire clock,
    input wire [213:0] cmd_data,
    input wire cmd_valid,
    input wire result_ready,
    input wire [15:0] i_rd_data,
    input wire signed [39:0] tdbv_rd_a,
    input wire signed [39:0] tdbv_rd_b,
    input wire signed [55:0] tdbv_rd_c
);
    wire cmd_ready, result_valid, i_re, i_we, tdbv_re, tdbv_we;
    wire [19:0] result_data, i_rd_addr, i_wr_addr;
    wire [15:0] i_wr_data, tdbv_rd_addr, tdbv_wr_addr;
    wire signed [39:0] tdbv_wr_a, tdbv_wr_b;
    wire signed [55:0] tdbv_wr_c;
    rc3 dut (
        .clock(clock), .cmd$data(cmd_data), .cmd$valid(cmd_valid), .cmd$ready(cmd_ready),
        .result$data(result_data), .result$valid(result_valid), .result$ready(result_ready),
        .i_re(i_re), .i_rd_addr(i_rd_addr), .i_rd_data(i_rd_data),
        .i_we(i_we), .i_wr_addr(i_wr_addr), .i_wr_data(i_wr_data),
        .tdbv_re(tdbv_re), .tdbv_rd_addr(tdbv_rd_addr),
        .tdbv_rd_a(tdbv_rd_a), .tdbv_rd_b(tdbv_rd_b), .tdbv_rd_c(tdbv_rd_c),
        .tdbv_we(tdbv_we), .tdbv_wr_addr(tdbv_wr_addr),
        .tdbv_wr_a(tdbv_wr_a), .tdbv_wr_b(tdbv_wr_b), .tdbv_wr_c(tdbv_wr_c)
    );

    `define RC_ORDER (REACH < 0 && INDEX_ONLY == 0)
    `include "stream.vh"
    `include "rc_protocol.vh"
    (* anyconst *) reg [15:0] tracked_index;
    reg index_taken = 1'b0;             // a triangle command with tracked_index was taken
    always @(posedge clock) if (take && kind == 2'd1 && cmd_data[18:3] == tracked_index) index_taken <= 1'b1;
    always @(*) begin
        if (i_we && i_wr_data == tracked_index) if (REACH < 0) assert (index_taken);
        if (tdbv_we && tdbv_wr_addr == tracked_index) if (REACH < 0) assert (index_taken);
        if (!i_re) if (REACH < 0 && INDEX_ONLY == 0) assert (i_rd_addr == 20'd0);
        if (!i_we) if (REACH < 0 && INDEX_ONLY == 0) assert (i_wr_addr == 20'd0 && i_wr_data == 16'd0);
        if (!tdbv_re) if (REACH < 0 && INDEX_ONLY == 0) assert (tdbv_rd_addr == 16'd0);
        if (!tdbv_we) if (REACH < 0 && INDEX_ONLY == 0) assert (tdbv_wr_addr == 16'd0 && tdbv_wr_a == 40'sd0
            && tdbv_wr_b == 40'sd0 && tdbv_wr_c == 56'sd0);
    end
    always @(posedge clock) if (past_valid) begin
        cover (tdbv_we);
        if (REACH == 3 || REACH_SET[3]) reach_3: assert (!tdbv_we);
        cover (i_we);
        if (REACH == 4 || REACH_SET[4]) reach_4: assert (!i_we);
    end
endmodule
