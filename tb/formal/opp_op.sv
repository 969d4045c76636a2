// Formal harness of one object processor, module `opp$ops$0` of the `opp` top's Verilog (all eight
// OPs instantiate it; RustHDL source hdl/src/proof/object_processor.rs). Run by `bash
// scripts/formal.sh opp_op`; see docs/verification.md. The whole-OPP harness (opp.sv) cannot see a
// list of two entries leave the pipeline before depth 19, deeper than its bmc reaches; one OP shows
// the list invariants within a few clocks, and by induction over the chain they hold for the OPP.
//
// Assumed: upstream valid held until ready and data stable while stalled; the lists coming in have
// the invariants asserted on the way out (one position per list, an empty slot is a whole list, a
// full entry ends its list, sorted by (depth, id)); a load only while `free`.
// Asserted on the way out: valid held until ready and data stable while stalled; the same list
// invariants; one list out per list in, in order (the n-th list's position, n solver-chosen).
// Reach points: the own entry inserted before an entry of the list, a list of three entries, a full
// own entry ending a list that had more entries, a stall on the output.
//
// ProofSlot: x 9:0, y 19:10, last 20, has_entry 21, id 37:22, depth 61:38, full 62.
`include "stream.vh"

module opp_op_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0,  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
    parameter integer INDUCT = 0  // 1: assert the strengthening invariants too (the `prove` task)
) (
    input wire clock,
    input wire load,
    input wire [731:0] load_params,
    input wire [158:0] up_data,
    input wire up_valid,
    input wire down_ready
);
    wire up_ready;
    wire [158:0] down_data;
    wire down_valid;
    wire free;
    opp$ops$0 dut (
        .clock(clock), .load(load), .load_params(load_params),
        .upstream$data(up_data), .upstream$valid(up_valid), .upstream$ready(up_ready),
        .downstream$data(down_data), .downstream$valid(down_valid), .downstream$ready(down_ready),
        .free(free)
    );

    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;
    wire up_fire = up_valid && up_ready;
    wire down_fire = down_valid && down_ready;

    // ---- The lists coming in.
    reg up_in_list = 1'b0;
    reg up_cont = 1'b0;            // the last slot taken continued a list (for the `prove` task)
    reg [19:0] up_pos = 20'd0;
    reg [39:0] up_key = 40'd0;
    always @(posedge clock) if (up_fire) begin
        up_in_list <= !up_data[20];
        up_cont <= up_in_list;
        up_pos <= up_data[19:0];
        up_key <= {up_data[61:38], up_data[37:22]};
    end
    always @(*) begin
        if (load) assume (free);
        if (up_valid) begin
            if (!up_data[21]) assume (up_data[20] && !up_in_list);
            if (up_data[21] && up_data[62]) assume (up_data[20]);
            if (up_in_list) assume (up_data[19:0] == up_pos && {up_data[61:38], up_data[37:22]} >= up_key);
        end
    end
    `STREAM_IN(up_valid, up_ready, up_data)

    // ---- The lists going out.
    `STREAM_OUT(down_valid, down_ready, down_data, REACH < 0)
    reg in_list = 1'b0;
    reg [19:0] list_pos = 20'd0;
    reg [39:0] list_key = 40'd0;
    reg [1:0] list_len = 2'd0;     // entries so far in the list going out, saturating at 3
    always @(posedge clock) if (down_fire) begin
        in_list <= !down_data[20];
        list_pos <= down_data[19:0];
        list_key <= {down_data[61:38], down_data[37:22]};
        list_len <= down_data[20] ? 2'd0 : (list_len == 2'd3 ? 2'd3 : list_len + {1'b0, down_data[21]});
    end
    always @(*) if (down_valid) begin
        if (!down_data[21]) if (REACH < 0) assert (down_data[20] && !in_list);
        if (down_data[21] && down_data[62]) if (REACH < 0) assert (down_data[20]);
        if (in_list) begin
            if (REACH < 0) assert (down_data[19:0] == list_pos);
            if (REACH < 0) assert ({down_data[61:38], down_data[37:22]} >= list_key);
        end
    end

    // ---- One list out per list in, in order.
    reg [7:0] lists_in = 8'd0;
    reg [7:0] lists_out = 8'd0;
    (* anyconst *) reg [7:0] tracked;
    reg [19:0] tracked_pos = 20'd0;
    always @(posedge clock) begin
        // A list counts in at its first slot: a full own entry ends the list going out before the
        // rest of the list coming in (dropped) has arrived.
        if (up_fire && !up_in_list) lists_in <= lists_in + 8'd1;
        if (down_fire && down_data[20]) lists_out <= lists_out + 8'd1;
        if (up_fire && !up_in_list && lists_in == tracked) tracked_pos <= up_data[19:0];
    end
    // Counters modulo 256: the checks hold for streams of any length (at most two lists are in the
    // OP), which is what lets the `prove` task's induction close.
    wire [7:0] in_flight = lists_in - lists_out;
    always @(*) begin
        if (REACH < 0) assert (in_flight <= 8'd2);
        if (down_fire && down_data[20] && lists_out == tracked) if (REACH < 0) assert (in_flight != 8'd0 && down_data[19:0] == tracked_pos);
    end

    // ---- Strengthening invariants (the `prove` task's k-induction), on the OP's registers probed by
    // their names in the generated Verilog (the .sby's `connect` lines, after `flatten`). H is the
    // FIFO's slot (depth 1 in this build), O the output register, E the last slot emitted (O while
    // valid, else the last slot taken downstream). H is the last slot taken upstream; it continues
    // the OP's list (`mid`, not after its last slot: not `tail`) or starts a new one. While `mid`
    // and not `dropping`, E is of the OP's pixel and not last, and every slot still to come of the
    // list (the own entry while pending, H or the next upstream slots) has a key at least E's; the
    // lists in the OP are E's (when O is valid or a list is open downstream) and H's new one.
    wire [158:0] p_h;
    wire [3:0] p_count, p_wr, p_rd;
    wire p_out_valid;
    wire [158:0] p_out;
    wire p_mid, p_own_pending, p_tail, p_dropping, p_pix_act, p_loaded, p_done;
    wire [9:0] p_px, p_py;
    wire [158:0] p_own;
    wire h_valid = p_count != 4'd0;
    wire e_open = p_out_valid ? !p_out[20] : in_list;
    wire [19:0] e_pos = p_out_valid ? p_out[19:0] : list_pos;
    wire [39:0] e_key = p_out_valid ? p_out[61:22] : list_key;
    wire [19:0] op_pos = {p_py, p_px};
    wire cur = p_mid && !p_dropping;
    wire in_op = p_mid && !p_tail;   // the OP is in the list of the last slot taken upstream (H's, or the one H would continue)
    wire h_waiting = h_valid && !up_cont && !in_op;  // H starts a list the OP has not begun
    generate if (INDUCT) begin : invariants
        always @(*) if (REACH < 0) begin
            assert (p_count <= 4'd1 && p_wr == 4'd0 && p_rd == 4'd0);
            assert (in_flight == {7'd0, p_out_valid || in_list} + {7'd0, h_waiting});
            // H and the upstream side.
            if (h_valid) assert (p_h[19:0] == up_pos && p_h[61:22] == up_key && up_in_list == !p_h[20]);
            if (h_valid && !p_h[21]) assert (p_h[20] && !up_cont && !in_op);
            if (h_valid && p_h[21] && p_h[62]) assert (p_h[20]);
            if (h_valid && up_cont) assert (in_op);
            if (h_valid && in_op) assert (op_pos == p_h[19:0]);
            if (!h_valid) assert (in_op == up_in_list);
            if (!h_valid && up_in_list) assert (op_pos == up_pos);
            if (up_in_list && lists_in - 8'd1 == tracked) assert (up_pos == tracked_pos);
            if (h_valid && lists_in - 8'd1 == tracked) assert (p_h[19:0] == tracked_pos);
            // The OP's list state and what it has emitted.
            if (p_tail) assert (p_mid && p_own_pending && !p_dropping);
            if (p_dropping) assert (p_mid && !p_own_pending);
            if (p_own_pending) assert (p_mid && p_pix_act && p_loaded && !p_done);
            if (cur) assert (e_open && e_pos == op_pos);
            if (!cur) assert (!e_open);
            if (cur && p_own_pending) assert (p_own[61:22] >= e_key);
            if (cur && !p_tail && (h_valid || up_in_list)) assert (up_key >= e_key);
            if ((p_out_valid || in_list) && lists_out == tracked) assert (e_pos == tracked_pos);
            if (p_out_valid && !p_out[21]) assert (p_out[20] && !in_list);
            if (p_out_valid && p_out[21] && p_out[62]) assert (p_out[20]);
            if (p_out_valid && in_list) assert (p_out[19:0] == list_pos && p_out[61:22] >= list_key);
            if (p_out_valid) assert (p_out == down_data);
            assert (p_out_valid == down_valid);
        end
    end endgenerate

    // ---- Reach points. "Own entry" = the id the OP was loaded with (load_params' first field).
    reg [15:0] own_id = 16'd0;
    always @(posedge clock) if (load) own_id <= load_params[15:0];
    wire own_out = down_fire && down_data[21] && down_data[37:22] == own_id;
    `STALL_REACH(down_valid, down_ready, 3)
    always @(posedge clock) if (past_valid) begin
        cover (own_out && !down_data[20] && up_in_list);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!(own_out && !down_data[20]));
        cover (down_fire && down_data[21] && list_len == 2'd2);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(down_fire && down_data[21] && list_len == 2'd2));
        cover (own_out && down_data[62] && list_len != 2'd0);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(own_out && down_data[62] && list_len != 2'd0));
    end
endmodule
