//! The per-task library calls, checked from their outputs alone: the file-to-file
//! example (`examples/file_to_file.rs`, shown in the README) run on a mesh the
//! repository carries, each written file read back and checked independently; and the
//! README's copy of the example kept equal to the file.

use std::path::Path;

use contractible::diagnose::diagnose;
use contractible::io::{self, PolyMesh};
use contractible::task::component_types;
use contractible::{ConedSurfaces, Surfaces, TriMesh};

#[allow(dead_code)]
#[path = "../../examples/file_to_file.rs"]
mod file_to_file;

fn temp_dir(name: &str) -> std::path::PathBuf {
    let d = std::env::temp_dir().join(format!("contractible-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&d).expect("a temporary directory");
    d
}

/// The topological types of a closed mesh's components, sorted.
fn types(m: &TriMesh) -> Vec<(i64, bool, usize)> {
    component_types(&ConedSurfaces::from_mesh(m).expect("a surface"))
}

#[test]
fn the_file_to_file_example_writes_three_checked_results() {
    let input = crate::common::data_meshes().join("closed/bunny_npm.off.gz");
    let mesh = io::read_tri_mesh(&input).expect("the repository's bunny");
    let out = temp_dir("file-to-file");
    file_to_file::run(&input, &out).expect("the example runs");

    // The irreducible triangulation: closed, the input's topology, and no edge passes
    // the link condition by its definition.
    let irr = io::read_tri_mesh(&out.join("irreducible.off")).expect("written");
    assert_eq!(types(&irr), types(&mesh));
    let s = Surfaces::from_mesh(&irr).expect("closed surfaces");
    assert!(s.components.iter().all(|c| c.tri.is_irreducible_naive()));
    assert!(irr.faces.len() < mesh.faces.len());
    // Survivors keep their input coordinates.
    let input_points = mesh.positions.as_deref().expect("positions");
    for p in irr.positions.as_deref().expect("positions") {
        assert!(input_points.contains(p), "{p:?} is not an input vertex");
    }

    // The quads: one per two input triangles, a closed polygon surface of the input's
    // χ on the input's vertices and positions.
    let quads = io::read_poly_mesh(&out.join("quads.obj"), None).expect("written");
    let q: &PolyMesh = &quads.mesh;
    assert_eq!(q.face_count(), mesh.faces.len() / 2);
    assert!(q.faces().all(|f| f.len() == 4));
    let d = diagnose(q, 5);
    assert!(d.is_closed_surface(), "{d:?}");
    let chi: i64 = types(&mesh).iter().map(|t| t.0).sum();
    assert_eq!(d.euler_characteristic, chi);
    assert_eq!(q.positions.as_deref(), mesh.positions.as_deref());

    // The simplification: the input's components and topology, fewer faces, and no
    // edge shorter than ε = 2 % of the bounding-box diagonal left unless it is one the
    // method cannot contract (counted by the library; here only the topology and size).
    let simp = io::read_tri_mesh(&out.join("simplified.ply")).expect("written");
    assert_eq!(types(&simp), types(&mesh));
    assert!(simp.faces.len() < mesh.faces.len());
    std::fs::remove_dir_all(&out).ok();
}

/// The README shows the example as it is in `examples/file_to_file.rs`.
#[test]
fn the_readme_shows_the_example_file() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let example = std::fs::read_to_string(root.join("examples/file_to_file.rs")).expect("read");
    let readme = std::fs::read_to_string(root.join("README.md")).expect("read");
    assert!(
        readme.contains(example.trim_end()),
        "README.md must show examples/file_to_file.rs verbatim (in a ```rust block)"
    );
    assert!(example.lines().count() <= 25, "the example stays short");
}

/// Every generated closed surface in one mesh (16 components of both orientabilities),
/// every reduction and tri-quad algorithm run with the components in parallel on a pool
/// of 4 threads and one after another: the outputs are the same, timings aside; the
/// parallel runs do use several threads; and a cancellation during the parallel runs
/// still cancels the call.
#[test]
fn parallel_components_give_the_sequential_results() {
    use contractible::task::{Event, Monitor, Step};
    use contractible::{quadrangulate, reduce, Error, QuadOptions, ReduceOptions};
    use std::sync::atomic::{AtomicBool, Ordering};
    use std::sync::Arc;

    let all = crate::closed_inputs::closed_surfaces();
    let parts: Vec<&TriMesh> = all.iter().map(|g| &g.mesh).collect();
    let mesh = crate::closed_inputs::union(&parts);
    let components = crate::closed_inputs::COMPONENTS;
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(4)
        .build()
        .expect("a pool");
    for algorithm in contractible::irreducible::Algorithm::ALL {
        let run = |parallel| {
            let options = ReduceOptions {
                algorithm,
                seed: 5,
                count_retests: true,
                parallel,
                ..ReduceOptions::default()
            };
            let mut r = pool.install(|| reduce(&mesh, &options)).expect("closed");
            for c in &mut r.components {
                c.stats.seconds = 0.0;
            }
            r.totals.seconds = 0.0;
            r
        };
        let (one, par) = (run(false), run(true));
        assert_eq!(par.components.len(), components);
        assert_eq!(par.mesh, one.mesh, "{algorithm}");
        assert_eq!(par.vertex_map, one.vertex_map, "{algorithm}");
        assert_eq!(par.totals, one.totals, "{algorithm}");
        for (p, o) in par.components.iter().zip(&one.components) {
            assert_eq!(p.stats, o.stats, "{algorithm}");
            assert_eq!(p.reduction.history, o.reduction.history, "{algorithm}");
            assert_eq!(p.vertex_origin, o.vertex_origin, "{algorithm}");
        }
    }
    for algorithm in contractible::quad::Algorithm::ALL {
        let run = |parallel| {
            let options = QuadOptions {
                algorithm,
                seed: 5,
                parallel,
                ..QuadOptions::default()
            };
            let mut q = pool
                .install(|| quadrangulate(&mesh, &options))
                .expect("closed");
            for s in q
                .components
                .iter_mut()
                .map(|c| &mut c.stats)
                .chain([&mut q.totals])
            {
                (s.initial_seconds, s.completion_seconds, s.total_seconds) = (0.0, 0.0, 0.0);
            }
            q
        };
        let (one, par) = (run(false), run(true));
        assert_eq!(par.components.len(), components);
        assert_eq!(par.mesh, one.mesh, "{algorithm}");
        assert_eq!(par.triangles, one.triangles, "{algorithm}");
        assert_eq!(par.pairs, one.pairs, "{algorithm}");
        assert_eq!(par.totals, one.totals, "{algorithm}");
        let stats = |q: &contractible::QuadResult| -> Vec<_> {
            q.components.iter().map(|c| c.stats.clone()).collect()
        };
        assert_eq!(stats(&par), stats(&one), "{algorithm}");
    }
    // Simplification, both modes, on the closed components and on a mesh of two discs
    // with boundary beside them.
    let hyperboloid = contractible::gen::isosurface(&contractible::gen::IsoParams::new(
        contractible::gen::Implicit::TwoSheetHyperboloid {
            c: 0.25,
            half_width: 1.0,
            half_height: 1.0,
        },
        contractible::gen::Tessellation::SixTetrahedra,
        10,
    ))
    .expect("a hyperboloid");
    let bounded = crate::closed_inputs::union(&[&mesh, &hyperboloid]);
    for input in [&mesh, &bounded] {
        for mode in contractible::simplify::Mode::ALL {
            let run = |parallel| {
                let options = contractible::SimplifyOptions {
                    mode,
                    parallel,
                    ..contractible::SimplifyOptions::relative(0.05)
                };
                let mut s = pool
                    .install(|| contractible::simplify(input, &options))
                    .expect("surfaces with positions");
                s.stats.seconds = 0.0;
                (s.seconds_build, s.seconds_verify) = (0.0, None);
                s
            };
            let (one, par) = (run(false), run(true));
            assert!(par.stats.components >= components, "{mode:?}");
            assert!(par.stats.edges_contracted > 0, "{mode:?}");
            assert_eq!(par.mesh, one.mesh, "{mode:?}");
            assert_eq!(par.stats, one.stats, "{mode:?}");
            assert_eq!(
                (par.eps, par.bbox_diagonal, par.dropped_vertices),
                (one.eps, one.bbox_diagonal, one.dropped_vertices),
                "{mode:?}"
            );
        }
    }

    // The parallel run does use several threads of the pool; the sequential one, one.
    for (parallel, several) in [(false, false), (true, true)] {
        let threads = Arc::new(std::sync::Mutex::new(std::collections::BTreeSet::new()));
        let t = Arc::clone(&threads);
        let monitor = Monitor::new().observe(move |e| {
            if let Event::Step {
                step: Step::Run, ..
            } = e
            {
                let id = format!("{:?}", std::thread::current().id());
                t.lock().expect("not poisoned").insert(id);
            }
        });
        let options = ReduceOptions {
            parallel,
            monitor,
            ..ReduceOptions::default()
        };
        pool.install(|| reduce(&mesh, &options)).expect("closed");
        let used = threads.lock().expect("not poisoned").len();
        assert_eq!(used > 1, several, "{parallel}: {used} threads");
    }

    // Cancelled as soon as a component starts: each thread had at most one component
    // under way, every component started later fails, and the call returns the
    // cancellation (the sequential case is `task::reduce`'s own test).
    let flag = Arc::new(AtomicBool::new(false));
    let f = Arc::clone(&flag);
    let starts = move |e: &Event| {
        matches!(
            e,
            Event::Step {
                step: Step::Run,
                ..
            }
        )
    };
    let monitor = Monitor::new()
        .observe(move |e| {
            f.fetch_or(starts(e), Ordering::Relaxed);
        })
        .cancel_on(flag);
    let options = ReduceOptions {
        parallel: true,
        monitor,
        ..ReduceOptions::default()
    };
    let e = pool.install(|| reduce(&mesh, &options)).unwrap_err();
    assert!(matches!(e, Error::Cancelled), "{e}");
}
