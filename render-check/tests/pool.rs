//! Cases on several devices at once (`render_check::pool`, `--jobs`): the results come back in
//! the jobs' order whichever thread finishes first, and the binary's summary does not depend on
//! the number of jobs.

use render_check::pool::{devices, on_devices};
use std::path::Path;
use std::process::Command;

/// The jobs finish in reverse order (the first sleeps longest), yet come back in their own.
#[test]
fn results_come_back_in_the_jobs_order() {
    let gpus = devices(3, &render_check::gpu::shader_source()).unwrap_or_else(|e| panic!("{e}"));
    assert_eq!(gpus.len(), 3);
    let jobs: Vec<u64> = (0..9).collect();
    let finished = std::sync::Mutex::new(Vec::new());
    let out = on_devices(&gpus, &jobs, |_, &j| {
        std::thread::sleep(std::time::Duration::from_millis(5 * (9 - j)));
        finished.lock().unwrap().push(j);
        j * j
    })
    .unwrap();
    assert_eq!(out, [0, 1, 4, 9, 16, 25, 36, 49, 64]);
    // The threads did run at once: some job finished before one started earlier.
    let order = finished.into_inner().unwrap();
    assert!(
        order.windows(2).any(|w| w[0] > w[1]),
        "finish order {order:?}"
    );
}

#[test]
fn no_device_is_an_error_not_an_empty_success() {
    let e = on_devices(&[], &[1, 2, 3], |_, &j: &i32| j).unwrap_err();
    assert!(e.contains("no device"), "{e}");
}

/// The binary's summary.json at three jobs is byte for byte the one at one job.
#[test]
fn the_summary_does_not_depend_on_the_number_of_jobs() {
    let dir = std::env::temp_dir().join(format!("render-check-jobs-{}", std::process::id()));
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/thin_casters.json");
    let run = |jobs: &str| {
        let out = dir.join(format!("j{jobs}"));
        let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
            .args(["--out", out.to_str().unwrap()])
            .args(["--scene", scene.to_str().unwrap()])
            .args(["--width", "160", "--height", "120", "--frames", "4"])
            .args(["--jobs", jobs])
            .output()
            .unwrap();
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        std::fs::read_to_string(out.join("summary.json")).unwrap()
    };
    let (one, three) = (run("1"), run("3"));
    assert!(one.contains("\"scheme\""), "{one}");
    assert_eq!(one, three);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn jobs_out_of_range_is_an_error_naming_the_option() {
    let o = Command::new(env!("CARGO_BIN_EXE_render-check"))
        .args(["--jobs", "0"])
        .output()
        .unwrap();
    assert!(!o.status.success());
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("--jobs 0"), "{err}");
}
