//! The conformance protocol, version 1 (`spec/conformance.md`): one case in on the
//! implementation's standard input, one answer out on its standard output, as JSON.

use contractible::TriMesh;
use serde::{Deserialize, Serialize};
use serde_json::{Map, Value};

/// The protocol version this build speaks.
pub const PROTOCOL: u32 = 1;

/// The tasks of the protocol, by name.
pub const TASKS: [&str; 4] = ["reduce", "quad", "simplify", "decimate"];

/// One case, as the implementation receives it.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct CaseMessage {
    /// The protocol version (1).
    pub protocol: u32,
    /// The case's id in the suite (for the implementation's own logs).
    pub id: String,
    /// `reduce`, `quad`, `simplify` or `decimate`.
    pub task: String,
    /// The task's options (`spec/conformance.md` lists them per task).
    pub options: Map<String, Value>,
    /// Vertices are `0 .. vertex_count`.
    pub vertex_count: usize,
    /// Triangles, as vertex ids.
    pub faces: Vec<[u32; 3]>,
    /// One position per vertex, or `null`.
    pub positions: Option<Vec<[f64; 3]>>,
}

impl CaseMessage {
    /// The input as a mesh, refused when its counts are not backed by its data: a
    /// vertex count above `max(3 × faces, positions)`, or positions of another count.
    pub fn mesh(&self) -> Result<TriMesh, String> {
        match &self.positions {
            Some(p) if p.len() != self.vertex_count => Err(format!(
                "vertex_count is {} but there are {} positions",
                self.vertex_count,
                p.len()
            )),
            None if self.vertex_count > 3 * self.faces.len() => Err(format!(
                "vertex_count {} is more than three per face ({} faces) without positions",
                self.vertex_count,
                self.faces.len()
            )),
            _ => Ok(TriMesh {
                vertex_count: self.vertex_count,
                positions: self.positions.clone(),
                faces: self.faces.clone(),
            }),
        }
    }
}

/// What an implementation refuses a case with.
#[derive(Serialize, Deserialize, Clone, Debug, PartialEq)]
pub struct Refusal {
    /// A short snake-case kind (`boundary_edge`, `non_manifold_edge`, `unsupported`...).
    pub kind: String,
    /// A sentence saying what and where.
    pub message: String,
}

/// One answer, as the implementation writes it: the output, or an error.
#[derive(Serialize, Deserialize, Clone, Debug, Default, PartialEq)]
pub struct Answer {
    /// The output's faces: triangles (`reduce`, `simplify`) or quads (`quad`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub faces: Option<Vec<Vec<u32>>>,
    /// The output's positions; `null` (or absent): the faces use the input's vertex ids.
    #[serde(default)]
    pub positions: Option<Vec<[f64; 3]>>,
    /// `quad`: the paired triangulation K, when the conversion flipped edges.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub triangles: Option<Vec<[u32; 3]>>,
    /// `quad`: per quad, its two rows of K (of the input's faces without `triangles`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub pairs: Option<Vec<[u32; 2]>>,
    /// `reduce`: the contractions made, `[kept, removed]` in input vertex ids, oldest
    /// first (optional: when given, the checker replays them).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub history: Option<Vec<[u32; 2]>>,
    /// `decimate`: per output vertex, the input vertex that survives as it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vertex_map: Option<Vec<u32>>,
    /// `decimate`: per input vertex, the output vertex it went into (`null`: a vertex no
    /// face uses).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub collapse_map: Option<Vec<Option<u32>>>,
    /// `decimate`: per output face, the input face it descends from.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub face_origin: Option<Vec<u32>>,
    /// The refusal of an input, instead of an output.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub error: Option<Refusal>,
}

impl Answer {
    /// The output's faces as `N`-gons, with the vertex count the checker reads them over:
    /// the positions' count, else the input's (ids are the input's).
    pub fn mesh<const N: usize>(
        &self,
        input_vertices: usize,
    ) -> Result<contractible::Mesh<N>, String> {
        let faces = self.faces.as_deref().ok_or("the answer has no \"faces\"")?;
        let mut out = Vec::with_capacity(faces.len());
        for (i, f) in faces.iter().enumerate() {
            let f: [u32; N] = f
                .as_slice()
                .try_into()
                .map_err(|_| format!("answer face {i} has {} corners, not {N}", f.len()))?;
            out.push(f);
        }
        Ok(contractible::Mesh {
            vertex_count: self.positions.as_ref().map_or(input_vertices, Vec::len),
            positions: self.positions.clone(),
            faces: out,
        })
    }
}

/// The stored answer of a valid case, for `--exact`.
#[derive(Clone, Debug, PartialEq)]
pub struct Expected {
    /// The output faces, in order (`None` for `quad`, whose quads follow from K and the
    /// pairs).
    pub faces: Option<Vec<Vec<u32>>>,
    /// The output positions (`simplify`), else `None` (input ids).
    pub positions: Option<Vec<[f64; 3]>>,
    /// `quad`: K and the pairs.
    pub triangles: Option<Vec<[u32; 3]>>,
    pub pairs: Option<Vec<[u32; 2]>>,
    /// `decimate`: the three maps.
    pub maps: Option<StoredMaps>,
}

/// A decimation's stored maps: `vertex_map`, `collapse_map` (`None`: a vertex no face
/// uses), `face_origin`.
pub type StoredMaps = (Vec<u32>, Vec<Option<u32>>, Vec<u32>);

/// Where an answer differs from the stored one (`None`: the same bytes of data).
pub fn differs(answer: &Answer, expected: &Expected) -> Option<String> {
    let bits = |p: &Option<Vec<[f64; 3]>>| {
        p.as_ref()
            .map(|v| v.iter().map(|x| x.map(f64::to_bits)).collect::<Vec<_>>())
    };
    if let Some(want) = &expected.faces {
        let got = answer.faces.as_deref().unwrap_or_default();
        if got != want.as_slice() {
            let at = got
                .iter()
                .zip(want)
                .position(|(a, b)| a != b)
                .unwrap_or(got.len().min(want.len()));
            return Some(format!(
                "faces differ from the stored output from face {at} on ({} faces, {} stored)",
                got.len(),
                want.len()
            ));
        }
    }
    if bits(&answer.positions) != bits(&expected.positions) {
        return Some("positions differ from the stored output".into());
    }
    if expected.triangles.is_some() && answer.triangles != expected.triangles {
        return Some("triangles (K) differ from the stored output".into());
    }
    if expected.pairs.is_some() && answer.pairs != expected.pairs {
        return Some("pairs differ from the stored output".into());
    }
    if let Some((vm, cm, fo)) = &expected.maps {
        if answer.vertex_map.as_ref() != Some(vm)
            || answer.collapse_map.as_ref() != Some(cm)
            || answer.face_origin.as_ref() != Some(fo)
        {
            return Some("the maps differ from the stored ones".into());
        }
    }
    None
}
