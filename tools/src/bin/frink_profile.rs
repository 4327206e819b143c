//! Frink's reduction on paper family members (`B0`…`B9`, `C0`…`C7`; the biggest
//! component): wall time of `frink::solve` on the dual graph with the Diks–Stańczyk
//! strategy, the Biedl–Bose–Demaine–Lubiw strategy (`bbdl`), the link–cut cover-count
//! strategy (and, with `--naive`, the naive one),
//! the run's counters and the strategy's (DS: how steps were decided, digon steps,
//! replacement edges; lct: how many steps were tree-stable, rebuilds / naive steps).
//!
//! Wall and CPU time of the thread (which means more on a shared machine).
//!
//! Run: `cargo run --release -p contractible-tools --bin frink_profile -- B4 B2 B0 [--naive] [--only ds|bbdl|lct]`

use contractible_tools::cpu;
use std::time::Instant;

use contractible::gen::paper_family;
use contractible::quad::frink::{self, BiedlBoseDemaineLubiw, CoverTree, DiksStanczyk, Naive};
use contractible::Surfaces;

/// FNV-1a of the matching, to tell at a glance whether a change kept DS's output.
fn fnv(mate: &[u32]) -> u64 {
    mate.iter().fold(0xcbf2_9ce4_8422_2325, |h, &m| {
        (h ^ u64::from(m)).wrapping_mul(0x0100_0000_01b3)
    })
}

fn main() {
    let mut names = Vec::new();
    let mut naive = false;
    let mut only: Option<String> = None;
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        if a == "--naive" {
            naive = true;
        } else if a == "--only" {
            only = args.next();
        } else {
            names.push(a);
        }
    }
    let run = |s: &str| only.as_deref().is_none_or(|o| o == s);
    for name in names {
        let mut c = name.chars();
        let group = c.next().expect("member name");
        let mesh = paper_family(group, c.as_str().parse().expect("member index"))
            .expect("valid brick parameters");
        let s = Surfaces::from_mesh(&mesh).expect("closed surface");
        let tri = s
            .components
            .into_iter()
            .max_by_key(|c| c.tri.face_count())
            .expect("a component")
            .tri;
        let f = tri.face_count();
        let (g, _) = frink::dual_graph(&tri).expect("dual");
        let nlogn = f as f64 * (f as f64).log2();
        if run("ds") {
            let mut ds = DiksStanczyk::new();
            let (t, c0) = (Instant::now(), cpu());
            let sol = frink::solve(g.clone(), &mut ds).expect("bridgeless");
            let (secs, cpu_secs) = (t.elapsed().as_secs_f64(), cpu() - c0);
            println!(
                "{name}: F {f} ds {secs:.3} s (cpu {cpu_secs:.2} s), {:.1} ns cpu per F log2² F; {:?}; {:?}; mate hash {:016x}",
                cpu_secs * 1e9 / (nlogn * (f as f64).log2()),
                sol.stats,
                ds.counters(),
                fnv(&sol.mate)
            );
        }
        if run("bbdl") {
            let mut bbdl = BiedlBoseDemaineLubiw::new();
            let (t, c0) = (Instant::now(), cpu());
            let sol = frink::solve(g.clone(), &mut bbdl).expect("bridgeless");
            let (secs, cpu_secs) = (t.elapsed().as_secs_f64(), cpu() - c0);
            println!(
                "{name}: F {f} bbdl {secs:.3} s (cpu {cpu_secs:.2} s), {:.1} ns cpu per F log2² F; {:?}; {:?}",
                cpu_secs * 1e9 / (nlogn * (f as f64).log2()),
                sol.stats,
                bbdl.counters()
            );
        }
        if run("lct") {
            let mut lct = CoverTree::new();
            let (t, c0) = (Instant::now(), cpu());
            let sol = frink::solve(g.clone(), &mut lct).expect("bridgeless");
            let (secs, cpu_secs) = (t.elapsed().as_secs_f64(), cpu() - c0);
            println!(
                "{name}: F {f} frink-lct {secs:.3} s (cpu {cpu_secs:.2} s), {:.1} ns cpu per F log2 F; {:?}; {:?}",
                cpu_secs * 1e9 / nlogn,
                sol.stats,
                lct.counters()
            );
        }
        if naive {
            let (t, c0) = (Instant::now(), cpu());
            let sol = frink::solve(g, &mut Naive::new()).expect("bridgeless");
            let (secs, cpu_secs) = (t.elapsed().as_secs_f64(), cpu() - c0);
            println!(
                "{name}: F {f} ds-naive {secs:.3} s (cpu {cpu_secs:.2} s), {:.2} ns cpu per F²; case (iv) {}",
                cpu_secs * 1e9 / (f as f64 * f as f64),
                sol.stats.case_iv
            );
        }
    }
}
