//! SIGINT and SIGTERM remove the temporary output file being written, then end the
//! process the way the signal would have (the default action, so the parent sees
//! "killed by SIGINT/SIGTERM": status 130/143 in a shell). A write registers its
//! temporary file before creating it and renames it into place while holding the same
//! lock the handler takes, so the handler never removes a finished output and never
//! misses a temporary one.

use std::path::{Path, PathBuf};
use std::sync::Mutex;

use signal_hook::consts::{SIGINT, SIGTERM};

/// The temporary files being written (usually zero or one).
static TEMPORARIES: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

fn temporaries() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    // A panic while the lock was held leaves the list itself intact.
    TEMPORARIES.lock().unwrap_or_else(|e| e.into_inner())
}

/// Starts the thread that handles SIGINT and SIGTERM. If the handler cannot be
/// installed the signals keep their default action (nothing is cleaned up), which is
/// reported once on stderr.
pub fn install() {
    let mut signals = match signal_hook::iterator::Signals::new([SIGINT, SIGTERM]) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("warning: cannot handle SIGINT/SIGTERM ({e}); an interrupted write may leave a temporary file");
            return;
        }
    };
    let spawned = std::thread::Builder::new()
        .name("signals".into())
        .spawn(move || {
            if let Some(sig) = signals.forever().next() {
                let list = temporaries();
                for p in list.iter() {
                    let _ = std::fs::remove_file(p);
                }
                // Keep the lock: no write may rename its file into place from here on.
                let _ = signal_hook::low_level::emulate_default_handler(sig);
                // Only reached if the default action did not end the process.
                std::process::exit(128 + sig);
            }
        });
    if let Err(e) = spawned {
        eprintln!("warning: cannot handle SIGINT/SIGTERM ({e}); an interrupted write may leave a temporary file");
    }
}

/// A temporary file that a signal removes; dropping it removes it too (a failed
/// write), [`TempFile::persist`] renames it into place instead.
pub struct TempFile {
    path: PathBuf,
    done: bool,
}

impl TempFile {
    /// Registers `path` (before the caller creates it).
    pub fn register(path: &Path) -> Self {
        temporaries().push(path.to_path_buf());
        TempFile {
            path: path.to_path_buf(),
            done: false,
        }
    }

    pub fn path(&self) -> &Path {
        &self.path
    }

    /// Renames the file to `to` under the handler's lock and unregisters it.
    pub fn persist(mut self, to: &Path) -> std::io::Result<()> {
        let mut list = temporaries();
        let r = std::fs::rename(&self.path, to);
        if r.is_err() {
            let _ = std::fs::remove_file(&self.path);
        }
        list.retain(|p| p != &self.path);
        self.done = true;
        r
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        if !self.done {
            let mut list = temporaries();
            let _ = std::fs::remove_file(&self.path);
            list.retain(|p| p != &self.path);
        }
    }
}

/// Ends the process as a closed pipe does by default (killed by SIGPIPE, status 141 in
/// a shell, like `yes | head`): what a write to stdout does when its reader went away.
pub fn die_of_broken_pipe() -> ! {
    let _ = signal_hook::low_level::emulate_default_handler(signal_hook::consts::SIGPIPE);
    std::process::exit(141);
}
