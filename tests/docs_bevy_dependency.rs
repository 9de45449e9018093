//! docs/bevy.md says how to add the plugin to a game's `Cargo.toml`: the snippet names the
//! package as integrations/bevy/Cargo.toml names it, at a path ending in that folder, and the
//! Bevy version the plugin pins.

use std::fs;
use std::path::Path;

/// The value of `key = "…"` on the first line of `text` that starts with `key`.
fn quoted(text: &str, key: &str) -> String {
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with(key))
        .unwrap_or_else(|| panic!("no line starting with {key:?}"));
    line.split('"').nth(1).expect("a quoted value").to_string()
}

#[test]
fn bevy_guide_shows_the_dependency_the_plugin_declares() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let guide = fs::read_to_string(root.join("docs/bevy.md")).unwrap();
    let manifest = fs::read_to_string(root.join("integrations/bevy/Cargo.toml")).unwrap();
    let snippet = guide
        .split("```toml")
        .nth(1)
        .and_then(|s| s.split("```").next())
        .expect("docs/bevy.md has a ```toml block");
    let package = quoted(&manifest, "name");
    assert_eq!(package, "shadow-aliasing-bevy");
    let dep = snippet
        .lines()
        .find(|l| l.starts_with(&format!("{package} = {{ path = ")))
        .unwrap_or_else(|| panic!("the snippet does not depend on {package} by path:\n{snippet}"));
    let path = dep.split('"').nth(1).unwrap();
    assert!(path.ends_with("/integrations/bevy"), "{path}");
    // The plugin pins "=0.19.0": the game's `bevy = "0.19"` must be the same minor version.
    let pinned = manifest
        .lines()
        .find(|l| l.starts_with("bevy = "))
        .and_then(|l| l.split("version = \"=").nth(1))
        .and_then(|v| v.split('"').next())
        .expect("the plugin pins bevy's version");
    let game = quoted(snippet, "bevy =");
    assert!(
        pinned.starts_with(&format!("{game}.")),
        "the guide's bevy {game} is not the plugin's {pinned}"
    );
    assert!(
        guide.contains(&format!("Bevy {game}")),
        "the guide names Bevy {game}"
    );
}
