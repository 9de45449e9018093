//! Every test the docs cite as `file::test` exists: docs/equations.md maps each equation to the
//! tests that compare it with a measurement, and the other pages cite tests as evidence, so a
//! renamed or deleted test must not leave a citation pointing at nothing.

use std::fs;
use std::path::Path;

/// The `a::b` spans in backticks of `text` (identifiers of lower-case letters, digits and `_`).
fn cited_paths(text: &str) -> Vec<(String, String)> {
    let mut out = Vec::new();
    // Line by line, so that a code fence or an odd backtick cannot shift the pairing for the
    // rest of the page.
    for span in text.lines().flat_map(|l| l.split('`').skip(1).step_by(2)) {
        let ident = |s: &str| {
            !s.is_empty()
                && s.bytes()
                    .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_')
        };
        if let Some((file, test)) = span.split_once("::") {
            if ident(file) && ident(test) {
                out.push((file.to_string(), test.to_string()));
            }
        }
    }
    out
}

/// The text of every `.rs` file under `dir`, concatenated.
fn sources_under(dir: &Path) -> String {
    let mut all = String::new();
    for entry in fs::read_dir(dir).expect("source directory") {
        let path = entry.expect("directory entry").path();
        if path.is_dir() {
            all += &sources_under(&path);
        } else if path.extension().is_some_and(|e| e == "rs") {
            all += &fs::read_to_string(&path).expect("source file");
        }
    }
    all
}

#[test]
fn every_cited_test_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    // `partition::splits_storage_factor` may name the library's function (`analytic::partition`)
    // rather than a test of tests/partition.rs: a public function of that name settles it.
    let library = sources_under(&root.join("src"));
    let mut checked = 0;
    let mut missing = Vec::new();
    for entry in fs::read_dir(root.join("docs")).expect("docs/") {
        let page = entry.expect("docs entry").path();
        if page.extension().is_none_or(|e| e != "md") {
            continue;
        }
        let text = fs::read_to_string(&page).expect("doc page");
        for (file, test) in cited_paths(&text) {
            // Only citations of a test file: `tests/<file>.rs` (module paths such as
            // `overhead::mx` name no test file and are left to rustdoc's link check).
            let Ok(source) = fs::read_to_string(root.join("tests").join(format!("{file}.rs")))
            else {
                continue;
            };
            checked += 1;
            let is_library_fn = library.contains(&format!("pub fn {test}("))
                || library.contains(&format!("pub fn {test}<"));
            // `plan::clipmap` names the library's module src/plan/clipmap.rs, not a test of
            // tests/plan.rs.
            let src = root.join("src").join(&file);
            let is_module = src.join(format!("{test}.rs")).is_file()
                || src.join(&test).join("mod.rs").is_file();
            if !source.contains(&format!("fn {test}(")) && !is_library_fn && !is_module {
                missing.push(format!("{}: {file}::{test}", page.display()));
            }
        }
    }
    assert!(
        checked >= 80,
        "only {checked} test citations found in docs/"
    );
    assert!(
        missing.is_empty(),
        "docs cite tests that do not exist: {missing:#?}"
    );
}
