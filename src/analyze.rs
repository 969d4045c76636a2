//! `idxrender analyze`: placeholder until the analysis lands (issue 6).

#[derive(clap::Args, Debug)]
pub struct AnalyzeArgs {}

pub fn run(_args: &AnalyzeArgs) -> Result<(), String> {
    Err("analyze is not implemented yet".into())
}
