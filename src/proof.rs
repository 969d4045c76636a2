//! `idxrender render --arch proof`: placeholder until the PROOF pipeline lands (issue 5).

use crate::cli::RenderArgs;
use golden::render::RenderOptions;
use golden::scene::Mesh;

pub fn run_render(_args: &RenderArgs, _mesh: &Mesh, _opts: &RenderOptions) -> Result<(), String> {
    Err("--arch proof is not implemented yet".into())
}
