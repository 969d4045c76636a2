// Formal harness of the `proof_filter2x2` top (PROOF's filter stage with the 2x2-pixel area, RustHDL
// source hdl/src/proof/filter2x2.rs and box2x2.rs) built for a 4x3 screen (`idxrender verilog --size
// 4x3 --block proof_filter2x2`): the line buffer is one word per column, so a 4-column build keeps
// the state small enough for bmc to see whole frames; the RTL is the same for every width >= 2 (the
// width only sets two constants and the line buffer's depth). Run by `bash scripts/formal.sh
// proof_filter2x2`; see docs/verification.md.
//
// Assumed: upstream valid held until ready and data stable while stalled; the lists are well formed
// (an empty slot is a whole list) and, as the top requires, whole frames in raster order: every slot
// of the k-th list carries the position (k mod 4, (k div 4) mod 3). Table writes (cfg_*) are
// arbitrary. Asserted: downstream valid held until ready and data stable while stalled; one pixel out
// per list in, in order: the n-th pixel out (n solver-chosen) has the n-th list's position; a pixel's
// own covered subpixels are at most 64. Reach points: a stall on the output, a stall on the input (the
// flush holds the input off, too), a pixel of the last row delivered (it leaves in the flush), the first
// pixel of the second frame delivered (the line buffer reused across frames).
//
// ShadedSlot (in): x 9:0, y 19:10, last 20, has_entry 21, id 37:22, full 38, d0..d2 86:39,
// r g b 110:87. FilteredPixel (out): x 9:0, y 19:10, r g b 43:20, covered 50:44.
`include "stream.vh"

module proof_filter2x2_formal #(
    parameter integer REACH = -1,     // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer ORDER_ONLY = 0  // 1: the assertions on valid, position and count only (no colour
                                      // in their cone, so bmc goes a frame and a half deeper)
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
    localparam [9:0] W = 10'd4;
    localparam [9:0] H = 10'd3;
    wire up_ready;
    wire [50:0] down_data;
    wire down_valid;
    proof_filter2x2 dut (
        .clock(clock), .cfg_write(cfg_write), .cfg_sel(cfg_sel), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .upstream$data(up_data), .upstream$valid(up_valid), .upstream$ready(up_ready),
        .downstream$data(down_data), .downstream$valid(down_valid), .downstream$ready(down_ready)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire up_fire = up_valid && up_ready;
    wire down_fire = down_valid && down_ready;

    // The position of the list coming in, raster order, frame after frame.
    reg [9:0] in_x = 10'd0;
    reg [9:0] in_y = 10'd0;
    always @(posedge clock) if (up_fire && up_data[20]) begin
        in_x <= (in_x == W - 10'd1) ? 10'd0 : in_x + 10'd1;
        if (in_x == W - 10'd1) in_y <= (in_y == H - 10'd1) ? 10'd0 : in_y + 10'd1;
    end
    always @(*) if (up_valid) begin
        if (!up_data[21]) assume (up_data[20]);
        assume (up_data[9:0] == in_x && up_data[19:10] == in_y);
    end
    `STREAM_IN(up_valid, up_ready, up_data)
    always @(posedge clock) if (past_valid && $past(down_valid && !down_ready)) begin
        if (REACH < 0) assert (down_valid);
        if (REACH < 0) assert (down_data[19:0] == $past(down_data[19:0]));
        if (REACH < 0 && ORDER_ONLY == 0) assert (down_data == $past(down_data));
    end

    reg [7:0] lists_in = 8'd0;
    reg [7:0] pixels_out = 8'd0;
    (* anyconst *) reg [7:0] tracked;
    reg [19:0] tracked_pos = 20'd0;
    always @(posedge clock) begin
        if (up_fire && up_data[20]) begin
            lists_in <= lists_in + 8'd1;
            if (lists_in == tracked) tracked_pos <= up_data[19:0];
        end
        if (down_fire) pixels_out <= pixels_out + 8'd1;
    end
    wire delivered = down_fire && pixels_out == tracked;
    always @(*) begin
        if (REACH < 0) assert (pixels_out <= lists_in);
        if (down_valid) if (REACH < 0 && ORDER_ONLY == 0) assert (down_data[50:44] <= 7'd64);
        if (delivered) if (REACH < 0) assert (tracked < lists_in && down_data[19:0] == tracked_pos);
    end

    `STALL_REACH(down_valid, down_ready, 0)
    `STALL_REACH(up_valid, up_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (down_fire && down_data[19:10] == H - 10'd1);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(down_fire && down_data[19:10] == H - 10'd1));
        cover (down_fire && pixels_out == 8'd12);
        if (REACH == 3 || REACH_SET[3]) reach_3: assert (!(down_fire && pixels_out == 8'd12));
    end
endmodule
