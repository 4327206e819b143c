//! `include/contractible.h` is what cbindgen generates from the sources now: a header
//! that drifted from the library fails here (`CONTRACTIBLE_BLESS=1` rewrites it).

use std::path::Path;

#[test]
fn header_is_generated_from_the_sources() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    let config = cbindgen::Config::from_file(dir.join("cbindgen.toml")).expect("the config");
    let bindings = cbindgen::Builder::new()
        .with_crate(dir)
        .with_config(config)
        .generate()
        .expect("cbindgen reads the sources");
    let mut generated = Vec::new();
    bindings.write(&mut generated);
    let path = dir.join("include").join("contractible.h");
    if std::env::var_os("CONTRACTIBLE_BLESS").is_some() {
        std::fs::write(&path, &generated).expect("writes the header");
    }
    let checked_in = std::fs::read(&path).unwrap_or_default();
    assert!(
        checked_in == generated,
        "{} differs from what the sources generate: run \
         `CONTRACTIBLE_BLESS=1 cargo test -p contractible-c --test c header` and commit it",
        path.display()
    );
}
