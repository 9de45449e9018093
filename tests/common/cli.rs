//! Running the `shadow-aliasing` binary from the command-line tests (feature `cli`): the runners
//! (`run`, `run_with_stdin`, `run_bytes`, `run_to_full`), the argument vectors most calls share
//! (`view_args`, `warp_args`, `set`), JSON output (`run_json`, `warp_json`), `help`, and the
//! checks of a refused call (`run_failing`, `assert_error`, `assert_infinite_view_refused`,
//! `assert_lambda_refused`, `assert_parameter_refused`).

use serde_json::Value;
use std::io::Write;
use std::process::{Command, Stdio};

/// Runs the binary with `args` and no input; returns (exit code, stdout, stderr).
pub fn run(args: &[&str]) -> (i32, String, String) {
    run_with_stdin(args, "")
}

/// Runs the binary with `args`, feeding `stdin`; returns (exit code, stdout, stderr).
pub fn run_with_stdin(args: &[&str], stdin: &str) -> (i32, String, String) {
    let (code, out, err) = run_raw(args, stdin, Stdio::piped());
    (code, String::from_utf8(out).expect("stdout is UTF-8"), err)
}

/// Runs the binary with `args` and no input; returns (exit code, the raw bytes of stdout, stderr).
pub fn run_bytes(args: &[&str]) -> (i32, Vec<u8>, String) {
    run_raw(args, "", Stdio::piped())
}

/// Runs the binary with `args`, feeding `stdin`, with standard output on /dev/full (every write
/// fails with ENOSPC); returns (exit code, stderr).
#[cfg(target_os = "linux")]
pub fn run_to_full(args: &[&str], stdin: &str) -> (i32, String) {
    let full = std::fs::OpenOptions::new()
        .write(true)
        .open("/dev/full")
        .expect("/dev/full opens");
    let (code, _, err) = run_raw(args, stdin, Stdio::from(full));
    (code, err)
}

/// Runs the binary with `args`, feeding `stdin`, standard output to `stdout`; returns (exit code,
/// the bytes of stdout (none unless piped), stderr).
fn run_raw(args: &[&str], stdin: &str, stdout: Stdio) -> (i32, Vec<u8>, String) {
    let mut child = Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(stdout)
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary starts");
    // The binary may exit before reading everything (for instance on a bad argument).
    let _ = child
        .stdin
        .take()
        .expect("stdin is piped")
        .write_all(stdin.as_bytes());
    let out = child.wait_with_output().expect("the binary finishes");
    (
        out.status.code().expect("exited normally, not by a signal"),
        out.stdout,
        String::from_utf8(out.stderr).expect("stderr is UTF-8"),
    )
}

/// `command --help`: asserts exit 0 and returns stdout.
pub fn help(command: &str) -> String {
    let (code, out, err) = run(&[command, "--help"]);
    assert_eq!(code, 0, "{err}");
    out
}

/// `command --near 1 --far 100 --half-fov <half_fov>` followed by `extra`: the view most calls
/// of `warp` and `sweep` use.
pub fn view_args<'a>(command: &'a str, half_fov: &'a str, extra: &[&'a str]) -> Vec<&'a str> {
    let mut args = vec![
        command,
        "--near",
        "1",
        "--far",
        "100",
        "--half-fov",
        half_fov,
    ];
    args.extend_from_slice(extra);
    args
}

/// Runs `args`, asserts exit 0 and an empty stderr, and returns stdout parsed as JSON.
pub fn run_json(args: &[&str]) -> Value {
    let (code, out, err) = run(args);
    assert_eq!(code, 0, "{args:?}: {err}");
    assert!(err.is_empty(), "{args:?}: {err}");
    serde_json::from_str(&out).unwrap_or_else(|e| panic!("{args:?}: {out}: {e}"))
}

/// `args` with the value after `flag` replaced by `value`.
pub fn set<'a>(mut args: Vec<&'a str>, flag: &str, value: &'a str) -> Vec<&'a str> {
    let i = args
        .iter()
        .position(|a| *a == flag)
        .unwrap_or_else(|| panic!("{flag} in {args:?}"));
    args[i + 1] = value;
    args
}

/// `warp --near 1 --far 100 --half-fov <half_fov> --light-dir <dir> --warp <warp>` followed by
/// `extra`.
pub fn warp_args<'a>(
    half_fov: &'a str,
    dir: &'a str,
    warp: &'a str,
    extra: &[&'a str],
) -> Vec<&'a str> {
    let mut args = view_args("warp", half_fov, &["--light-dir", dir, "--warp", warp]);
    args.extend_from_slice(extra);
    args
}

/// [`warp_args`] with `--json`, through [`run_json`].
pub fn warp_json(half_fov: &str, dir: &str, warp: &str, extra: &[&str]) -> Value {
    let mut args = warp_args(half_fov, dir, warp, extra);
    args.push("--json");
    run_json(&args)
}

/// Runs `args` with `stdin` and asserts a refusal: a non-zero exit, nothing on stdout, one line
/// on stderr. Returns (exit code, stderr) for the caller's checks of the code and message.
pub fn run_failing(args: &[&str], stdin: &str) -> (i32, String) {
    let (code, out, err) = run_with_stdin(args, stdin);
    assert_ne!(code, 0, "{args:?} {stdin:?}");
    assert!(out.is_empty(), "{args:?} {stdin:?}: {out}");
    assert_eq!(err.lines().count(), 1, "{args:?} {stdin:?}: {err}");
    (code, err)
}

/// Runs `args` and asserts exit 1, nothing on stdout, and exactly `want` and a newline on stderr.
pub fn assert_error(args: &[&str], want: &str) {
    let (code, out, err) = run(args);
    assert_eq!(
        (code, out.as_str(), err.as_str()),
        (1, "", format!("{want}\n").as_str()),
        "{args:?}"
    );
}

/// `-inf` as the value of each of `--near`, `--far` and `--half-fov` in
/// `view_args(command, "0.5", extra)` is refused with the message that names it.
pub fn assert_infinite_view_refused(command: &str, extra: &[&str]) {
    for (flag, name) in [
        ("--near", "near"),
        ("--far", "far"),
        ("--half-fov", "half_fov"),
    ] {
        assert_error(
            &set(view_args(command, "0.5", extra), flag, "-inf"),
            &format!("error: {name} must be a finite number (got -inf)"),
        );
    }
}

/// `--lambda 0.3` after `base` with each of `partitions` (`--partition` name, `--k`) is refused:
/// exit 1, nothing on stdout, and the message that λ belongs to the practical partition only.
pub fn assert_lambda_refused(base: &[&str], partitions: &[(&str, &str)]) {
    assert_parameter_refused(base, ("lambda", "0.3", "practical"), partitions);
}

/// `--NAME VALUE` after `base` with each of `partitions` (`--partition` name, `--k`) is refused:
/// exit 1, nothing on stdout, and the message that NAME belongs to `--partition OWNER` only.
pub fn assert_parameter_refused(
    base: &[&str],
    (name, value, owner): (&str, &str, &str),
    partitions: &[(&str, &str)],
) {
    let flag = format!("--{name}");
    for (partition, k) in partitions {
        let mut args = base.to_vec();
        args.extend(["--partition", partition, "--k", k, &flag, value]);
        assert_error(
            &args,
            &format!(
                "error: {name} is not an argument of --partition {partition} (only of --partition {owner})"
            ),
        );
    }
}
