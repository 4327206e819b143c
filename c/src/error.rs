//! The error struct, and the guard every exported function runs its body in.

use std::ffi::c_char;
use std::mem::{offset_of, size_of};
use std::panic::{catch_unwind, AssertUnwindSafe};

use contractible::core::BuildError;
use contractible::io::{Location, ReadErrorKind};
use contractible::Error;

/// No error.
pub const CTR_OK: i32 = 0;
/// A failure that is not the input's fault: a file could not be written, an output
/// failed its independent check, the call was cancelled (the command line's exit code 1).
pub const CTR_FAILURE: i32 = 1;
/// The input is at fault: a file that cannot be read or parsed, a mesh that is not what
/// the task accepts, an option out of range (the command line's exit code 2).
pub const CTR_INPUT: i32 = 2;
/// The call itself is wrong: a NULL or misaligned pointer, a count whose array cannot
/// exist, an unknown enumeration value, an options struct of an unknown size, a path that
/// is not UTF-8.
pub const CTR_INVALID_ARGUMENT: i32 = 3;
/// A bug in the library, caught before it crossed the boundary (please report it).
pub const CTR_INTERNAL: i32 = 4;

/// Bytes of the `kind` of `ctr_error`, its NUL included.
pub const CTR_KIND_LEN: usize = 32;
/// Bytes of the `message` of `ctr_error`, its NUL included.
pub const CTR_MESSAGE_LEN: usize = 1024;

/// Why a call failed: what (`code`, `kind`, `message`) and where (`face`, `vertex`,
/// `line`, each -1 when it does not apply).
#[repr(C)]
#[derive(Clone, Copy)]
pub struct ctr_error {
    /// `sizeof(ctr_error)` as the caller was compiled: set by `ctr_error_init`. The
    /// library writes no byte past it.
    pub size: u32,
    /// `CTR_OK`, `CTR_FAILURE`, `CTR_INPUT`, `CTR_INVALID_ARGUMENT` or
    /// `CTR_INTERNAL`.
    pub code: i32,
    /// A stable snake-case name (`boundary_edge`, `non_manifold_edge`, `read`, `io`,
    /// `bad_option`, `invalid_argument`, `internal`...; the library's error kinds),
    /// NUL-terminated; empty when `code` is `CTR_OK`.
    pub kind: [c_char; CTR_KIND_LEN],
    /// A sentence saying what and where, NUL-terminated UTF-8 (cut at a character
    /// boundary if longer than the array).
    pub message: [c_char; CTR_MESSAGE_LEN],
    /// The input face involved (0-based), or -1.
    pub face: i64,
    /// The input vertex involved (0-based), or -1.
    pub vertex: i64,
    /// The line of the file involved (1-based), or -1.
    pub line: i64,
}

/// Sets `*err` to "no error" with `size = sizeof(ctr_error)`; call it once before
/// passing `err` to the library. NULL is ignored.
///
/// # Safety
/// `err` is NULL or points to a writable `ctr_error`.
#[no_mangle]
pub unsafe extern "C" fn ctr_error_init(err: *mut ctr_error) {
    if err.is_null() || !err.is_aligned() {
        return;
    }
    let value = ctr_error {
        size: size_of::<ctr_error>() as u32,
        code: CTR_OK,
        kind: [0; CTR_KIND_LEN],
        message: [0; CTR_MESSAGE_LEN],
        face: -1,
        vertex: -1,
        line: -1,
    };
    // SAFETY: non-null and aligned (checked), and the caller promises a writable
    // `ctr_error` there.
    unsafe { err.write(value) };
}

/// A failure on its way to the caller's `ctr_error`.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct Failure {
    pub code: i32,
    pub kind: &'static str,
    pub message: String,
    pub face: i64,
    pub vertex: i64,
    pub line: i64,
}

impl Failure {
    /// `CTR_INVALID_ARGUMENT` with `message`.
    pub fn argument(message: impl Into<String>) -> Self {
        Failure {
            code: CTR_INVALID_ARGUMENT,
            kind: "invalid_argument",
            message: message.into(),
            face: -1,
            vertex: -1,
            line: -1,
        }
    }
}

fn int(x: impl TryInto<i64>) -> i64 {
    x.try_into().unwrap_or(i64::MAX)
}

impl From<Error> for Failure {
    fn from(e: Error) -> Self {
        let (mut face, mut vertex, mut line) = (-1, -1, -1);
        match &e {
            Error::Read(r) => match r.location {
                Location::Line(n) => line = int(n),
                Location::Face(f) => face = int(f),
                _ => {}
            },
            Error::Mesh(b) => match b {
                BuildError::VertexOutOfRange {
                    face: f, vertex: v, ..
                } => {
                    face = int(*f);
                    vertex = i64::from(*v);
                }
                BuildError::DegenerateFace { face: f, .. }
                | BuildError::DuplicateFace { face: f, .. }
                | BuildError::BoundaryEdge { face: f, .. }
                | BuildError::NonManifoldEdge { face: f, .. }
                | BuildError::MultipleEdges { face: f, .. } => face = int(*f),
                BuildError::VertexLinkNotCycle { vertex: v, .. }
                | BuildError::PinchedBoundaryVertex { vertex: v, .. }
                | BuildError::VertexDegreeTooLow { vertex: v, .. }
                | BuildError::UnusedVertex { vertex: v } => vertex = i64::from(*v),
                _ => {}
            },
            Error::NotClosed { face: f, .. } => face = int(*f),
            Error::NonFiniteCoordinate { vertex: v, .. } => vertex = int(*v),
            _ => {}
        }
        let code = if e.is_input() {
            CTR_INPUT
        } else if matches!(&e, Error::Read(r) if matches!(r.kind, ReadErrorKind::Io(_))) {
            // A file that cannot be opened is the input's fault too (as the command
            // line's exit code 2).
            CTR_INPUT
        } else {
            CTR_FAILURE
        };
        Failure {
            code,
            kind: e.kind(),
            message: e.to_string(),
            face,
            vertex,
            line,
        }
    }
}

/// Copies `text` into `out` NUL-terminated, cut at a UTF-8 character boundary.
fn copy_text(out: &mut [c_char], text: &str) {
    let mut end = text.len().min(out.len() - 1);
    while !text.is_char_boundary(end) {
        end -= 1;
    }
    for (o, &b) in out.iter_mut().zip(&text.as_bytes()[..end]) {
        *o = b as c_char;
    }
    out[end] = 0;
}

/// Writes `f` into the caller's error struct: each field only if `size` covers it.
///
/// # Safety
/// `err` is NULL or points to a writable region of at least 4 bytes whose first `u32`
/// is the region's size in bytes (a `ctr_error` from `ctr_error_init`).
unsafe fn report(err: *mut ctr_error, f: &Failure) {
    if err.is_null() || !err.is_aligned() {
        return;
    }
    // SAFETY: non-null and aligned; the caller promises the `size` field is there.
    let size = unsafe { (*err).size } as usize;
    let mut value = ctr_error {
        size: size as u32,
        code: f.code,
        kind: [0; CTR_KIND_LEN],
        message: [0; CTR_MESSAGE_LEN],
        face: f.face,
        vertex: f.vertex,
        line: f.line,
    };
    copy_text(&mut value.kind, f.kind);
    copy_text(&mut value.message, &f.message);
    let whole = size_of::<ctr_error>();
    if size >= whole {
        // SAFETY: the region holds a whole `ctr_error` (size covers it), aligned.
        unsafe { err.write(value) };
        return;
    }
    // An older, shorter struct: the fields that fit, byte by byte.
    let src = (&value as *const ctr_error).cast::<u8>();
    let dst = err.cast::<u8>();
    for (offset, len) in [
        (offset_of!(ctr_error, code), size_of::<i32>()),
        (offset_of!(ctr_error, kind), CTR_KIND_LEN),
        (offset_of!(ctr_error, message), CTR_MESSAGE_LEN),
        (offset_of!(ctr_error, face), size_of::<i64>()),
        (offset_of!(ctr_error, vertex), size_of::<i64>()),
        (offset_of!(ctr_error, line), size_of::<i64>()),
    ] {
        if offset + len <= size {
            // SAFETY: `offset + len` is within both `value` and the caller's `size`
            // bytes; the two do not overlap.
            unsafe { std::ptr::copy_nonoverlapping(src.add(offset), dst.add(offset), len) };
        }
    }
}

/// Runs `body`, a panic caught as a [`CTR_INTERNAL`] failure.
fn run<T>(body: impl FnOnce() -> Result<T, Failure>) -> Result<T, Failure> {
    catch_unwind(AssertUnwindSafe(body)).unwrap_or_else(|payload| {
        let what = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a panic".into());
        Err(Failure {
            code: CTR_INTERNAL,
            kind: "internal",
            message: format!("internal error (a bug, please report it): {what}"),
            face: -1,
            vertex: -1,
            line: -1,
        })
    })
}

/// Reports `outcome` in `err` ("no error" on success) and gives its value, or `failed`.
fn finish<T>(err: *mut ctr_error, outcome: Result<T, Failure>, failed: T) -> T {
    let none = Failure {
        code: CTR_OK,
        kind: "",
        message: String::new(),
        face: -1,
        vertex: -1,
        line: -1,
    };
    let (value, failure) = match outcome {
        Ok(v) => (v, none),
        Err(f) => (failed, f),
    };
    // SAFETY: every exported function documents `err` as NULL or a `ctr_error` made by
    // `ctr_error_init` (so its `size` field is there).
    unsafe { report(err, &failure) };
    value
}

/// Runs `body`, reporting its failure or panic in `err` (else "no error") and giving
/// `failed` in their place: the functions that return a handle.
pub(crate) fn guard<T>(
    err: *mut ctr_error,
    failed: T,
    body: impl FnOnce() -> Result<T, Failure>,
) -> T {
    finish(err, run(body), failed)
}

/// Runs `body`, reporting its failure or panic in `err` (else "no error"), and gives
/// the status: [`CTR_OK`] or the failure's code: the functions that return a status.
pub(crate) fn status(err: *mut ctr_error, body: impl FnOnce() -> Result<(), Failure>) -> i32 {
    let outcome = run(body);
    let code = outcome.as_ref().map_or_else(|f| f.code, |()| CTR_OK);
    finish(err, outcome.map(|()| CTR_OK), code)
}

/// `ptr` as a slice of `len` elements: an empty slice for `len == 0` (whatever `ptr`);
/// else refused when NULL, misaligned, or more bytes than an allocation can hold.
///
/// # Safety
/// When `len > 0` and `ptr` passes the checks, it points to `len` readable elements that
/// stay unchanged for `'a`.
pub(crate) unsafe fn slice<'a, T>(
    ptr: *const T,
    len: usize,
    what: &str,
) -> Result<&'a [T], Failure> {
    if len == 0 {
        return Ok(&[]);
    }
    if ptr.is_null() {
        return Err(Failure::argument(format!(
            "{what} is NULL with a count of {len}"
        )));
    }
    if !ptr.is_aligned() {
        return Err(Failure::argument(format!(
            "{what} is not aligned for its type ({} bytes)",
            std::mem::align_of::<T>()
        )));
    }
    if len
        .checked_mul(size_of::<T>())
        .is_none_or(|b| b > isize::MAX as usize)
    {
        return Err(Failure::argument(format!(
            "{what}: {len} elements cannot exist"
        )));
    }
    // SAFETY: non-null, aligned, within isize::MAX bytes (checked); readable and
    // unchanged for 'a by the caller's promise.
    Ok(unsafe { std::slice::from_raw_parts(ptr, len) })
}

/// `value` as a reference, refused when NULL or misaligned.
///
/// # Safety
/// A non-null aligned `value` points to a valid `T` for `'a`.
pub(crate) unsafe fn object<'a, T>(value: *const T, what: &str) -> Result<&'a T, Failure> {
    if value.is_null() {
        return Err(Failure::argument(format!("{what} is NULL")));
    }
    if !value.is_aligned() {
        return Err(Failure::argument(format!("{what} is not aligned")));
    }
    // SAFETY: non-null and aligned (checked), valid by the caller's promise.
    Ok(unsafe { &*value })
}

/// `out` as a writable struct the library fills whole: refused when NULL, misaligned, or
/// its leading `size` (a `u32`) is not `sizeof(T)` (`init` names the function that sets
/// it).
///
/// # Safety
/// A non-null aligned `out` points to a writable `T` whose first field is its size.
pub(crate) unsafe fn sized_out<'a, T>(out: *mut T, init: &str) -> Result<&'a mut T, Failure> {
    // SAFETY: checked for NULL and alignment; the caller promises the size field.
    let size = unsafe { object(out.cast_const().cast::<u32>(), "out") }.map(|s| *s as usize)?;
    let whole = size_of::<T>();
    if size != whole {
        return Err(Failure::argument(format!(
            "out->size is {size}: this library writes {whole} bytes (initialise it with {init}())"
        )));
    }
    // SAFETY: non-null, aligned and of this struct's size (checked); writable by the
    // caller's promise.
    Ok(unsafe { &mut *out })
}

/// Reads an options struct whose first field is its `size` (a `u32`): the caller's
/// bytes over `default` (fields past the caller's size keep their default), or `default`
/// for NULL. A size below 4 or above `sizeof(T)` is refused.
///
/// # Safety
/// A non-null aligned `options` points to a readable region of the size its first `u32`
/// states, holding valid values of the fields it covers.
pub(crate) unsafe fn read_options<T: Copy>(
    options: *const T,
    default: T,
    what: &str,
) -> Result<T, Failure> {
    if options.is_null() {
        return Ok(default);
    }
    if !options.is_aligned() {
        return Err(Failure::argument(format!("{what} is not aligned")));
    }
    // SAFETY: non-null and aligned; the caller promises the leading `size` field.
    let size = unsafe { options.cast::<u32>().read() } as usize;
    let whole = size_of::<T>();
    if !(4..=whole).contains(&size) {
        return Err(Failure::argument(format!(
            "{what}.size is {size}: this library knows {whole} bytes (initialise the options \
             with their *_default() function)"
        )));
    }
    let mut out = default;
    // SAFETY: the caller's region holds `size` ≤ sizeof(T) readable bytes of valid field
    // values; `out` is a distinct local `T`.
    unsafe {
        std::ptr::copy_nonoverlapping(
            options.cast::<u8>(),
            (&mut out as *mut T).cast::<u8>(),
            size,
        )
    };
    Ok(out)
}

/// A NUL-terminated UTF-8 path.
///
/// # Safety
/// A non-null `path` points to a NUL-terminated string that stays unchanged meanwhile.
pub(crate) unsafe fn path<'a>(path: *const c_char) -> Result<&'a std::path::Path, Failure> {
    if path.is_null() {
        return Err(Failure::argument("the path is NULL"));
    }
    // SAFETY: non-null, NUL-terminated by the caller's promise.
    let s = unsafe { std::ffi::CStr::from_ptr(path) };
    let s = s
        .to_str()
        .map_err(|e| Failure::argument(format!("the path is not UTF-8: {e}")))?;
    Ok(std::path::Path::new(s))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn text(a: &[c_char]) -> String {
        let bytes: Vec<u8> = a
            .iter()
            .take_while(|&&c| c != 0)
            .map(|&c| c as u8)
            .collect();
        String::from_utf8(bytes).unwrap()
    }

    #[test]
    fn long_messages_are_cut_at_a_character_boundary() {
        let mut out = [1 as c_char; 8];
        copy_text(&mut out, "aaaaaaé");
        // 7 bytes fit: "aaaaaa" and half of 'é' is cut back to "aaaaaa".
        assert_eq!(text(&out), "aaaaaa");
        copy_text(&mut out, "aaaaaé");
        assert_eq!(text(&out), "aaaaaé", "exactly 7 bytes fit");
        copy_text(&mut out, "ab");
        assert_eq!(text(&out), "ab");
    }

    #[test]
    fn a_panic_is_an_internal_error_and_success_clears_the_error() {
        let mut e = std::mem::MaybeUninit::<ctr_error>::uninit();
        // SAFETY: a writable ctr_error.
        unsafe { ctr_error_init(e.as_mut_ptr()) };
        // SAFETY: initialised just above.
        let mut e = unsafe { e.assume_init() };
        let v = guard(&mut e, 7, || -> Result<i32, Failure> { panic!("boom") });
        assert_eq!((v, e.code), (7, CTR_INTERNAL));
        assert!(text(&e.message).contains("boom"), "{}", text(&e.message));
        assert_eq!(text(&e.kind), "internal");
        assert_eq!((e.face, e.vertex, e.line), (-1, -1, -1), "no location");
        let located = || -> Result<i32, Failure> {
            Err(Failure {
                face: 4,
                vertex: 5,
                line: 6,
                ..Failure::argument("located")
            })
        };
        assert_eq!(guard(&mut e, 7, located), 7);
        assert_eq!((e.face, e.vertex, e.line), (4, 5, 6));
        let v = guard(&mut e, 7, || Ok(3));
        assert_eq!((v, e.code), (3, CTR_OK));
        assert_eq!(text(&e.kind), "");
        assert_eq!((e.face, e.vertex, e.line), (-1, -1, -1), "cleared");
        // A status is the failure's code, with or without an error struct.
        let bad = || Err(Failure::argument("no"));
        assert_eq!(status(&mut e, bad), CTR_INVALID_ARGUMENT);
        assert_eq!(status(std::ptr::null_mut(), bad), CTR_INVALID_ARGUMENT);
        assert_eq!(status(&mut e, || Ok(())), CTR_OK);
        assert_eq!(e.code, CTR_OK);
    }

    #[test]
    fn a_shorter_error_struct_gets_only_the_fields_it_has() {
        // An older caller's struct: size, code and kind only (40 bytes), then a canary.
        let mut region = [0u64; 16];
        let base = region.as_mut_ptr().cast::<u8>();
        let short = (offset_of!(ctr_error, kind) + CTR_KIND_LEN) as u32;
        // SAFETY: the region is 128 bytes, aligned for u64 (so for ctr_error's fields).
        unsafe { base.cast::<u32>().write(short) };
        region[short as usize / 8] = 0xdead_beef;
        let f = Failure::argument("x".repeat(100));
        // SAFETY: the region's first u32 is its (claimed) size, within the region.
        unsafe { report(base.cast::<ctr_error>(), &f) };
        assert_eq!(
            region[short as usize / 8],
            0xdead_beef,
            "no byte past size written"
        );
        // SAFETY: code is within the short struct.
        let code = unsafe { base.add(offset_of!(ctr_error, code)).cast::<i32>().read() };
        assert_eq!(code, CTR_INVALID_ARGUMENT);
    }

    #[test]
    fn options_of_an_unknown_size_are_refused() {
        #[derive(Clone, Copy, Debug, PartialEq)]
        #[repr(C)]
        struct O {
            size: u32,
            a: u32,
            b: u64,
        }
        let default = O {
            size: 16,
            a: 1,
            b: 2,
        };
        let given = O {
            size: 8,
            a: 5,
            b: 9,
        };
        // SAFETY: a valid O.
        let got = unsafe { read_options(&given, default, "o") }.unwrap();
        assert_eq!(
            got,
            O {
                size: 8,
                a: 5,
                b: 2
            },
            "fields past size keep their default"
        );
        for size in [0, 3, 17, 1 << 20] {
            let bad = O { size, a: 5, b: 9 };
            // SAFETY: a valid O.
            let e = unsafe { read_options(&bad, default, "o") }.unwrap_err();
            assert_eq!(e.code, CTR_INVALID_ARGUMENT);
        }
        // SAFETY: NULL is allowed.
        let none = unsafe { read_options(std::ptr::null(), default, "o") };
        assert_eq!(none.unwrap(), default);
    }
}
