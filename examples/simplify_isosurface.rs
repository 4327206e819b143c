//! Simplify a marching-tetrahedra genus-2 surface: every edge shorter than 2 % of the
//! bounding-box diagonal goes, the surface type stays. `cargo run --release --example
//! simplify_isosurface`.

use contractible::gen::{isosurface, Implicit, IsoParams, Tessellation};
use contractible::simplify::{bbox_diagonal, simplify, Mode, Options};
use contractible::{SurfaceType, Surfaces};

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mesh = isosurface(&IsoParams::new(
        Implicit::GenusG { g: 2 },
        Tessellation::BodyCentred,
        48,
    ))?;
    let diagonal = bbox_diagonal(mesh.positions.iter().flatten().copied());
    let options = Options {
        mode: Mode::Nested,
        ..Options::new(0.02 * diagonal)
    };
    let out = simplify(&mesh, &options)?;
    let s = &out.stats;
    println!(
        "genus 2: {} → {} faces in {} passes, {} contractions, {} discs removed, {} short edges left",
        s.faces_in, s.faces_out, s.passes, s.edges_contracted, s.discs_removed,
        s.short_edges_remaining
    );
    // The surface is the same: rebuild the output and compare its type.
    let types = |m| -> Result<Vec<SurfaceType>, contractible::BuildError> {
        Ok(Surfaces::from_mesh_with_boundary(m)?
            .components
            .iter()
            .map(|c| c.surface_type())
            .collect())
    };
    assert_eq!(types(&mesh)?, types(&out.mesh)?);
    println!("same surface: {:?}", types(&out.mesh)?);
    Ok(())
}
