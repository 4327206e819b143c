//! `contractible answer`: the library as an implementation of the conformance protocol
//! (`spec/conformance.md`): one case on standard input, its answer on standard output.
//! `contractible conformance --impl 'contractible answer'` runs the suite through it.

use std::io::Read;
use std::str::FromStr;

use contractible::{
    DecimateOptions, Eps, MaxError, QuadOptions, ReduceOptions, SimplifyOptions, TriMesh,
};
use serde_json::{Map, Value};

use super::conformance::protocol::{Answer, CaseMessage, Refusal, PROTOCOL};
use super::{print_json, CliError};

/// A refusal: the kind and the message.
type Refused = (String, String);

fn refused(kind: &str, message: impl Into<String>) -> Refused {
    (kind.to_string(), message.into())
}

/// Reads `options` as the task's: only `known` keys, each of the right type.
struct Options<'a> {
    map: &'a Map<String, Value>,
}

impl<'a> Options<'a> {
    fn new(map: &'a Map<String, Value>, known: &[&str]) -> Result<Self, Refused> {
        if let Some(k) = map.keys().find(|k| !known.contains(&k.as_str())) {
            return Err(refused(
                "bad_option",
                format!("unknown option {k:?} (expected {})", known.join(", ")),
            ));
        }
        Ok(Options { map })
    }

    fn text(&self, key: &str, default: &'a str) -> Result<&'a str, Refused> {
        match self.map.get(key) {
            None => Ok(default),
            Some(Value::String(s)) => Ok(s),
            Some(v) => Err(refused(
                "bad_option",
                format!("option {key:?} is {v}, not a string"),
            )),
        }
    }

    fn choice<T: FromStr>(&self, key: &str, default: &'a str) -> Result<T, Refused>
    where
        T::Err: std::fmt::Display,
    {
        self.text(key, default)?
            .parse()
            .map_err(|e: T::Err| refused("unknown_name", e.to_string()))
    }

    fn seed(&self) -> Result<u64, Refused> {
        match self.map.get("seed") {
            None => Ok(0),
            Some(v) => v.as_u64().ok_or_else(|| {
                refused(
                    "bad_option",
                    format!("option \"seed\" is {v}, not an integer >= 0"),
                )
            }),
        }
    }

    fn count(&self, key: &str) -> Result<Option<usize>, Refused> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(v) => v
                .as_u64()
                .and_then(|n| usize::try_from(n).ok())
                .map(Some)
                .ok_or_else(|| {
                    refused("bad_option", format!("option {key:?} is {v}, not a count"))
                }),
        }
    }

    fn ids(&self, key: &str) -> Result<Vec<u32>, Refused> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(Vec::new()),
            Some(Value::Array(items)) => items
                .iter()
                .map(|x| {
                    x.as_u64()
                        .and_then(|v| u32::try_from(v).ok())
                        .ok_or_else(|| {
                            refused(
                                "bad_option",
                                format!("option {key:?} holds {x}, not a vertex id"),
                            )
                        })
                })
                .collect(),
            Some(v) => Err(refused(
                "bad_option",
                format!("option {key:?} is {v}, not a list of ids"),
            )),
        }
    }

    fn number(&self, key: &str) -> Result<Option<f64>, Refused> {
        match self.map.get(key) {
            None | Some(Value::Null) => Ok(None),
            Some(v) => v.as_f64().map(Some).ok_or_else(|| {
                refused("bad_option", format!("option {key:?} is {v}, not a number"))
            }),
        }
    }

    fn flag(&self, key: &str, default: bool) -> Result<bool, Refused> {
        match self.map.get(key) {
            None => Ok(default),
            Some(Value::Bool(b)) => Ok(*b),
            Some(v) => Err(refused(
                "bad_option",
                format!("option {key:?} is {v}, not true or false"),
            )),
        }
    }
}

fn library(e: &contractible::Error) -> Refused {
    refused(e.kind(), e.to_string())
}

/// The input's faces in its own ids.
fn in_input_ids(mesh: &TriMesh, vertex_map: &[u32]) -> Vec<Vec<u32>> {
    mesh.faces
        .iter()
        .map(|f| f.iter().map(|&v| vertex_map[v as usize]).collect())
        .collect()
}

/// The library's answer to `case`.
pub fn respond(case: &CaseMessage) -> Result<Answer, Refused> {
    if case.protocol != PROTOCOL {
        return Err(refused(
            "protocol",
            format!(
                "protocol {} (this implementation speaks {PROTOCOL})",
                case.protocol
            ),
        ));
    }
    let mesh = case.mesh().map_err(|m| refused("protocol", m))?;
    match case.task.as_str() {
        "reduce" => {
            let o = Options::new(&case.options, &["algorithm", "seed"])?;
            let options = ReduceOptions {
                algorithm: o.choice("algorithm", "rs")?,
                seed: o.seed()?,
                ..ReduceOptions::default()
            };
            let r = contractible::reduce(&mesh, &options).map_err(|e| library(&e))?;
            Ok(Answer {
                faces: Some(in_input_ids(&r.mesh, &r.vertex_map)),
                history: Some(r.contractions()),
                ..Answer::default()
            })
        }
        "quad" => {
            let o = Options::new(&case.options, &["algorithm", "seed"])?;
            let options = QuadOptions {
                algorithm: o.choice("algorithm", "lrs")?,
                seed: o.seed()?,
                ..QuadOptions::default()
            };
            let r = contractible::quadrangulate(&mesh, &options).map_err(|e| library(&e))?;
            Ok(Answer {
                faces: Some(r.mesh.faces.iter().map(|q| q.to_vec()).collect()),
                triangles: Some(r.triangles),
                pairs: Some(r.pairs),
                ..Answer::default()
            })
        }
        "simplify" => {
            let o = Options::new(
                &case.options,
                &["eps", "eps_rel", "mode", "side", "position", "guard"],
            )?;
            let eps = match (o.number("eps")?, o.number("eps_rel")?) {
                (Some(e), None) => Eps::Absolute(e),
                (None, Some(r)) => Eps::Relative(r),
                _ => {
                    return Err(refused(
                        "bad_option",
                        "give exactly one of \"eps\" and \"eps_rel\"",
                    ))
                }
            };
            let options = SimplifyOptions {
                eps,
                mode: o.choice("mode", "nested")?,
                side: o.choice("side", "count")?,
                position: o.choice("position", "midpoint")?,
                allow_foldover: !o.flag("guard", true)?,
                ..SimplifyOptions::default()
            };
            let r = contractible::simplify(&mesh, &options).map_err(|e| library(&e))?;
            Ok(Answer {
                faces: Some(r.mesh.faces.iter().map(|f| f.to_vec()).collect()),
                positions: r.mesh.positions,
                ..Answer::default()
            })
        }
        "decimate" => {
            let o = Options::new(
                &case.options,
                &[
                    "faces",
                    "keep",
                    "max_error",
                    "max_error_rel",
                    "placement",
                    "schedule",
                    "guard",
                    "lock_boundary",
                    "locked",
                ],
            )?;
            let max_error = match (o.number("max_error")?, o.number("max_error_rel")?) {
                (None, None) => None,
                (Some(e), None) => Some(MaxError::Absolute(e)),
                (None, Some(r)) => Some(MaxError::Relative(r)),
                _ => {
                    return Err(refused(
                        "bad_option",
                        "give at most one of \"max_error\" and \"max_error_rel\"",
                    ))
                }
            };
            let options = DecimateOptions {
                faces: o.count("faces")?,
                keep: o.number("keep")?,
                max_error,
                placement: o.choice("placement", "optimal")?,
                schedule: o.choice("schedule", "exact")?,
                allow_foldover: !o.flag("guard", true)?,
                lock_boundary: o.flag("lock_boundary", false)?,
                locked: o.ids("locked")?,
                ..DecimateOptions::default()
            };
            let r = contractible::decimate(&mesh, &options).map_err(|e| library(&e))?;
            let none = contractible::decimate::NO_VERTEX;
            Ok(Answer {
                faces: Some(r.mesh.faces.iter().map(|f| f.to_vec()).collect()),
                positions: r.mesh.positions,
                vertex_map: Some(r.vertex_map),
                collapse_map: Some(
                    r.collapse_map
                        .iter()
                        .map(|&o| (o != none).then_some(o))
                        .collect(),
                ),
                face_origin: Some(r.face_origin),
                ..Answer::default()
            })
        }
        other => Err(refused(
            "unsupported",
            format!("unknown task {other:?} (expected reduce, quad, simplify or decimate)"),
        )),
    }
}

/// Reads one case from standard input and prints its answer (exit 0), or the refusal
/// (exit 2) as `{"error": {"kind", "message"}}`.
pub fn run() -> Result<(), CliError> {
    let mut text = String::new();
    std::io::stdin()
        .read_to_string(&mut text)
        .map_err(|e| CliError::Input(format!("-: cannot read the case: {e}")))?;
    let result = serde_json::from_str::<CaseMessage>(&text)
        .map_err(|e| refused("protocol", format!("the case is no protocol message: {e}")))
        .and_then(|case| respond(&case));
    match result {
        Ok(answer) => print_json(&answer),
        Err((kind, message)) => {
            print_json(&Answer {
                error: Some(Refusal {
                    kind,
                    message: message.clone(),
                }),
                ..Answer::default()
            })?;
            Err(CliError::Input(message))
        }
    }
}
