//! A deliberately wrong implementation of the conformance protocol
//! (`spec/conformance.md`), for the harness's tests and as a small example of the
//! protocol: it validates nothing and computes little.
//!
//! - `reduce` and `simplify`: answers the input itself (right only where the input
//!   already is a correct answer: an irreducible input, no short edge left);
//! - `quad`: pairs each triangle, in face order, with its first unpaired neighbour and
//!   never repairs a triangle left alone (no augmenting paths);
//! - never refuses an input, so it fails every invalid case.
//!
//! `contractible conformance --impl target/release/examples/wrong_adapter`

use std::collections::HashMap;
use std::io::Read;

use serde_json::{json, Value};

/// Greedy pairing: quads `[c, a, d, b]` for triangles `(c, a, b)` and `(b, a, d)` sharing
/// `[a, b]`; triangles left unpaired are dropped.
fn greedy_quads(faces: &[[u64; 3]]) -> Vec<[u64; 4]> {
    let mut at_edge: HashMap<(u64, u64), Vec<usize>> = HashMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            at_edge.entry((a.min(b), a.max(b))).or_default().push(i);
        }
    }
    let mut paired = vec![false; faces.len()];
    let mut quads = Vec::new();
    for (i, f) in faces.iter().enumerate() {
        if paired[i] {
            continue;
        }
        for k in 0..3 {
            let (c, a, b) = (f[k], f[(k + 1) % 3], f[(k + 2) % 3]);
            let mate = at_edge[&(a.min(b), a.max(b))]
                .iter()
                .copied()
                .find(|&j| j != i && !paired[j]);
            if let Some(j) = mate {
                let d = faces[j].iter().copied().find(|&x| x != a && x != b);
                if let Some(d) = d {
                    paired[i] = true;
                    paired[j] = true;
                    quads.push([c, a, d, b]);
                    break;
                }
            }
        }
    }
    quads
}

fn main() {
    let mut text = String::new();
    if std::io::stdin().read_to_string(&mut text).is_err() {
        std::process::exit(2);
    }
    let case: Value = match serde_json::from_str(&text) {
        Ok(v) => v,
        Err(e) => {
            println!(
                "{}",
                json!({"error": {"kind": "protocol", "message": e.to_string()}})
            );
            std::process::exit(2);
        }
    };
    let faces: Vec<[u64; 3]> = serde_json::from_value(case["faces"].clone()).unwrap_or_default();
    let answer = match case["task"].as_str() {
        Some("quad") => json!({"faces": greedy_quads(&faces), "positions": null}),
        _ => json!({"faces": faces, "positions": case["positions"]}),
    };
    println!("{answer}");
}
