// Formal harness of the RC's Z-test stage, module `rc$z_test` of the `rc` top's Verilog
// (`idxrender verilog --block rc`; RustHDL source hdl/src/rc/z_test.rs). Run by
// `bash scripts/formal.sh rc_z_test`; see docs/verification.md.
//
// The Z-buffer and the I-buffer are modelled at one solver-chosen address A (any other address
// returns arbitrary words): a synchronous read on the stage's read port (`z_re`, `z_rd_addr`) returns,
// one cycle later, the word held before the writes of that edge, as the external memories do. Tokens
// are arbitrary; a token is registered in F0 (which issues its read) and decided on in F1.
// Assumed: a token that pushes a result (a result token, or a fragment marked last) is issued only
// while `result_free`; a fragment's triangle index is not 0 (the background index; the host's
// triangles are numbered from 1); the result port's `ready` is arbitrary.
// Asserted:
//   * F0 reads exactly for a covered fragment, at its address, and the read port is 0 otherwise;
//   * the Z-test compares a fragment at A with the depth last written to A, even when that write
//     happened at the previous edge (the read-after-write forwarding), and with the far plane where
//     the I-buffer holds the background index 0;
//   * writes: a passing fragment writes its depth and index at its address, a clear token writes the
//     far plane and index 0, nothing else writes; Z and I are written together;
//   * results: valid held until ready and data stable while stalled, never more than four held,
//     and the n-th result (n solver-chosen) is the n-th pushed token's index and flags, with
//     `visible` the OR of the Z-test passes of that triangle's fragments.
// Reach points (each must be reachable; sby's reachN tasks): the forwarding used on the same pixel
// within a triangle, and across two triangles with no gap; forwarding changing the outcome; a full
// result queue; a stall of the result port.
//
// RcToken layout (rust-hdl packs the first field at bit 0): kind 1:0 (0 none, 1 clear, 2 fragment,
// 3 result), covered 2, last 3, addr 23:4, x 33:24, y 43:34, z 67:44, index 83:68, eof 84,
// culled 85, zero_area 86. RcResult: eof 0, index 16:1, culled 17, zero_area 18, visible 19.
`include "stream.vh"
`include "rc_result_queue.vh"

module rc_z_test_formal #(
    // -1: check every assertion; n >= 0: check only that reach point n is unreachable, a run that
    // sby expects to fail (its counterexample is the witness that the point is reachable).
    parameter integer REACH = -1,
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
) (
    input wire clock,
    input wire [86:0] tok,
    input wire [23:0] z_other,
    input wire [15:0] i_other,
    input wire result_ready
);
    wire result_free;
    wire z_re;
    wire [19:0] z_rd_addr;
    reg [23:0] z_rd_data = 24'd0;
    reg [15:0] i_rd_data = 16'd0;
    wire z_we, i_we;
    wire [19:0] z_wr_addr, i_wr_addr;
    wire [23:0] z_wr_data;
    wire [15:0] i_wr_data;
    wire [19:0] result_data;
    wire result_valid;

    rc$z_test dut (
        .clock(clock), .tok(tok), .result_free(result_free), .z_re(z_re), .z_rd_addr(z_rd_addr),
        .z_rd_data(z_rd_data), .i_rd_data(i_rd_data),
        .z_we(z_we), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data),
        .i_we(i_we), .i_wr_addr(i_wr_addr), .i_wr_data(i_wr_data),
        .result$data(result_data), .result$valid(result_valid), .result$ready(result_ready)
    );

    localparam [1:0] CLEAR = 2'd1, FRAG = 2'd2, RESULT = 2'd3;
    localparam [23:0] FAR = 24'hffffff;

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;

    // ---- The memories at address A.
    (* anyconst *) reg [19:0] A;
    (* anyconst *) reg [23:0] z_init;
    (* anyconst *) reg [15:0] i_init;
    reg written = 1'b0;
    reg [23:0] z_a = 24'd0;
    reg [15:0] i_a = 16'd0;
    wire [23:0] z_now = written ? z_a : z_init;
    wire [15:0] i_now = written ? i_a : i_init;
    always @(posedge clock) begin
        z_rd_data <= z_re && z_rd_addr == A ? z_now : z_other;
        i_rd_data <= z_re && z_rd_addr == A ? i_now : i_other;
        if (z_we && z_wr_addr == A) begin
            written <= 1'b1;
            z_a <= z_wr_data;
            i_a <= i_wr_data;
        end
    end

    // ---- The token that reads (F0), the token in the Z-test (F1) and what the memories hold for it.
    reg [86:0] f0 = 87'd0;
    reg [86:0] f1 = 87'd0;
    always @(posedge clock) begin
        f0 <= tok;
        f1 <= f0;
    end
    wire f0_reads = f0[1:0] == FRAG && f0[2];
    wire f0_pushes = f0[1:0] == RESULT || (f0[1:0] == FRAG && f0[3]);
    wire [1:0] f1_kind = f1[1:0];
    wire f1_covered = f1[2];
    wire f1_last = f1[3];
    wire [19:0] f1_addr = f1[23:4];
    wire [23:0] f1_z = f1[67:44];
    wire [15:0] f1_index = f1[83:68];
    wire f1_frag = f1_kind == FRAG;
    wire [23:0] true_old = i_now == 16'd0 ? FAR : z_now;

    // ---- Assumption: result tokens only with room.
    wire tok_pushes = tok[1:0] == RESULT || (tok[1:0] == FRAG && tok[3]);
    always @(*) begin
        if (tok_pushes) assume (result_free);
        if (tok[1:0] == FRAG) assume (tok[83:68] != 16'd0);
    end

    // ---- The read, the Z-test and the writes.
    always @(*) begin
        if (REACH < 0) assert (z_re == f0_reads && z_rd_addr == (f0_reads ? f0[23:4] : 20'd0));
        if (f1_frag && f1_covered && f1_addr == A) if (REACH < 0) assert (z_we == (f1_z < true_old));
        if (z_we) begin
            if (REACH < 0) assert (z_wr_addr == f1_addr && i_we && i_wr_addr == f1_addr);
            if (f1_frag) begin
                if (REACH < 0) assert (f1_covered && z_wr_data == f1_z && i_wr_data == f1_index);
            end else begin
                if (REACH < 0) assert (f1_kind == CLEAR && z_wr_data == FAR && i_wr_data == 16'd0);
            end
        end else begin
            if (REACH < 0) assert (!i_we && f1_kind != CLEAR);
        end
    end

    // ---- Results: protocol, depth, order and content (rc_result_queue.vh).
    `RC_RESULT_QUEUE(f1, z_we, 8'd4)

    // ---- Reach points.
    reg prev_last = 1'b0;
    always @(posedge clock) prev_last <= f1_frag && f1_last;
    reg prev_write_a = 1'b0;
    always @(posedge clock) prev_write_a <= z_we && z_wr_addr == A;

    // ---- Strengthening invariants (the `prove` task's k-induction), on the stage's registers probed by
    // their names in the generated Verilog (the .sby's `connect` lines, after `flatten`): F0 and F1
    // are the harness's tokens, with indices not 0 and their results fitting the queue; the forwarding register holds the write of the previous edge, and where that
    // was at A, A's depth; a read for the token in F1 at A returned A's words unless A was written at
    // the previous edge; A's words mean the far plane wherever its index is the background; the
    // result queue holds pushed - popped results, the k-th from the head being result popped + k,
    // and its `visible` is the harness's OR of the passes.
    wire [86:0] p_f0, p_f1;
    wire p_fwd_valid;
    wire [19:0] p_fwd_addr;
    wire [23:0] p_fwd_z;
    wire p_visible;
    wire [19:0] p_q0, p_q1, p_q2, p_q3;
    wire [2:0] p_len;
    generate if (INDUCT) begin : invariants
        always @(*) if (REACH < 0) begin
            assert (p_f0 == f0 && p_f1 == f1 && p_visible == rq_vis);
            // The tokens in F0 and F1 came in under the assumptions: fragments' indices are not 0, and
            // the results in flight fit the queue.
            if (f0[1:0] == FRAG) assert (f0[83:68] != 16'd0);
            if (f1_frag) assert (f1_index != 16'd0);
            assert ({5'd0, p_len} + (f0_pushes ? 8'd1 : 8'd0) + (rq_pushes ? 8'd1 : 8'd0) <= 8'd4);
            if (p_fwd_valid && p_fwd_addr == A) assert (written && p_fwd_z == z_a);
            if (prev_write_a) assert (p_fwd_valid && p_fwd_addr == A);
            if (past_valid && f1_frag && f1_covered && f1_addr == A && !prev_write_a) assert (z_rd_data == z_now && i_rd_data == i_now);
            if (written && i_a == 16'd0) assert (z_a == FAR);
            assert ({5'd0, p_len} == pushed - popped);
            if (p_len > 3'd0 && popped == tracked) assert (p_q0 == tracked_result);
            if (p_len > 3'd1 && popped + 8'd1 == tracked) assert (p_q1 == tracked_result);
            if (p_len > 3'd2 && popped + 8'd2 == tracked) assert (p_q2 == tracked_result);
            if (p_len > 3'd3 && popped + 8'd3 == tracked) assert (p_q3 == tracked_result);
        end
    end endgenerate
    wire forwarded = prev_write_a && f1_frag && f1_covered && f1_addr == A;
    `STALL_REACH(result_valid, result_ready, 4)
    always @(posedge clock) if (past_valid) begin
        cover (forwarded && !prev_last);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!(forwarded && !prev_last));
        cover (forwarded && prev_last);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(forwarded && prev_last));
        cover (forwarded && (z_we != (f1_z < z_rd_data)));
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(forwarded && (z_we != (f1_z < z_rd_data))));
        cover (pushed - popped == 8'd4);
        if (REACH == 3 || REACH_SET[3]) reach_3: assert (!(pushed - popped == 8'd4));
    end
endmodule
