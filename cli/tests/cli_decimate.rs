//! `decimate` through the binary. Every output is read back and checked here without the
//! decimator: the topology of each output component against the input component it
//! descends from (χ, orientability and boundary loops from the test's own edge counting,
//! components by the test's own union–find), the `--maps` file against both meshes, the
//! locked and boundary vertices at their input positions in the written file, the
//! quadric error of every output vertex recomputed from the input's planes, the targets
//! against the face counts. Bad values: exit code 2, the message, nothing written.

use crate::cli_common;
use crate::cli_simplify::{topology, Topo};
use crate::common::{find, union};

use std::collections::{BTreeMap, BTreeSet};
use std::ffi::{OsStr, OsString};
use std::path::{Path, PathBuf};

use cli_common::{
    data_closed, gen_file, int, read_mesh, run, run_json, run_ok, stderr, untimed, with_holes,
    write_off_text, Scratch,
};
use contractible::TriMesh;
use serde_json::Value;

/// The three maps of a `--maps` file.
struct Maps {
    vertex_map: Vec<u32>,
    collapse_map: Vec<Option<u32>>,
    face_origin: Vec<u32>,
}

fn read_maps(path: &Path) -> (Value, Maps) {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let v: Value = serde_json::from_str(&text).expect("the maps file is JSON");
    let ids = |key: &str| -> Vec<Option<u32>> {
        v[key]
            .as_array()
            .unwrap_or_else(|| panic!("no array {key}"))
            .iter()
            .map(|x| x.as_u64().map(|n| u32::try_from(n).expect("a u32 id")))
            .collect()
    };
    let all = |key: &str| -> Vec<u32> {
        ids(key)
            .into_iter()
            .map(|x| x.unwrap_or_else(|| panic!("null in {key}")))
            .collect()
    };
    let maps = Maps {
        vertex_map: all("vertex_map"),
        collapse_map: ids("collapse_map"),
        face_origin: all("face_origin"),
    };
    (v, maps)
}

/// The value after `flag` in `args`, if given.
fn flag<'a>(args: &[&'a str], flag: &str) -> Option<&'a str> {
    args.windows(2).find(|w| w[0] == flag).map(|w| w[1])
}

/// Per face, its connected component (faces joined through shared edges), numbered by
/// smallest face; and the components' face lists.
fn face_components(faces: &[[u32; 3]]) -> (Vec<usize>, Vec<Vec<usize>>) {
    let mut parent: Vec<usize> = (0..faces.len()).collect();
    let mut first: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for (i, f) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            if let Some(&g) = first.get(&(a.min(b), a.max(b))) {
                union(&mut parent, i, g);
            } else {
                first.insert((a.min(b), a.max(b)), i);
            }
        }
    }
    let mut parts: Vec<Vec<usize>> = Vec::new();
    let mut index: BTreeMap<usize, usize> = BTreeMap::new();
    let label = (0..faces.len())
        .map(|i| {
            let r = find(&mut parent, i);
            let k = *index.entry(r).or_insert_with(|| {
                parts.push(Vec::new());
                parts.len() - 1
            });
            parts[k].push(i);
            k
        })
        .collect();
    (label, parts)
}

fn subset(faces: &[[u32; 3]], which: &[usize]) -> Vec<[u32; 3]> {
    which.iter().map(|&i| faces[i]).collect()
}

/// Vertices on an edge that lies in exactly one face.
fn boundary_vertices(faces: &[[u32; 3]]) -> BTreeSet<u32> {
    let mut count: BTreeMap<(u32, u32), usize> = BTreeMap::new();
    for f in faces {
        for k in 0..3 {
            let (a, b) = (f[k], f[(k + 1) % 3]);
            *count.entry((a.min(b), a.max(b))).or_default() += 1;
        }
    }
    count
        .into_iter()
        .filter(|&(_, n)| n == 1)
        .flat_map(|((a, b), _)| [a, b])
        .collect()
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

fn norm(a: [f64; 3]) -> f64 {
    dot(a, a).sqrt()
}

/// The diagonal of the bounding box of the vertices the faces use.
fn diagonal(m: &TriMesh) -> f64 {
    let p = m.positions.as_ref().expect("positions");
    let used: BTreeSet<u32> = m.faces.iter().flatten().copied().collect();
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for &v in &used {
        for k in 0..3 {
            lo[k] = lo[k].min(p[v as usize][k]);
            hi[k] = hi[k].max(p[v as usize][k]);
        }
    }
    norm(sub(hi, lo))
}

/// Per output vertex, sqrt(Q(x) / W), written from the definition of `decimate`'s
/// error: the root mean square distance of its written position from the planes of the
/// input faces at the input vertices merged into it (weighted by area) and of the
/// boundary planes at those vertices (through each boundary edge, perpendicular to its
/// face, weighted by 10 × the face's area).
fn quadric_errors(input: &TriMesh, output: &TriMesh, collapse_map: &[Option<u32>]) -> Vec<f64> {
    let p = input.positions.as_ref().expect("positions");
    let q = output.positions.as_ref().expect("positions");
    let mut sum = vec![0.0f64; output.vertex_count];
    let mut weight = vec![0.0f64; output.vertex_count];
    let mut add = |v: u32, normal: [f64; 3], point: [f64; 3], w: f64| {
        let o = collapse_map[v as usize].expect("a used vertex") as usize;
        let r = dot(normal, sub(q[o], point));
        sum[o] += w * r * r;
        weight[o] += w;
    };
    let mut units = Vec::with_capacity(input.faces.len());
    for f in &input.faces {
        let [a, b, c] = f.map(|v| p[v as usize]);
        let n = cross(sub(b, a), sub(c, a));
        let twice = norm(n);
        let unit = if twice > 0.0 {
            Some((n.map(|x| x / twice), 0.5 * twice))
        } else {
            None
        };
        units.push(unit);
        if let Some((u, w)) = unit {
            for &v in f {
                add(v, u, a, w);
            }
        }
    }
    let mut faces_of: BTreeMap<(u32, u32), Vec<usize>> = BTreeMap::new();
    for (i, f) in input.faces.iter().enumerate() {
        for k in 0..3 {
            faces_of
                .entry((f[k].min(f[(k + 1) % 3]), f[k].max(f[(k + 1) % 3])))
                .or_default()
                .push(i);
        }
    }
    for (&(a, b), fs) in &faces_of {
        let [f] = fs[..] else { continue };
        let Some((u, w)) = units[f] else { continue };
        let m = cross(sub(p[b as usize], p[a as usize]), u);
        let length = norm(m);
        if length == 0.0 {
            continue;
        }
        for x in [a, b] {
            add(x, m.map(|c| c / length), p[a as usize], 10.0 * w);
        }
    }
    sum.iter()
        .zip(&weight)
        .map(|(&s, &w)| if w > 0.0 { (s / w).sqrt() } else { 0.0 })
        .collect()
}

fn args_of(input: &Path, output: &Path, extra: &[&str]) -> Vec<OsString> {
    let mut all: Vec<OsString> = vec!["decimate".into(), input.into(), "-o".into(), output.into()];
    all.extend(extra.iter().map(OsString::from));
    all
}

/// Runs `decimate --json --maps` on a file read without `--weld` or `--triangulate`
/// (its numbering is the mesh's), then checks the written mesh, the maps and the report
/// against each other and against the input, independently of the decimator. Returns
/// the report.
fn decimate_checked(input: &Path, output: &Path, extra: &[&str]) -> Value {
    let maps_path = output.with_extension("maps.json");
    let mut all = args_of(input, output, extra);
    all.extend(["--maps".into(), maps_path.clone().into()]);
    let j = run_json(&all);
    let what = format!("{} {extra:?}", input.display());
    let before = read_mesh(input);
    let after = read_mesh(output);
    let (doc, m) = read_maps(&maps_path);
    assert_eq!(doc["index_base"], 0, "{what}");
    assert_eq!(doc["file"], input.display().to_string(), "{what}");
    assert_eq!(doc["output"], output.display().to_string(), "{what}");
    assert_eq!(j["maps"], maps_path.display().to_string(), "{what}");
    let (nv_in, nv_out) = (before.vertex_count, after.vertex_count);

    // The maps against both meshes.
    let used: BTreeSet<u32> = before.faces.iter().flatten().copied().collect();
    assert_eq!(m.vertex_map.len(), nv_out, "{what}");
    assert_eq!(m.collapse_map.len(), nv_in, "{what}");
    assert_eq!(m.face_origin.len(), after.faces.len(), "{what}");
    assert!(m.vertex_map.windows(2).all(|w| w[0] < w[1]), "{what}");
    assert!(m.face_origin.windows(2).all(|w| w[0] < w[1]), "{what}");
    for (o, &i) in m.vertex_map.iter().enumerate() {
        assert!(used.contains(&i), "{what}: vertex_map[{o}] = {i} is unused");
        assert_eq!(m.collapse_map[i as usize], Some(o as u32), "{what}");
    }
    for (i, c) in m.collapse_map.iter().enumerate() {
        match c {
            None => assert!(!used.contains(&(i as u32)), "{what}: {i} is used"),
            Some(o) => assert!((*o as usize) < nv_out, "{what}"),
        }
    }
    for (k, (&f, face)) in m.face_origin.iter().zip(&after.faces).enumerate() {
        let renamed = before.faces[f as usize].map(|v| m.collapse_map[v as usize].unwrap());
        assert_eq!(renamed, *face, "{what}: output face {k} vs input face {f}");
    }
    let used_after: BTreeSet<u32> = after.faces.iter().flatten().copied().collect();
    assert_eq!(used_after.len(), nv_out, "{what}: an unused output vertex");

    // The topology, component by component: each output component descends from one
    // input component, one to one, with the same (χ, orientable, boundary loops).
    let (label_in, parts_in) = face_components(&before.faces);
    let (_, parts_out) = face_components(&after.faces);
    assert_eq!(parts_out.len(), parts_in.len(), "{what}: components");
    let mut origins = BTreeSet::new();
    for part in &parts_out {
        let from: BTreeSet<usize> = part
            .iter()
            .map(|&k| label_in[m.face_origin[k] as usize])
            .collect();
        assert_eq!(from.len(), 1, "{what}: an output component of {from:?}");
        let from = *from.first().unwrap();
        origins.insert(from);
        let want: Vec<Topo> = topology(&subset(&before.faces, &parts_in[from]));
        assert_eq!(
            topology(&subset(&after.faces, part)),
            want,
            "{what}: component {from}"
        );
    }
    assert_eq!(origins.len(), parts_in.len(), "{what}");
    let topo_before = topology(&before.faces);

    // The report against the files.
    assert_eq!(j["file"], input.display().to_string());
    assert_eq!(j["output"], output.display().to_string());
    assert_eq!(int(&j, "vertices_in"), used.len() as i64, "{what}");
    assert_eq!(int(&j, "faces_in"), before.faces.len() as i64, "{what}");
    assert_eq!(int(&j, "vertices_out"), nv_out as i64, "{what}");
    assert_eq!(int(&j, "faces_out"), after.faces.len() as i64, "{what}");
    assert_eq!(int(&j, "collapses"), (used.len() - nv_out) as i64, "{what}");
    assert_eq!(int(&j, "components"), parts_in.len() as i64, "{what}");
    let loops: usize = topo_before.iter().map(|t| t.2).sum();
    assert_eq!(int(&j, "boundary_loops"), loops as i64, "{what}");
    assert_eq!(
        int(&j, "dropped_vertices"),
        (nv_in - used.len()) as i64,
        "{what}"
    );
    let per = j["component_list"].as_array().expect("component_list");
    assert_eq!(per.len(), parts_in.len(), "{what}");
    for (k, c) in per.iter().enumerate() {
        // Components in the order of their smallest input face, as the test numbers them.
        assert_eq!(int(c, "faces_in"), parts_in[k].len() as i64, "{what}: {k}");
    }
    let faces_out: i64 = per.iter().map(|c| int(c, "faces_out")).sum();
    assert_eq!(faces_out, after.faces.len() as i64, "{what}");
    let guards = ["lock", "boundary", "error", "link_condition", "foldover"];
    let total = |r: &Value| guards.iter().map(|g| int(r, g)).sum::<i64>();
    for g in guards {
        let sum: i64 = per.iter().map(|c| int(&c["remaining"], g)).sum();
        assert_eq!(int(&j["remaining"], g), sum, "{what}: remaining.{g}");
        assert!(j["refused"][g].is_u64(), "{what}: refused.{g}");
    }

    // The targets.
    let faces_in = before.faces.len();
    let by_keep = flag(extra, "--keep").map(|k| {
        let k: f64 = k.parse().unwrap();
        (k * faces_in as f64).ceil() as usize
    });
    let by_faces = flag(extra, "--faces").map(|n| n.parse::<usize>().unwrap());
    let target = match (by_faces, by_keep) {
        (Some(a), Some(b)) => Some(a.max(b)),
        (a, b) => a.or(b),
    };
    assert_eq!(
        j["target_faces"].as_u64().map(|t| t as usize),
        target,
        "{what}"
    );
    let diag = diagonal(&before);
    let got_diag = j["bbox_diagonal"].as_f64().unwrap();
    assert!((got_diag - diag).abs() <= 1e-12 * diag, "{what}");
    let cap = match (flag(extra, "--max-error"), flag(extra, "--max-error-rel")) {
        (Some(e), _) => Some(e.parse::<f64>().unwrap()),
        (None, Some(r)) => Some(r.parse::<f64>().unwrap() * diag),
        (None, None) => None,
    };
    match cap {
        Some(c) => {
            let got = j["max_error_cap"].as_f64().expect("a cap");
            assert!(
                (got - c).abs() <= 1e-12 * c.max(1e-300),
                "{what}: {got} vs {c}"
            );
        }
        None => assert!(j["max_error_cap"].is_null(), "{what}"),
    }
    match j["stopped"].as_str().unwrap() {
        "target" => {
            let t = target.expect("stopped at a target without one");
            assert!(after.faces.len() <= t, "{what}");
            assert_eq!(total(&j["remaining"]), 0, "{what}");
        }
        why @ ("error" | "blocked") => {
            if let Some(t) = target {
                assert!(after.faces.len() > t, "{what}: {why} below the target");
            }
            assert!(total(&j["remaining"]) > 0, "{what}");
            assert_eq!(
                int(&j["remaining"], "error") > 0,
                why == "error",
                "{what}: {why}"
            );
        }
        other => panic!("{what}: stopped {other:?}"),
    }

    // The error of every output vertex, recomputed from the input's planes: at most the
    // largest reported, which is at most the cap.
    let errors = quadric_errors(&before, &after, &m.collapse_map);
    let largest = errors.iter().copied().fold(0.0, f64::max);
    let reported = j["max_error"].as_f64().expect("max_error");
    // The decimator evaluates quadrics as matrices, whose cancellation leaves about
    // sqrt(ε_machine) × the coordinates in a distance: on flat parts it reports 0 where
    // the planes give 1e-8 of the diagonal.
    let tol = 1e-7 * diag;
    assert!(largest <= reported + tol, "{what}: {largest} > {reported}");
    if let Some(c) = cap {
        assert!(reported <= c + tol, "{what}: {reported} over the cap {c}");
    }

    // Locks and placements, on the written positions.
    let (pin, pout) = (
        before.positions.as_ref().unwrap(),
        after.positions.as_ref().unwrap(),
    );
    let stays = |i: u32, why: &str| {
        let o = m.collapse_map[i as usize].expect("a used vertex");
        assert_eq!(
            m.vertex_map[o as usize], i,
            "{what}: {why} {i} did not survive"
        );
        assert_eq!(pout[o as usize], pin[i as usize], "{what}: {why} {i} moved");
    };
    // Every --lock flag, each a comma-separated list.
    let locked: Vec<u32> = extra
        .windows(2)
        .filter(|w| w[0] == "--lock")
        .flat_map(|w| w[1].split(','))
        .map(|x| x.parse().unwrap())
        .collect();
    let mut sorted = locked.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(
        j["locked"],
        serde_json::to_value(&sorted).unwrap(),
        "{what}"
    );
    for &i in &locked {
        stays(i, "locked vertex");
    }
    assert_eq!(j["lock_boundary"], extra.contains(&"--lock-boundary"));
    if extra.contains(&"--lock-boundary") {
        for b in boundary_vertices(&before.faces) {
            stays(b, "boundary vertex");
        }
    }
    let placement = flag(extra, "--placement").unwrap_or("optimal");
    assert_eq!(j["placement"], placement, "{what}");
    let schedule = flag(extra, "--schedule").unwrap_or("exact");
    assert_eq!(j["schedule"], schedule, "{what}");
    assert_eq!(int(&j, "passes") > 0, schedule == "passes", "{what}");
    if placement == "endpoint" {
        // Every written position is an input position, and its own vertex's.
        let inputs: BTreeSet<[u64; 3]> = pin.iter().map(|p| p.map(f64::to_bits)).collect();
        for (o, q) in pout.iter().enumerate() {
            assert!(inputs.contains(&q.map(f64::to_bits)), "{what}: {o} moved");
            assert_eq!(*q, pin[m.vertex_map[o] as usize], "{what}");
        }
    }
    let guard = !extra.contains(&"--allow-foldover");
    assert_eq!(j["guard"], guard, "{what}");
    if !guard {
        assert_eq!(int(&j["refused"], "foldover"), 0, "{what}");
        assert_eq!(int(&j["remaining"], "foldover"), 0, "{what}");
    }
    let verify = !extra.contains(&"--no-verify");
    assert_eq!(j["verified"], verify, "{what}");
    assert_eq!(j.get("seconds_verify").is_some(), verify, "{what}");
    for k in ["seconds", "seconds_read", "seconds_build", "seconds_write"] {
        assert!(j[k].as_f64().is_some_and(|x| x >= 0.0), "{what}: {k}");
    }
    assert!(j["seconds_write_maps"].as_f64().is_some(), "{what}");
    j
}

fn gen_iso(dir: &Scratch, file: &str, args: &[&str]) -> PathBuf {
    let mut all = vec!["isosurface"];
    all.extend_from_slice(args);
    gen_file(dir, file, &all)
}

#[test]
fn closed_real_meshes_reach_their_targets_keeping_each_component_s_topology() {
    let d = Scratch::new("decimate-closed");
    for (name, extra) in [
        ("bunny_npm", &["--keep", "0.2"][..]),
        (
            "high_genus_3",
            &["--faces", "500", "--placement", "midpoint"],
        ),
        ("box_stl", &["--faces", "3000", "--placement", "endpoint"]),
        ("plate_holes_stl", &["--keep", "0.3", "--allow-foldover"]),
        ("bunny_npm", &["--keep", "0.05", "--schedule", "passes"]),
        (
            "box_stl",
            &[
                "--faces",
                "3000",
                "--schedule",
                "passes",
                "--placement",
                "midpoint",
            ],
        ),
    ] {
        let j = decimate_checked(&data_closed(name), &d.path(&format!("{name}.ply")), extra);
        assert_eq!(j["stopped"], "target", "{name}");
        assert!(int(&j, "collapses") > 0, "{name}");
    }
}

#[test]
fn surfaces_with_boundary_and_several_components() {
    let d = Scratch::new("decimate-boundary");
    // Two discs (two components, each with one boundary loop).
    let hyp = gen_iso(
        &d,
        "hyp.off",
        &["--surface", "hyperboloid", "--resolution", "24"],
    );
    let j = decimate_checked(&hyp, &d.path("hyp-out.off"), &["--keep", "0.3"]);
    assert_eq!(int(&j, "components"), 2);
    assert_eq!(int(&j, "boundary_loops"), 2);
    assert_eq!(j["component_list"].as_array().unwrap().len(), 2);
    let j = decimate_checked(
        &hyp,
        &d.path("hyp-locked.obj"),
        &["--keep", "0.3", "--lock-boundary"],
    );
    assert_eq!(int(&j, "components"), 2);
    // The bunny with two holes: genus 0, two boundary loops; its boundary locked and a
    // few vertices besides.
    let open = d.path("open_bunny.off");
    write_off_text(&open, &with_holes(&read_mesh(&data_closed("bunny_npm")), 2));
    let j = decimate_checked(
        &open,
        &d.path("open-out.off"),
        &[
            "--keep",
            "0.1",
            "--lock-boundary",
            "--lock",
            "5,900,17",
            "--max-error",
            "0.2",
        ],
    );
    assert_eq!(int(&j, "boundary_loops"), 2);
    // Two closed components, the smaller one a tetrahedron that cannot lose a face.
    let j = decimate_checked(
        &data_closed("two_objects"),
        &d.path("two.off"),
        &["--faces", "4"],
    );
    assert_eq!(j["stopped"], "blocked");
    let per = j["component_list"].as_array().unwrap();
    assert_eq!(int(&per[1], "faces_in"), 4);
    assert_eq!(int(&per[1], "faces_out"), 4);
    assert!(int(&per[1]["remaining"], "link_condition") > 0);
}

#[test]
fn the_error_cap_holds_and_absolute_and_relative_caps_agree() {
    let d = Scratch::new("decimate-cap");
    let input = data_closed("high_genus_3");
    let a = d.path("rel.off");
    let j = decimate_checked(&input, &a, &["--max-error-rel", "0.005"]);
    assert_eq!(j["stopped"], "error");
    assert!(j["target_faces"].is_null());
    assert_eq!(j["targets"]["max_error_rel"].as_f64(), Some(0.005));
    assert!(j["targets"]["max_error"].is_null());
    // The same cap given as a distance: the same file.
    let cap = j["max_error_cap"].to_string();
    let b = d.path("abs.off");
    let k = decimate_checked(&input, &b, &["--max-error", &cap]);
    assert_eq!(k["max_error_cap"], j["max_error_cap"]);
    assert!(k["targets"]["max_error_rel"].is_null());
    assert!(std::fs::read(&a).unwrap() == std::fs::read(&b).unwrap());
    // A target and a cap: the first reached stops the run.
    let loose = decimate_checked(
        &input,
        &d.path("loose.off"),
        &["--faces", "2000", "--max-error-rel", "0.05"],
    );
    assert_eq!(loose["stopped"], "target");
    let tight = decimate_checked(
        &input,
        &d.path("tight.off"),
        &["--faces", "100", "--max-error-rel", "0.001"],
    );
    assert_eq!(tight["stopped"], "error");
    // A zero cap allows only collapses without error.
    decimate_checked(&input, &d.path("zero.off"), &["--max-error", "0"]);
}

#[test]
fn targets_combine_and_no_target_goes_as_far_as_the_guards_allow() {
    let d = Scratch::new("decimate-targets");
    let input = data_closed("bunny_npm");
    let j = decimate_checked(
        &input,
        &d.path("both.off"),
        &["--faces", "500", "--keep", "0.5"],
    );
    assert_eq!(int(&j, "target_faces"), 1837);
    assert_eq!(
        j["targets"],
        serde_json::json!({"faces": 500, "keep": 0.5, "max_error": null, "max_error_rel": null})
    );
    for keep in ["0", "1"] {
        let j = decimate_checked(&input, &d.path("k.off"), &["--keep", keep]);
        if keep == "1" {
            assert_eq!(int(&j, "collapses"), 0);
            assert_eq!(j["stopped"], "target");
        } else {
            assert_eq!(j["stopped"], "blocked");
        }
    }
    // No target: as coarse as the guards allow, and then no edge left passes them.
    let j = decimate_checked(&input, &d.path("none.off"), &[]);
    assert!(j["target_faces"].is_null() && j["max_error_cap"].is_null());
    assert_eq!(j["stopped"], "blocked");
    assert_eq!(int(&j["remaining"], "error"), 0);
    assert!(int(&j, "faces_out") < 100, "{}", j["faces_out"]);
}

#[test]
fn locked_vertices_keep_their_input_positions_in_every_format() {
    let d = Scratch::new("decimate-lock");
    let bunny = read_mesh(&data_closed("bunny_npm"));
    let p = bunny.positions.clone().unwrap();
    let locked = [0u32, 7, 100, 1838];
    // OBJ counts vertices from 1 in its text; --lock counts from 0 in every format.
    let obj = d.path("bunny.obj");
    contractible::io::write_mesh(&obj, &bunny).unwrap();
    let first_v = std::fs::read_to_string(&obj)
        .unwrap()
        .lines()
        .find(|l| l.starts_with("v "))
        .map(str::to_string)
        .unwrap();
    let xyz: Vec<f64> = first_v[2..]
        .split_whitespace()
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(xyz, p[0], "the first `v` line is vertex 0");
    for input in [data_closed("bunny_npm"), obj] {
        let ext = if input.to_string_lossy().ends_with(".obj") {
            "obj"
        } else {
            "off"
        };
        let out = d.path(&format!("locked.{ext}"));
        decimate_checked(&input, &out, &["--keep", "0.05", "--lock", "0,7,100,1838"]);
        // Independently of the maps: every locked position is in the written file.
        let written = read_mesh(&out);
        let have: BTreeSet<[u64; 3]> = written
            .positions
            .unwrap()
            .iter()
            .map(|q| q.map(f64::to_bits))
            .collect();
        for v in locked {
            assert!(
                have.contains(&p[v as usize].map(f64::to_bits)),
                "{ext}: {v}"
            );
        }
    }
    // Repeated flags add up; repeats are one lock.
    let j = decimate_checked(
        &data_closed("bunny_npm"),
        &d.path("twice.off"),
        &["--keep", "0.05", "--lock", "7", "--lock", "7,3"],
    );
    assert_eq!(j["locked"], serde_json::json!([3, 7]));
    // A locked vertex blocks its edges: locking everything leaves nothing to collapse.
    let all: Vec<String> = (0..bunny.vertex_count).map(|v| v.to_string()).collect();
    let j = run_json(&args_of(
        &data_closed("bunny_npm"),
        &d.path("all.off"),
        &["--keep", "0.5", "--lock", &all.join(",")],
    ));
    assert_eq!(int(&j, "collapses"), 0);
    assert_eq!(j["stopped"], "blocked");
    assert_eq!(
        int(&j["remaining"], "lock"),
        int(&j, "faces_in") * 3 / 2,
        "every edge refused by the lock"
    );
}

#[test]
fn endpoint_placement_writes_only_input_positions() {
    let d = Scratch::new("decimate-endpoint");
    let torus = gen_iso(&d, "t.ply", &["--surface", "torus", "--resolution", "24"]);
    for extra in [
        &["--placement", "endpoint", "--keep", "0.1"][..],
        &["--placement", "endpoint", "--allow-foldover"],
        &["--placement", "midpoint", "--keep", "0.1"],
        &["--placement", "optimal", "--keep", "0.1", "--no-verify"],
    ] {
        decimate_checked(&torus, &d.path("out.ply"), extra);
    }
}

#[test]
fn weld_and_triangulate_maps_count_in_the_file_s_numbering() {
    let d = Scratch::new("decimate-input-options");
    // A soup: every face with its own three vertices (the first copy of each position
    // is the one --weld keeps).
    let tet = gen_iso(
        &d,
        "sphere.off",
        &["--surface", "sphere", "--resolution", "8"],
    );
    let mesh = read_mesh(&tet);
    let p = mesh.positions.as_ref().unwrap();
    let mut positions = Vec::new();
    let mut faces = Vec::new();
    for f in &mesh.faces {
        let base = positions.len() as u32;
        positions.extend(f.map(|v| p[v as usize]));
        faces.push([base, base + 1, base + 2]);
    }
    let soup = TriMesh::with_positions(positions.clone(), faces.clone());
    let soup_file = d.path("soup.off");
    write_off_text(&soup_file, &soup);
    let out = d.path("soup-out.off");
    let maps = d.path("soup.json");
    let j = run_json(&args_of(
        &soup_file,
        &out,
        &[
            "--weld",
            "--keep",
            "0.5",
            "--maps",
            maps.to_str().unwrap(),
            "--lock",
            "5",
        ],
    ));
    assert_eq!(j["welded_vertices"], positions.len() - mesh.vertex_count);
    let after = read_mesh(&out);
    let (_, m) = read_maps(&maps);
    assert_eq!(
        m.collapse_map.len(),
        positions.len(),
        "one entry per file vertex"
    );
    for (k, (&f, face)) in m.face_origin.iter().zip(&after.faces).enumerate() {
        let renamed = faces[f as usize].map(|v| m.collapse_map[v as usize].unwrap());
        assert_eq!(renamed, *face, "output face {k}");
    }
    let q = after.positions.as_ref().unwrap();
    for (o, &v) in m.vertex_map.iter().enumerate() {
        // The surviving file vertex is the first of its position: every earlier file
        // vertex is elsewhere.
        assert!(positions[..v as usize]
            .iter()
            .all(|x| *x != positions[v as usize]));
        assert_eq!(m.collapse_map[v as usize], Some(o as u32));
    }
    // File vertex 5 locked: its welded group survives at its position.
    let o = m.collapse_map[5].unwrap() as usize;
    assert_eq!(q[o], positions[5]);
    // Quads cut by --triangulate: face_origin names the file's quads.
    let quads = d.path("quads.obj");
    run_ok(&[
        OsStr::new("-q"),
        OsStr::new("quad"),
        data_closed("round_stl").as_os_str(),
        OsStr::new("-o"),
        quads.as_os_str(),
    ]);
    let text = std::fs::read_to_string(&quads).unwrap();
    let polygons: Vec<Vec<u32>> = text
        .lines()
        .filter_map(|l| l.strip_prefix("f "))
        .map(|l| {
            l.split_whitespace()
                .map(|x| x.parse::<u32>().unwrap() - 1)
                .collect()
        })
        .collect();
    let out = d.path("from-quads.off");
    let maps = d.path("quads.json");
    run_ok(&args_of(
        &quads,
        &out,
        &[
            "--triangulate",
            "--keep",
            "0.3",
            "--maps",
            maps.to_str().unwrap(),
            "-q",
        ],
    ));
    let after = read_mesh(&out);
    let (_, m) = read_maps(&maps);
    assert!(m.face_origin.windows(2).all(|w| w[0] <= w[1]));
    for (k, (&f, face)) in m.face_origin.iter().zip(&after.faces).enumerate() {
        let corners: BTreeSet<u32> = polygons[f as usize]
            .iter()
            .map(|&v| m.collapse_map[v as usize].unwrap())
            .collect();
        assert!(
            face.iter().all(|v| corners.contains(v)),
            "output face {k} {face:?} is not on quad {f}"
        );
    }
    assert_eq!(
        topology(&after.faces),
        topology(&read_mesh(&data_closed("round_stl")).faces)
    );
}

#[test]
fn format_options_and_stdout() {
    let d = Scratch::new("decimate-formats");
    // A name that does not tell the format: --format does.
    let odd = d.path("mesh.dat");
    write_off_text(&odd, &read_mesh(&data_closed("high_genus_3")));
    let out = d.path("o.ply");
    run_ok(&args_of(
        &odd,
        &out,
        &["--format", "off", "--keep", "0.2", "-q"],
    ));
    let o = run_ok(&args_of(&odd, &out, &["--format", "obj", "--keep", "0.2"]));
    assert!(
        stderr(&o).contains("the content is OFF, not OBJ as --format says"),
        "{}",
        stderr(&o)
    );
    assert_eq!(
        topology(&read_mesh(&out).faces),
        topology(&read_mesh(&odd).faces)
    );
    // The mesh to stdout, the report to stderr.
    let o = run_ok(&args_of(
        &data_closed("high_genus_3"),
        Path::new("-"),
        &["--output-format", "off", "--keep", "0.2"],
    ));
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.starts_with("OFF\n"), "{text}");
    let err = stderr(&o);
    assert!(err.contains("stopped: target reached"), "{err}");
    let from_stdout = d.path("stdout.off");
    std::fs::write(&from_stdout, &o.stdout).unwrap();
    let file = d.path("file.off");
    run_ok(&args_of(
        &data_closed("high_genus_3"),
        &file,
        &["--keep", "0.2", "-q"],
    ));
    assert!(std::fs::read(&file).unwrap() == o.stdout);
    // The maps to stdout, the report to stderr.
    let o = run_ok(&args_of(
        &data_closed("high_genus_3"),
        &file,
        &["--keep", "0.2", "--maps", "-"],
    ));
    let v: Value = serde_json::from_slice(&o.stdout).expect("the maps on stdout");
    assert_eq!(
        v["face_origin"].as_array().unwrap().len(),
        read_mesh(&file).faces.len()
    );
    assert!(stderr(&o).contains("wrote -"), "{}", stderr(&o));
}

#[test]
fn human_report_of_a_target_and_of_a_blocked_run() {
    let d = Scratch::new("decimate-human");
    let input = data_closed("high_genus_3");
    let out = d.path("o.off");
    let o = run_ok(&args_of(&input, &out, &["--keep", "0.25"]));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let after = read_mesh(&out);
    for want in [
        format!(
            "{} -> {}: optimal placement, fold-over guard on",
            input.display(),
            out.display()
        ),
        format!(
            "  faces 3328 -> {}, vertices 1660 -> {}; 1 component, 0 boundary loops (kept, \
             checked independently)",
            after.faces.len(),
            after.vertex_count
        ),
        "  target: 832 faces (--keep 0.25)".into(),
        "  stopped: target reached".into(),
        format!("  collapses {}; largest error ", 1660 - after.vertex_count),
        "  time: read ".into(),
        ", check input ".into(),
        ", decimate ".into(),
        ", verify ".into(),
        ", write ".into(),
        format!("wrote {}", out.display()),
    ] {
        assert!(text.contains(&want), "missing {want:?} in:\n{text}");
    }
    assert!(!text.contains("edges left"), "{text}");
    // A genus-3 surface cannot go down to 10 faces (an irreducible triangulation of
    // genus 3 has more): blocked, with the edges left by guard, as the JSON says.
    let o = run_ok(&args_of(&input, &out, &["--faces", "10"]));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    let j = run_json(&args_of(&input, &d.path("j.off"), &["--faces", "10"]));
    let r = &j["remaining"];
    for want in [
        "  target: 10 faces (--faces 10)".to_string(),
        "  stopped: blocked, every edge left is refused by a guard (10 faces not reached)".into(),
        format!(
            "  edges left {}, refused by: link condition {}, fold-over {}, lock 0, boundary 0, \
             error cap 0",
            int(r, "link_condition") + int(r, "foldover"),
            int(r, "link_condition"),
            int(r, "foldover")
        ),
    ] {
        assert!(text.contains(&want), "missing {want:?} in:\n{text}");
    }
    assert!(int(r, "link_condition") > 0);
    let left = read_mesh(&out);
    assert!(left.faces.len() > 10);
    assert_eq!(topology(&left.faces), topology(&read_mesh(&input).faces));
    // Several components: one line each; the error cap named.
    let o = run_ok(&args_of(
        &data_closed("box_stl"),
        &out,
        &["--max-error-rel", "0.001"],
    ));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    assert!(text.contains("10 components"), "{text}");
    assert!(
        text.contains("(0.001 × the bounding-box diagonal "),
        "{text}"
    );
    assert!(
        text.contains("  stopped: error cap, every edge left would exceed it or is refused"),
        "{text}"
    );
    for k in 0..10 {
        assert!(
            text.contains(&format!("    component {k}: faces ")),
            "{text}"
        );
    }
    // No target; --no-verify; locks named.
    let o = run_ok(&args_of(
        &input,
        &out,
        &["--no-verify", "--lock", "1,2", "--lock-boundary"],
    ));
    let text = String::from_utf8_lossy(&o.stdout).into_owned();
    for want in [
        ": optimal placement, fold-over guard on, boundary locked, 2 vertices locked",
        "(not checked: --no-verify)",
        "  target: none, as far as the guards allow",
        "  stopped: blocked, every edge left is refused by a guard\n",
    ] {
        assert!(text.contains(want), "missing {want:?} in:\n{text}");
    }
    assert!(!text.contains("verify "), "{text}");
    // Quiet: nothing at all.
    let o = run_ok(&args_of(&input, &out, &["--keep", "0.5", "-q"]));
    assert!(o.stdout.is_empty() && o.stderr.is_empty());
}

/// Files in `dir` (names), to see that a failed run left nothing behind.
fn listing(dir: &Scratch) -> BTreeSet<String> {
    std::fs::read_dir(&dir.0)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect()
}

/// Runs `decimate` expecting exit code 2 with `want` in its message, no stdout (or,
/// with `--json`, the error object) and no new file.
fn refused(dir: &Scratch, input: &Path, extra: &[&str], want: &str) {
    let before = listing(dir);
    let out_path = dir.path("out.off");
    for json in [false, true] {
        let mut all = args_of(input, &out_path, extra);
        if json {
            all.insert(0, "--json".into());
        }
        let out = run(&all);
        let err = stderr(&out);
        assert_eq!(out.status.code(), Some(2), "{extra:?}: {err}");
        if json {
            let v: Value = serde_json::from_slice(&out.stdout).expect("one JSON value");
            assert_eq!(v["error"]["exit_code"], 2, "{v}");
            let m = v["error"]["message"].as_str().expect("a message");
            let want = want.strip_prefix("error: ").unwrap_or(want);
            assert!(m.contains(want), "{extra:?}: {want:?} not in {m}");
        } else {
            assert!(out.stdout.is_empty(), "{extra:?}: stdout on error");
        }
        assert!(err.starts_with("error: "), "{err}");
        assert!(err.contains(want), "{extra:?}: {want:?} not in {err}");
        assert!(!out_path.exists(), "{extra:?}: wrote an output");
        assert_eq!(listing(dir), before, "{extra:?}: left a file behind");
    }
}

#[test]
fn bad_values_are_refused_before_anything_is_written() {
    let d = Scratch::new("decimate-bad");
    let input = gen_iso(&d, "s.off", &["--surface", "sphere", "--resolution", "8"]);
    let n = read_mesh(&input).vertex_count;
    let fraction = "the fraction of the faces kept must be a number in [0, 1]";
    let cap = "the error cap must be a finite number >= 0";
    let rel = "the fraction of the bounding-box diagonal must be a finite number >= 0";
    for (args, want) in [
        (
            &["--keep", "1.5"][..],
            format!("error: --keep 1.5: {fraction}"),
        ),
        (
            &["--keep", "-0.1"],
            format!("error: --keep -0.1: {fraction}"),
        ),
        (&["--keep", "nan"], format!("error: --keep NaN: {fraction}")),
        (
            &["--max-error", "-1"],
            format!("error: --max-error -1.0: {cap}"),
        ),
        (
            &["--max-error", "inf"],
            format!("error: --max-error inf: {cap}"),
        ),
        (
            &["--max-error-rel", "-0.5"],
            format!("error: --max-error-rel -0.5: {rel}"),
        ),
        (
            &["--max-error-rel", "NaN"],
            format!("error: --max-error-rel NaN: {rel}"),
        ),
        (
            &["--max-error-rel", "1e308"],
            "error: --max-error-rel 1e308 times the diagonal".into(),
        ),
        (
            &["--lock", &n.to_string()],
            format!(
                "error: --lock {n}: {} has {n} vertices, counted from 0 in every format (the \
                 last is {})",
                input.display(),
                n - 1
            ),
        ),
        (
            &["--lock", "x"],
            "invalid value 'x' for '--lock <V>'".into(),
        ),
        (&["--lock", "-1"], "unexpected argument '-1' found".into()),
        (&["--faces", "-3"], "unexpected argument '-3' found".into()),
        (
            &["--placement", "nope"],
            "invalid value 'nope' for '--placement".into(),
        ),
        (
            &["--schedule", "fast"],
            "invalid value 'fast' for '--schedule".into(),
        ),
        (
            &["--max-error", "1", "--max-error-rel", "0.1"],
            "cannot be used with".into(),
        ),
        (&["--jobs", "0"], "--jobs must be at least 1".into()),
        (
            &["--maps", "no/such/dir/m.json"],
            "no/such/dir/m.json: the directory no/such/dir does not exist".into(),
        ),
    ] {
        refused(&d, &input, args, &want);
    }
    // Both to stdout.
    let o = run(&[
        OsStr::new("decimate"),
        input.as_os_str(),
        OsStr::new("-o"),
        OsStr::new("-"),
        OsStr::new("--output-format"),
        OsStr::new("off"),
        OsStr::new("--maps"),
        OsStr::new("-"),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("would both write to stdout"));
    // No coordinates (as `gen random` writes): refused as simplify refuses it.
    let random = d.path("random.off");
    run_ok(&[
        "gen",
        "random",
        "--genus",
        "1",
        "--faces",
        "200",
        "-o",
        random.to_str().unwrap(),
    ]);
    let n = read_mesh(&random).vertex_count;
    refused(
        &d,
        &random,
        &["--keep", "0.5"],
        &format!(
            "{}: all {n} vertices are at the same point (0, 0, 0): the file carries no \
             coordinates (as `gen random` writes its surfaces); `decimate` needs vertex \
             positions",
            random.display()
        ),
    );
    // Not a surface: located.
    let bowtie = d.path("bowtie.off");
    std::fs::write(
        &bowtie,
        "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n",
    )
    .unwrap();
    refused(
        &d,
        &bowtie,
        &["--keep", "0.5"],
        "bowtie.off: vertex 0 is pinched: 4 boundary edges meet there",
    );
}

#[test]
fn batch_runs_decimate_on_every_file() {
    let d = Scratch::new("decimate-batch");
    let outdir = d.path("out");
    let names = ["high_genus_3", "two_objects", "round_stl"];
    let files = names.map(data_closed);
    let mut args: Vec<&OsStr> = vec![OsStr::new("batch")];
    args.extend(files.iter().map(|f| f.as_os_str()));
    args.extend(
        ["--task", "decimate", "-j", "2", "-o"]
            .iter()
            .map(OsStr::new),
    );
    args.push(outdir.as_os_str());
    args.extend(["--", "--keep", "0.25"].iter().map(OsStr::new));
    let out = run(&args);
    assert!(out.status.success(), "{}", stderr(&out));
    let lines: Vec<Value> = String::from_utf8_lossy(&out.stdout)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), names.len());
    // Files sorted: high_genus_3, round_stl, two_objects.
    let mut sorted = names;
    sorted.sort_unstable();
    for (name, l) in sorted.iter().zip(&lines) {
        assert_eq!(l["ok"], true, "{l}");
        assert_eq!(l["task"], "decimate");
        let written = outdir.join(format!("{name}.decimate.off.gz"));
        assert_eq!(l["result"]["output"], written.display().to_string());
        // The same as the command alone.
        let alone = d.path(&format!("{name}.off.gz"));
        let j = run_json(&args_of(&data_closed(name), &alone, &["--keep", "0.25"]));
        let mut a = untimed(&l["result"]);
        let mut b = untimed(&j);
        a["output"] = Value::Null;
        b["output"] = Value::Null;
        assert_eq!(a, b, "{name}");
        assert!(
            read_mesh(&written).faces == read_mesh(&alone).faces,
            "{name}"
        );
        let topo = topology(&read_mesh(&written).faces);
        assert_eq!(topo, topology(&read_mesh(&data_closed(name)).faces));
    }
    // Without -o (the command needs an output) and with --maps: refused before any work.
    for extra in [
        &["--task", "decimate", "--", "--keep", "0.5"][..],
        &["--task", "decimate", "-o", "x", "--", "--maps", "m.json"],
        &["--task", "decimate", "-o", "x", "--", "--keep", "2"],
    ] {
        let mut args: Vec<&OsStr> = vec![OsStr::new("batch"), files[0].as_os_str()];
        args.extend(extra.iter().map(OsStr::new));
        let o = std::process::Command::new(env!("CARGO_BIN_EXE_contractible"))
            .args(&args)
            .current_dir(&d.0)
            .output()
            .unwrap();
        let code = o.status.code();
        // A bad value (--keep 2) is the task's own error for the file (exit 1, its
        // line says why); the others fail up front (exit 2).
        if extra.contains(&"2") {
            assert_eq!(code, Some(1), "{extra:?}");
            let l: Value = serde_json::from_slice(&o.stdout).unwrap();
            assert_eq!(l["error"]["exit_code"], 2, "{l}");
            assert!(l["error"]["message"]
                .as_str()
                .unwrap()
                .contains("--keep 2.0: the fraction"));
        } else {
            assert_eq!(code, Some(2), "{extra:?}: {}", stderr(&o));
            assert!(o.stdout.is_empty());
        }
    }
}

#[test]
fn the_output_is_the_same_for_every_number_of_jobs() {
    let d = Scratch::new("decimate-jobs");
    // Over 262,144 faces, so that the input's and the output's checks run on the pool.
    let big = gen_iso(
        &d,
        "big.off.gz",
        &["--surface", "torus", "--resolution", "150"],
    );
    let faces = read_mesh(&big).faces.len();
    assert!(faces >= 1 << 18, "{faces} faces");
    let mut first: Option<(Vec<u8>, Vec<u8>, Value)> = None;
    for jobs in ["1", "2", "8"] {
        for round in 0..2 {
            let out = d.path(&format!("out-{jobs}-{round}.ply"));
            let maps = d.path(&format!("maps-{jobs}-{round}.json"));
            let j = run_json(&args_of(
                &big,
                &out,
                &[
                    "--keep",
                    "0.01",
                    "--jobs",
                    jobs,
                    "--maps",
                    maps.to_str().unwrap(),
                ],
            ));
            let mut j = untimed(&j);
            j["output"] = Value::Null;
            j["maps"] = Value::Null;
            let got = (
                std::fs::read(&out).unwrap(),
                std::fs::read(&maps).unwrap(),
                j,
            );
            let got_maps = &got.1;
            // The maps name their own output; compare the rest byte for byte.
            let strip = |b: &[u8]| -> String {
                String::from_utf8_lossy(b)
                    .lines()
                    .filter(|l| !l.contains("\"output\""))
                    .collect::<Vec<_>>()
                    .join("\n")
            };
            match &first {
                None => {
                    assert_eq!(got.2["stopped"], "target");
                    first = Some(got.clone());
                }
                Some(f) => {
                    assert!(got.0 == f.0, "--jobs {jobs} round {round}: another mesh");
                    assert_eq!(strip(got_maps), strip(&f.1), "--jobs {jobs}: other maps");
                    assert_eq!(got.2, f.2, "--jobs {jobs}: another report");
                }
            }
        }
    }
    let (mesh, _, j) = first.unwrap();
    let written = d.path("check.ply");
    std::fs::write(&written, mesh).unwrap();
    let out = read_mesh(&written);
    assert_eq!(int(&j, "faces_out"), out.faces.len() as i64);
    assert_eq!(topology(&out.faces), topology(&read_mesh(&big).faces));
}
