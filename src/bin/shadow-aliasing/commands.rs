//! What each subcommand does.

use crate::args::{Cli, Command, EvalArgs};
use std::io::{Read, Write};
use std::process::ExitCode;

/// Runs the parsed command line.
pub fn run(cli: Cli) -> ExitCode {
    match cli.command {
        Command::Eval(a) => eval(&a),
        Command::Warp(_) => fail("warp is not available in this build yet"),
        Command::Sweep(_) => fail("sweep is not available in this build yet"),
        Command::Figures(_) => fail("figures is not available in this build yet"),
    }
}

/// One line on standard error, exit status 1.
pub fn fail(message: impl std::fmt::Display) -> ExitCode {
    eprintln!("error: {message}");
    ExitCode::from(1)
}

fn eval(a: &EvalArgs) -> ExitCode {
    let mut bytes = Vec::new();
    let read = match a.file.as_deref() {
        None => std::io::stdin().read_to_end(&mut bytes).map(|_| ()),
        Some(p) if p.as_os_str() == "-" => std::io::stdin().read_to_end(&mut bytes).map(|_| ()),
        Some(p) => std::fs::read(p).map(|b| bytes = b),
    };
    if let Err(e) = read {
        let what = a
            .file
            .as_deref()
            .map_or("standard input".to_string(), |p| p.display().to_string());
        eprintln!("error: cannot read {what}: {e}");
        return ExitCode::from(2);
    }
    let Ok(text) = String::from_utf8(bytes) else {
        eprintln!("error: the input is not UTF-8 text");
        return ExitCode::from(2);
    };
    let out = shadow_aliasing::eval::eval_json(&text);
    let mut stdout = std::io::stdout().lock();
    if stdout
        .write_all(out.stdout.as_bytes())
        .and_then(|()| stdout.flush())
        .is_err()
    {
        // A closed pipe: nothing more useful can be said on standard output.
        return ExitCode::from(2);
    }
    eprint!("{}", out.stderr);
    ExitCode::from(u8::try_from(out.exit_code).unwrap_or(2))
}
