//! Regenerates the counter tables of the RS paper (Tables 6, 8, 10: ℓ and ε of RS, S and
//! BF on the families B, C, D) on our regenerated families, with the paper's figures
//! beside ours, as Markdown on stdout. Timing ratios come from `cargo bench --bench
//! irreducible` (medians), not from here.
//!
//! Usage: `cargo run --release -p contractible-tools --bin paper_tables -- [GROUPS] [BF_RUNS]`
//! e.g. `-- BCD 3` (the paper averaged BF over 10 shuffles; default here 3).

use contractible::gen::paper_family;
use contractible::irreducible::{reduce, Algorithm, Options};
use contractible::Triangulation;

/// The paper's Tables 6, 8, 10: (member, ℓ_rs, ℓ_s, ℓ_bf, ε_s, ε_bf).
const PAPER: &[(&str, f64, f64, f64, f64, f64)] = &[
    ("B0", 2079539.0, 2097158.0, 3406091.5, 6.0, 19011.7),
    ("B1", 1085325.0, 1097194.0, 1783418.4, 9.0, 10034.9),
    ("B2", 588335.0, 597196.0, 968511.9, 7.0, 5495.3),
    ("B3", 289520.0, 297174.0, 479536.2, 8.0, 2863.7),
    ("B4", 145338.0, 147193.0, 232984.4, 7.0, 1482.1),
    ("B5", 68454.0, 72190.0, 111673.8, 7.0, 816.4),
    ("B6", 29827.0, 34675.0, 50936.6, 6.0, 458.9),
    ("B7", 14085.0, 15908.0, 18838.2, 6.0, 292.5),
    ("B8", 7979.0, 8408.0, 9941.4, 6.0, 159.4),
    ("B9", 4063.0, 4408.0, 5246.4, 6.0, 92.1),
    ("C0", 3499517.0, 3336889.0, 3595222.5, 346735.0, 52815.0),
    ("C1", 1846458.0, 1780868.0, 1967691.3, 200636.0, 49757.9),
    ("C2", 1018801.0, 1006051.0, 1131182.2, 128339.0, 48063.1),
    ("C3", 605195.0, 615112.0, 742667.4, 91493.0, 47180.6),
    ("C4", 318114.0, 347941.0, 459221.8, 66975.0, 46630.6),
    ("C5", 171599.0, 209767.0, 316699.6, 54353.0, 46300.9),
    ("C6", 90867.0, 135245.0, 232041.0, 47094.0, 46105.7),
    ("C7", 54594.0, 100181.0, 188700.6, 45856.0, 46000.5),
    ("D0", 3499517.0, 3336889.0, 3585933.5, 346735.0, 52866.6),
    ("D1", 3298209.0, 3161516.0, 3576091.5, 297628.0, 47936.2),
    ("D2", 3095251.0, 2981813.0, 3554938.0, 247822.0, 43124.9),
    ("D3", 2895440.0, 2804562.0, 3522016.4, 197884.0, 38400.2),
    ("D4", 2693425.0, 2628433.0, 3495457.5, 148587.0, 33570.1),
    ("D5", 2493458.0, 2451622.0, 3466912.2, 99075.0, 28706.5),
    ("D6", 2293492.0, 2274066.0, 3436328.4, 49415.0, 23811.3),
    ("D7", 2129696.0, 2132148.0, 3412062.2, 9718.0, 19991.1),
    ("D8", 2110987.0, 2115194.0, 3409289.6, 4948.0, 19357.0),
    ("D9", 2087627.0, 2100756.0, 3406560.1, 1019.0, 19072.6),
];

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let groups = args.get(1).cloned().unwrap_or_else(|| "BCD".into());
    let runs: u64 = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(3);
    println!("| member | genus | F | ℓ_rs | ℓ_s | ℓ_bf (mean of {runs}) | ε_rs | ε_s | ε_bf | paper ℓ_rs | paper ℓ_s | paper ℓ_bf | paper ε_s | paper ε_bf |");
    println!("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|");
    for &(name, p_rs, p_s, p_bf, p_es, p_ebf) in PAPER {
        let group = name.chars().next().expect("name");
        if !groups.contains(group) {
            continue;
        }
        let index: u32 = name[1..].parse().expect("index");
        let mesh = paper_family(group, index).expect("valid brick parameters");
        let tri = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("surface");
        let genus = tri.euler_genus() / 2;
        let opts = |seed| Options {
            seed,
            count_retests: true,
            keep_history: true,
        };
        let rs = reduce(tri.clone(), Algorithm::Rs, &opts(0)).stats;
        let s = reduce(tri.clone(), Algorithm::Schipper, &opts(0)).stats;
        let (mut l_bf, mut e_bf) = (0.0, 0.0);
        for seed in 0..runs {
            let b = reduce(tri.clone(), Algorithm::Brute, &opts(seed)).stats;
            l_bf += b.link_tests as f64 / runs as f64;
            e_bf += b.edges_tested_more_than_once as f64 / runs as f64;
        }
        println!(
            "| {name} | {genus} | {} | {} | {} | {:.1} | {} | {} | {:.1} | {p_rs} | {p_s} | {p_bf} | {p_es} | {p_ebf} |",
            tri.face_count(),
            rs.link_tests,
            s.link_tests,
            l_bf,
            rs.edges_tested_more_than_once,
            s.edges_tested_more_than_once,
            e_bf,
        );
    }
}
