use std::path::{Path, PathBuf};

use contractible::{io, Error, SimplifyOptions};

/// Reads `input`, prints its topology, writes the three results into `outdir`.
pub fn run(input: &Path, outdir: &Path) -> Result<(), Error> {
    let mesh = io::read_tri_mesh(input)?;
    println!("{}", contractible::describe(&mesh)?);
    let irreducible = contractible::reduce(&mesh, &Default::default())?;
    io::write_mesh(&outdir.join("irreducible.off"), &irreducible.mesh)?;
    let quads = contractible::quadrangulate(&mesh, &Default::default())?;
    io::write_mesh(&outdir.join("quads.obj"), &quads.mesh)?;
    let simplified = contractible::simplify(&mesh, &SimplifyOptions::relative(0.02))?;
    io::write_mesh(&outdir.join("simplified.ply"), &simplified.mesh)?;
    Ok(())
}

fn main() -> Result<(), Error> {
    let mut args = std::env::args_os().skip(1).map(PathBuf::from);
    let input = args
        .next()
        .unwrap_or("tests/data/meshes/closed/bunny_npm.off.gz".into());
    run(&input, &args.next().unwrap_or(std::env::temp_dir()))
}
