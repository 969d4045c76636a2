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
    parameter integer PIXEL_MAX = 3,
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
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
    // The plane of index k at the pixel (x, y): the depth the traversal steps to,
    // clamp(floor((C + A*x + B*y + 2^15) / 2^16), 0, 2^24-1). The products and sums have the operand
    // widths and the order of the DUT's (40x11 products, 56-bit sums, (A*x + B*y) + (C + 2^15)): no
    // term wraps, so the value is the same, and the prove task's solver sees the same terms.
    function [23:0] plane_z(input [15:0] k, input [9:0] x, input [9:0] y);
        reg [3:0] a4, b4;
        reg [41:0] c42;
        reg signed [39:0] a40, b40;
        reg signed [10:0] x11, y11;
        reg signed [50:0] ax, by;
        reg signed [55:0] raw;
        begin
            a4 = plane_a(k);
            b4 = plane_b(k);
            c42 = plane_c(k);
            a40 = {{36{a4[3]}}, a4};
            b40 = {{36{b4[3]}}, b4};
            x11 = {1'b0, x};
            y11 = {1'b0, y};
            ax = a40 * x11;
            by = b40 * y11;
            raw = ({{5{ax[50]}}, ax} + {{5{by[50]}}, by}) + ({{14{c42[41]}}, c42} + 56'd32768);
            if (raw[55]) plane_z = 24'd0;
            else if (raw[54:40] != 15'd0) plane_z = FAR;
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

    // ---- Strengthening invariants (the `prove` task's k-induction), on the stage's registers probed by
    // their names in the generated Verilog (the .sby's `connect` lines, after `flatten`): F1..F4 are
    // the harness's tokens; each holds the I-buffer word read for its token (`word2..4`), fresh where
    // no write to A came after the read; F2's and F3's ownership, the TdbV read and F3's products and
    // C follow from that word; F4's base is the word's plane at A; the write history h1..h4 is the
    // writes of the last four edges, the newest write to A holding A's depth; A's depth is its
    // index's plane; the result queue holds pushed - popped results (with the results still in
    // F1..F4, at most six), the k-th from the head being result popped + k, and its `visible` is the
    // harness's OR.
    reg [15:0] word2 = 16'd0, word3 = 16'd0, word4 = 16'd0;
    always @(posedge clock) begin
        word2 <= i_rd_data; word3 <= word2; word4 <= word3;
    end
    wire [86:0] p_f1, p_f2, p_f3, p_f4;
    wire [23:0] p_f4_base;
    wire p_f2_owned, p_f3_owned;
    wire [50:0] p_f3_ax, p_f3_by;
    wire [55:0] p_f3_c;
    wire p_h1_v, p_h2_v, p_h3_v, p_h4_v;
    wire [19:0] p_h1_addr, p_h2_addr, p_h3_addr, p_h4_addr;
    wire [23:0] p_h1_z, p_h2_z, p_h3_z, p_h4_z;
    wire p_visible;
    wire [19:0] p_q0, p_q1, p_q2, p_q3, p_q4, p_q5;
    wire [2:0] p_len;
    function frag_cov(input [86:0] t); frag_cov = t[1:0] == FRAG && t[2]; endfunction
    function pushes(input [86:0] t); pushes = t[1:0] == RESULT || (t[1:0] == FRAG && t[3]); endfunction
    wire [3:0] a3 = plane_a(word3);
    wire [3:0] b3 = plane_b(word3);
    wire [41:0] c3 = plane_c(word3);
    wire signed [39:0] a3_40 = {{36{a3[3]}}, a3};
    wire signed [39:0] b3_40 = {{36{b3[3]}}, b3};
    wire signed [10:0] xa11 = {1'b0, XA};
    wire signed [10:0] ya11 = {1'b0, YA};
    wire signed [50:0] ax3 = a3_40 * xa11;  // the DUT's operand widths (see plane_z)
    wire signed [50:0] by3 = b3_40 * ya11;
    wire [7:0] in_queue = pushed - popped;
    generate if (INDUCT) begin : invariants
        always @(*) if (REACH < 0) begin
            assert (p_f1 == f1 && p_f2 == f2 && p_f3 == f3 && p_f4 == f4 && p_visible == rq_vis);
            // The contract on the tokens still holds in F1..F4.
            if (f1[1:0] != 2'd0 && f1[23:4] == A) assert (f1[33:24] == XA && f1[43:34] == YA);
            if (f2[1:0] != 2'd0 && f2[23:4] == A) assert (f2[33:24] == XA && f2[43:34] == YA);
            if (f3[1:0] != 2'd0 && f3[23:4] == A) assert (f3[33:24] == XA && f3[43:34] == YA);
            if (f4[1:0] != 2'd0 && f4[23:4] == A) assert (f4[33:24] == XA && f4[43:34] == YA);
            if (f1[1:0] == FRAG && f1[23:4] == A) assert (f1[83:68] != 16'd0 && f1[67:44] == plane_z(f1[83:68], XA, YA));
            if (f2[1:0] == FRAG && f2[23:4] == A) assert (f2[83:68] != 16'd0 && f2[67:44] == plane_z(f2[83:68], XA, YA));
            if (f3[1:0] == FRAG && f3[23:4] == A) assert (f3[83:68] != 16'd0 && f3[67:44] == plane_z(f3[83:68], XA, YA));
            if (f4[1:0] == FRAG && f4[23:4] == A) assert (f4[83:68] != 16'd0 && f4[67:44] == plane_z(f4[83:68], XA, YA));
            // The I-buffer words and what each stage made of its word.
            if (past_valid && frag_cov(f1) && f1[23:4] == A && !w1) assert (i_rd_data == i_now);
            if (frag_cov(f2) && f2[23:4] == A && !w1 && !w2) assert (word2 == i_now);
            if (frag_cov(f3) && f3[23:4] == A && !w1 && !w2 && !w3) assert (word3 == i_now);
            if (frag_cov(f4) && f4[23:4] == A && !w1 && !w2 && !w3 && !w4) assert (word4 == i_now);
            assert (p_f2_owned == (frag_cov(f2) && word2 != 16'd0) && read_q == p_f2_owned);
            assert (read_k == (read_q ? word2 : 16'd0));
            assert (p_f3_owned == (frag_cov(f3) && word3 != 16'd0));
            if (p_f3_owned && f3[23:4] == A)
                assert (p_f3_ax == ax3 && p_f3_by == by3 && p_f3_c == {{14{c3[41]}}, c3});
            if (frag_cov(f4) && f4[23:4] == A)
                assert (p_f4_base == (word4 == 16'd0 ? FAR : plane_z(word4, XA, YA)));
            // The write history and A's words.
            assert ((p_h1_v && p_h1_addr == A) == w1 && (p_h2_v && p_h2_addr == A) == w2);
            assert ((p_h3_v && p_h3_addr == A) == w3 && (p_h4_v && p_h4_addr == A) == w4);
            if (w1) assert (p_h1_z == z_a);
            if (!w1 && w2) assert (p_h2_z == z_a);
            if (!w1 && !w2 && w3) assert (p_h3_z == z_a);
            if (!w1 && !w2 && !w3 && w4) assert (p_h4_z == z_a);
            if (w1 || w2 || w3 || w4) assert (written);
            if (written) assert (z_a == (i_a == 16'd0 ? FAR : plane_z(i_a, XA, YA)));
            // The result queue.
            assert ({5'd0, p_len} == in_queue);
            assert (in_queue + {7'd0, pushes(f1)} + {7'd0, pushes(f2)} + {7'd0, pushes(f3)} + {7'd0, pushes(f4)} <= 8'd6);
            if (p_len > 3'd0 && popped == tracked) assert (p_q0 == tracked_result);
            if (p_len > 3'd1 && popped + 8'd1 == tracked) assert (p_q1 == tracked_result);
            if (p_len > 3'd2 && popped + 8'd2 == tracked) assert (p_q2 == tracked_result);
            if (p_len > 3'd3 && popped + 8'd3 == tracked) assert (p_q3 == tracked_result);
            if (p_len > 3'd4 && popped + 8'd4 == tracked) assert (p_q4 == tracked_result);
            if (p_len > 3'd5 && popped + 8'd5 == tracked) assert (p_q5 == tracked_result);
        end
    end endgenerate
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
