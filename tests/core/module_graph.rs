//! The dependency graph between the library's top-level modules (`src/core/`,
//! `src/gen/`, `src/mesh.rs`...) has no cycle, so that the layers read bottom up: every
//! `crate::X` path (in a `use` or inline, braces expanded, names re-exported at the crate
//! root resolved through `src/lib.rs`) in a module's non-test code is an edge to module
//! `X`. Test code (`#[cfg(test)]` items and the files of `#[cfg(test)] mod x;`) may reach
//! any module for its fixtures and is left out; so are comments, doc links included.
//!
//! `cargo test --test core module_graph -- --nocapture` prints the edges and the layers.

use std::collections::{BTreeMap, BTreeSet};
use std::fs;
use std::path::{Path, PathBuf};

/// The crate's source folder.
fn src() -> PathBuf {
    PathBuf::from(concat!(env!("CARGO_MANIFEST_DIR"), "/src"))
}

/// `text` without comments (line, block and doc comments), string and char literals
/// blanked out so that nothing inside them reads as a path.
fn strip_comments(text: &str) -> String {
    let b = text.as_bytes();
    let mut out = String::with_capacity(text.len());
    let mut i = 0;
    while i < b.len() {
        if b[i..].starts_with(b"//") {
            while i < b.len() && b[i] != b'\n' {
                i += 1;
            }
        } else if b[i..].starts_with(b"/*") {
            let mut depth = 0;
            while i < b.len() {
                if b[i..].starts_with(b"/*") {
                    depth += 1;
                    i += 2;
                } else if b[i..].starts_with(b"*/") {
                    depth -= 1;
                    i += 2;
                    if depth == 0 {
                        break;
                    }
                } else {
                    i += 1;
                }
            }
        } else if b[i] == b'"' {
            // A plain string literal (raw strings with quotes inside do not occur in
            // paths' neighbourhoods; they are blanked the same way up to the next quote).
            i += 1;
            while i < b.len() && b[i] != b'"' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("\"\"");
        } else if b[i] == b'\'' && i + 2 < b.len() && (b[i + 2] == b'\'' || b[i + 1] == b'\\') {
            // A char literal ('x' or '\n'); a lifetime ('a) is left alone.
            i += 1;
            while i < b.len() && b[i] != b'\'' {
                i += if b[i] == b'\\' { 2 } else { 1 };
            }
            i += 1;
            out.push_str("' '");
        } else {
            let c = text[i..].chars().next().unwrap_or(' ');
            out.push(c);
            i += c.len_utf8();
        }
    }
    out
}

/// The position and length of the first attribute of `code` that compiles its item only
/// in tests: `#[cfg(test)]` or `#[cfg(all(test, …))]`.
fn next_test_attribute(code: &str) -> Option<(usize, usize)> {
    let mut from = 0;
    while let Some(k) = code[from..].find("#[cfg(") {
        let at = from + k;
        let mut depth = 0;
        let mut len = code.len() - at;
        for (j, c) in code[at..].char_indices() {
            match c {
                '[' | '(' => depth += 1,
                ']' | ')' => {
                    depth -= 1;
                    if depth == 0 {
                        len = j + 1;
                        break;
                    }
                }
                _ => {}
            }
        }
        let predicate: String = code[at + "#[cfg(".len()..at + len]
            .chars()
            .filter(|c| !c.is_whitespace())
            .collect();
        if predicate == "test)]" || predicate.starts_with("all(test,") {
            return Some((at, len));
        }
        from = at + len;
    }
    None
}

/// `code` (comments stripped) without its test-only items ([`next_test_attribute`]): from
/// the attribute to
/// the end of the item (its first `;` or `,` outside brackets, its first top-level
/// `{…}` block, or the bracket that closes around it). Also returns the names of the `#[cfg(test)] mod name;` declarations.
fn strip_test_items(code: &str) -> (String, Vec<String>) {
    let mut out = String::new();
    let mut test_mods = Vec::new();
    let mut rest = code;
    while let Some((at, len)) = next_test_attribute(rest) {
        out.push_str(&rest[..at]);
        let item = &rest[at + len..];
        let mut depth = 0i32;
        let mut end = item.len();
        for (k, c) in item.char_indices() {
            match c {
                '{' | '(' | '[' => depth += 1,
                '}' | ')' | ']' => {
                    depth -= 1;
                    if depth < 0 {
                        // The last field of a struct or literal: the item ends before.
                        end = k;
                        break;
                    }
                    if depth == 0 && c == '}' {
                        end = k + 1;
                        break;
                    }
                }
                // The end of a statement, or of a field of a struct or literal.
                ';' | ',' if depth == 0 => {
                    end = k + 1;
                    break;
                }
                _ => {}
            }
        }
        let words: Vec<&str> = item[..end]
            .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ';'))
            .filter(|w| !w.is_empty())
            .collect();
        if let Some(p) = words.iter().position(|&w| w == "mod") {
            if let Some(name) = words.get(p + 1) {
                if let Some(name) = name.strip_suffix(';') {
                    test_mods.push(name.to_string());
                }
            }
        }
        rest = &item[end..];
    }
    out.push_str(rest);
    (out, test_mods)
}

/// The first path segments after every `crate::` in `code`, braces expanded
/// (`crate::{a, b::c}` gives `a` and `b`).
fn crate_paths(code: &str) -> Vec<String> {
    let mut found = Vec::new();
    let mut rest = code;
    while let Some(at) = rest.find("crate::") {
        let before = code.len() - rest.len() + at;
        rest = &rest[at + "crate::".len()..];
        // `$crate::` and `other_crate::` are not this crate's root.
        let prev = code[..before].chars().next_back();
        if prev.is_some_and(|c| c.is_alphanumeric() || c == '_' || c == '$') {
            continue;
        }
        if let Some(group) = rest.strip_prefix('{') {
            let mut depth = 1;
            let mut segment = String::new();
            let mut first = true;
            for c in group.chars() {
                match c {
                    '{' => depth += 1,
                    '}' => {
                        depth -= 1;
                        if depth == 0 {
                            break;
                        }
                    }
                    ',' if depth == 1 => {
                        if !segment.is_empty() {
                            found.push(std::mem::take(&mut segment));
                        }
                        first = true;
                        continue;
                    }
                    _ => {}
                }
                if depth == 1 && first {
                    if c.is_alphanumeric() || c == '_' {
                        segment.push(c);
                    } else if !segment.is_empty() {
                        found.push(std::mem::take(&mut segment));
                        first = false;
                    }
                }
            }
            if !segment.is_empty() {
                found.push(segment);
            }
        } else {
            let name: String = rest
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            if !name.is_empty() {
                found.push(name);
            }
        }
    }
    found
}

/// The non-test code of `file` and, recursively, of its child module files (the files
/// of its `#[cfg(test)] mod x;` declarations left out).
fn module_code(file: &Path, out: &mut String) {
    let Ok(text) = fs::read_to_string(file) else {
        return;
    };
    let (code, test_mods) = strip_test_items(&strip_comments(&text));
    // Where this file's child modules live: beside it for `mod.rs`, in a folder named
    // after it otherwise.
    let dir = if file.file_name().is_some_and(|n| n == "mod.rs") {
        file.parent().map(Path::to_path_buf)
    } else {
        file.parent()
            .zip(file.file_stem())
            .map(|(p, stem)| p.join(stem))
    };
    let words: Vec<&str> = code
        .split(|c: char| !(c.is_alphanumeric() || c == '_' || c == ';'))
        .filter(|w| !w.is_empty())
        .collect();
    for w in words.windows(2) {
        if w[0] != "mod" {
            continue;
        }
        let Some(name) = w[1].strip_suffix(';') else {
            continue;
        };
        if test_mods.iter().any(|t| t == name) {
            continue;
        }
        if let Some(dir) = &dir {
            for child in [
                dir.join(format!("{name}.rs")),
                dir.join(name).join("mod.rs"),
            ] {
                if child.is_file() {
                    module_code(&child, out);
                }
            }
        }
    }
    out.push_str(&code);
    out.push('\n');
}

/// The top-level modules (declared in `src/lib.rs`) and the root re-exports: name →
/// the module it comes from.
fn crate_root() -> (Vec<String>, BTreeMap<String, String>) {
    let lib = fs::read_to_string(src().join("lib.rs")).expect("src/lib.rs");
    let lib = strip_comments(&lib);
    let mut modules = Vec::new();
    let mut reexports = BTreeMap::new();
    for stmt in lib.split(';') {
        let stmt = stmt.trim();
        let words: Vec<&str> = stmt.split_whitespace().collect();
        if let Some(p) = words.iter().position(|&w| w == "mod") {
            if let Some(name) = words.get(p + 1) {
                modules.push(name.to_string());
            }
        } else if let Some(path) = stmt.strip_prefix("pub use ") {
            let path = path.trim_start_matches("crate::");
            let module: String = path
                .chars()
                .take_while(|c| c.is_alphanumeric() || *c == '_')
                .collect();
            let names = path[module.len()..].trim_start_matches("::");
            let names = names.trim_start_matches('{').trim_end_matches('}');
            for name in names.split(',') {
                let name = name.trim();
                let name = name.rsplit(" as ").next().unwrap_or(name);
                let name = name.rsplit("::").next().unwrap_or(name).trim();
                if !name.is_empty() {
                    reexports.insert(name.to_string(), module.clone());
                }
            }
        }
    }
    (modules, reexports)
}

/// The edges `module → module it uses` of the library's non-test code.
fn edges() -> BTreeMap<String, BTreeSet<String>> {
    let (modules, reexports) = crate_root();
    let mut graph = BTreeMap::new();
    for m in &modules {
        let mut code = String::new();
        for file in [src().join(format!("{m}.rs")), src().join(m).join("mod.rs")] {
            if file.is_file() {
                module_code(&file, &mut code);
            }
        }
        let mut uses = BTreeSet::new();
        for first in crate_paths(&code) {
            // A root re-export may name a re-exported module (`pub use crate::core::x;`
            // then `pub use x::Y;`): follow the chain to a module.
            let mut target = first;
            for _ in 0..4 {
                match reexports.get(&target) {
                    Some(m) if !modules.contains(&target) => target = m.clone(),
                    _ => break,
                }
            }
            if !modules.contains(&target) {
                continue;
            }
            if &target != m {
                uses.insert(target);
            }
        }
        graph.insert(m.clone(), uses);
    }
    graph
}

/// The modules in layers (each uses only modules of lower layers), or the modules left
/// on cycles.
fn layers(graph: &BTreeMap<String, BTreeSet<String>>) -> Result<Vec<Vec<String>>, Vec<String>> {
    let mut placed: BTreeSet<&String> = BTreeSet::new();
    let mut out = Vec::new();
    while placed.len() < graph.len() {
        let layer: Vec<String> = graph
            .iter()
            .filter(|(m, uses)| !placed.contains(m) && uses.iter().all(|u| placed.contains(u)))
            .map(|(m, _)| m.clone())
            .collect();
        if layer.is_empty() {
            return Err(graph
                .keys()
                .filter(|m| !placed.contains(m))
                .cloned()
                .collect());
        }
        for m in &layer {
            placed.insert(graph.get_key_value(m).map(|(k, _)| k).expect("a module"));
        }
        out.push(layer);
    }
    Ok(out)
}

#[test]
fn the_top_level_modules_have_no_import_cycle() {
    let graph = edges();
    for (m, uses) in &graph {
        eprintln!(
            "{m} -> {}",
            uses.iter().cloned().collect::<Vec<_>>().join(", ")
        );
    }
    assert!(graph.contains_key("core") && graph.contains_key("quad"));
    match layers(&graph) {
        Ok(layers) => {
            for (k, layer) in layers.iter().enumerate() {
                eprintln!("layer {k}: {}", layer.join(", "));
            }
        }
        Err(left) => {
            // The modules left are on cycles or use one; name those on cycles, with
            // their edges among themselves.
            let cyclic: Vec<&String> = left.iter().filter(|m| reaches(&graph, m, m)).collect();
            let on: Vec<String> = cyclic
                .iter()
                .map(|&m| {
                    let inner: Vec<&String> =
                        graph[m].iter().filter(|u| cyclic.contains(u)).collect();
                    format!("{m} -> {inner:?}")
                })
                .collect();
            panic!(
                "import cycle among the top-level modules: {}",
                on.join("; ")
            );
        }
    }
}

/// Whether `to` is reachable from `from` by one edge or more.
fn reaches(graph: &BTreeMap<String, BTreeSet<String>>, from: &String, to: &String) -> bool {
    let mut seen = BTreeSet::new();
    let mut todo: Vec<&String> = graph[from].iter().collect();
    while let Some(m) = todo.pop() {
        if m == to {
            return true;
        }
        if seen.insert(m) {
            todo.extend(graph.get(m).into_iter().flatten());
        }
    }
    false
}

/// The check sees what it must: paths in braces, root re-exports, and not comments or
/// test items.
#[test]
fn the_path_scan_reads_groups_and_skips_tests_and_comments() {
    let code = strip_comments(
        "use crate::{a::X, b, c::{d, e}};\n// use crate::f;\n/// [`crate::g`]\n\
         let x = crate::h::y(\"crate::i\");\nmacro_rules! m { () => { $crate::j } }",
    );
    assert_eq!(crate_paths(&code), ["a", "b", "c", "h"]);
    let (kept, mods) = strip_test_items(
        "use crate::a;\n#[cfg(test)]\nuse crate::b;\n#[cfg(test)]\nmod tests {\n use \
         crate::c;\n}\n#[cfg(test)]\nmod more;\nstruct S {\n #[cfg(test)]\n t: crate::t::T,\n}\n\
         #[cfg(all(test, feature = \"x\"))]\nmod corpus {\n use crate::u;\n}\n\
         fn f() { crate::d::e(); }",
    );
    assert_eq!(crate_paths(&kept), ["a", "d"]);
    assert_eq!(mods, ["more"]);
    let cyclic: BTreeMap<String, BTreeSet<String>> = [("a", "b"), ("b", "c"), ("c", "a")]
        .into_iter()
        .map(|(m, u)| (m.to_string(), BTreeSet::from([u.to_string()])))
        .collect();
    assert!(layers(&cyclic).is_err());
}
