//! The layering of docs/architecture.md is the code's: every `crate::<module>` path used in the
//! code of a module (comments and doc links aside) names a module that the page's layer table
//! allows it to use. So `measure` can never import `maps` or `scheme`, and the page cannot drift.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The table between the `layers: begin` and `layers: end` markers: module → modules it may use.
fn allowed() -> BTreeMap<String, BTreeSet<String>> {
    let page = fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/docs/architecture.md"))
        .expect("docs/architecture.md");
    let start = page.find("<!-- layers: begin -->").expect("begin marker");
    let end = page.find("<!-- layers: end -->").expect("end marker");
    let mut table = BTreeMap::new();
    for row in page[start..end].lines().filter(|l| l.starts_with("| `")) {
        let cells: Vec<&str> = row.split('|').map(str::trim).collect();
        let module = cells[1].trim_matches('`').to_string();
        let uses = cells[2]
            .split(',')
            .map(|s| s.trim().trim_matches('`').to_string())
            .filter(|s| !s.is_empty() && s != "—")
            .collect();
        table.insert(module, uses);
    }
    table
}

fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("read src") {
        let path = entry.expect("entry").path();
        if path.is_dir() {
            rust_files(&path, out);
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// The code of a file with comments cut off, one string.
fn code_of(text: &str) -> String {
    text.lines()
        .map(|l| l.split("//").next().unwrap_or(""))
        .collect::<Vec<_>>()
        .join("\n")
}

fn ident(s: &str) -> String {
    s.trim_start()
        .chars()
        .take_while(|c| c.is_ascii_alphanumeric() || *c == '_')
        .collect()
}

/// The first path segment after each `crate::` in code, `crate::{a, b::c}` giving `a` and `b`.
fn crate_paths(code: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in code.match_indices("crate::") {
        let rest = &code[i + "crate::".len()..];
        if let Some(group) = rest.strip_prefix('{') {
            let (mut depth, mut start) = (0usize, 0usize);
            for (j, c) in group.char_indices() {
                match c {
                    '{' => depth += 1,
                    '}' if depth == 0 => {
                        out.push(ident(&group[start..j]));
                        break;
                    }
                    '}' => depth -= 1,
                    ',' if depth == 0 => {
                        out.push(ident(&group[start..j]));
                        start = j + 1;
                    }
                    _ => {}
                }
            }
        } else {
            out.push(ident(rest));
        }
    }
    out.retain(|s| !s.is_empty());
    out
}

/// The crate root's re-exports (`pub use frustum::{ViewFrustum, …};` in lib.rs): a path such as
/// `crate::ViewFrustum` uses the module it comes from.
fn root_reexports() -> BTreeMap<String, String> {
    let lib = fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/src/lib.rs")).expect("lib");
    let mut map = BTreeMap::new();
    for line in lib.lines() {
        if let Some(rest) = line.strip_prefix("pub use ") {
            let (module, names) = rest.split_once("::").expect("pub use module::…");
            for name in names
                .trim_end_matches(';')
                .trim_matches(['{', '}'])
                .split(',')
            {
                map.insert(name.trim().to_string(), module.to_string());
            }
        }
    }
    map
}

#[test]
fn every_module_uses_only_the_layers_its_row_allows() {
    let table = allowed();
    let reexports = root_reexports();
    assert!(reexports.contains_key("ViewFrustum"), "{reexports:?}");
    assert!(
        table.len() >= 10,
        "the layer table has {} rows",
        table.len()
    );
    let src = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src"));
    let mut violations = Vec::new();
    let mut checked = 0;
    for (module, uses) in &table {
        let (dir, file) = (src.join(module), src.join(format!("{module}.rs")));
        let mut files = Vec::new();
        if dir.is_dir() {
            rust_files(&dir, &mut files);
        }
        if file.is_file() {
            files.push(file);
        }
        assert!(
            !files.is_empty(),
            "module `{module}` of the table has no source"
        );
        for path in files {
            let text = fs::read_to_string(&path).expect("read");
            for used in crate_paths(&code_of(&text)) {
                let used = reexports.get(&used).cloned().unwrap_or(used);
                checked += 1;
                if used != *module && !uses.contains(&used) {
                    violations.push(format!(
                        "{}: `{module}` uses `crate::{used}`",
                        path.display()
                    ));
                }
            }
        }
    }
    assert!(checked > 100, "only {checked} crate paths found");
    assert!(violations.is_empty(), "{}", violations.join("\n"));
}

#[test]
fn the_check_sees_a_forbidden_import() {
    let code = code_of("use crate::maps::WarpRule; // crate::scheme\n/// [`crate::geom`]");
    assert_eq!(crate_paths(&code), ["maps"]);
    let code = code_of("use crate::{\n    error::Error,\n    maps::{warp, ShadowMatrix},\n};");
    assert_eq!(crate_paths(&code), ["error", "maps"]);
}
