//! The check of the fuzz target `c_abi`: the C interface (`contractible-c`) on arbitrary
//! meshes and raw option values. Every call gives what the Rust call gives (the same
//! refusal kind, the same output arrays bit for bit), an option value outside its
//! enumeration is `CTR_INVALID_ARGUMENT`, nothing is ever `CTR_INTERNAL` (a caught
//! panic), and the C checkers pass every output the tasks return.
//!
//! Not part of the harness library (`lib.rs`), which the main crate's tests include and
//! which depends on the library alone: the target includes this file with `#[path]`, and
//! so do the C interface's tests (`c/tests/fuzz_seeds.rs`), which replay its seeds. Both
//! have the harness library as `crate::harness`.

use arbitrary::Arbitrary;
use contractible::{Error, TriMesh};
use contractible_c::*;

use crate::harness::{task_mesh, TaskInput};

/// The input of `c_abi`: a mesh as `tasks` assembles it, how the C side holds it, and
/// raw option values (each decoded as the C interface documents, out-of-range values
/// included).
#[derive(Arbitrary, Clone, Debug)]
pub struct CAbiInput {
    /// The mesh (only its faces, vertex count and positions are used).
    pub mesh: TaskInput,
    /// The C mesh reads the arrays in place (`ctr_mesh_borrow`) instead of copying them.
    pub borrow: bool,
    /// `ctr_reduce_options.algorithm` (valid: 0–2).
    pub reduce_algorithm: u8,
    /// `ctr_quad_options.algorithm` (valid: 0–7).
    pub quad_algorithm: u8,
    /// The seed of both.
    pub seed: u8,
    /// `ctr_simplify_options`: mode (0–1), side (0–2), position (0–1).
    pub simplify: [u8; 3],
    /// ε: a relative fraction in 1/256 steps (0 is refused).
    pub eps: u8,
    /// `allow_foldover` of simplify and decimate.
    pub foldover: bool,
    /// `ctr_decimate_options`: placement (0–2), schedule (0–1).
    pub decimate: [u8; 2],
    /// The face target of decimate (0: none).
    pub faces: u8,
    /// `keep`, in 1/128 steps (0: none; above 128 is refused).
    pub keep: u8,
}

/// The error a failed C call reported: its code and kind.
fn reported(err: &ctr_error) -> (i32, String) {
    // SAFETY: the library writes a NUL-terminated kind into the array.
    let kind = unsafe { std::ffi::CStr::from_ptr(err.kind.as_ptr()) };
    (err.code, kind.to_string_lossy().into_owned())
}

/// A fresh error struct.
fn fresh() -> ctr_error {
    let mut err = std::mem::MaybeUninit::<ctr_error>::uninit();
    // SAFETY: `ctr_error_init` writes the whole struct.
    unsafe {
        ctr_error_init(err.as_mut_ptr());
        err.assume_init()
    }
}

/// Compares a C call's outcome with the Rust call's: NULL exactly when Rust refused, with
/// the same error kind (an input error), never an internal error.
fn same_outcome<T, U>(what: &str, c: *const T, err: &ctr_error, rust: &Result<U, Error>) {
    let (code, kind) = reported(err);
    assert_ne!(code, CTR_INTERNAL, "{what}: internal error {kind}");
    match rust {
        Ok(_) => assert!(!c.is_null() && code == CTR_OK, "{what}: C refused ({kind})"),
        Err(e) => {
            assert!(c.is_null(), "{what}: C accepted what Rust refused ({e})");
            assert_eq!(kind, e.kind(), "{what}: error kind");
        }
    }
}

/// The C mesh's arrays equal `m`'s, bit for bit.
///
/// # Safety
/// `c` is a live mesh.
unsafe fn same_mesh(what: &str, c: *const ctr_mesh, m: &TriMesh) {
    // SAFETY: a live mesh, by the caller's promise; the arrays have the counts stated.
    unsafe {
        let n = ctr_mesh_vertex_count(c);
        let k = ctr_mesh_face_count(c);
        assert_eq!((n, k), (m.vertex_count, m.faces.len()), "{what}: counts");
        let f = std::slice::from_raw_parts(ctr_mesh_faces(c), 3 * k);
        assert!(
            f.chunks_exact(3).eq(m.faces.iter().map(|x| &x[..])),
            "{what}: faces"
        );
        let p = ctr_mesh_positions(c);
        match &m.positions {
            None => assert!(p.is_null(), "{what}: positions"),
            Some(q) => {
                let got = std::slice::from_raw_parts(p, 3 * n);
                let want = q.iter().flatten();
                assert!(
                    got.iter()
                        .map(|x| x.to_bits())
                        .eq(want.map(|x| x.to_bits())),
                    "{what}: positions"
                );
            }
        }
    }
}

/// The verdict passed, and was freed.
///
/// # Safety
/// `v` is NULL or a live verdict, not used after.
unsafe fn passed(what: &str, v: *mut ctr_verdict, err: &ctr_error) {
    let (code, kind) = reported(err);
    assert!(
        !v.is_null(),
        "{what}: the checker refused ({kind}, code {code})"
    );
    // SAFETY: live, freed once.
    unsafe {
        assert!(
            ctr_verdict_passed(v),
            "{what}: the checker failed the output"
        );
        ctr_verdict_free(v);
    }
}

/// Runs every C call on the input's mesh and compares it with the Rust call.
pub fn check_c_abi(input: &CAbiInput) {
    let mut mesh = task_mesh(&input.mesh);
    // The C mesh has one position per vertex or none.
    if mesh
        .positions
        .as_ref()
        .is_some_and(|p| p.len() != mesh.vertex_count)
    {
        mesh.positions = None;
    }
    if mesh.vertex_count > contractible::core::MAX_VERTICES {
        return;
    }
    let flat_p: Option<Vec<f64>> = mesh.positions.as_ref().map(|p| p.concat());
    let flat_f: Vec<u32> = mesh.faces.concat();
    let make = if input.borrow {
        ctr_mesh_borrow
    } else {
        ctr_mesh_new
    };
    let mut err = fresh();
    // SAFETY: the arrays have the stated lengths and outlive the mesh, freed at the end;
    // every handle is freed once; accessors are read while their handle lives.
    unsafe {
        let m = make(
            flat_p.as_ref().map_or(std::ptr::null(), |p| p.as_ptr()),
            mesh.vertex_count,
            flat_f.as_ptr(),
            mesh.faces.len(),
            &mut err,
        );
        assert!(!m.is_null(), "mesh: {:?}", reported(&err));
        same_mesh("mesh", m, &mesh);

        // describe.
        let mut d = ctr_description_default();
        let code = ctr_describe(m, &mut d, &mut err);
        assert_ne!(code, CTR_INTERNAL, "describe: {:?}", reported(&err));
        // A face list that is no surface is described as its problems by the Rust call
        // and refused with the first one by the C call.
        match contractible::describe(&mesh) {
            Ok(contractible::Description::Surfaces { components, .. }) => {
                assert_eq!(code, CTR_OK, "describe: C refused {:?}", reported(&err));
                assert_eq!(
                    d.components as usize,
                    components.len(),
                    "describe: components"
                );
                assert_eq!(d.faces as usize, mesh.faces.len(), "describe: faces");
            }
            Ok(contractible::Description::Problems { first, .. }) => {
                let kind = Error::Mesh(first).kind().to_string();
                assert_eq!(reported(&err), (CTR_INPUT, kind), "describe: problems");
            }
            Err(e) => assert_eq!(reported(&err), (code, e.kind().to_string()), "describe"),
        }

        // reduce.
        let mut ro = ctr_reduce_options_default();
        ro.algorithm = u32::from(input.reduce_algorithm % 4);
        ro.seed = u64::from(input.seed);
        ro.keep_history = true;
        let r = ctr_reduce(m, &ro, &mut err);
        if ro.algorithm > 2 {
            assert!(
                r.is_null() && err.code == CTR_INVALID_ARGUMENT,
                "reduce: algorithm 3"
            );
        } else {
            let options = contractible::ReduceOptions {
                algorithm: contractible::irreducible::Algorithm::ALL[ro.algorithm as usize],
                seed: ro.seed,
                keep_history: true,
                ..Default::default()
            };
            let rust = contractible::reduce(&mesh, &options);
            same_outcome("reduce", r, &err, &rust);
            if let Ok(rr) = &rust {
                same_mesh("reduce", ctr_reduce_result_mesh(r), &rr.mesh);
                let vm = std::slice::from_raw_parts(
                    ctr_reduce_result_vertex_map(r),
                    rr.mesh.vertex_count,
                );
                assert_eq!(vm, &rr.vertex_map[..], "reduce: vertex map");
                let mut steps = 0;
                let h = ctr_reduce_result_contractions(r, &mut steps);
                let history = rr.contractions();
                assert_eq!(
                    std::slice::from_raw_parts(h, 2 * steps),
                    history.concat(),
                    "reduce: history"
                );
                // The checker on the answer in input ids, with its history.
                let faces: Vec<u32> = rr
                    .mesh
                    .faces
                    .iter()
                    .flatten()
                    .map(|&v| rr.vertex_map[v as usize])
                    .collect();
                let answer = ctr_mesh_new(
                    flat_p.as_ref().map_or(std::ptr::null(), |p| p.as_ptr()),
                    mesh.vertex_count,
                    faces.as_ptr(),
                    rr.mesh.faces.len(),
                    &mut err,
                );
                passed(
                    "check reduce",
                    ctr_check_reduce(m, answer, h, steps, &mut err),
                    &err,
                );
                ctr_mesh_free(answer);
            }
        }
        ctr_reduce_result_free(r);

        // quadrangulate.
        let mut qo = ctr_quad_options_default();
        qo.algorithm = u32::from(input.quad_algorithm % 9);
        qo.seed = u64::from(input.seed);
        let q = ctr_quadrangulate(m, &qo, &mut err);
        if qo.algorithm > 7 {
            assert!(
                q.is_null() && err.code == CTR_INVALID_ARGUMENT,
                "quad: algorithm 8"
            );
        } else {
            let algorithm = [
                contractible::quad::Algorithm::Lrs,
                contractible::quad::Algorithm::PulliSegal,
                contractible::quad::Algorithm::SimpleGreedy,
                contractible::quad::Algorithm::Matching,
                contractible::quad::Algorithm::DiksStanczyk,
                contractible::quad::Algorithm::BiedlBoseDemaineLubiw,
                contractible::quad::Algorithm::FrinkLct,
                contractible::quad::Algorithm::DsNaive,
            ][qo.algorithm as usize];
            let options = contractible::QuadOptions {
                algorithm,
                seed: qo.seed,
                ..Default::default()
            };
            let rust = contractible::quadrangulate(&mesh, &options);
            same_outcome("quad", q, &err, &rust);
            if let Ok(rq) = &rust {
                let (mut nq, mut nt, mut np) = (0, 0, 0);
                let quads = ctr_quad_result_quads(q, &mut nq);
                let tris = ctr_quad_result_triangles(q, &mut nt);
                let pairs = ctr_quad_result_pairs(q, &mut np);
                assert_eq!(
                    std::slice::from_raw_parts(quads, 4 * nq),
                    rq.mesh.faces.concat(),
                    "quad: quads"
                );
                assert_eq!(
                    std::slice::from_raw_parts(tris, 3 * nt),
                    rq.triangles.concat(),
                    "quad: K"
                );
                assert_eq!(
                    std::slice::from_raw_parts(pairs, 2 * np),
                    rq.pairs.concat(),
                    "quad: pairs"
                );
                passed(
                    "check quad",
                    ctr_check_quad(m, quads, nq, tris, nt, pairs, &mut err),
                    &err,
                );
            }
        }
        ctr_quad_result_free(q);

        // simplify.
        let mut so = ctr_simplify_options_default();
        so.mode = u32::from(input.simplify[0] % 3);
        so.side = u32::from(input.simplify[1] % 4);
        so.position = u32::from(input.simplify[2] % 3);
        so.eps = f64::from(input.eps) / 256.0;
        so.allow_foldover = input.foldover;
        let s = ctr_simplify(m, &so, &mut err);
        if so.mode > 1 || so.side > 2 || so.position > 1 {
            assert!(
                s.is_null() && err.code == CTR_INVALID_ARGUMENT,
                "simplify: option"
            );
        } else {
            let options = contractible::SimplifyOptions {
                eps: contractible::Eps::Relative(so.eps),
                mode: [
                    contractible::simplify::Mode::Nested,
                    contractible::simplify::Mode::Naive,
                ][so.mode as usize],
                side: contractible::simplify::Side::ALL[so.side as usize],
                position: [
                    contractible::simplify::Position::Midpoint,
                    contractible::simplify::Position::Quadric,
                ][so.position as usize],
                allow_foldover: so.allow_foldover,
                ..Default::default()
            };
            let rust = contractible::simplify(&mesh, &options);
            same_outcome("simplify", s, &err, &rust);
            if let Ok(rs) = &rust {
                let out = ctr_simplify_result_mesh(s);
                same_mesh("simplify", out, &rs.mesh);
                let mut stats = ctr_simplify_stats_default();
                assert_eq!(ctr_simplify_result_stats(s, &mut stats, &mut err), CTR_OK);
                assert_eq!(stats.eps.to_bits(), rs.eps.to_bits(), "simplify: ε");
                assert_eq!(stats.edges_contracted as usize, rs.stats.edges_contracted);
                passed(
                    "check simplify",
                    ctr_check_simplify(m, out, &so, &mut err),
                    &err,
                );
            }
        }
        ctr_simplify_result_free(s);

        // decimate.
        let mut dopt = ctr_decimate_options_default();
        dopt.placement = u32::from(input.decimate[0] % 4);
        dopt.schedule = u32::from(input.decimate[1] % 3);
        dopt.faces = u64::from(input.faces);
        dopt.keep = f64::from(input.keep) / 128.0;
        dopt.allow_foldover = input.foldover;
        let dd = ctr_decimate(m, &dopt, &mut err);
        if dopt.placement > 2 || dopt.schedule > 1 {
            assert!(
                dd.is_null() && err.code == CTR_INVALID_ARGUMENT,
                "decimate: option"
            );
        } else {
            use contractible::decimate::{Placement, Schedule};
            let options = contractible::DecimateOptions {
                faces: (dopt.faces > 0).then_some(dopt.faces as usize),
                keep: (dopt.keep != 0.0).then_some(dopt.keep),
                placement: [Placement::Optimal, Placement::Midpoint, Placement::Endpoint]
                    [dopt.placement as usize],
                schedule: [Schedule::Exact, Schedule::Passes][dopt.schedule as usize],
                allow_foldover: dopt.allow_foldover,
                ..Default::default()
            };
            let rust = contractible::decimate(&mesh, &options);
            same_outcome("decimate", dd, &err, &rust);
            if let Ok(rd) = &rust {
                let out = ctr_decimate_result_mesh(dd);
                same_mesh("decimate", out, &rd.mesh);
                let vm = ctr_decimate_result_vertex_map(dd);
                let cm = ctr_decimate_result_collapse_map(dd);
                let fo = ctr_decimate_result_face_origin(dd);
                assert_eq!(
                    std::slice::from_raw_parts(vm, rd.vertex_map.len()),
                    &rd.vertex_map[..]
                );
                assert_eq!(
                    std::slice::from_raw_parts(cm, mesh.vertex_count),
                    &rd.collapse_map[..]
                );
                assert_eq!(
                    std::slice::from_raw_parts(fo, rd.face_origin.len()),
                    &rd.face_origin[..]
                );
                let mut stats = ctr_decimate_stats_default();
                assert_eq!(ctr_decimate_result_stats(dd, &mut stats, &mut err), CTR_OK);
                assert_eq!(stats.faces_out as usize, rd.stats.faces_out);
                assert_eq!(stats.max_error.to_bits(), rd.stats.max_error.to_bits());
                passed(
                    "check decimate",
                    ctr_check_decimate(m, out, &dopt, vm, cm, fo, &mut err),
                    &err,
                );
            }
        }
        ctr_decimate_result_free(dd);
        ctr_mesh_free(m);
    }
}
