// Formal harness of Type III's visibility test, module `rc3$vis` of the `rc3` top's Verilog
// (`idxrender verilog --block rc3`; RustHDL source hdl/src/rc/tdbv_test.rs). Run by
// `bash scripts/formal.sh rc3_tdbv_test`; see docs/verification.md.
//
// Type III keeps no Z-buffer: a pixel's old depth is regenerated from TdbV, the depth plane of the
// triangle whose index the I-buffer holds. The I-buffer is modelled at one solver-chosen address A
// (pixel XA, YA; any other address returns arbitrary words) with the memory's timing: a read issued
// with each token returns, one cycle later, the word held before the writes of that edge. TdbV holds
// a plane for every index, a function of the index and of solver-chosen constants: A and B are
// signed 4-bit values, C a signed 42-bit value (all sign-extended to the port widths), and the pixel
// A is in the 16x16 corner of the screen, so that the harness's own products are small (with 8-bit
// coefficients and any pixel, abc's bmc3 had not reached depth 20 after 15 minutes: it has to show
// the DUT's 40x11 multipliers equal to the harness's); a read returns its index's plane one cycle
// later and arbitrary words after a cycle without a read. Tokens elsewhere have any pixel.
// Assumed, the contract the traversal and setup keep: a token that pushes a result (a result token,
// or a fragment marked last) is issued only while `result_free`; a fragment's index is not 0 (the
// background index); a token at A carries the pixel XA, YA; a fragment at A has the depth its
// triangle's plane gives there, `clamp(floor((C + A*x + B*y + 2^15) / 2^16), 0, 2^24-1)`, the value
// the traversal stepped to. The result port's `ready` is arbitrary.
// Asserted:
//   * the test compares a covered fragment at A with the depth last written to A (far after a clear,
//     the plane of the initial owner, or far where the initial index is 0) whether that write was
//     made one, two, three or four cycles earlier (still in flight when the I-buffer was read: the
//     forwarding) or before;
//   * TdbV is read for a covered fragment exactly when the I-buffer word is not 0, at that word;
//   * writes: a passing fragment writes its index at its address, a clear writes index 0, nothing
//     else writes, and the write port is 0 when not enabled;
//   * results: valid held until ready and data stable while stalled, never more than six held, and
//     the n-th result (n solver-chosen) is the n-th pushed token's index and flags, with `visible` the
//     OR of the passes of that triangle's fragments.
// Reach points (each must be reachable; sby's reachN tasks): the forwarding of a write made 1, 2, 3
// and 4 cycles earlier; at distance 1 across two triangles with no gap; forwarding changing the
// outcome (the regenerated depth of the word read would decide otherwise); a full result queue; a
// stall of the result port.
//
// RcToken layout (rust-hdl packs the first field at bit 0): kind 1:0 (0 none, 1 clear, 2 fragment,
// 3 result), covered 2, last 3, addr 23:4, x 33:24, y 43:34, z 67:44, index 83:68, eof 84,
// culled 85, zero_area 86. RcResult: eof 0, index 16:1, culled 17, zero_area 18, visible 19.
`include "stream.vh"
`include "rc_result_queue.vh"

module rc3_tdbv_test_formal #(
    // -1: check every assertion; n >= 0: check only that reach point n is unreachable, a run that
    // sby expects to fail (its counterexample is the witness that the point is reachable).
    parameter integer REACH = -1,
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    // The pixel A is at most (PIXEL_MAX, PIXEL_MAX).
    parameter integer PIXEL_MAX = 3
) (
    input wire clock,
    input wire [86:0] tok,
    input wire [15:0] i_other,
    input wire [39:0] a_other,
    input wire [39:0] b_other,
    input wire [55:0] c_other,
    input wire result_ready
);
    wire result_free;
    reg [15:0] i_rd_data = 16'd0;
    wire tdbv_re;
    wire [15:0] tdbv_rd_addr;
    wire [39:0] tdbv_rd_a, tdbv_rd_b;
    wire [55:0] tdbv_rd_c;
    wire i_we;
    wire [19:0] i_wr_addr;
    wire [15:0] i_wr_data;
    wire [19:0] result_data;
    wire result_valid;

    rc3$vis dut (
        .clock(clock), .tok(tok), .result_free(result_free), .i_rd_data(i_rd_data),
        .tdbv_re(tdbv_re), .tdbv_rd_addr(tdbv_rd_addr),
        .tdbv_rd_a(tdbv_rd_a), .tdbv_rd_b(tdbv_rd_b), .tdbv_rd_c(tdbv_rd_c),
        .i_we(i_we), .i_wr_addr(i_wr_addr), .i_wr_data(i_wr_data),
        .result$data(result_data), .result$valid(result_valid), .result$ready(result_ready)
    );

    localparam [1:0] CLEAR = 2'd1, FRAG = 2'd2, RESULT = 2'd3;
    localparam [23:0] FAR = 24'hffffff;

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;

    // ---- TdbV: the plane of index k.
    (* anyconst *) reg [3:0] pa;
    (* anyconst *) reg [3:0] pb;
    (* anyconst *) reg [41:0] pc;
    function [3:0] plane_a(input [15:0] k); plane_a = pa ^ k[3:0] ^ k[11:8]; endfunction
    function [3:0] plane_b(input [15:0] k); plane_b = pb ^ k[7:4] ^ k[15:12]; endfunction
    function [41:0] plane_c(input [15:0] k); plane_c = pc ^ {k, 26'd0}; endfunction
    // The plane of index k at the pixel (x, y): the depth the traversal steps to.
    function [23:0] plane_z(input [15:0] k, input [9:0] x, input [9:0] y);
        reg signed [55:0] raw;
        begin
            raw = $signed(plane_c(k)) + $signed(plane_a(k)) * $signed({1'b0, x})
                + $signed(plane_b(k)) * $signed({1'b0, y}) + 56'sd32768;
            if (raw < 0) plane_z = 24'd0;
            else if (raw[55:40] != 16'd0) plane_z = FAR;
            else plane_z = raw[39:16];
        end
    endfunction
    reg read_q = 1'b0;
    reg [15:0] read_k = 16'd0;
    always @(posedge clock) begin
        read_q <= tdbv_re;
        read_k <= tdbv_rd_addr;
    end
    wire [3:0] ra = plane_a(read_k);
    wire [3:0] rb = plane_b(read_k);
    wire [41:0] rc = plane_c(read_k);
    assign tdbv_rd_a = read_q ? {{36{ra[3]}}, ra} : a_other;
    assign tdbv_rd_b = read_q ? {{36{rb[3]}}, rb} : b_other;
    assign tdbv_rd_c = read_q ? {{14{rc[41]}}, rc} : c_other;

    // ---- The I-buffer at address A, and the depth last written there.
    (* anyconst *) reg [19:0] A;
    (* anyconst *) reg [9:0] XA;
    (* anyconst *) reg [9:0] YA;
    (* anyconst *) reg [15:0] i_init;
    reg written = 1'b0;
    reg [15:0] i_a = 16'd0;
    reg [23:0] z_a = 24'd0;
    wire [15:0] i_now = written ? i_a : i_init;
    wire [23:0] z_init = i_init == 16'd0 ? FAR : plane_z(i_init, XA, YA);
    wire [23:0] z_now = written ? z_a : z_init;
    always @(posedge clock) i_rd_data <= tok[23:4] == A ? i_now : i_other;

    // ---- The tokens in F1..F4 (the harness's own copy of the pipeline's timing).
    reg [86:0] f1 = 87'd0, f2 = 87'd0, f3 = 87'd0, f4 = 87'd0;
    // The depth the I-buffer word read for each token regenerates to (without forwarding).
    reg [23:0] stale2 = 24'd0, stale3 = 24'd0, stale4 = 24'd0;
    wire [23:0] stale1 = i_rd_data == 16'd0 ? FAR : plane_z(i_rd_data, XA, YA);
    always @(posedge clock) begin
        f1 <= tok; f2 <= f1; f3 <= f2; f4 <= f3;
        stale2 <= stale1; stale3 <= stale2; stale4 <= stale3;
    end
    wire [1:0] f4_kind = f4[1:0];
    wire f4_covered = f4[2];
    wire f4_last = f4[3];
    wire [19:0] f4_addr = f4[23:4];
    wire [23:0] f4_z = f4[67:44];
    wire [15:0] f4_index = f4[83:68];
    wire f4_frag = f4_kind == FRAG;
    always @(posedge clock) if (i_we && i_wr_addr == A) begin
        written <= 1'b1;
        i_a <= i_wr_data;
        z_a <= f4_frag ? f4_z : FAR;
    end

    // ---- Assumptions: the traversal's and setup's contract.
    wire tok_pushes = tok[1:0] == RESULT || (tok[1:0] == FRAG && tok[3]);
    always @(*) begin
        if (tok_pushes) assume (result_free);
        if (tok[1:0] == FRAG) assume (tok[83:68] != 16'd0);
        if (tok[1:0] != 2'd0 && tok[23:4] == A) assume (tok[33:24] == XA && tok[43:34] == YA);
        assume (XA <= PIXEL_MAX && YA <= PIXEL_MAX);
        if (tok[1:0] == FRAG && tok[23:4] == A) assume (tok[67:44] == plane_z(tok[83:68], XA, YA));
    end

    // ---- The test against the depth last written, TdbV reads, the writes.
    wire [1:0] f1_kind = f1[1:0];
    always @(*) begin
        if (f4_frag && f4_covered && f4_addr == A) if (REACH < 0) assert (i_we == (f4_z < z_now));
        if (REACH < 0) assert (tdbv_re == (f1_kind == FRAG && f1[2] && i_rd_data != 16'd0));
        if (REACH < 0) assert (tdbv_rd_addr == (tdbv_re ? i_rd_data : 16'd0));
        if (i_we) begin
            if (REACH < 0) assert (i_wr_addr == f4_addr);
            if (f4_frag) begin
                if (REACH < 0) assert (f4_covered && i_wr_data == f4_index);
            end else begin
                if (REACH < 0) assert (f4_kind == CLEAR && i_wr_data == 16'd0);
            end
        end else begin
            if (REACH < 0) assert (f4_kind != CLEAR && i_wr_addr == 20'd0 && i_wr_data == 16'd0);
        end
    end

    // ---- Results: protocol, depth, order and content (rc_result_queue.vh).
    `RC_RESULT_QUEUE(f4, i_we, 8'd6)

    // ---- Reach points.
    // w1..w4: a write to A one to four edges ago; the newest one is the one forwarded.
    reg w1 = 1'b0, w2 = 1'b0, w3 = 1'b0, w4 = 1'b0;
    reg last1 = 1'b0;
    always @(posedge clock) begin
        w1 <= i_we && i_wr_addr == A; w2 <= w1; w3 <= w2; w4 <= w3;
        last1 <= f4_frag && f4_last;
    end
    wire at_a = f4_frag && f4_covered && f4_addr == A;
    wire fwd1 = at_a && w1;
    wire fwd2 = at_a && !w1 && w2;
    wire fwd3 = at_a && !w1 && !w2 && w3;
    wire fwd4 = at_a && !w1 && !w2 && !w3 && w4;
    wire changed = at_a && (w1 || w2 || w3 || w4) && ((f4_z < stale4) != (f4_z < z_now));
    `STALL_REACH(result_valid, result_ready, 7)
    always @(posedge clock) if (past_valid) begin
        cover (fwd1 && !last1);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!(fwd1 && !last1));
        cover (fwd1 && last1);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(fwd1 && last1));
        cover (fwd2);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!fwd2);
        cover (fwd3);
        if (REACH == 3 || REACH_SET[3]) reach_3: assert (!fwd3);
        cover (fwd4);
        if (REACH == 4 || REACH_SET[4]) reach_4: assert (!fwd4);
        cover (changed);
        if (REACH == 5 || REACH_SET[5]) reach_5: assert (!changed);
        cover (pushed - popped == 8'd6);
        if (REACH == 6 || REACH_SET[6]) reach_6: assert (!(pushed - popped == 8'd6));
    end
endmodule
