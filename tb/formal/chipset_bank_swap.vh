// The host protocol, bank-swap assertions and reach points shared by chipset.sv and chipset3.sv
// (`include`d inside each harness module, after the top's instance; REACH is the module's parameter).
// See chipset.sv's header for what is assumed and asserted. Reach point 7, a frame's last beat taken,
// is numbered above the harnesses' own points (chipset_tex has 0-6).
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

    // ---- The video frames: every scan start taken gives one frame of the build's 4x3 pixels, in
    // order: no beat before a scan start (or of more frames than were started), tuser on a frame's
    // first beat only, tlast on each row's last beat only.
    wire vbeat = video_tvalid && video_tready;
    reg [7:0] frames_started = 8'd0;
    reg [7:0] frames_shown = 8'd0;
    reg [1:0] vx = 2'd0;
    reg [1:0] vy = 2'd0;
    always @(posedge clock) begin
        if (swap) frames_started <= frames_started + 8'd1;
        if (vbeat) begin
            vx <= (vx == 2'd3) ? 2'd0 : vx + 2'd1;
            if (vx == 2'd3) vy <= (vy == 2'd2) ? 2'd0 : vy + 2'd1;
            if (vx == 2'd3 && vy == 2'd2) frames_shown <= frames_shown + 8'd1;
        end
    end
    always @(*) if (video_tvalid) begin
        if (REACH < 0) assert (frames_shown < frames_started);
        if (REACH < 0) assert (video_tuser == (vx == 2'd0 && vy == 2'd0));
        if (REACH < 0) assert (video_tlast == (vx == 2'd3));
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
        cover (vbeat && vx == 2'd3 && vy == 2'd2);
        if (REACH == 7 || REACH_SET[7]) reach_7: assert (!(vbeat && vx == 2'd3 && vy == 2'd2));
    end
