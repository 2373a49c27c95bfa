//! Temp files of saves: recognisable names, and cleaning the stale ones a
//! killed save left behind.

use std::ffi::OsStr;
use std::fs;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Duration;

/// A temp file older than this is stale even if its pid is alive (pids are
/// reused); no save takes anywhere near this long.
pub const STALE_AFTER: Duration = Duration::from_secs(3600);
/// Folder entries looked at when cleaning, so a huge folder cannot stall a save.
const MAX_SCAN: usize = 100_000;

/// Marker in every temp name.
pub(crate) const TAG: &str = ".biodyn-tmp.";
/// `.NAME.biodyn-tmp.PID.N`, unique per process and per call.
pub(crate) fn temp_name(dir: &Path, base: &OsStr) -> PathBuf {
    static SEQ: AtomicU64 = AtomicU64::new(0);
    let n = SEQ.fetch_add(1, Ordering::Relaxed);
    let mut name = std::ffi::OsString::from(".");
    name.push(base);
    name.push(format!("{TAG}{}.{n}", std::process::id()));
    dir.join(name)
}

/// The pid in a temp name of ours or of an older biodyn build, if `name` is one.
fn temp_pid(name: &str) -> Option<u32> {
    let rest = name.strip_prefix('.')?;
    // This build: .NAME.biodyn-tmp.PID.N
    if let Some(at) = rest.rfind(TAG) {
        let (pid, n) = rest[at + TAG.len()..].split_once('.')?;
        n.parse::<u64>().ok()?;
        return pid.parse().ok();
    }
    // Older builds: .NAME.PID-N.tmp and .NAME.PID.tmp
    let stem = rest.strip_suffix(".tmp")?;
    let (_, last) = stem.rsplit_once('.')?;
    let pid = match last.split_once('-') {
        Some((pid, n)) => {
            n.parse::<u64>().ok()?;
            pid
        }
        None => last,
    };
    pid.parse().ok()
}

/// Removes stale temp files in `dir`; never fails (a file it cannot remove
/// stays for the next save).
pub(crate) fn clean_stale(dir: &Path) {
    let Ok(entries) = fs::read_dir(dir) else {
        return;
    };
    for entry in entries.take(MAX_SCAN).flatten() {
        let name = entry.file_name();
        let Some(pid) = name.to_str().and_then(temp_pid) else {
            continue;
        };
        let Ok(meta) = entry.metadata() else { continue };
        if !meta.is_file() {
            continue;
        }
        let old = meta
            .modified()
            .ok()
            .and_then(|t| t.elapsed().ok())
            .is_some_and(|age| age > STALE_AFTER);
        if old || !process_alive(pid) {
            let _ = fs::remove_file(entry.path());
        }
    }
}

/// Whether a process with this id exists (on other systems: assume it does,
/// and let age decide).
fn process_alive(pid: u32) -> bool {
    #[cfg(unix)]
    {
        if pid == std::process::id() {
            return true;
        }
        let Ok(pid) = libc::pid_t::try_from(pid) else {
            return false;
        };
        if pid <= 0 {
            return false;
        }
        // SAFETY: signal 0 only checks that the process exists.
        if unsafe { libc::kill(pid, 0) } == 0 {
            return true;
        }
        std::io::Error::last_os_error().raw_os_error() != Some(libc::ESRCH)
    }
    #[cfg(not(unix))]
    {
        let _ = pid;
        true
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::save_atomic;

    fn names(dir: &Path) -> Vec<String> {
        let mut v: Vec<String> = fs::read_dir(dir)
            .unwrap()
            .flatten()
            .map(|e| e.file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    }

    #[test]
    fn temp_names_are_recognised() {
        assert_eq!(temp_pid(".a.toml.biodyn-tmp.123.0"), Some(123));
        assert_eq!(temp_pid(".a.toml.4567-0.tmp"), Some(4567));
        assert_eq!(temp_pid(".net.json.89.tmp"), Some(89));
        assert_eq!(temp_pid("a.toml"), None);
        assert_eq!(temp_pid(".a.toml.biodyn-tmp.x.0"), None);
        assert_eq!(temp_pid(".hidden.tmp"), None);
        let t = temp_name(Path::new("d"), OsStr::new("p.toml"));
        let n = t.file_name().unwrap().to_str().unwrap();
        assert_eq!(temp_pid(n), Some(std::process::id()));
    }

    #[test]
    fn stale_temps_are_cleaned_and_live_ones_kept() {
        let dir = tempfile::tempdir().unwrap();
        // No process has pid 2^31-2 (above Linux's pid_max).
        let dead = dir.path().join(".p.toml.biodyn-tmp.2147483646.0");
        let legacy = dir.path().join(".p.toml.2147483646-3.tmp");
        let live = dir
            .path()
            .join(format!(".p.toml.biodyn-tmp.{}.999", std::process::id()));
        let other = dir.path().join(".notes.tmp");
        for p in [&dead, &legacy, &live, &other] {
            fs::write(p, b"x").unwrap();
        }
        save_atomic(&dir.path().join("q.toml"), b"q").unwrap();
        let left = names(dir.path());
        assert_eq!(
            left,
            [
                ".notes.tmp".to_string(),
                live.file_name().unwrap().to_string_lossy().into(),
                "q.toml".into()
            ]
        );
    }
}
