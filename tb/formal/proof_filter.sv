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
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
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
    wire delivered = down_fire && pixels_out == tracked;
    always @(*) begin
        if (REACH < 0) assert (pixels_out <= lists_in);
        if (down_valid) if (REACH < 0) assert (down_data[50:44] <= 7'd64);
        if (delivered) if (REACH < 0) assert (tracked < lists_in && down_data[19:0] == tracked_pos);
    end

    `STALL_REACH(down_valid, down_ready, 0)
    `STALL_REACH(up_valid, up_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (delivered && tracked_two);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(delivered && tracked_two));
    end
endmodule
