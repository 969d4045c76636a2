//! `idxrender verilog`: write the generated Verilog of the RTL tops.

use std::path::PathBuf;

#[derive(clap::Args, Debug)]
pub struct VerilogArgs {
    /// The top to generate (one of `hdl::TOPS`); all of them when left out.
    #[arg(long)]
    pub block: Option<String>,
    /// Output directory: one `<block>.v` per top.
    #[arg(long, default_value = "out/verilog")]
    pub out: PathBuf,
}

pub fn run(args: &VerilogArgs) -> Result<(), String> {
    let blocks: Vec<String> = match &args.block {
        Some(b) => vec![b.clone()],
        None => hdl::TOPS.iter().map(|t| t.0.to_string()).collect(),
    };
    if blocks.is_empty() {
        return Err("no RTL tops are defined yet".into());
    }
    std::fs::create_dir_all(&args.out).map_err(|e| format!("cannot create {}: {e}", args.out.display()))?;
    for b in blocks {
        let v = hdl::verilog_top(&b)?;
        let path = crate::output::write_atomic(&args.out, &format!("{b}.v"), v.as_bytes())?;
        crate::say!("wrote {} ({} lines)", path.display(), v.lines().count());
    }
    Ok(())
}
