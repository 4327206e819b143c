//! Raw bytes into the mesh reader (Some(Format::Stl)), then into `Surfaces::from_mesh`; every
//! component that builds must validate. Any panic is a bug.
#![no_main]
#[allow(unused_imports)]
use contractible::io::Format;
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    contractible_fuzz::check_parse(data, Some(Format::Stl));
});
