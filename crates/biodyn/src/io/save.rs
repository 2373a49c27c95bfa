//! Atomic saves that never clobber: the one way every file is written.
//!
//! - A symlink is followed (up to 40 hops) and its final target replaced, so
//!   the link stays a link; the temp file lives in the target's own folder,
//!   which is what makes the rename atomic.
//! - Only a regular file (or nothing) is replaced: a directory, FIFO, socket
//!   or device at the path is refused and left untouched.
//! - A replaced file keeps its permission bits, and its owner and group where
//!   the process may set them (root, or a group it belongs to).
//! - The bytes are written to a temp file, fsynced, renamed over the target,
//!   and the folder is fsynced, so a crash leaves either the old or the new
//!   file, never half of one.
//!
//! Temp files. On Linux the data is first written to an unnamed file
//! (`O_TMPFILE`), which a killed process cannot leave behind; it is linked
//! under a temp name only for the instant before the rename, because
//! `linkat` cannot replace an existing file. Where `O_TMPFILE` is not
//! supported (other systems, some file systems) the temp file is named from
//! the start. Either way the name is `.NAME.biodyn-tmp.PID.N`, and every save
//! removes the stale ones in its folder: those whose process is gone, or
//! older than [`STALE_AFTER`](super::temp::STALE_AFTER). Temp names of older biodyn builds
//! (`.NAME.PID-N.tmp`, `.NAME.PID.tmp`) are removed by the same rule.
//!
//! Known limits: a file swapped in between the check and the rename is
//! replaced (no portable atomic "rename unless special" exists); a hard
//! link to the old file keeps the old contents, as with any atomic save.

use super::temp::{clean_stale, temp_name};
use std::ffi::OsStr;
use std::fs::{self, File};
use std::path::{Path, PathBuf};

/// Symlink hops followed before giving up (Linux's own limit).
const MAX_HOPS: usize = 40;

/// Why a save did not happen. In every case the file at the path, if any,
/// is unchanged.
#[derive(Debug, thiserror::Error)]
pub enum SaveError {
    #[error("{path}: {}", reason_not_regular(.target, .what))]
    NotRegular {
        path: PathBuf,
        /// Where the path's links lead, when it is a link.
        target: Option<PathBuf>,
        what: &'static str,
    },
    /// The path is a file the same command reads.
    #[error(
        "{path}: is the input {input} of this command; saving there would replace it: choose another file"
    )]
    OwnInput { path: PathBuf, input: PathBuf },
    /// The file's mode says this user may not write it.
    #[error(
        "{path}: is read-only (mode {mode:04o}); make it writable (chmod u+w) or save under another name"
    )]
    ReadOnly { path: PathBuf, mode: u32 },
    #[error("{path}: {action}: {source}")]
    Io {
        path: PathBuf,
        action: &'static str,
        #[source]
        source: std::io::Error,
    },
}

fn reason_not_regular(target: &Option<PathBuf>, what: &str) -> String {
    match target {
        Some(t) => format!(
            "links to {}, which is a {what}; only a regular file is replaced",
            t.display()
        ),
        None => format!("is a {what}; only a regular file is replaced"),
    }
}

impl SaveError {
    /// The reason without the path, for callers that print the path themselves.
    pub fn reason(&self) -> String {
        match self {
            SaveError::NotRegular { target, what, .. } => reason_not_regular(target, what),
            SaveError::OwnInput { input, .. } => format!(
                "is the input {} of this command; saving there would replace it: choose another file",
                input.display()
            ),
            SaveError::ReadOnly { mode, .. } => format!(
                "is read-only (mode {mode:04o}); make it writable (chmod u+w) or save under another name"
            ),
            SaveError::Io { action, source, .. } => format!("{action}: {source}"),
        }
    }

    /// As an `io::Error` carrying [`reason`](Self::reason), for error types
    /// that hold one.
    pub fn into_io(self) -> std::io::Error {
        let reason = self.reason();
        match self {
            SaveError::NotRegular { .. } | SaveError::OwnInput { .. } => {
                std::io::Error::new(std::io::ErrorKind::InvalidInput, reason)
            }
            SaveError::ReadOnly { .. } => {
                std::io::Error::new(std::io::ErrorKind::PermissionDenied, reason)
            }
            SaveError::Io { source, .. } => std::io::Error::new(source.kind(), reason),
        }
    }
}

/// The save: `check` judges the file that is there (path, where its links
/// lead, its metadata) before anything is written; `unnamed` allows the
/// unnamed temp file (tests take the named path too, which other systems
/// always take).
pub(crate) fn replace(
    path: &Path,
    check: impl FnOnce(&Path, &Path, &fs::Metadata) -> Result<(), SaveError>,
    write: impl FnOnce(&mut File) -> std::io::Result<()>,
    unnamed: bool,
) -> Result<(), SaveError> {
    let err = |action, source| SaveError::Io {
        path: path.to_path_buf(),
        action,
        source,
    };
    let (target, existing) = resolve(path).map_err(|e| err("cannot follow the path", e))?;
    if let Some(meta) = &existing {
        check(path, &target, meta)?;
    }
    let (dir, name) = dir_and_name(path, &target)?;
    clean_stale(&dir);

    let mut temp =
        Temp::create(&dir, name, unnamed).map_err(|e| err("cannot create a temp file", e))?;
    let written = (|| {
        if let Some(meta) = &existing {
            keep_owner_and_mode(&temp.file, meta)?;
        }
        write(&mut temp.file)?;
        temp.file.sync_all()
    })();
    if let Err(e) = written {
        temp.discard();
        return Err(err("cannot write", e));
    }
    if let Err(e) = temp.publish(&target) {
        return Err(err("cannot replace the file", e));
    }
    // Make the rename itself durable; a folder that cannot be fsynced
    // (some network file systems) still has the new file.
    if let Ok(d) = File::open(&dir) {
        let _ = d.sync_all();
    }
    Ok(())
}

/// The folder a save to `target` (reached from `path`) writes in, and the
/// file's name, or why the path names no file.
pub(crate) fn dir_and_name<'a>(
    path: &Path,
    target: &'a Path,
) -> Result<(PathBuf, &'a OsStr), SaveError> {
    let name = target.file_name().ok_or_else(|| SaveError::Io {
        path: path.to_path_buf(),
        action: "cannot save",
        source: std::io::Error::new(
            std::io::ErrorKind::InvalidInput,
            "the path names no file (it ends in '..' or '/')",
        ),
    })?;
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    Ok((dir, name))
}

/// Whether a temp file for `name` can be made in `dir`: the folder exists,
/// is a folder, and takes new files. The probe leaves nothing behind.
pub(crate) fn probe(dir: &Path, name: &OsStr) -> std::io::Result<()> {
    let meta = fs::metadata(dir).map_err(|e| match e.kind() {
        std::io::ErrorKind::NotFound => std::io::Error::new(
            e.kind(),
            format!("the folder {} does not exist", dir.display()),
        ),
        _ => e,
    })?;
    if !meta.is_dir() {
        return Err(std::io::Error::new(
            std::io::ErrorKind::NotADirectory,
            format!("{} is not a folder", dir.display()),
        ));
    }
    Temp::create(dir, name, true).map(Temp::discard)
}

/// Follows symlinks from `path` to the file a save must replace, and that
/// file's metadata if it exists. A dangling link leads to the file it names,
/// which the save creates.
pub(crate) fn resolve(path: &Path) -> std::io::Result<(PathBuf, Option<fs::Metadata>)> {
    let mut p = path.to_path_buf();
    for _ in 0..MAX_HOPS {
        match fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let next = fs::read_link(&p)?;
                p = if next.is_absolute() {
                    next
                } else {
                    p.parent().unwrap_or(Path::new("")).join(next)
                };
            }
            Ok(m) => return Ok((p, Some(m))),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok((p, None)),
            Err(e) => return Err(e),
        }
    }
    Err(std::io::Error::other(format!(
        "more than {MAX_HOPS} symbolic links in a row (a loop?)"
    )))
}

/// Gives the new file the old one's permission bits, and its owner and
/// group where allowed (failing to chown is not an error: a user saving a
/// file someone else owns gets it as their own, as with any editor).
fn keep_owner_and_mode(file: &File, old: &fs::Metadata) -> std::io::Result<()> {
    #[cfg(unix)]
    {
        use std::os::unix::fs::{MetadataExt, PermissionsExt};
        use std::os::unix::io::AsRawFd;
        // Owner first: chown clears set-id bits, the chmod after restores the mode.
        let fd = file.as_raw_fd();
        // SAFETY: fchown on a valid, open descriptor; failures are expected
        // (not root) and only mean the new file is ours.
        if unsafe { libc::fchown(fd, old.uid(), old.gid()) } != 0 {
            // Not root: at least keep the group, if we are in it.
            let _ = unsafe { libc::fchown(fd, u32::MAX, old.gid()) };
        }
        file.set_permissions(fs::Permissions::from_mode(old.mode() & 0o7777))?;
    }
    #[cfg(not(unix))]
    {
        file.set_permissions(old.permissions())?;
    }
    Ok(())
}

/// The temp file of one save.
struct Temp {
    file: File,
    dir: PathBuf,
    base: std::ffi::OsString,
    /// Set once the file has a name in the folder.
    named: Option<PathBuf>,
}

impl Temp {
    fn create(dir: &Path, base: &OsStr, unnamed: bool) -> std::io::Result<Temp> {
        #[cfg(target_os = "linux")]
        if unnamed && let Some(file) = open_unnamed(dir) {
            // Linked later through /proc/self/fd (see `link`).
            return Ok(Temp {
                file,
                dir: dir.to_path_buf(),
                base: base.to_os_string(),
                named: None,
            });
        }
        let mut last = None;
        // A stale file of a dead process may hold a name; try a few.
        for _ in 0..16 {
            let tmp = temp_name(dir, base);
            match fs::OpenOptions::new()
                .write(true)
                .create_new(true)
                .open(&tmp)
            {
                Ok(file) => {
                    return Ok(Temp {
                        file,
                        dir: dir.to_path_buf(),
                        base: base.to_os_string(),
                        named: Some(tmp),
                    });
                }
                Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => last = Some(e),
                Err(e) => return Err(e),
            }
        }
        Err(last.unwrap_or_else(|| std::io::Error::other("no free temp name")))
    }

    /// Gives the file its temp name (if unnamed) and renames it over `target`.
    fn publish(mut self, target: &Path) -> std::io::Result<()> {
        let tmp = match self.named.take() {
            Some(t) => t,
            None => self.link()?,
        };
        fs::rename(&tmp, target).inspect_err(|_| {
            let _ = fs::remove_file(&tmp);
        })
    }

    #[cfg(target_os = "linux")]
    fn link(&self) -> std::io::Result<PathBuf> {
        use std::os::unix::ffi::OsStrExt;
        use std::os::unix::io::AsRawFd;
        let from = std::ffi::CString::new(format!("/proc/self/fd/{}", self.file.as_raw_fd()))
            .map_err(std::io::Error::other)?;
        for _ in 0..16 {
            let tmp = temp_name(&self.dir, &self.base);
            let to = std::ffi::CString::new(tmp.as_os_str().as_bytes())
                .map_err(std::io::Error::other)?;
            // SAFETY: both paths are NUL-terminated C strings that outlive the call.
            let rc = unsafe {
                libc::linkat(
                    libc::AT_FDCWD,
                    from.as_ptr(),
                    libc::AT_FDCWD,
                    to.as_ptr(),
                    libc::AT_SYMLINK_FOLLOW,
                )
            };
            if rc == 0 {
                return Ok(tmp);
            }
            let e = std::io::Error::last_os_error();
            if e.kind() != std::io::ErrorKind::AlreadyExists {
                return Err(e);
            }
        }
        Err(std::io::Error::other("no free temp name"))
    }

    #[cfg(not(target_os = "linux"))]
    fn link(&self) -> std::io::Result<PathBuf> {
        Err(std::io::Error::other("unnamed temp files are Linux-only"))
    }

    fn discard(self) {
        if let Some(t) = &self.named {
            let _ = fs::remove_file(t);
        }
    }
}

/// An unnamed file in `dir`, or None where the system or file system has no
/// `O_TMPFILE` (then a named temp file is used).
#[cfg(target_os = "linux")]
fn open_unnamed(dir: &Path) -> Option<File> {
    use std::os::unix::fs::OpenOptionsExt;
    if !Path::new("/proc/self/fd").is_dir() {
        return None;
    }
    fs::OpenOptions::new()
        .write(true)
        .mode(0o666)
        .custom_flags(libc::O_TMPFILE)
        .open(dir)
        .ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::io::Write;

    /// The policy-free save (a regular file or nothing; see `Guard` for the rest).
    fn save(
        path: &Path,
        write: impl FnOnce(&mut File) -> std::io::Result<()>,
        unnamed: bool,
    ) -> Result<(), SaveError> {
        replace(path, regular, write, unnamed)
    }

    fn regular(path: &Path, target: &Path, meta: &fs::Metadata) -> Result<(), SaveError> {
        if meta.is_file() {
            return Ok(());
        }
        Err(SaveError::NotRegular {
            path: path.to_path_buf(),
            target: (target != path).then(|| target.to_path_buf()),
            what: crate::io::read::describe(meta.file_type()),
        })
    }

    fn save_atomic(path: &Path, bytes: &[u8]) -> Result<(), SaveError> {
        save(path, |f| f.write_all(bytes), true)
    }

    fn save_atomic_with(
        path: &Path,
        write: impl FnOnce(&mut File) -> std::io::Result<()>,
    ) -> Result<(), SaveError> {
        save(path, write, true)
    }

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
    fn a_failing_write_keeps_the_old_file_and_leaves_no_temp() {
        let dir = tempfile::tempdir().unwrap();
        let target = dir.path().join("keep.toml");
        fs::write(&target, b"old").unwrap();
        let e = save_atomic_with(&target, |f| {
            f.write_all(b"half")?;
            Err(std::io::Error::other("disk full"))
        })
        .unwrap_err();
        assert!(e.to_string().contains("disk full"), "{e}");
        assert_eq!(fs::read(&target).unwrap(), b"old");
        assert_eq!(names(dir.path()), ["keep.toml"]);
    }

    /// Both kinds of temp file give the same result: the target replaced,
    /// its mode kept, nothing left behind.
    #[cfg(unix)]
    #[test]
    fn named_and_unnamed_temps_replace_alike() {
        use std::os::unix::fs::PermissionsExt;
        for unnamed in [false, true] {
            let dir = tempfile::tempdir().unwrap();
            let target = dir.path().join("t.toml");
            fs::write(&target, b"old").unwrap();
            fs::set_permissions(&target, fs::Permissions::from_mode(0o640)).unwrap();
            save(&target, |f| f.write_all(b"new"), unnamed).unwrap();
            assert_eq!(fs::read(&target).unwrap(), b"new");
            let mode = fs::metadata(&target).unwrap().permissions().mode() & 0o777;
            assert_eq!(mode, 0o640, "unnamed = {unnamed}");
            let e = save(&target, |_| Err(std::io::Error::other("full")), unnamed);
            assert!(e.is_err());
            assert_eq!(fs::read(&target).unwrap(), b"new");
            save(
                &dir.path().join("fresh.toml"),
                |f| f.write_all(b"x"),
                unnamed,
            )
            .unwrap();
            assert_eq!(
                names(dir.path()),
                ["fresh.toml", "t.toml"],
                "unnamed = {unnamed}"
            );
        }
    }

    #[cfg(unix)]
    #[test]
    fn links_are_followed_and_special_files_refused() {
        use std::os::unix::fs::{PermissionsExt, symlink};
        let dir = tempfile::tempdir().unwrap();
        let real = dir.path().join("real.toml");
        fs::write(&real, b"old").unwrap();
        fs::set_permissions(&real, fs::Permissions::from_mode(0o600)).unwrap();
        let link = dir.path().join("link.toml");
        symlink("real.toml", &link).unwrap();
        save_atomic(&link, b"new").unwrap();
        assert!(
            fs::symlink_metadata(&link)
                .unwrap()
                .file_type()
                .is_symlink()
        );
        assert_eq!(fs::read(&real).unwrap(), b"new");
        let mode = fs::metadata(&real).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o600);

        let dangling = dir.path().join("dangling.toml");
        symlink("made.toml", &dangling).unwrap();
        save_atomic(&dangling, b"x").unwrap();
        assert_eq!(fs::read(dir.path().join("made.toml")).unwrap(), b"x");

        let null = dir.path().join("null.toml");
        symlink("/dev/null", &null).unwrap();
        let e = save_atomic(&null, b"x").unwrap_err();
        assert!(e.to_string().contains("character device"), "{e}");

        let looped = dir.path().join("loop.toml");
        symlink("loop.toml", &looped).unwrap();
        assert!(save_atomic(&looped, b"x").is_err());
        assert_eq!(
            names(dir.path()),
            [
                "dangling.toml",
                "link.toml",
                "loop.toml",
                "made.toml",
                "null.toml",
                "real.toml"
            ]
        );
    }
}
