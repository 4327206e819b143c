//! `--jobs`: how many components of one mesh `reduce`, `quad` and `simplify` process at
//! once, and how many threads `decimate` builds its surfaces on.

use super::CliError;

/// Runs `f(parallel)` where the library's parallel components get `jobs` threads:
/// `None` leaves rayon's current pool (one thread per CPU, or the pool of `batch` when
/// the call runs inside it), `Some(1)` runs the components one after another, `Some(k)`
/// gives them a pool of `k` threads. The library's output is the same in every case.
pub fn with_jobs<R: Send>(
    jobs: Option<usize>,
    f: impl FnOnce(bool) -> R + Send,
) -> Result<R, CliError> {
    match jobs {
        None => Ok(f(true)),
        Some(0) => Err(CliError::Input(
            "--jobs must be at least 1 (1 processes the components one after another)".into(),
        )),
        Some(1) => Ok(f(false)),
        Some(k) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .map_err(|e| CliError::Failure(format!("cannot start {k} worker threads: {e}")))?;
            Ok(pool.install(|| f(true)))
        }
    }
}

/// Runs `f` on a pool of `jobs` threads (`None`: rayon's current pool, one thread per
/// CPU or the pool of `batch`), for tasks that are sequential but whose surface builds
/// use the pool on large meshes: `Some(1)` really is one thread. The library's output
/// is the same in every case.
pub fn in_pool<R: Send>(jobs: Option<usize>, f: impl FnOnce() -> R + Send) -> Result<R, CliError> {
    match jobs {
        None => Ok(f()),
        Some(0) => Err(CliError::Input(
            "--jobs must be at least 1 (1 checks the input and the output on one thread)".into(),
        )),
        Some(k) => {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(k)
                .build()
                .map_err(|e| CliError::Failure(format!("cannot start {k} worker threads: {e}")))?;
            Ok(pool.install(f))
        }
    }
}
