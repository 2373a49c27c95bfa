//! What a save may replace, checked before the work that leads to it.
//!
//! A save must never replace a file the same command reads (`fit --data
//! my.csv --save my.csv` would write a preset over the measurements), nor a
//! read-only file unless the user insists (as editors refuse a read-only
//! buffer until told `:w!`), and a save that cannot happen (a folder that is
//! missing or not writable, a path naming a folder) must be found out before
//! a long fit or training, not after it.
//!
//! Files are the same when their device and inode are, after following
//! links: another path to the input (`./my.csv`, a symlink, a hard link) is
//! the input.

use super::save::{SaveError, replace};
use std::fs::{self, File};
use std::io::Write;
use std::path::{Path, PathBuf};

/// Replaces the file at `path` (or the file its links lead to) with `bytes`
/// (see [`super::save`] for how); a special or read-only file is refused.
pub fn save_atomic(path: &Path, bytes: &[u8]) -> Result<(), SaveError> {
    save_guarded(path, &Guard::default(), bytes)
}

/// [`save_atomic`] with the writing step supplied (a serialiser writing
/// straight into the file, or a failure midway in tests).
pub fn save_atomic_with(
    path: &Path,
    write: impl FnOnce(&mut File) -> std::io::Result<()>,
) -> Result<(), SaveError> {
    let guard = Guard::default();
    replace(path, |p, t, m| guard.check_existing(p, t, m), write, true)
}

/// [`save_atomic`] held to `guard`: never one of its inputs, a read-only
/// file only when forced.
pub fn save_guarded(path: &Path, guard: &Guard, bytes: &[u8]) -> Result<(), SaveError> {
    replace(
        path,
        |p, t, m| guard.check_existing(p, t, m),
        |f| f.write_all(bytes),
        true,
    )
}

/// The files a command reads, and whether a read-only target may be replaced.
#[derive(Debug, Clone, Default)]
pub struct Guard {
    /// Every file the command reads (missing ones are simply not matched).
    pub inputs: Vec<PathBuf>,
    /// Replace a read-only file (its mode is kept).
    pub force: bool,
}

impl Guard {
    /// A guard for a command reading `inputs`.
    pub fn reading<P: AsRef<Path>>(inputs: impl IntoIterator<Item = P>, force: bool) -> Guard {
        Guard {
            inputs: inputs
                .into_iter()
                .map(|p| p.as_ref().to_path_buf())
                .collect(),
            force,
        }
    }

    /// The guard for saving the document at `own` (a preset onto the file it
    /// was opened from): that file is not an input of its own save.
    pub fn without(mut self, own: Option<&Path>) -> Guard {
        if let Some(meta) = own.and_then(|p| fs::metadata(p).ok()) {
            self.inputs.retain(|i| !same_file(&meta, i));
        }
        self
    }

    /// Everything a save to `path` can be refused for, checked now: the path
    /// names a file, is not a special file, is not one of the inputs, is not
    /// read-only (unless forced), and its folder exists and takes a new file.
    pub fn check(&self, path: &Path) -> Result<(), SaveError> {
        // `Path` drops a trailing `/` (`x.svg/` has the file name `x.svg`),
        // but the kernel reads it as a folder: refused now, not after the work.
        if path
            .as_os_str()
            .to_string_lossy()
            .ends_with(std::path::is_separator)
        {
            return Err(SaveError::Io {
                path: path.to_path_buf(),
                action: "cannot save",
                source: std::io::Error::new(
                    std::io::ErrorKind::InvalidInput,
                    "the path names a folder (it ends in '/'): leave the '/' off",
                ),
            });
        }
        let (target, existing) = super::save::resolve(path).map_err(|e| SaveError::Io {
            path: path.to_path_buf(),
            action: "cannot follow the path",
            source: e,
        })?;
        if let Some(meta) = &existing {
            self.check_existing(path, &target, meta)?;
        }
        let (dir, name) = super::save::dir_and_name(path, &target)?;
        // The one test that tells a read-only mount, a missing folder and a
        // folder without write permission alike: make a temp file there.
        super::save::probe(&dir, name).map_err(|e| SaveError::Io {
            path: path.to_path_buf(),
            action: "cannot write in its folder",
            source: e,
        })
    }

    /// The checks on a file that is there: regular, not an input, writable.
    pub(crate) fn check_existing(
        &self,
        path: &Path,
        target: &Path,
        meta: &fs::Metadata,
    ) -> Result<(), SaveError> {
        if !meta.is_file() {
            return Err(SaveError::NotRegular {
                path: path.to_path_buf(),
                target: (target != path).then(|| target.to_path_buf()),
                what: crate::io::read::describe(meta.file_type()),
            });
        }
        if let Some(input) = self.inputs.iter().find(|i| same_file(meta, i)) {
            return Err(SaveError::OwnInput {
                path: path.to_path_buf(),
                input: input.clone(),
            });
        }
        if !self.force
            && let Some(mode) = read_only(meta)
        {
            return Err(SaveError::ReadOnly {
                path: path.to_path_buf(),
                mode,
            });
        }
        Ok(())
    }
}

/// Whether two save targets name one file: the same device and inode when
/// both are there (links followed, as for the inputs), else the same
/// resolved path (links followed, the folder made absolute) for a file not
/// yet there. `./s2.svg`, `s2.svg` and a symlink to it are one file; a
/// string comparison would let one save overwrite the other.
pub fn same_target(a: &Path, b: &Path) -> bool {
    let (Ok((ta, ma)), Ok((tb, mb))) = (super::save::resolve(a), super::save::resolve(b)) else {
        return a == b;
    };
    match (ma, mb) {
        (Some(m), Some(_)) => same_file(&m, &tb),
        (None, None) => absolute(&ta) == absolute(&tb),
        _ => false,
    }
}

/// `path` with its folder canonicalised (the file itself need not exist).
fn absolute(path: &Path) -> Option<PathBuf> {
    let name = path.file_name()?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    Some(fs::canonicalize(dir).ok()?.join(name))
}

/// Whether `input` (links followed) is the file `meta` describes.
fn same_file(meta: &fs::Metadata, input: &Path) -> bool {
    let Ok(other) = fs::metadata(input) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        meta.dev() == other.dev() && meta.ino() == other.ino()
    }
    #[cfg(not(unix))]
    {
        // No inode to compare here; Linux is the platform this guards.
        let _ = (meta, other);
        false
    }
}

/// The file's permission bits when this user may not write it by its mode:
/// the owner's bit for the owner, the group's for a member, the others'
/// otherwise; for root (whom the kernel lets write anything) any write bit.
/// An editor's notion of read-only, not the kernel's: the folder's
/// permissions would let the rename through either way.
fn read_only(meta: &fs::Metadata) -> Option<u32> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        let mode = meta.mode() & 0o7777;
        // SAFETY: geteuid/getegid/getgroups only read the process's ids.
        let (uid, gid) = unsafe { (libc::geteuid(), libc::getegid()) };
        let bit = if uid == 0 {
            0o222
        } else if uid == meta.uid() {
            0o200
        } else if gid == meta.gid() || in_group(meta.gid()) {
            0o020
        } else {
            0o002
        };
        (mode & bit == 0).then_some(mode)
    }
    #[cfg(not(unix))]
    {
        meta.permissions().readonly().then_some(0o444)
    }
}

/// Whether the process belongs to supplementary group `gid`.
#[cfg(unix)]
fn in_group(gid: u32) -> bool {
    let mut groups = [0 as libc::gid_t; 256];
    // SAFETY: the buffer holds 256 entries and its length is passed.
    let n = unsafe { libc::getgroups(groups.len() as libc::c_int, groups.as_mut_ptr()) };
    n > 0 && groups[..n as usize].contains(&gid)
}

#[cfg(test)]
mod tests;
