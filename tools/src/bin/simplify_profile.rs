//! One run of the simplifier on a ≥ 1M-triangle marching-tetrahedra surface, with the
//! time of each phase and the throughput: `cargo run --release -p contractible-tools
//! --bin simplify_profile [torus|hyperboloid|paper_torus|paper_hyperboloid] [six|bcc]
//! [eps_rel] [naive|nested]` (defaults:
//! torus, bcc, 0.01, nested). For the peak memory of the command line, write the input
//! with `contractible gen isosurface --preset large-torus --tessellation bcc -o IN.ply`
//! and run `contractible simplify` on it under `/usr/bin/time -v`.

use std::time::Instant;

use contractible::gen::{
    isosurface, large_hyperboloid, large_torus, paper_hyperboloid, paper_torus, Tessellation,
};
use contractible::simplify::{bbox_diagonal, simplify_with, Mode, Options};
use contractible::ConedSurfaces;

/// CPU time of this thread in seconds (Linux `/proc/thread-self/schedstat`), so that
/// the figure means something on a loaded machine too; 0 where unavailable.
fn cpu_seconds() -> f64 {
    std::fs::read_to_string("/proc/thread-self/schedstat")
        .ok()
        .and_then(|s| s.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(0.0, |ns| ns / 1e9)
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let arg = |i: usize, d: &str| args.get(i).cloned().unwrap_or_else(|| d.to_string());
    let tess = match arg(1, "bcc").as_str() {
        "six" => Tessellation::SixTetrahedra,
        _ => Tessellation::BodyCentred,
    };
    let params = match arg(0, "torus").as_str() {
        "hyperboloid" => large_hyperboloid(tess),
        // The paper's Table 1 sizes: small enough for `valgrind --tool=callgrind`.
        "paper_torus" => paper_torus(tess),
        "paper_hyperboloid" => paper_hyperboloid(tess),
        _ => large_torus(tess),
    };
    let rel: f64 = arg(2, "0.01").parse().unwrap_or(0.01);
    let mode = match arg(3, "nested").as_str() {
        "naive" => Mode::Naive,
        _ => Mode::Nested,
    };
    let t = Instant::now();
    let mesh = isosurface(&params).expect("a valid preset");
    let t_gen = t.elapsed().as_secs_f64();
    let positions = mesh.positions.as_deref().unwrap_or(&[]);
    let eps = rel * bbox_diagonal(positions.iter().copied());
    let t = Instant::now();
    let built = ConedSurfaces::from_mesh(&mesh).expect("a surface");
    let t_build = t.elapsed().as_secs_f64();
    drop(built);
    let opts = Options {
        mode,
        ..Options::new(eps)
    };
    let t = Instant::now();
    let cpu = cpu_seconds();
    let mut last = cpu_seconds();
    let verbose = std::env::var_os("PASSES").is_some();
    let out = simplify_with(&mesh, &opts, &mut |r| {
        if verbose {
            eprintln!(
                "pass {:>3}: {:>8} contracted, {:>8} faces, {:.4} s CPU",
                r.pass,
                r.contracted,
                r.faces,
                cpu_seconds() - last
            );
        }
        last = cpu_seconds();
    })
    .expect("simplified");
    let mut t_all = t.elapsed().as_secs_f64();
    let mut cpu_all = cpu_seconds() - cpu;
    // `REPEAT=n`: n - 1 more timed runs; the medians of all n are reported.
    let repeat: usize = std::env::var("REPEAT")
        .ok()
        .and_then(|x| x.parse().ok())
        .unwrap_or(1);
    if repeat > 1 {
        let (mut walls, mut cpus) = (vec![t_all], vec![cpu_all]);
        for _ in 1..repeat {
            let t = Instant::now();
            let cpu = cpu_seconds();
            let again = simplify_with(&mesh, &opts, &mut |_| {}).expect("simplified");
            cpus.push(cpu_seconds() - cpu);
            walls.push(t.elapsed().as_secs_f64());
            assert_eq!(again.mesh.faces, out.mesh.faces, "deterministic");
        }
        eprintln!("wall {walls:.3?}\ncpu  {cpus:.3?}");
        let median = |v: &mut Vec<f64>| {
            v.sort_by(f64::total_cmp);
            v[v.len() / 2]
        };
        t_all = median(&mut walls);
        cpu_all = median(&mut cpus);
    }
    let s = &out.stats;
    let f = mesh.faces.len() as f64;
    println!(
        "{} faces, {} vertices; gen {t_gen:.3} s; build alone {t_build:.3} s; simplify (build included) {t_all:.3} s wall = {:.2} M tri/s, {cpu_all:.3} s CPU = {:.2} M tri/s; passes {}; after {} V / {} F; contracted {}, discs {}, remaining {:?}",
        mesh.faces.len(),
        mesh.vertex_count,
        f / t_all / 1e6,
        f / cpu_all / 1e6,
        s.passes,
        s.vertices_out,
        s.faces_out,
        s.edges_contracted,
        s.discs_removed,
        s.remaining
    );
}
