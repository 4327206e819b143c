//! The C ABI of `contractible` (header `include/contractible.h`, generated from this
//! crate by cbindgen and checked in; `docs/c.md` is its guide).
//!
//! **Guarantees.** No function unwinds or aborts across the boundary: a panic inside is
//! caught and reported as `CTR_INTERNAL`. A NULL or misaligned pointer, a count whose
//! array cannot exist, an unknown enumeration value or an options struct of an unknown
//! size is `CTR_INVALID_ARGUMENT`, never undefined behaviour on this side. Every
//! function that can fail takes a `ctr_error *err` last (NULL: no details wanted) and
//! returns a status (`CTR_OK` is 0) or a handle (NULL on failure); on success `err`
//! says `CTR_OK`. Handles are owned by the caller and freed by their own `*_free`
//! function (NULL is accepted); pointers a handle's accessors return stay valid until
//! that handle is freed. Handles are immutable once made: any number of threads may read
//! one at once.
//!
//! **Structs that grow.** Options and the error start with `size`, the `sizeof` the
//! caller was compiled with (set by their `*_default()`/`ctr_error_init`): the library
//! reads and writes no byte past it, so a program built against this header keeps
//! working with a later library whose structs have grown at the end; a struct larger than
//! this library knows is refused.
#![allow(non_camel_case_types)]
#![deny(unsafe_op_in_unsafe_fn)]
#![deny(clippy::undocumented_unsafe_blocks)]

mod check;
mod decimate;
mod describe;
mod error;
mod mesh;
mod quadrangulate;
mod reduce;
mod simplify;

pub use check::*;
pub use decimate::*;
pub use describe::*;
pub use error::*;
pub use mesh::*;
pub use quadrangulate::*;
pub use reduce::*;
pub use simplify::*;

/// The version of this ABI: incremented when a function's meaning or a struct's existing
/// fields change (new functions and new trailing fields do not change it).
pub const CTR_ABI_VERSION: u32 = 1;

/// `CTR_ABI_VERSION` as the library was built, to compare with the header's at run
/// time.
#[no_mangle]
pub extern "C" fn ctr_abi_version() -> u32 {
    CTR_ABI_VERSION
}
