// Formal harness of the `proof_filter` top (PROOF's filter stage, 1x1 box, `idxrender verilog
// --block proof_filter`; RustHDL source hdl/src/proof/filter.rs). Run by `bash scripts/formal.sh
// proof_filter`; see docs/verification.md.
//
// Assumed: upstream valid held until ready and data stable while stalled; the lists are well formed
// as the OPP's harness (opp.sv) asserts they leave the OPP: an empty slot is a whole list. Table
// writes (cfg_*) are arbitrary. Asserted: downstream valid held until ready and data stable while
// stalled; one pixel out per list in, in order: the n-th pixel out (n solver-chosen) has the n-th
// list's position; a pixel's covered subpixels are at most 64. Reach points: a stall on the output,
// a stall on the input, the tracked pixel delivered after a list of two entries.
//
// ShadedSlot (in): x 9:0, y 19:10, last 20, has_entry 21, id 37:22, full 38, d0..d2 86:39,
// r g b 110:87. FilteredPixel (out): x 9:0, y 19:10, r g b 43:20, covered 50:44.
`include "stream.vh"

module proof_filter_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
) (
    input wire clock,
    input wire cfg_write,
    input wire [3:0] cfg_sel,
    input wire [15:0] cfg_addr,
    input wire [95:0] cfg_data,
    input wire [110:0] up_data,
    input wire up_valid,
    input wire down_ready
);
    wire up_ready;
    wire [50:0] down_data;
    wire down_valid;
    proof_filter dut (
        .clock(clock), .cfg_write(cfg_write), .cfg_sel(cfg_sel), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .upstream$data(up_data), .upstream$valid(up_valid), .upstream$ready(up_ready),
        .downstream$data(down_data), .downstream$valid(down_valid), .downstream$ready(down_ready)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire up_fire = up_valid && up_ready;
    wire down_fire = down_valid && down_ready;

    always @(*) if (up_valid && !up_data[21]) assume (up_data[20]);
    `STREAM_IN(up_valid, up_ready, up_data)
    `STREAM_OUT(down_valid, down_ready, down_data, REACH < 0)

    // List and pixel counters modulo 256: the checks below hold for streams of any length (at most 8
    // lists are in flight), which is what lets the `prove` task's induction close.
    reg [7:0] lists_in = 8'd0;
    reg [7:0] pixels_out = 8'd0;
    reg [1:0] entries = 2'd0;      // entries of the list coming in, saturating at 2
    reg tracked_two = 1'b0;        // the tracked list had two entries or more
    (* anyconst *) reg [7:0] tracked;
    reg [19:0] tracked_pos = 20'd0;
    always @(posedge clock) begin
        if (up_fire) begin
            entries <= up_data[20] ? 2'd0 : (entries == 2'd2 ? 2'd2 : entries + {1'b0, up_data[21]});
            if (up_data[20]) lists_in <= lists_in + 8'd1;
            if (up_data[20] && lists_in == tracked) begin
                tracked_pos <= up_data[19:0];
                tracked_two <= entries + {1'b0, up_data[21]} >= 2'd2;
            end
        end
        if (down_fire) pixels_out <= pixels_out + 8'd1;
    end
    wire [7:0] in_flight = lists_in - pixels_out;
    wire delivered = down_fire && pixels_out == tracked;
    always @(*) begin
        if (REACH < 0) assert (in_flight <= 8'd8);
        if (down_valid) if (REACH < 0) assert (down_data[50:44] <= 7'd64);
        if (delivered) if (REACH < 0) assert (in_flight != 8'd0 && down_data[19:0] == tracked_pos);
    end

    // Strengthening invariants (the `prove` task's k-induction): the registers F0..F6 and OUT, probed
    // by their names in the generated Verilog (the .sby's `connect` lines, after `flatten`), hold the
    // lists in flight, oldest at the output: a register holding a list's last slot holds list number
    // pixels_out + (such registers after it), and the tracked list's position where that number is
    // `tracked`; the covered counts behind OUT are at most 64. FilterTag: valid 0, x 10:1, y 20:11,
    // last 21; ShadedSlot (F0, valid apart): x 9:0, y 19:10, last 20.
    wire [110:0] p_f0;
    wire p_f0_valid;
    wire [40:0] p_f1, p_f2, p_f3, p_f4, p_f5, p_f6;
    wire [6:0] p_f5_covered, p_f6_covered;
    wire p_out_valid;
    wire [50:0] p_out_data;
    // {last, y, x, valid} of register j at st[22 j +: 22], input end first (F0 .. F6, OUT).
    wire [175:0] st = {{1'b1, p_out_data[19:0], p_out_valid}, p_f6[21:0], p_f5[21:0], p_f4[21:0],
                       p_f3[21:0], p_f2[21:0], p_f1[21:0], {p_f0[20:0], p_f0_valid}};
    wire [63:0] after;  // at 8 j +: 8, the registers after register j holding a list's last slot
    assign after[63:56] = 8'd0;
    genvar j;
    generate
        for (j = 0; j < 7; j = j + 1) begin : count
            assign after[8 * j +: 8] = after[8 * (j + 1) +: 8] + {7'd0, st[22 * (j + 1)] && st[22 * (j + 1) + 21]};
        end
        if (INDUCT) begin : invariants
            always @(*) if (REACH < 0) begin
                assert (p_out_valid == down_valid && p_out_data == down_data);
                assert (in_flight == after[7:0] + {7'd0, st[0] && st[21]});
                assert (p_f5_covered <= 7'd64 && p_f6_covered <= 7'd64 && p_out_data[50:44] <= 7'd64);
            end
            for (j = 0; j < 8; j = j + 1) begin : stage
                always @(*) if (REACH < 0 && st[22 * j] && st[22 * j + 21] && pixels_out + after[8 * j +: 8] == tracked)
                    assert (st[22 * j + 1 +: 20] == tracked_pos);
            end
        end
    endgenerate

    `STALL_REACH(down_valid, down_ready, 0)
    `STALL_REACH(up_valid, up_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (delivered && tracked_two);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(delivered && tracked_two));
    end
endmodule
