//! The conformance suite: the cases of a suite folder, read from the vectors
//! (`vectors/*.jsonl`, valid cases with this library's exact outputs) and the case files
//! (`suite/*.jsonl`: invalid inputs, and wrong answers for the checker's self-test).

use std::path::{Path, PathBuf};

use serde::Deserialize;
use serde_json::{json, Map, Value};

use super::protocol::{Answer, CaseMessage, Expected, PROTOCOL};

/// The suite version of the case files this build reads.
pub const SUITE: u32 = 1;

/// Whether an implementation must answer a case or refuse it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Class {
    /// The input is a valid input of the task: any correct output passes.
    Valid,
    /// The input is not: the implementation must refuse it.
    Invalid,
}

impl Class {
    pub fn name(self) -> &'static str {
        match self {
            Class::Valid => "valid",
            Class::Invalid => "invalid",
        }
    }
}

/// One case of the suite.
#[derive(Clone, Debug)]
pub struct Case {
    pub class: Class,
    /// What the implementation receives (its `id` is the case's).
    pub message: CaseMessage,
    /// A valid case's stored output (`--exact`).
    pub expected: Option<Expected>,
    /// An invalid case: why the input must be refused.
    pub why: Option<String>,
}

impl Case {
    pub fn id(&self) -> &str {
        &self.message.id
    }
    pub fn task(&self) -> &str {
        &self.message.task
    }
}

/// A wrong answer the checker must reject, with the failure kind it must name.
#[derive(Clone, Debug)]
pub struct WrongAnswer {
    pub case: Case,
    pub answer: Answer,
    pub kind: String,
}

/// Everything a suite folder holds.
#[derive(Debug, Default)]
pub struct Suite {
    pub cases: Vec<Case>,
    pub wrong: Vec<WrongAnswer>,
}

/// Vector groups with no protocol task (marching tetrahedra: a generator, not a task on
/// a mesh): read and left out.
const NOT_IN_PROTOCOL: [&str; 2] = ["iso-exact", "iso-rounded"];

/// The `*.jsonl` files of `dir`, in name order (none if `dir` is missing).
fn files(dir: &Path) -> Result<Vec<PathBuf>, String> {
    if !dir.is_dir() {
        return Ok(Vec::new());
    }
    let mut out: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
        .collect();
    out.sort();
    Ok(out)
}

/// Reads the suite of `dir` (`dir/vectors/*.jsonl`, `dir/suite/*.jsonl`): every line
/// of every file becomes cases, or the error names the file and line.
pub fn load(dir: &Path) -> Result<Suite, String> {
    let vectors = files(&dir.join("vectors"))?;
    let case_files = files(&dir.join("suite"))?;
    if vectors.is_empty() && case_files.is_empty() {
        return Err(format!(
            "{}: no suite here (no vectors/*.jsonl or suite/*.jsonl): run from the \
             repository's root or give --suite DIR",
            dir.display()
        ));
    }
    let mut suite = Suite::default();
    for (path, is_vector) in vectors
        .iter()
        .map(|p| (p, true))
        .chain(case_files.iter().map(|p| (p, false)))
    {
        let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
        for (n, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            let at = |e: String| format!("{}:{}: {e}", path.display(), n + 1);
            let value: Value = serde_json::from_str(line).map_err(|e| at(e.to_string()))?;
            if is_vector {
                suite.cases.extend(from_vector(&value).map_err(at)?);
            } else {
                case_line(&value, &mut suite).map_err(at)?;
            }
        }
    }
    let mut ids: Vec<&str> = suite.cases.iter().map(Case::id).collect();
    ids.sort_unstable();
    if let Some(w) = ids.windows(2).find(|w| w[0] == w[1]) {
        return Err(format!(
            "{}: two cases have the id {:?}",
            dir.display(),
            w[0]
        ));
    }
    Ok(suite)
}

fn field<'v>(v: &'v Value, key: &str) -> Result<&'v Value, String> {
    v.get(key).ok_or_else(|| format!("no {key:?}"))
}

fn parse<T: for<'de> Deserialize<'de>>(v: &Value, key: &str) -> Result<T, String> {
    T::deserialize(field(v, key)?).map_err(|e| format!("{key:?}: {e}"))
}

fn message(
    id: String,
    task: &str,
    options: Map<String, Value>,
    vector: &Value,
) -> Result<CaseMessage, String> {
    Ok(CaseMessage {
        protocol: PROTOCOL,
        id,
        task: task.to_string(),
        options,
        vertex_count: parse(vector, "vertex_count")?,
        faces: parse(vector, "faces")?,
        positions: match vector.get("positions") {
            None | Some(Value::Null) => None,
            Some(_) => Some(parse(vector, "positions")?),
        },
    })
}

fn object(v: Value) -> Map<String, Value> {
    match v {
        Value::Object(m) => m,
        _ => Map::new(),
    }
}

fn valid(message: CaseMessage, expected: Expected) -> Case {
    Case {
        class: Class::Valid,
        message,
        expected: Some(expected),
        why: None,
    }
}

fn triangles_expected(faces: Vec<[u32; 3]>, positions: Option<Vec<[f64; 3]>>) -> Expected {
    Expected {
        faces: Some(faces.iter().map(|f| f.to_vec()).collect()),
        positions,
        triangles: None,
        pairs: None,
        maps: None,
    }
}

/// The cases of one vector line, by its group.
fn from_vector(v: &Value) -> Result<Vec<Case>, String> {
    let group: String = parse(v, "group")?;
    let name: String = parse(v, "name")?;
    if NOT_IN_PROTOCOL.contains(&group.as_str()) {
        return Ok(Vec::new());
    }
    let mut cases = Vec::new();
    if group == "decimate" {
        let runs: Vec<Value> = parse(v, "runs")?;
        for (i, run) in runs.iter().enumerate() {
            let o = field(run, "options")?;
            let mut options = Map::new();
            for key in ["faces", "keep", "placement", "schedule", "lock_boundary"] {
                if !o[key].is_null() {
                    options.insert(key.to_string(), o[key].clone());
                }
            }
            options.insert(
                "guard".into(),
                json!(!o["allow_foldover"].as_bool().unwrap_or(false)),
            );
            if o["locked"].as_array().is_some_and(|l| !l.is_empty()) {
                options.insert("locked".into(), o["locked"].clone());
            }
            match (
                o["max_error"].get("absolute"),
                o["max_error"].get("relative"),
            ) {
                (Some(e), _) => {
                    options.insert("max_error".into(), e.clone());
                }
                (None, Some(r)) => {
                    options.insert("max_error_rel".into(), r.clone());
                }
                (None, None) => {}
            }
            let id = format!("decimate/{group}/{name}/run{i}");
            let mut expected = triangles_expected(
                parse(run, "output_faces")?,
                Some(parse(run, "output_positions")?),
            );
            expected.maps = Some((
                parse(run, "vertex_map")?,
                parse(run, "collapse_map")?,
                parse(run, "face_origin")?,
            ));
            cases.push(valid(message(id, "decimate", options, v)?, expected));
        }
    } else if group.starts_with("quad-") {
        let runs: Vec<Value> = parse(v, "runs")?;
        for run in &runs {
            let algorithm: String = parse(run, "algorithm")?;
            let seed: u64 = parse(run, "seed")?;
            let id = format!("quad/{group}/{name}/{algorithm}-s{seed}");
            let options = object(json!({"algorithm": algorithm, "seed": seed}));
            // K is stored where it differs from the input (LRS's flips).
            let k = match run.get("k_faces") {
                Some(_) => parse(run, "k_faces")?,
                None => parse(v, "faces")?,
            };
            let expected = Expected {
                faces: None,
                positions: None,
                triangles: Some(k),
                pairs: Some(parse(run, "pairs")?),
                maps: None,
            };
            cases.push(valid(message(id, "quad", options, v)?, expected));
        }
    } else if group.starts_with("simplify-") {
        let runs: Vec<Value> = parse(v, "runs")?;
        for (i, run) in runs.iter().enumerate() {
            let mut options = Map::new();
            for key in ["eps", "mode", "side", "position", "guard"] {
                options.insert(key.to_string(), field(run, key)?.clone());
            }
            let id = format!("simplify/{group}/{name}/run{i}");
            let expected = triangles_expected(
                parse(run, "output_faces")?,
                Some(parse(run, "output_positions")?),
            );
            cases.push(valid(message(id, "simplify", options, v)?, expected));
        }
    } else {
        // The irreducible-triangulation groups: RS, Schipper and the brute force.
        let rs = triangles_expected(parse(v, "output_faces")?, None);
        let id = format!("reduce/{group}/{name}/rs");
        cases.push(valid(
            message(id, "reduce", object(json!({"algorithm": "rs"})), v)?,
            rs,
        ));
        let schipper = field(v, "schipper")?;
        let id = format!("reduce/{group}/{name}/schipper");
        cases.push(valid(
            message(id, "reduce", object(json!({"algorithm": "schipper"})), v)?,
            triangles_expected(parse(schipper, "output_faces")?, None),
        ));
        let brute = field(v, "brute")?;
        let seed: u64 = parse(brute, "seed")?;
        let id = format!("reduce/{group}/{name}/brute-s{seed}");
        cases.push(valid(
            message(
                id,
                "reduce",
                object(json!({"algorithm": "brute", "seed": seed})),
                v,
            )?,
            triangles_expected(parse(brute, "output_faces")?, None),
        ));
    }
    Ok(cases)
}

/// One line of a case file: `{"suite": 1, "id", "task", "class", "options",
/// "vertex_count", "faces", "positions", ...}` with `"why"` (invalid) or `"answer"` and
/// `"kind"` (class `wrong_answer`).
fn case_line(v: &Value, suite: &mut Suite) -> Result<(), String> {
    let version: u32 = parse(v, "suite")?;
    if version != SUITE {
        return Err(format!("suite version {version}; this build reads {SUITE}"));
    }
    let id: String = parse(v, "id")?;
    let task: String = parse(v, "task")?;
    if !super::protocol::TASKS.contains(&task.as_str()) {
        return Err(format!("unknown task {task:?}"));
    }
    let options = object(field(v, "options")?.clone());
    let class: String = parse(v, "class")?;
    let msg = message(id, &task, options, v)?;
    match class.as_str() {
        "invalid" => suite.cases.push(Case {
            class: Class::Invalid,
            message: msg,
            expected: None,
            why: Some(parse(v, "why")?),
        }),
        "wrong_answer" => suite.wrong.push(WrongAnswer {
            case: Case {
                class: Class::Valid,
                message: msg,
                expected: None,
                why: None,
            },
            answer: parse(v, "answer")?,
            kind: parse(v, "kind")?,
        }),
        other => return Err(format!("unknown class {other:?} (invalid or wrong_answer)")),
    }
    Ok(())
}
