// Formal harness of the `chipset` top (RC + colour setup + Color Shader around the memory ports,
// RustHDL source hdl/src/chipset.rs and chipset/back.rs) built for a 4x3 screen (`idxrender verilog
// --size 4x3 --block chipset`: a clear takes 12 cycles, not 64,000). Run by `bash scripts/formal.sh
// chipset`; see docs/verification.md. The blocks' own properties are checked by rc.sv, rc_z_test.sv,
// colour_setup.sv and cs.sv; this harness checks what the chipset adds: the bank swap of the
// I-buffer and TdbS that lets the two pipelines and the scan-out run at once.
//
// Assumed, the host's side of the protocol (chipset.rs): streams held while stalled; RC commands of
// kinds 0-2, triangle indices not 0; the host draws a frame (RC commands; colour-setup commands at any
// time), and after the RC's end-of-frame result sends no RC command until it has started the scan; it
// starts the scan only once the end-of-frame result has come, no colour-setup command is waiting and
// colour setup is idle; light and material writes only while the CS is idle. Memory read data are
// arbitrary. Asserted: `draw_bank` changes exactly at the edges where a scan start is taken; every
// draw-side access (the RC's I-buffer reads and writes, colour setup's TdbS writes) is in bank
// `draw_bank`, every scan-side access (the CS's I-buffer reads and clear-behind writes, its TdbS
// reads) in the other bank; the RC's result and the video beat held, with tuser and tlast, while
// stalled; the video frames (no beat before a scan start or of more frames than were started, tuser on
// a frame's first beat only, tlast on each 4-pixel row's last beat only). Reach points: a bank swap;
// the RC writing bank 1 (after a swap); colour setup writing TdbS bank 1; the CS reading bank 0 after
// a swap; a frame's last beat taken (4, only when named).
module chipset_formal #(
    parameter integer REACH = -1,  // -1: every assertion; n >= 0: only "reach point n is unreachable"
    parameter integer REACH_SET = 0  // bit n set: check reach point n too (the `reach` task: REACH 99, many points, one model)
) (
    input wire clock,
    input wire [213:0] rc_cmd_data,
    input wire rc_cmd_valid,
    input wire rc_result_ready,
    input wire [320:0] setup_cmd_data,
    input wire setup_cmd_valid,
    input wire scan_start,
    input wire [23:0] scan_background,
    input wire scan_clear_behind,
    input wire scan_phong,
    input wire light_write_enable,
    input wire [1:0] light_write_address,
    input wire [95:0] light_write_data,
    input wire material_write_enable,
    input wire [3:0] material_write_address,
    input wire [2:0] material_write_slot,
    input wire [95:0] material_write_data,
    input wire video_tready,
    input wire [23:0] z_rd_data,
    input wire [15:0] id_rd_data,
    input wire [15:0] is_rd_data,
    input wire [423:0] t_rd_data
);
    wire rc_cmd_ready, rc_result_valid, setup_cmd_ready, setup_busy, scan_busy;
    wire [19:0] rc_result_data;
    wire [23:0] video_tdata;
    wire video_tvalid, video_tuser, video_tlast;
    wire z_re, z_we, id_re, id_we, is_re, is_we, t_re, t_we, draw_bank;
    wire [19:0] z_rd_addr, z_wr_addr;
    wire [23:0] z_wr_data;
    wire [20:0] id_rd_addr, id_wr_addr, is_rd_addr, is_wr_addr;
    wire [15:0] id_wr_data, is_wr_data;
    wire [16:0] t_rd_addr, t_wr_addr;
    wire [423:0] t_wr_data;
    chipset dut (
        .clock(clock),
        .rc_cmd$data(rc_cmd_data), .rc_cmd$valid(rc_cmd_valid), .rc_cmd$ready(rc_cmd_ready),
        .rc_result$data(rc_result_data), .rc_result$valid(rc_result_valid), .rc_result$ready(rc_result_ready),
        .setup_cmd$data(setup_cmd_data), .setup_cmd$valid(setup_cmd_valid), .setup_cmd$ready(setup_cmd_ready),
        .setup_busy(setup_busy), .scan_start(scan_start), .scan_background(scan_background),
        .scan_clear_behind(scan_clear_behind), .scan_phong(scan_phong),
        .light_write_enable(light_write_enable), .light_write_address(light_write_address),
        .light_write_data(light_write_data), .material_write_enable(material_write_enable),
        .material_write_address(material_write_address), .material_write_slot(material_write_slot),
        .material_write_data(material_write_data), .scan_busy(scan_busy),
        .video_tdata(video_tdata), .video_tvalid(video_tvalid), .video_tready(video_tready),
        .video_tuser(video_tuser), .video_tlast(video_tlast),
        .z_re(z_re), .z_rd_addr(z_rd_addr), .z_rd_data(z_rd_data),
        .z_we(z_we), .z_wr_addr(z_wr_addr), .z_wr_data(z_wr_data),
        .id_re(id_re), .id_rd_addr(id_rd_addr), .id_rd_data(id_rd_data),
        .id_we(id_we), .id_wr_addr(id_wr_addr), .id_wr_data(id_wr_data),
        .is_re(is_re), .is_rd_addr(is_rd_addr), .is_rd_data(is_rd_data),
        .is_we(is_we), .is_wr_addr(is_wr_addr), .is_wr_data(is_wr_data),
        .t_re(t_re), .t_rd_addr(t_rd_addr), .t_rd_data(t_rd_data),
        .t_we(t_we), .t_wr_addr(t_wr_addr), .t_wr_data(t_wr_data),
        .draw_bank(draw_bank)
    );

    `include "chipset_bank_swap.vh"

    // ---- The video frames: every scan start taken gives one frame of the build's 4x3 pixels, in
    // order: no beat before a scan start (or of more frames than were started), tuser on a frame's
    // first beat only, tlast on each row's last beat only. In this harness only: in chipset3's (through
    // chipset_bank_swap.vh) the same lines kept its bmc at depth 32 running for more than 9 minutes,
    // where it takes 4 s.
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

    always @(posedge clock) if (past_valid) begin
        cover (vbeat && vx == 2'd3 && vy == 2'd2);
        if (REACH == 4 || REACH_SET[4]) reach_4: assert (!(vbeat && vx == 2'd3 && vy == 2'd2));
    end
endmodule
