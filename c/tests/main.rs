//! The C ABI's tests: the header against the sources, and C programs compiled with the
//! system compiler (warnings as errors) against the static library and run.

mod c_programs;
mod header;
