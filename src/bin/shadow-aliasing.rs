//! The `shadow-aliasing` command line: `figures` (the main job), `eval` (the JSON contract of
//! docs/eval.md), `warp` (a camera's shadow matrices with their measured error) and `sweep`
//! (the storage factor over the hemisphere of light directions, as CSV or a NumPy `.npy` array)
//! `plan` (the cheapest shadow set-up for a target error, or the least error for a budget) and
//! `replay` (the error-budget controller over a camera path file).
//!
//! Errors are one line on standard error and a non-zero exit status.

#[path = "shadow-aliasing/args.rs"]
mod args;
#[path = "shadow-aliasing/commands.rs"]
mod commands;
#[path = "shadow-aliasing/output.rs"]
mod output;
#[path = "shadow-aliasing/path_file.rs"]
mod path_file;
#[path = "shadow-aliasing/plan.rs"]
mod plan;
#[path = "shadow-aliasing/replay.rs"]
mod replay;
#[path = "shadow-aliasing/replay_figure.rs"]
mod replay_figure;
#[path = "shadow-aliasing/scene.rs"]
mod scene;
#[path = "shadow-aliasing/scheme.rs"]
mod scheme;
#[path = "shadow-aliasing/sweep_out.rs"]
mod sweep_out;

use clap::Parser;
use std::process::ExitCode;

fn main() -> ExitCode {
    let cli = match args::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => return args::clap_exit(&e),
    };
    commands::run(cli)
}
