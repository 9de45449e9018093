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

/// Whether `name` is a module somewhere under `dir` (`name.rs` or `name/`), or a crate the docs
/// write module paths of (`glam::…`, `std::…`).
fn is_module_name(dir: &Path, name: &str) -> bool {
    // Crates and primitive types the docs write paths of, and equations.md's own description of
    // the form (`file::test`).
    let known = [
        "glam",
        "std",
        "core",
        "nalgebra",
        "mint",
        "bytemuck",
        "wgpu",
        "naga",
        "f64",
        "f32",
        "shadow_aliasing",
        "render_check",
        "file",
    ];
    if known.contains(&name) || name.starts_with("bevy") {
        return true;
    }
    fs::read_dir(dir).expect("source directory").any(|entry| {
        let path = entry.expect("directory entry").path();
        let stem = path.file_stem().and_then(|s| s.to_str());
        stem == Some(name) || (path.is_dir() && is_module_name(&path, name))
    })
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
                // Not a test file: then it must name one of the library's modules
                // (`overhead::mx`), or the citation points at a file that does not exist.
                let members = [
                    "src",
                    "render-check/src",
                    "python/src",
                    "integrations/bevy/src",
                ];
                if !members.iter().any(|m| is_module_name(&root.join(m), &file)) {
                    missing.push(format!(
                        "{}: {file}::{test} (no tests/{file}.rs)",
                        page.display()
                    ));
                }
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

/// A test-file path as the docs write it (`tests/x.rs`, `render-check/tests/x.rs`,
/// `python/tests/test_x.py`), with surrounding punctuation and backticks stripped.
fn test_path(token: &str) -> Option<&str> {
    let t = token.trim_matches(|c: char| "`,;:.".contains(c) || c.is_whitespace());
    let (dir, file) = t.rsplit_once('/')?;
    let stem = file
        .strip_suffix(".rs")
        .or_else(|| file.strip_suffix(".py"))?;
    let ok = |s: &str| {
        !s.is_empty()
            && s.bytes()
                .all(|c| c.is_ascii_alphanumeric() || c == b'_' || c == b'-' || c == b'/')
    };
    (dir.ends_with("tests") && ok(dir) && ok(stem)).then_some(t)
}

/// An identifier in backticks that can name a test (lower case, digits, `_`, at least one `_`).
fn test_ident(span: &str) -> Option<&str> {
    let s = span.strip_prefix('`')?.strip_suffix('`')?;
    let ok = s.contains('_')
        && s.bytes()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == b'_');
    ok.then_some(s)
}

/// One citation in the docs' usual forms: "`name` (tests/x.rs)", "`a` and `b` (tests/x.rs)",
/// "(tests/x.rs, `name`)", "(`tests/x.rs`)": the cited files and the test names.
#[derive(Debug, PartialEq)]
struct Citation {
    files: Vec<String>,
    names: Vec<String>,
}

/// The citations of a page: every parenthesis that names a test file, with the backticked names
/// inside it and those written just before it. Code fences are skipped; a paragraph's lines are
/// joined, so a citation broken over two lines is still read.
fn parenthesised_citations(text: &str) -> Vec<Citation> {
    let mut prose = String::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if !fenced {
            prose.push_str(line);
            prose.push(' ');
        }
    }
    let mut out = Vec::new();
    let mut rest = prose.as_str();
    let mut consumed = 0;
    while let Some(open) = rest.find('(') {
        let before = &prose[..consumed + open];
        let after = &rest[open + 1..];
        let Some(close) = after.find([')', '(']) else {
            break;
        };
        let inside = &after[..close];
        consumed += open + 1;
        rest = &prose[consumed..];
        let mut files: Vec<String> = inside
            .split_whitespace()
            .filter_map(test_path)
            .map(str::to_string)
            .collect();
        let mut names: Vec<String> = inside
            .split_whitespace()
            .filter_map(|w| test_ident(w.trim_end_matches([',', ';', ':', '.'])))
            .map(str::to_string)
            .collect();
        if files.is_empty() {
            // The file before the parenthesis: "tests/x.rs (`name`)".
            match before.split_whitespace().last().and_then(test_path) {
                Some(file) if !names.is_empty() => files.push(file.to_string()),
                _ => continue,
            }
            out.push(Citation { files, names });
            continue;
        }
        // Backward from the parenthesis: `a`, `b` and `c` (tests/x.rs).
        let mut b = before.trim_end();
        while let Some(end) = b.strip_suffix('`') {
            let Some(start) = end.rfind('`') else {
                break;
            };
            let Some(name) = test_ident(&b[start..]) else {
                break;
            };
            names.push(name.to_string());
            b = b[..start].trim_end();
            for joint in [", and", ",", " and", " or"] {
                if let Some(s) = b.strip_suffix(joint) {
                    b = s.trim_end();
                    break;
                }
            }
        }
        out.push(Citation { files, names });
    }
    out
}

/// Where a cited path lives: from the repository's root, or a member's `tests/` folder when the
/// page names it as `tests/x.rs` (render-check's, the Bevy integration's, the Python package's).
fn resolve(root: &Path, file: &str) -> Option<String> {
    let mut candidates = vec![root.join(file)];
    if file.starts_with("tests/") {
        for member in [
            "render-check",
            "integrations/bevy",
            "python",
            "interop-check",
        ] {
            candidates.push(root.join(member).join(file));
        }
    }
    let texts: Vec<String> = candidates
        .iter()
        .filter_map(|p| fs::read_to_string(p).ok())
        .collect();
    (!texts.is_empty()).then(|| texts.concat())
}

/// A test named `name` in `source`: `fn name(` (plain tests, proptest properties, pytest's
/// `def name(`) or a test-generating macro's `name:` entry at the start of a line.
fn defines_test(source: &str, name: &str) -> bool {
    source.contains(&format!("fn {name}("))
        || source.contains(&format!("def {name}("))
        || source
            .lines()
            .any(|l| l.trim_start().starts_with(&format!("{name}:")))
}

#[test]
fn citation_parser_reads_the_docs_forms() {
    let c = parenthesised_citations(
        "the error of `a_b` and `c_d` (tests/x.rs). Also (tests/y.rs, `e_f`) and\n(`tests/z.rs`) and\n`g_h`\n(render-check/tests/r.rs); (not a citation `i_j`). tests/w.rs\n(`k_l`).",
    );
    let files = |c: &Citation| c.files.clone();
    assert_eq!(c.len(), 5, "{c:?}");
    assert_eq!(files(&c[0]), ["tests/x.rs"]);
    assert_eq!(c[0].names, ["c_d", "a_b"]);
    assert_eq!(c[1].names, ["e_f"]);
    assert!(c[2].names.is_empty());
    assert_eq!(files(&c[2]), ["tests/z.rs"]);
    assert_eq!(c[3].names, ["g_h"]);
    assert_eq!(files(&c[3]), ["render-check/tests/r.rs"]);
    assert_eq!(files(&c[4]), ["tests/w.rs"]);
    assert_eq!(c[4].names, ["k_l"]);
}

#[test]
fn every_parenthesised_citation_names_a_file_and_test_that_exist() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut pages = vec![root.join("README.md")];
    for entry in fs::read_dir(root.join("docs")).expect("docs/") {
        let page = entry.expect("docs entry").path();
        if page.extension().is_some_and(|e| e == "md") {
            pages.push(page);
        }
    }
    let (mut files_checked, mut names_checked) = (0, 0);
    let mut missing = Vec::new();
    for page in &pages {
        let text = fs::read_to_string(page).expect("doc page");
        for citation in parenthesised_citations(&text) {
            let mut sources = String::new();
            for file in &citation.files {
                files_checked += 1;
                match resolve(root, file) {
                    Some(s) => sources += &s,
                    None => missing.push(format!("{}: file {file}", page.display())),
                }
            }
            for name in &citation.names {
                names_checked += 1;
                if !defines_test(&sources, name) {
                    missing.push(format!(
                        "{}: {name} in {:?}",
                        page.display(),
                        citation.files
                    ));
                }
            }
        }
    }
    assert!(
        files_checked >= 40,
        "only {files_checked} cited files found"
    );
    assert!(
        names_checked >= 10,
        "only {names_checked} cited test names found"
    );
    assert!(
        missing.is_empty(),
        "docs cite files or tests that do not exist: {missing:#?}"
    );
}

/// The rustdoc front page (src/lib.rs's crate doc) names every public module as a link, so a
/// reader of docs.rs finds each layer, the renderer's `frame` among them.
#[test]
fn front_page_links_every_public_module() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let lib = fs::read_to_string(root.join("src/lib.rs")).expect("src/lib.rs");
    let doc: String = lib
        .lines()
        .filter_map(|l| l.strip_prefix("//!"))
        .collect::<Vec<_>>()
        .join("\n");
    let modules: Vec<&str> = lib
        .lines()
        .filter_map(|l| l.strip_prefix("pub mod "))
        .map(|m| m.trim_end_matches(';'))
        .collect();
    assert!(modules.len() >= 10, "{modules:?}");
    // `plot` and `eval` are behind features (named in backticks: a link would break the
    // default build's docs); `error` and `numeric` are named through their items.
    let unlinked: Vec<_> = modules
        .iter()
        .filter(|m| !["plot", "eval", "error", "numeric"].contains(m))
        .filter(|m| !doc.contains(&format!("[`{m}`]")))
        .collect();
    assert!(unlinked.is_empty(), "front page does not link {unlinked:?}");
}

/// The README's command synopsis shows every subcommand the binary has.
#[cfg(feature = "cli")]
#[test]
fn readme_synopsis_shows_every_subcommand() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let readme = fs::read_to_string(root.join("README.md")).expect("README.md");
    let synopsis = readme
        .split("## The command line")
        .nth(1)
        .and_then(|s| s.split("```").nth(1))
        .expect("the README's command synopsis");
    let help = std::process::Command::new(env!("CARGO_BIN_EXE_shadow-aliasing"))
        .arg("--help")
        .output()
        .expect("run shadow-aliasing --help");
    let help = String::from_utf8(help.stdout).expect("utf-8 help");
    let commands: Vec<&str> = help
        .split("Commands:")
        .nth(1)
        .expect("a Commands: section")
        .lines()
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|c| *c != "help")
        .collect();
    assert!(commands.len() >= 5, "{commands:?}");
    for c in commands {
        assert!(
            synopsis.contains(&format!("shadow-aliasing {c} ")),
            "the README's synopsis omits `{c}`"
        );
    }
}
