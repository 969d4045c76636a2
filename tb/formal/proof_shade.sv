// Formal harness of the `proof_shade` top (PROOF's shading stage, `idxrender verilog --block
// proof_shade`; RustHDL source hdl/src/proof/shading.rs). Run by `bash scripts/formal.sh
// proof_shade`; see docs/verification.md.
//
// Assumed: upstream valid held until ready and data stable while stalled; table writes (cfg_*) are
// arbitrary. Asserted: downstream valid held until ready and data stable while stalled; one slot out
// per slot in, in order: the n-th slot out (n solver-chosen) carries the n-th slot in's position,
// last, has_entry, id, full and edge distances. Reach points: a stall on the output, a stall on the
// input, the tracked slot delivered.
//
// ProofSlot (in): x 9:0, y 19:10, last 20, has_entry 21, id 37:22, depth 61:38, full 62, normal
// 110:63, d0..d2 158:111. ShadedSlot (out): x, y, last, has_entry, id 37:0 as above, full 38,
// d0..d2 86:39, r g b 110:87.
`include "stream.vh"

module proof_shade_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
) (
    input wire clock,
    input wire cfg_write,
    input wire [3:0] cfg_sel,
    input wire [15:0] cfg_addr,
    input wire [95:0] cfg_data,
    input wire [158:0] up_data,
    input wire up_valid,
    input wire down_ready
);
    wire up_ready;
    wire [110:0] down_data;
    wire down_valid;
    proof_shade dut (
        .clock(clock), .cfg_write(cfg_write), .cfg_sel(cfg_sel), .cfg_addr(cfg_addr), .cfg_data(cfg_data),
        .upstream$data(up_data), .upstream$valid(up_valid), .upstream$ready(up_ready),
        .downstream$data(down_data), .downstream$valid(down_valid), .downstream$ready(down_ready)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire up_fire = up_valid && up_ready;
    wire down_fire = down_valid && down_ready;

    `STREAM_IN(up_valid, up_ready, up_data)
    `STREAM_OUT(down_valid, down_ready, down_data, REACH < 0)

    wire [86:0] up_kept = {up_data[158:111], up_data[62], up_data[37:0]};
    // Slot counters modulo 256: the checks below hold for streams of any length (at most 10 slots are
    // in flight), which is what lets the `prove` task's induction close.
    reg [7:0] slots_in = 8'd0;
    reg [7:0] slots_out = 8'd0;
    (* anyconst *) reg [7:0] tracked;
    reg [86:0] tracked_slot = 87'd0;
    always @(posedge clock) begin
        if (up_fire) slots_in <= slots_in + 8'd1;
        if (down_fire) slots_out <= slots_out + 8'd1;
        if (up_fire && slots_in == tracked) tracked_slot <= up_kept;
    end
    wire [7:0] in_flight = slots_in - slots_out;
    wire delivered = down_fire && slots_out == tracked;
    always @(*) begin
        if (REACH < 0) assert (in_flight <= 8'd10);
        if (delivered) if (REACH < 0) assert (in_flight != 8'd0 && down_data[86:0] == tracked_slot);
    end

    // Strengthening invariants (the `prove` task's k-induction): the pipeline's ten registers, probed
    // by their names in the generated Verilog (the .sby's `connect` lines, after `flatten`), hold
    // exactly the slots in flight, oldest at the output: register j holds slot number
    // slots_out + (valid registers after j), and the tracked slot's kept fields where that number is
    // `tracked`. ShadeWork: valid 0, the kept fields 87:1 (x, y, last, has_entry, id, full, d0..d2).
    wire [296:0] p_r0, p_r1, p_r2, p_a, p_p1, p_p2, p_p3, p_p4, p_m;
    wire p_out_valid;
    wire [110:0] p_out_data;
    // {kept, valid} of register j at st[88 j +: 88], input end first.
    wire [879:0] st = {{p_out_data[86:0], p_out_valid}, p_m[87:0], p_p4[87:0], p_p3[87:0], p_p2[87:0],
                       p_p1[87:0], p_a[87:0], p_r2[87:0], p_r1[87:0], p_r0[87:0]};
    wire [79:0] after;  // at 8 j +: 8, the valid registers after register j (nearer the output)
    assign after[79:72] = 8'd0;
    genvar j;
    generate
        for (j = 0; j < 9; j = j + 1) begin : count
            assign after[8 * j +: 8] = after[8 * (j + 1) +: 8] + {7'd0, st[88 * (j + 1)]};
        end
        if (INDUCT) begin : invariants
            always @(*) if (REACH < 0) begin
                assert (p_out_valid == down_valid && p_out_data == down_data);
                assert (in_flight == after[7:0] + {7'd0, st[0]});
            end
            for (j = 0; j <= 9; j = j + 1) begin : stage
                always @(*) if (REACH < 0 && st[88 * j] && slots_out + after[8 * j +: 8] == tracked)
                    assert (st[88 * j + 1 +: 87] == tracked_slot);
            end
        end
    endgenerate

    `STALL_REACH(down_valid, down_ready, 0)
    `STALL_REACH(up_valid, up_ready, 1)
    always @(posedge clock) if (past_valid) begin
        cover (delivered && tracked == 8'd2);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(delivered && tracked == 8'd2));
    end
endmodule
