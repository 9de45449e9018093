//! The layering of docs/architecture.md is the code's: every `crate::<module>` path used in the
//! code of a module (comments and doc links aside) names a module that the page's layer table
//! allows it to use. So `measure` can never import `maps` or `scheme`, and the page cannot drift.
//! Within a layer, the submodules' uses of each other form no cycle.

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
    paths_after(code, "crate::")
}

/// The first path segment after each occurrence of `prefix` (ending in `::`) in code, a group
/// `prefix{a, b::c}` giving `a` and `b`.
fn paths_after(code: &str, prefix: &str) -> Vec<String> {
    let mut out = Vec::new();
    for (i, _) in code.match_indices(prefix) {
        // `super::` inside `crate::x::super::` or a longer name (`my_crate::`) is not this path.
        let before = code[..i].chars().next_back();
        if before.is_some_and(|c| c.is_ascii_alphanumeric() || c == '_' || c == ':') {
            continue;
        }
        let rest = &code[i + prefix.len()..];
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
            // `pub use glam;` (an external crate re-exported whole) names no module of ours.
            let Some((module, names)) = rest.split_once("::") else {
                continue;
            };
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

/// The items a module's `mod.rs` re-exports from its submodules (`pub use sub::{a, b};`,
/// `pub(crate) use sub::c;`): item → submodule.
fn submodule_reexports(mod_rs: &str, subs: &BTreeSet<String>) -> BTreeMap<String, String> {
    let code = code_of(mod_rs);
    let mut map = BTreeMap::new();
    for stmt in code.split(';') {
        let stmt = stmt.trim();
        let Some(rest) = stmt
            .strip_prefix("pub use ")
            .or_else(|| stmt.strip_prefix("pub(crate) use "))
        else {
            continue;
        };
        let Some((module, names)) = rest.split_once("::") else {
            continue;
        };
        if !subs.contains(module) {
            continue;
        }
        for name in names
            .trim_matches(|c: char| c == '{' || c == '}' || c.is_whitespace())
            .split(',')
        {
            let name = ident(name);
            if !name.is_empty() {
                map.insert(name, module.to_string());
            }
        }
    }
    map
}

/// The submodules of the layer `dir` (files `x.rs` and folders `x/`, `mod.rs` aside), and for
/// each the submodules its code names: `crate::<layer>::x…`, `super::x…` in a file directly
/// under the layer's folder, or an item the layer's `mod.rs` re-exports from `x`.
fn submodule_graph(layer: &str, dir: &Path) -> BTreeMap<String, BTreeSet<String>> {
    let mut subs = BTreeSet::new();
    for entry in fs::read_dir(dir).expect("read layer") {
        let path = entry.expect("entry").path();
        let stem = path
            .file_stem()
            .and_then(|s| s.to_str())
            .unwrap_or("")
            .to_string();
        if path.is_dir() || (path.extension().is_some_and(|e| e == "rs") && stem != "mod") {
            subs.insert(stem);
        }
    }
    let mod_rs = fs::read_to_string(dir.join("mod.rs")).unwrap_or_default();
    let reexported = submodule_reexports(&mod_rs, &subs);
    let prefix = format!("crate::{layer}::");
    let mut graph = BTreeMap::new();
    for sub in &subs {
        let mut files = Vec::new();
        let (folder, file) = (dir.join(sub), dir.join(format!("{sub}.rs")));
        if folder.is_dir() {
            rust_files(&folder, &mut files);
        }
        if file.is_file() {
            files.push(file.clone());
        }
        let mut uses = BTreeSet::new();
        for path in files {
            let code = code_of(&fs::read_to_string(&path).expect("read"));
            let mut named = paths_after(&code, &prefix);
            if path == file {
                named.extend(paths_after(&code, "super::"));
            }
            for name in named {
                let target = if subs.contains(&name) {
                    Some(name)
                } else {
                    reexported.get(&name).cloned()
                };
                if let Some(t) = target.filter(|t| t != sub) {
                    uses.insert(t);
                }
            }
        }
        graph.insert(sub.clone(), uses);
    }
    graph
}

/// A cycle of the graph (its nodes in order, the first repeated at the end), if there is one.
fn find_cycle(graph: &BTreeMap<String, BTreeSet<String>>) -> Option<Vec<String>> {
    fn visit(
        node: &str,
        graph: &BTreeMap<String, BTreeSet<String>>,
        done: &mut BTreeSet<String>,
        stack: &mut Vec<String>,
    ) -> Option<Vec<String>> {
        if let Some(at) = stack.iter().position(|s| s == node) {
            let mut cycle = stack[at..].to_vec();
            cycle.push(node.to_string());
            return Some(cycle);
        }
        if done.contains(node) {
            return None;
        }
        stack.push(node.to_string());
        for next in graph.get(node).into_iter().flatten() {
            if let Some(c) = visit(next, graph, done, stack) {
                return Some(c);
            }
        }
        stack.pop();
        done.insert(node.to_string());
        None
    }
    let mut done = BTreeSet::new();
    for node in graph.keys() {
        if let Some(c) = visit(node, graph, &mut done, &mut Vec::new()) {
            return Some(c);
        }
    }
    None
}

/// Within a layer too the dependencies run one way: no two submodules of a layer (`maps::warp`
/// and `maps::minimax`, say) use each other, directly or through others.
#[test]
fn no_submodules_of_a_layer_use_each_other() {
    let src = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/src"));
    let mut cycles = Vec::new();
    let mut edges = 0;
    for layer in allowed().keys() {
        let dir = src.join(layer);
        if !dir.is_dir() {
            continue;
        }
        let graph = submodule_graph(layer, &dir);
        edges += graph.values().map(BTreeSet::len).sum::<usize>();
        if let Some(c) = find_cycle(&graph) {
            cycles.push(format!("{layer}: {}", c.join(" → ")));
        }
    }
    assert!(edges > 20, "only {edges} uses between submodules found");
    assert!(cycles.is_empty(), "{}", cycles.join("\n"));
}

#[test]
fn the_cycle_check_sees_a_cycle() {
    let subs: BTreeSet<String> = ["fit", "warp"].iter().map(|s| s.to_string()).collect();
    let reexports = submodule_reexports(
        "pub use warp::{warp, WarpRule};\npub use fit::{\n    fit_warp,\n};",
        &subs,
    );
    assert_eq!(reexports.get("fit_warp").map(String::as_str), Some("fit"));
    assert_eq!(reexports.get("WarpRule").map(String::as_str), Some("warp"));
    let code = code_of("use super::{body::Body, Ctx};\nuse crate::maps::{fit::X, warp};");
    assert_eq!(paths_after(&code, "super::"), ["body", "Ctx"]);
    assert_eq!(paths_after(&code, "crate::maps::"), ["fit", "warp"]);
    let mut graph = BTreeMap::new();
    let set = |v: &[&str]| v.iter().map(|s| s.to_string()).collect::<BTreeSet<_>>();
    graph.insert("a".to_string(), set(&["b"]));
    graph.insert("b".to_string(), set(&["c"]));
    graph.insert("c".to_string(), set(&[]));
    assert_eq!(find_cycle(&graph), None);
    graph.insert("c".to_string(), set(&["a"]));
    assert_eq!(
        find_cycle(&graph),
        Some(vec!["a".into(), "b".into(), "c".into(), "a".into()])
    );
}
