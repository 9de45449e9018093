//! `sweep`'s output: CSV (shortest round-trip numbers) or a NumPy `.npy` array, to standard
//! output or a file, written through one fixed-size buffer (no allocation per row).

use shadow_aliasing::scheme::sweep::SweepGrid;
use std::io::{self, Write};
use std::path::{Path, PathBuf};

/// Bytes gathered before each write: large enough that the system calls cost nothing next to
/// the formatting, small enough to stay in cache.
const CHUNK: usize = 1 << 17;

/// Where the output goes.
#[derive(Debug, Clone)]
pub enum Sink {
    /// Standard output.
    Stdout,
    /// A file, created or truncated.
    File(PathBuf),
}

impl Sink {
    /// `--output`: absent or `-` is standard output.
    pub fn from_arg(output: Option<&Path>) -> Self {
        match output {
            None => Sink::Stdout,
            Some(p) if p.as_os_str() == "-" => Sink::Stdout,
            Some(p) => Sink::File(p.to_path_buf()),
        }
    }
}

/// A failed write, as the one line the user sees: `cannot write sweep.npy: …`.
#[derive(Debug)]
pub struct WriteError(pub String);

/// What writes one output's bytes.
pub type Body<'a> = dyn Fn(&mut dyn Write) -> io::Result<()> + 'a;

/// Writes `main` to the sink and, beside a regular file, each of `beside` (its axes) too.
///
/// - Standard output: `main` only. A closed standard output (the reader has gone) is not an
///   error, as for the other subcommands.
/// - A path that exists and is not a regular file (a device such as `/dev/null` or `/dev/full`,
///   a FIFO; symbolic links followed): `main` is written into it directly and `beside` is not
///   written (no `/dev/null.elevations.npy`).
/// - A regular file, or a path that does not exist yet: all or nothing. Each output is written
///   to a temporary file beside its destination (`main` first, so that its errors name it), then
///   the temporaries are renamed onto their destinations, `beside` first and `main` last; on any
///   failure every temporary and every destination already renamed are removed, so nothing
///   half-written or out of step is left.
pub fn write_output(
    sink: &Sink,
    main: &Body<'_>,
    beside: &[(PathBuf, &Body<'_>)],
) -> Result<(), WriteError> {
    let err = |p: &Path, e: io::Error| WriteError(format!("cannot write {}: {e}", p.display()));
    match sink {
        Sink::Stdout => {
            let mut out = io::stdout().lock();
            match main(&mut out).and_then(|()| out.flush()) {
                Ok(()) => Ok(()),
                Err(e) if e.kind() == io::ErrorKind::BrokenPipe => Ok(()),
                Err(e) => Err(WriteError(format!("cannot write to standard output: {e}"))),
            }
        }
        Sink::File(p) if std::fs::metadata(p).is_ok_and(|m| !m.is_file()) => {
            let mut f = std::fs::File::create(p).map_err(|e| err(p, e))?;
            main(&mut f).and_then(|()| f.flush()).map_err(|e| err(p, e))
        }
        Sink::File(p) => {
            let mut files: Vec<(PathBuf, &Body<'_>)> = vec![(through_link(p), main)];
            files.extend_from_slice(beside);
            write_all_or_nothing(&files).map_err(|(i, e)| {
                // The user's name for the main file, not its link's target.
                err(if i == 0 { p } else { &files[i].0 }, e)
            })
        }
    }
}

/// The file a symbolic link at `p` points to (so that the rename replaces the file, not the
/// link), or `p` itself.
fn through_link(p: &Path) -> PathBuf {
    match std::fs::symlink_metadata(p) {
        Ok(m) if m.file_type().is_symlink() => {
            std::fs::canonicalize(p).unwrap_or_else(|_| p.to_path_buf())
        }
        _ => p.to_path_buf(),
    }
}

/// The temporary file of `dest`: `.NAME.PID.tmp` in the same directory (so that the rename
/// stays within one file system).
fn temporary(dest: &Path) -> PathBuf {
    let mut name = std::ffi::OsString::from(".");
    name.push(dest.file_name().unwrap_or(dest.as_os_str()));
    name.push(format!(".{}.tmp", std::process::id()));
    dest.with_file_name(name)
}

/// Writes every `(destination, body)` to its temporary file, then renames them, the first
/// (the main file) last; on a failure removes what it wrote and returns the failing file's index
/// with the error.
fn write_all_or_nothing(files: &[(PathBuf, &Body<'_>)]) -> Result<(), (usize, io::Error)> {
    let temps: Vec<PathBuf> = files.iter().map(|(d, _)| temporary(d)).collect();
    let remove = |paths: &mut dyn Iterator<Item = &PathBuf>| {
        for p in paths {
            let _ = std::fs::remove_file(p);
        }
    };
    for (i, ((_, body), tmp)) in files.iter().zip(&temps).enumerate() {
        let written = std::fs::OpenOptions::new()
            .write(true)
            .create_new(true)
            .open(tmp)
            .and_then(|mut f| body(&mut f).and_then(|()| f.flush()));
        if let Err(e) = written {
            // The failing temporary too, if it was created.
            remove(&mut temps[..=i].iter());
            return Err((i, e));
        }
    }
    let order: Vec<usize> = (1..files.len()).chain([0]).collect();
    for (n, &i) in order.iter().enumerate() {
        if let Err(e) = std::fs::rename(&temps[i], &files[i].0) {
            let (done, left) = order.split_at(n);
            remove(
                &mut left
                    .iter()
                    .map(|&j| &temps[j])
                    .chain(done.iter().map(|&j| &files[j].0)),
            );
            return Err((i, e));
        }
    }
    Ok(())
}

/// Appends the shortest decimal that parses back to `v` (the formatter serde_json uses, so the
/// CSV keeps its bytes: `0.1`, `11.0`, `1e-7`, `1.5e300`).
fn push_num(buf: &mut Vec<u8>, fmt: &mut zmij::Buffer, v: f64) {
    if v.is_finite() {
        buf.extend_from_slice(fmt.format_finite(v).as_bytes());
    } else {
        // Never reached for a sweep (its values are finite), but not a silent number either.
        buf.extend_from_slice(if v.is_nan() {
            b"nan"
        } else if v > 0.0 {
            b"inf"
        } else {
            b"-inf"
        });
    }
}

/// The CSV: header `elevation,azimuth,storage_factor`, one row per direction, elevation-major.
pub fn write_csv(w: &mut dyn Write, grid: SweepGrid, values: &[f64]) -> io::Result<()> {
    let mut fmt = zmij::Buffer::new();
    // Every azimuth's text once, side by side in one buffer, with ",", ready to copy.
    let mut az_text = Vec::with_capacity(24 * grid.azimuths());
    let mut az_end = Vec::with_capacity(grid.azimuths());
    for j in 0..grid.azimuths() {
        push_num(&mut az_text, &mut fmt, grid.azimuth(j));
        az_text.push(b',');
        az_end.push(az_text.len());
    }
    let mut buf: Vec<u8> = Vec::with_capacity(CHUNK + 128);
    buf.extend_from_slice(b"elevation,azimuth,storage_factor\n");
    let mut el_text = Vec::with_capacity(32);
    for (i, row) in values.chunks(grid.azimuths()).enumerate() {
        el_text.clear();
        push_num(&mut el_text, &mut fmt, grid.elevation(i));
        el_text.push(b',');
        let mut start = 0;
        for (&end, &v) in az_end.iter().zip(row) {
            buf.extend_from_slice(&el_text);
            buf.extend_from_slice(&az_text[start..end]);
            start = end;
            push_num(&mut buf, &mut fmt, v);
            buf.push(b'\n');
            if buf.len() >= CHUNK {
                w.write_all(&buf)?;
                buf.clear();
            }
        }
    }
    w.write_all(&buf)
}

/// The `.npy` (format version 1.0) header of a little-endian `f64` array of `shape` in C order:
/// magic, version, header length, the header dictionary padded with spaces and ended by `\n`
/// so that the data starts at a multiple of 64 bytes.
pub fn npy_header(shape: &[usize]) -> Vec<u8> {
    let dims = match shape {
        [n] => format!("({n},)"),
        _ => format!(
            "({})",
            shape
                .iter()
                .map(usize::to_string)
                .collect::<Vec<_>>()
                .join(", ")
        ),
    };
    let mut dict = format!("{{'descr': '<f8', 'fortran_order': False, 'shape': {dims}, }}");
    // 6 magic + 2 version + 2 length + dictionary + '\n'.
    let unpadded = 10 + dict.len() + 1;
    dict.push_str(&" ".repeat((64 - unpadded % 64) % 64));
    dict.push('\n');
    let len = u16::try_from(dict.len()).unwrap_or(u16::MAX);
    let mut out = Vec::with_capacity(10 + dict.len());
    out.extend_from_slice(b"\x93NUMPY\x01\x00");
    out.extend_from_slice(&len.to_le_bytes());
    out.extend_from_slice(dict.as_bytes());
    out
}

/// A whole `.npy` file: the header, then `values` as little-endian `f64`.
pub fn write_npy(w: &mut dyn Write, shape: &[usize], values: &[f64]) -> io::Result<()> {
    let mut buf = npy_header(shape);
    buf.reserve(CHUNK + 8);
    for block in values.chunks(CHUNK / 8) {
        for v in block {
            buf.extend_from_slice(&v.to_le_bytes());
        }
        w.write_all(&buf)?;
        buf.clear();
    }
    if !buf.is_empty() {
        // An empty array: the header alone (a sweep is never empty).
        w.write_all(&buf)?;
    }
    Ok(())
}

/// The companion files of `--output FILE --format npy`: `sweep.npy` gives
/// `sweep.elevations.npy` and `sweep.azimuths.npy`; a name without `.npy` gets the suffixes
/// appended (`out` → `out.elevations.npy`).
pub fn axis_paths(output: &Path) -> (PathBuf, PathBuf) {
    let base = if output.extension().is_some_and(|e| e == "npy") {
        output.with_extension("").into_os_string()
    } else {
        output.as_os_str().to_os_string()
    };
    let with = |suffix: &str| {
        let mut p = base.clone();
        p.push(suffix);
        PathBuf::from(p)
    };
    (with(".elevations.npy"), with(".azimuths.npy"))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn header_is_64_byte_aligned_and_numpy_shaped() {
        for shape in [vec![360, 1440], vec![1], vec![90], vec![123_456_789, 7]] {
            let h = npy_header(&shape);
            assert_eq!(h.len() % 64, 0, "{shape:?}");
            assert_eq!(usize::from(u16::from_le_bytes([h[8], h[9]])), h.len() - 10);
            assert_eq!(h.last(), Some(&b'\n'));
        }
        let h = npy_header(&[3]);
        assert!(String::from_utf8_lossy(&h).contains("'shape': (3,), }"));
    }

    #[test]
    fn axis_names() {
        let (e, a) = axis_paths(Path::new("dir/sweep.npy"));
        assert_eq!(e, Path::new("dir/sweep.elevations.npy"));
        assert_eq!(a, Path::new("dir/sweep.azimuths.npy"));
        let (e, _) = axis_paths(Path::new("out"));
        assert_eq!(e, Path::new("out.elevations.npy"));
    }
}
