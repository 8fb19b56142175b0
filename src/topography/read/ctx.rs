//! The file being read: the readers' errors naming it, bounded
//! allocation, the intervals from the file or the options.

use super::*;

/// The file being read, for the readers' errors.
pub(super) struct Ctx<'a> {
    pub(super) path: &'a Path,
}

impl Ctx<'_> {
    pub(super) fn path(&self) -> PathBuf {
        self.path.to_path_buf()
    }

    pub(super) fn io(&self, source: io::Error) -> ReadError {
        ReadError::Io {
            path: self.path(),
            source,
        }
    }

    /// A failed read: `eof()` if the file ended early, else an I/O error.
    pub(super) fn eof_or(&self, e: io::Error, eof: impl FnOnce() -> ReadError) -> ReadError {
        if e.kind() == io::ErrorKind::UnexpectedEof {
            eof()
        } else {
            self.io(e)
        }
    }

    pub(super) fn too_large(&self, what: impl Into<String>, bytes: u64, limit: u64) -> ReadError {
        ReadError::TooLarge {
            path: self.path(),
            what: what.into(),
            bytes,
            limit,
        }
    }

    pub(super) fn size(&self, detail: impl Into<String>) -> ReadError {
        ReadError::Size {
            path: self.path(),
            detail: detail.into(),
        }
    }

    pub(super) fn unsupported(&self, detail: impl Into<String>) -> ReadError {
        ReadError::Unsupported {
            path: self.path(),
            detail: detail.into(),
        }
    }

    /// A malformed file of `format` (its description).
    pub(super) fn format(&self, format: &'static str, detail: impl Into<String>) -> ReadError {
        ReadError::Format {
            path: self.path(),
            format,
            detail: detail.into(),
        }
    }

    /// The index of the channel to read among `names` (the file's
    /// channels, in order): the one the options ask for, else `default`
    /// (the file's height channel, if the reader can tell), else the only
    /// one; an error listing them when the choice is wrong or ambiguous.
    pub(super) fn channel(
        &self,
        names: &[String],
        default: Option<usize>,
        options: &ReadOptions,
    ) -> Result<usize, ReadError> {
        let error = |detail: String| ReadError::Channel {
            path: self.path(),
            detail,
            available: names.to_vec(),
        };
        match &options.channel {
            Some(Channel::Index(i)) if *i < names.len() => Ok(*i),
            Some(Channel::Index(i)) => Err(error(format!(
                "channel {i} is out of range: must be 0 to {}",
                names.len().saturating_sub(1)
            ))),
            Some(Channel::Name(name)) => {
                let found: Vec<usize> = (0..names.len())
                    .filter(|&i| names[i].eq_ignore_ascii_case(name))
                    .collect();
                match found[..] {
                    [i] => Ok(i),
                    [] => Err(error(format!("no channel is called \"{}\"", clip(name, 40)))),
                    _ => Err(error(format!("several channels are called \"{name}\": give its index"))),
                }
            }
            None => match (default, names.len()) {
                (Some(i), _) if i < names.len() => Ok(i),
                (_, 1) => Ok(0),
                (_, 0) => Err(error("the file has no channel of heights".into())),
                _ => Err(error(
                    "the file has several channels and none is a height channel: choose one with the channel option"
                        .into(),
                )),
            },
        }
    }

    pub(super) fn topography(&self, source: TopographyError) -> ReadError {
        ReadError::Topography {
            path: self.path(),
            source,
        }
    }

    /// An empty vector with room for exactly `points` heights, if they are
    /// within [`ReadOptions::max_points`] (`what`: where the size comes
    /// from, for the error) and memory can be had.
    pub(super) fn heights(
        &self,
        what: impl FnOnce() -> String,
        points: u64,
        options: &ReadOptions,
    ) -> Result<Vec<f64>, ReadError> {
        self.check_points(what, points, options)?;
        self.vec(points)
    }

    /// `points` within [`ReadOptions::max_points`].
    pub(super) fn check_points(
        &self,
        what: impl FnOnce() -> String,
        points: u64,
        options: &ReadOptions,
    ) -> Result<(), ReadError> {
        if points > options.max_points {
            return Err(ReadError::TooManyPoints {
                path: self.path(),
                what: what(),
                points,
                limit: options.max_points,
            });
        }
        Ok(())
    }

    /// An empty vector with room for exactly `len` items, or an error if
    /// memory cannot be had (never an abort).
    pub(super) fn vec<T>(&self, len: u64) -> Result<Vec<T>, ReadError> {
        let out_of_memory = || ReadError::OutOfMemory {
            path: self.path(),
            points: len,
        };
        let len = usize::try_from(len).map_err(|_| out_of_memory())?;
        let mut v = Vec::new();
        v.try_reserve_exact(len).map_err(|_| out_of_memory())?;
        Ok(v)
    }

    /// The interval `name` from the file's value or else the options'.
    pub(super) fn interval(
        &self,
        name: &'static str,
        file: Option<f64>,
        option: Option<f64>,
    ) -> Result<f64, ReadError> {
        let agree = |a: f64, b: f64| (a - b).abs() <= CONFLICT_REL * a.abs().max(b.abs());
        match (file, option) {
            (Some(file), Some(option)) if !agree(file, option) => Err(ReadError::Conflict {
                path: self.path(),
                name,
                file,
                option,
            }),
            (Some(value), _) | (None, Some(value)) => Ok(value),
            (None, None) => Err(ReadError::NeedInterval {
                path: self.path(),
                name,
            }),
        }
    }

    /// A profile (`ny == 1`, with no y interval given by the file) or a map.
    pub(super) fn make(
        &self,
        heights: Vec<f64>,
        (nx, ny): (usize, usize),
        (dx, dy): (Option<f64>, Option<f64>),
        options: &ReadOptions,
        profile: bool,
    ) -> Result<Topography, ReadError> {
        let dx = self.interval("dx", dx, options.dx)?;
        if profile {
            Topography::profile(heights, dx)
        } else {
            // dy defaults to the dx of the options where neither the file
            // nor the options give one: a file's own dy is kept (only a dy
            // given explicitly contradicts it).
            let dy = match (dy, options.dy) {
                (None, None) => self.interval("dy", None, options.dx)?,
                _ => self.interval("dy", dy, options.dy)?,
            };
            Topography::map(heights, nx, ny, dx, dy)
        }
        .map_err(|e| self.topography(e))
    }
}
