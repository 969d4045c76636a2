// The host protocol, bank-swap assertions and reach points shared by chipset.sv and chipset3.sv
// (`include`d inside each harness module, after the top's instance; REACH is the module's parameter).
// See chipset.sv's header for what is assumed and asserted.
    reg past_valid = 1'b0;
    always @(posedge clock) past_valid <= 1'b1;

    // ---- The host.
    wire take_cmd = rc_cmd_valid && rc_cmd_ready;
    wire pop = rc_result_valid && rc_result_ready;
    wire swap = scan_start && !scan_busy;
    reg frame_drawn = 1'b0;   // the RC's end-of-frame result has come; no RC command until the scan starts
    always @(posedge clock) begin
        if (pop && rc_result_data[0]) frame_drawn <= 1'b1;
        if (swap) frame_drawn <= 1'b0;
    end
    always @(*) begin
        if (rc_cmd_valid) begin
            assume (!frame_drawn);
            assume (rc_cmd_data[1:0] != 2'd3);
            if (rc_cmd_data[1:0] == 2'd1) assume (rc_cmd_data[18:3] != 16'd0);
        end
        if (scan_start) assume (frame_drawn && !setup_cmd_valid && !setup_busy);
        if (scan_busy || swap) assume (!light_write_enable && !material_write_enable);
    end
    always @(posedge clock) if (past_valid) begin
        if ($past(rc_cmd_valid && !rc_cmd_ready)) assume (rc_cmd_valid && rc_cmd_data == $past(rc_cmd_data));
        if ($past(setup_cmd_valid && !setup_cmd_ready)) assume (setup_cmd_valid && setup_cmd_data == $past(setup_cmd_data));
    end

    // ---- The banks.
    always @(posedge clock) if (past_valid) begin
        if (REACH < 0) assert ((draw_bank != $past(draw_bank)) == $past(swap));
    end
    always @(*) begin
        if (id_re) if (REACH < 0) assert (id_rd_addr[20] == draw_bank);
        if (id_we) if (REACH < 0) assert (id_wr_addr[20] == draw_bank);
        if (t_we) if (REACH < 0) assert (t_wr_addr[16] == draw_bank);
        if (is_re) if (REACH < 0) assert (is_rd_addr[20] != draw_bank);
        if (is_we) if (REACH < 0) assert (is_wr_addr[20] != draw_bank);
        if (t_re) if (REACH < 0) assert (t_rd_addr[16] != draw_bank);
    end

    // ---- The streams out.
    always @(posedge clock) if (past_valid) begin
        if ($past(rc_result_valid && !rc_result_ready)) if (REACH < 0) assert (rc_result_valid && rc_result_data == $past(rc_result_data));
        if ($past(video_tvalid && !video_tready)) if (REACH < 0) assert (video_tvalid
            && video_tuser == $past(video_tuser) && video_tlast == $past(video_tlast));
    end

    reg swapped = 1'b0;
    always @(posedge clock) if (swap) swapped <= 1'b1;
    always @(posedge clock) if (past_valid) begin
        cover (swap);
        if (REACH == 0 || REACH_SET[0]) reach_0: assert (!swap);
        cover (id_we && draw_bank);
        if (REACH == 1 || REACH_SET[1]) reach_1: assert (!(id_we && draw_bank));
        cover (t_we && draw_bank);
        if (REACH == 2 || REACH_SET[2]) reach_2: assert (!(t_we && draw_bank));
        cover (is_re && swapped && !is_rd_addr[20]);
        if (REACH == 3 || REACH_SET[3]) reach_3: assert (!(is_re && swapped && !is_rd_addr[20]));
    end
