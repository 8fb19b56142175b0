//! Reading measured surfaces from files (MODEL.md §10): ISO 25178-72 X3P,
//! NumPy `.npy`, text, and the instruments' own formats (Digital Surf
//! `.sur`, Sensofar `.plu`, Bruker/Veeco `.opd`, Alicona `.al3d`, Zygo
//! MetroPro `.dat`, Bruker Nanoscope, Nanosurf `.nid`; the writer is
//! [`super::write`]).
//!
//! The formats are a registry ([`Format::all`]): each is a module here
//! with its entry (name, extensions, signature, reader). The format comes
//! from the extension, checked against the content's signature (a `.npy`
//! that is not one, a zip of an X3P called `.dat`), and from the content
//! where the extension is not a format's (`.x3p`, `.npy`, anything else is
//! text) unless [`ReadOptions::format`] says otherwise. Heights come out in
//! metres: X3P stores metres; `.npy` and text heights are multiplied by
//! [`ReadOptions::z_unit`] (1 by default, i.e. already metres); the
//! instruments' formats with their own scale factors and units. A file
//! with several channels (AFM) gives its first height channel, or the one
//! [`ReadOptions::channel`] names.
//!
//! Missing points (NaN in the file, or marked invalid by an X3P validity
//! mask) stay missing (NaN): never filled. Reads are bounded: a file, or an
//! X3P member, larger than [`ReadOptions::max_bytes`] (2 GiB by default) is
//! refused, and sizes declared by a file are checked against its data
//! before anything is allocated. A bad file gives a [`ReadError`] naming
//! the file and the problem; nothing panics.

mod ctx;
use ctx::Ctx;
mod binary;
mod instrument;
pub(super) use instrument::iso_date_in;

use std::fs::File;
use std::io::{self, BufReader, Cursor, Read, Seek};
use std::path::{Path, PathBuf};

use super::{Topography, TopographyError};
use crate::table::format::escape_text;

/// The default bound on the bytes read: a file, or an X3P member once
/// uncompressed, larger than this is refused (2 GiB).
pub const MAX_BYTES: u64 = 2 << 30;

/// The default bound on the points of a surface: 2²⁸ ≈ 2.7·10⁸, i.e.
/// 2 GiB of f64 heights. A file that declares more is refused before
/// anything is allocated or inflated ([`ReadOptions::max_points`]).
pub const MAX_POINTS: u64 = 1 << 28;

/// Relative difference above which an interval given in the options
/// contradicts the file's own.
const CONFLICT_REL: f64 = 1e-6;

/// How many of a file's first bytes a format's signature check sees.
const SNIFF_BYTES: usize = 64;

/// A file format the readers know: a handle to its entry in the
/// registry ([`Format::all`]). Compare by [`Format::name`].
#[derive(Clone, Copy)]
pub struct Format(&'static Entry);

/// A registry entry: everything about one format, in one place. Adding a
/// format is a reader module and one line in `readers!`.
struct Entry {
    name: &'static str,
    description: &'static str,
    extensions: &'static [&'static str],
    /// Whether the file's first bytes are this format's (`None`: the
    /// format has no signature, as text).
    sniff: Option<fn(&[u8]) -> bool>,
    read: ReadFn,
}

/// A reader: the file's context, its bytes, their length, the options.
type ReadFn = fn(&Ctx, &mut dyn Source, u64, &ReadOptions) -> Result<Topography, ReadError>;

/// Declares the readers' modules and writes [`REGISTRY`] from one line a
/// reader module: `module => [its entries]` (a module may read more than
/// one format: text and matrix).
macro_rules! readers {
    ($($vis:vis $module:ident => [$($entry:ident),+]),+ $(,)?) => {
        $($vis mod $module;)+

        /// The formats, in the order a format is chosen by sniffing (text
        /// and matrix have no signature: any file is text to them, chosen
        /// when no signature matches).
        static REGISTRY: [Entry; [$($(stringify!($entry)),+),+].len()] = [$($($module::$entry),+),+];
    };
}

readers! {
    pub(super) x3p => [ENTRY],
    npy => [ENTRY],
    text => [ENTRY, MATRIX],
    sur => [ENTRY],
    plu => [ENTRY],
    opd => [ENTRY],
    al3d => [ENTRY],
    metropro => [ENTRY],
    nanoscope => [ENTRY],
    nid => [ENTRY],
}

/// Extensions other programs use too (`.dat` for any data, `.spm`, the
/// numbered `.001`, ...): a file with one is its format's only if its
/// content has the format's signature; else it is detected as a file of
/// no known extension (by another format's signature, else text).
const SHARED_EXTENSIONS: [&str; 8] = ["dat", "di", "spm", "001", "002", "003", "004", "005"];

impl Format {
    /// ISO 25178-72 X3P: a zip of `main.xml` and the binary point data.
    pub const X3P: Format = Format(&REGISTRY[0]);
    /// A NumPy `.npy` array: 1-D = profile, 2-D = map (rows = y); `f4` or
    /// `f8`, either byte order, C or Fortran order.
    pub const NPY: Format = Format(&REGISTRY[1]);
    /// Text, numbers separated by white space, commas or semicolons (`#`
    /// starts a comment line; `nan` marks a missing point; LF, CR or CR LF
    /// end lines). By the number of columns: 1 = a profile; 2 = `x z`
    /// pairs of a profile; 3 = `x y z` triples on a regular grid (the
    /// intervals come from the grid); otherwise a matrix as in
    /// [`Format::MATRIX`]. A single line is a profile.
    pub const TEXT: Format = Format(&REGISTRY[2]);
    /// Text read as a matrix whatever its number of columns: a line is a
    /// row (rows = y), a column is x. A single line is a profile.
    pub const MATRIX: Format = Format(&REGISTRY[3]);
    /// Digital Surf `.sur` (MountainsMap): 16- or 32-bit integer heights
    /// with the header's scale and units; special points are missing.
    pub const SUR: Format = Format(&REGISTRY[4]);
    /// Sensofar `.plu` / `.apx`: f32 heights in µm, one channel a layer.
    pub const PLU: Format = Format(&REGISTRY[5]);
    /// Bruker/Veeco Vision `.opd`: a directory of blocks; each height
    /// raster a channel, in waves of the file's wavelength.
    pub const OPD: Format = Format(&REGISTRY[6]);
    /// Alicona `.al3d`: tags, then f32 heights in metres.
    pub const AL3D: Format = Format(&REGISTRY[7]);
    /// Zygo MetroPro `.dat` (a white-light interferometer's phase map;
    /// invalid points missing).
    pub const METROPRO: Format = Format(&REGISTRY[8]);
    /// Bruker (Digital Instruments, Veeco) Nanoscope AFM files (`.di`,
    /// `.spm`, `.001`, ...): several channels, the first height channel by
    /// default ([`ReadOptions::channel`]).
    pub const NANOSCOPE: Format = Format(&REGISTRY[9]);
    /// Nanosurf `.nid` (and `.ezd`) AFM files: several channels, the first
    /// height channel by default ([`ReadOptions::channel`]).
    pub const NID: Format = Format(&REGISTRY[10]);

    /// Every format, in the registry's order.
    pub fn all() -> impl Iterator<Item = Format> {
        REGISTRY.iter().map(Format)
    }

    /// The format's name: `"x3p"`, `"npy"`, `"text"`, `"matrix"`, ...
    pub fn name(self) -> &'static str {
        self.0.name
    }

    /// What the format is, in a few words.
    pub fn description(self) -> &'static str {
        self.0.description
    }

    /// The file name extensions that select it (lower case, no dot).
    pub fn extensions(self) -> &'static [&'static str] {
        self.0.extensions
    }

    /// The format called `name` (any case).
    pub fn from_name(name: &str) -> Option<Format> {
        Format::all().find(|f| f.name().eq_ignore_ascii_case(name))
    }

    /// The format by the file's extension (any case), else text.
    pub fn from_path(path: &Path) -> Format {
        Format::by_extension(path).unwrap_or(Format::TEXT)
    }

    fn by_extension(path: &Path) -> Option<Format> {
        let ext = path.extension()?.to_str()?;
        Format::all().find(|f| f.extensions().iter().any(|e| e.eq_ignore_ascii_case(ext)))
    }

    /// The format of a file called `path` whose first bytes are `head`:
    /// by an extension of a format with a signature (its reader says what
    /// is wrong if the content is not one), unless the extension is one
    /// other programs use too (`.dat`, `.di`, `.spm`, `.001` … `.005`) and
    /// the signature is not there; else by the content's signature (a zip of an X3P called
    /// `.dat`, a `.npy` without its extension); else by a text extension;
    /// else text.
    pub fn detect(path: &Path, head: &[u8]) -> Format {
        let by_name = Format::by_extension(path);
        let shared = path
            .extension()
            .and_then(|e| e.to_str())
            .is_some_and(|e| SHARED_EXTENSIONS.iter().any(|s| s.eq_ignore_ascii_case(e)));
        match by_name {
            Some(f) if f.0.sniff.is_some_and(|sniff| !shared || sniff(head)) => f,
            _ => Format::all()
                .find(|f| f.0.sniff.is_some_and(|sniff| sniff(head)))
                .or(by_name.filter(|f| f.0.sniff.is_none()))
                .unwrap_or(Format::TEXT),
        }
    }
}

impl PartialEq for Format {
    fn eq(&self, other: &Format) -> bool {
        std::ptr::eq(self.0, other.0)
    }
}

impl Eq for Format {}

impl std::fmt::Debug for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Format({})", self.name())
    }
}

impl std::fmt::Display for Format {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

/// What [`read_file`] needs beyond the file.
///
/// Intervals in the options fill in what the file does not give (a `.npy`
/// array or a text matrix has none); one that contradicts the file's own is
/// an error ([`ReadError::Conflict`]), not silently preferred.
#[derive(Debug, Clone, PartialEq)]
pub struct ReadOptions {
    /// Sampling interval along x (metres), for files that give none.
    pub dx: Option<f64>,
    /// Sampling interval along y (metres), for maps from files that give
    /// none; `None`: the `dx` given here where the file gives no dy either (a file's own
    /// dy is kept: only a dy given here contradicts it).
    pub dy: Option<f64>,
    /// Metres per unit of the heights in `.npy` and text files (1 = metres,
    /// 1e-6 = micrometres). Not applied to X3P, which stores metres, nor
    /// to the instruments' formats, which give their own units.
    pub z_unit: f64,
    /// Metres per unit of the x and y columns of `x z` and `x y z` text.
    pub xy_unit: f64,
    /// The format; `None` = by extension and content ([`Format::detect`]).
    pub format: Option<Format>,
    /// The most bytes read from the file, or from one X3P member once
    /// uncompressed ([`MAX_BYTES`] by default).
    pub max_bytes: u64,
    /// The most points (heights) a surface may have ([`MAX_POINTS`] by
    /// default): checked against the size a file declares before anything
    /// is allocated, so that memory stays bounded by the result.
    pub max_points: u64,
    /// The channel to read from a file with several (AFM: height,
    /// amplitude, phase, ...); `None` = the height channel.
    pub channel: Option<Channel>,
}

/// A channel of a file with several, by name (any case) or by its index in
/// the file (from 0, in the order the error lists them).
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Channel {
    /// The channel's name as the file gives it (any case).
    Name(String),
    /// The channel's index in the file, from 0.
    Index(usize),
}

impl std::str::FromStr for Channel {
    type Err = std::convert::Infallible;

    /// A whole number is an index; anything else a name.
    fn from_str(text: &str) -> Result<Channel, Self::Err> {
        Ok(match text.trim().parse::<usize>() {
            Ok(index) => Channel::Index(index),
            Err(_) => Channel::Name(text.trim().to_string()),
        })
    }
}

impl std::fmt::Display for Channel {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            Channel::Name(name) => f.write_str(name),
            Channel::Index(index) => write!(f, "{index}"),
        }
    }
}

/// How many channels an error message lists (the rest are counted).
const LISTED_CHANNELS: usize = 20;

/// `0 Height, 1 Phase, ...` for an error message: the names escaped and
/// cut ([`clip`]), the first [`LISTED_CHANNELS`] and a count of the rest.
fn list_channels(names: &[String]) -> String {
    if names.is_empty() {
        return "none".into();
    }
    let listed: Vec<String> = names
        .iter()
        .take(LISTED_CHANNELS)
        .enumerate()
        .map(|(i, n)| format!("{i} {}", clip(n, 40)))
        .collect();
    match names.len().checked_sub(LISTED_CHANNELS) {
        Some(more @ 1..) => format!("{} … and {} more", listed.join(", "), thousands(more)),
        _ => listed.join(", "),
    }
}

/// `4389` as `4,389`.
fn thousands(n: usize) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

impl Default for ReadOptions {
    fn default() -> ReadOptions {
        ReadOptions {
            dx: None,
            dy: None,
            z_unit: 1.0,
            xy_unit: 1.0,
            format: None,
            max_bytes: MAX_BYTES,
            max_points: MAX_POINTS,
            channel: None,
        }
    }
}

/// Why a surface file cannot be read. Every message names the file.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The file cannot be opened or read (see [`ReadError::is_io`]).
    #[error("cannot read {}: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The failure.
        source: io::Error,
    },
    /// The file, or a member of the X3P archive, is over the size bound.
    #[error("{}: {what} is {bytes} bytes, over the limit of {limit} bytes", path.display())]
    TooLarge {
        /// The file.
        path: PathBuf,
        /// What is too large.
        what: String,
        /// Its size (bytes).
        bytes: u64,
        /// The bound ([`ReadOptions::max_bytes`]).
        limit: u64,
    },
    /// The file declares more points than [`ReadOptions::max_points`].
    #[error(
        "{}: {what} makes {points} points, over the limit of {limit} (raise it with the max_points option)",
        path.display()
    )]
    TooManyPoints {
        /// The file.
        path: PathBuf,
        /// Where the size comes from.
        what: String,
        /// The points declared.
        points: u64,
        /// The bound ([`ReadOptions::max_points`]).
        limit: u64,
    },
    /// Memory for the heights could not be allocated.
    #[error("{}: cannot allocate memory for {points} points", path.display())]
    OutOfMemory {
        /// The file.
        path: PathBuf,
        /// The points asked for.
        points: u64,
    },
    /// Not a readable zip archive, or a member is missing or damaged
    /// (truncated file, bad CRC).
    #[error("{}: not a readable X3P archive: {detail}", path.display())]
    Archive {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        detail: String,
    },
    /// The X3P `main.xml` is malformed, or lacks or misstates an element.
    #[error("{}: main.xml: {detail}", path.display())]
    Xml {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        detail: String,
    },
    /// An X3P member's MD5 checksum differs from the one in `main.xml`.
    #[error("{}: the MD5 checksum of {member} is {actual}, main.xml says {expected}", path.display())]
    Checksum {
        /// The file.
        path: PathBuf,
        /// The archive member.
        member: String,
        /// The checksum in `main.xml` (hex).
        expected: String,
        /// The checksum of the member (hex).
        actual: String,
    },
    /// Sizes disagree: the data with the sizes declared for it, the rows
    /// of a matrix, or there is no data.
    #[error("{}: inconsistent sizes: {detail}", path.display())]
    Size {
        /// The file.
        path: PathBuf,
        /// What disagrees.
        detail: String,
    },
    /// Something valid but not read here: a data type (dtype), a feature
    /// type, an axis type, volumetric data.
    #[error("{}: unsupported: {detail}", path.display())]
    Unsupported {
        /// The file.
        path: PathBuf,
        /// What is not supported.
        detail: String,
    },
    /// A malformed `.npy` file.
    #[error("{}: not a readable .npy file: {detail}", path.display())]
    Npy {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        detail: String,
    },
    /// A text file's line that cannot be read (a field that is not a
    /// number, an infinite value, a row of another length, not UTF-8).
    #[error("{}, line {line}: {detail}", path.display())]
    Text {
        /// The file.
        path: PathBuf,
        /// The line (from 1).
        line: usize,
        /// What is wrong.
        detail: String,
    },
    /// `x z` or `x y z` text whose points are not on a regular grid.
    #[error("{}: not a regular grid: {detail}", path.display())]
    Irregular {
        /// The file.
        path: PathBuf,
        /// What is irregular.
        detail: String,
    },
    /// Neither the file nor the options give a sampling interval.
    #[error("{}: the file gives no sampling interval {name}: give the sampling interval {name} (metres)", path.display())]
    NeedInterval {
        /// The file.
        path: PathBuf,
        /// `"dx"` or `"dy"`.
        name: &'static str,
    },
    /// An interval in the options contradicts the file's own.
    #[error("{}: the file gives {name} = {file:e} m, the options {option:e} m", path.display())]
    Conflict {
        /// The file.
        path: PathBuf,
        /// `"dx"` or `"dy"`.
        name: &'static str,
        /// The file's interval (metres).
        file: f64,
        /// The options' interval (metres).
        option: f64,
    },
    /// A unit in the options (`z_unit`, `xy_unit`) is not finite and
    /// positive.
    #[error("{}: the unit {name} = {value} is out of range: must be finite and > 0", path.display())]
    Options {
        /// The file.
        path: PathBuf,
        /// The option.
        name: &'static str,
        /// Its value.
        value: f64,
    },
    /// A malformed file of an instrument's own format (`.sur`, `.plu`,
    /// `.opd`, MetroPro `.dat`, Nanoscope `.di`, `.nid`, `.al3d`): a bad
    /// header, an offset or size outside the file.
    #[error("{}: not a readable {format} file: {detail}", path.display())]
    Format {
        /// The file.
        path: PathBuf,
        /// The format's description.
        format: &'static str,
        /// What is wrong.
        detail: String,
    },
    /// The channel asked for ([`ReadOptions::channel`]) is not in the file,
    /// or the file has several height channels and none was asked for.
    #[error("{}: {detail}; the file's channels: {}", path.display(), list_channels(available))]
    Channel {
        /// The file.
        path: PathBuf,
        /// What is wrong.
        detail: String,
        /// The file's channels, in its order.
        available: Vec<String>,
    },
    /// The data read do not make a topography (an infinite height, an
    /// interval out of range).
    #[error("{}: {source}", path.display())]
    Topography {
        /// The file.
        path: PathBuf,
        /// Why.
        source: TopographyError,
    },
}

impl ReadError {
    /// The file the error is about.
    pub fn path(&self) -> &Path {
        match self {
            ReadError::Io { path, .. }
            | ReadError::TooLarge { path, .. }
            | ReadError::TooManyPoints { path, .. }
            | ReadError::OutOfMemory { path, .. }
            | ReadError::Archive { path, .. }
            | ReadError::Xml { path, .. }
            | ReadError::Checksum { path, .. }
            | ReadError::Size { path, .. }
            | ReadError::Unsupported { path, .. }
            | ReadError::Npy { path, .. }
            | ReadError::Text { path, .. }
            | ReadError::Irregular { path, .. }
            | ReadError::NeedInterval { path, .. }
            | ReadError::Conflict { path, .. }
            | ReadError::Options { path, .. }
            | ReadError::Format { path, .. }
            | ReadError::Channel { path, .. }
            | ReadError::Topography { path, .. } => path,
        }
    }

    /// Whether the file could not be read at all (an I/O failure), as
    /// opposed to a file read whose content is bad or unsupported.
    pub fn is_io(&self) -> bool {
        matches!(self, ReadError::Io { .. })
    }
}

/// A file that cannot be read is [`ErrorKind::Io`](crate::ErrorKind::Io);
/// one read whose content is bad, unsupported or too large is the
/// caller's ([`ErrorKind::Argument`](crate::ErrorKind::Argument)); so is
/// one whose heights do not fit in memory (a smaller `max_points` or a
/// bigger machine is the remedy).
impl crate::Classify for ReadError {
    fn kind(&self) -> crate::ErrorKind {
        match self {
            ReadError::Io { .. } => crate::ErrorKind::Io,
            ReadError::Topography { source, .. } => source.kind(),
            _ => crate::ErrorKind::Argument,
        }
    }
}

/// Reads a height map or profile from `path` (see the module docs for the
/// formats, units and bounds).
///
/// ```no_run
/// use ke_friction::topography::{read_file, ReadOptions};
/// // A text matrix of heights in micrometres, sampled every 0.5 µm.
/// let options = ReadOptions { dx: Some(0.5e-6), dy: Some(0.5e-6), z_unit: 1e-6, ..ReadOptions::default() };
/// let surface = read_file("surface.txt".as_ref(), &options)?;
/// println!("{} x {} points", surface.nx(), surface.ny());
/// # Ok::<(), ke_friction::topography::ReadError>(())
/// ```
pub fn read_file(path: &Path, options: &ReadOptions) -> Result<Topography, ReadError> {
    let cx = Ctx { path };
    check_options(&cx, options)?;
    // A device, pipe or directory is refused before it is opened (opening
    // a pipe waits for a writer; /dev/zero would read as 0 bytes).
    regular(&cx, &std::fs::metadata(path).map_err(|e| cx.io(e))?)?;
    let file = File::open(path).map_err(|e| cx.io(e))?;
    let metadata = file.metadata().map_err(|e| cx.io(e))?;
    regular(&cx, &metadata)?;
    let len = metadata.len();
    if len > options.max_bytes {
        return Err(cx.too_large("the file", len, options.max_bytes));
    }
    // Streamed: the file is never held whole, only the heights it makes.
    let mut source = BufReader::with_capacity(CHUNK, file);
    read_from(&cx, &mut source, len, options)
}

/// A regular file, else an I/O error saying what it is.
fn regular(cx: &Ctx, metadata: &std::fs::Metadata) -> Result<(), ReadError> {
    let kind = metadata.file_type();
    if kind.is_file() {
        return Ok(());
    }
    let what = if kind.is_dir() {
        "a directory"
    } else {
        special_kind(&kind).unwrap_or("not a regular file")
    };
    Err(cx.io(io::Error::other(format!(
        "it is {what}, not a regular file: only files are read"
    ))))
}

/// What a special file is: a device, a pipe, a socket.
#[cfg(unix)]
fn special_kind(kind: &std::fs::FileType) -> Option<&'static str> {
    use std::os::unix::fs::FileTypeExt;
    if kind.is_char_device() {
        Some("a character device")
    } else if kind.is_block_device() {
        Some("a block device")
    } else if kind.is_fifo() {
        Some("a pipe (FIFO)")
    } else if kind.is_socket() {
        Some("a socket")
    } else {
        None
    }
}

/// What a special file is (only Unix tells).
#[cfg(not(unix))]
fn special_kind(_: &std::fs::FileType) -> Option<&'static str> {
    None
}

/// Reads a height map or profile from `bytes`, the content of a file
/// called `name` (for the format by extension and for the errors): what a
/// program that holds the file in memory (a web page, a network service)
/// calls in place of [`read_file`]. The same formats, bounds and errors.
///
/// ```
/// use ke_friction::topography::{read_bytes, ReadOptions};
/// let text = b"1 2 3 4\n5 6 7 8\n";
/// let options = ReadOptions { dx: Some(1e-6), dy: Some(1e-6), z_unit: 1e-6, ..ReadOptions::default() };
/// let surface = read_bytes(text, "heights.txt", &options)?;
/// assert_eq!((surface.nx(), surface.ny()), (4, 2));
/// # Ok::<(), ke_friction::topography::ReadError>(())
/// ```
pub fn read_bytes(bytes: &[u8], name: &str, options: &ReadOptions) -> Result<Topography, ReadError> {
    let cx = Ctx { path: Path::new(name) };
    check_options(&cx, options)?;
    let len = bytes.len() as u64;
    if len > options.max_bytes {
        return Err(cx.too_large("the file", len, options.max_bytes));
    }
    read_from(&cx, &mut Cursor::new(bytes), len, options)
}

/// The units in the options are finite and positive.
fn check_options(cx: &Ctx, options: &ReadOptions) -> Result<(), ReadError> {
    for (name, value) in [("z_unit", options.z_unit), ("xy_unit", options.xy_unit)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(ReadError::Options {
                path: cx.path(),
                name,
                value,
            });
        }
    }
    Ok(())
}

/// A file's content, read in order or by position: a buffered file or
/// bytes in memory.
trait Source: Read + Seek {}

impl<T: Read + Seek> Source for T {}

/// The size of the pieces a reader decodes at a time (bytes).
const CHUNK: usize = 1 << 16;

/// Reads the `len` bytes of `source` in the format of the options, or
/// else of the name and content.
fn read_from(cx: &Ctx, source: &mut dyn Source, len: u64, options: &ReadOptions) -> Result<Topography, ReadError> {
    let format = match options.format {
        Some(format) => format,
        None => {
            let mut head = [0u8; SNIFF_BYTES];
            let mut got = 0;
            while got < head.len() {
                match source.read(&mut head[got..]) {
                    Ok(0) => break,
                    Ok(n) => got += n,
                    Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
                    Err(e) => return Err(cx.io(e)),
                }
            }
            source.rewind().map_err(|e| cx.io(e))?;
            Format::detect(cx.path, &head[..got])
        }
    };
    let topography = (format.0.read)(cx, source, len, options)?;
    if options.channel.is_some() && topography.metadata().channels.is_empty() {
        return Err(ReadError::Channel {
            path: cx.path(),
            detail: format!("a channel is chosen, but a {} file has only one", format.name()),
            available: Vec::new(),
        });
    }
    // Every reading says its format; a reader fills in the rest.
    let mut metadata = topography.metadata().clone();
    metadata.format.get_or_insert(format.name());
    Ok(topography.with_metadata(metadata))
}

/// Text from a file for an error message: cut to at most `max`
/// characters, then escaped ([`escape_text`]: control characters such as
/// ESC, CR or \x1c as `\u{…}`, so that a file cannot clear or forge the
/// terminal's output). Every reader puts every string it takes from a
/// file (a name, a value, a line) into its messages through this.
fn clip(text: &str, max: usize) -> String {
    match text.char_indices().nth(max) {
        Some((i, _)) => format!("{}…", escape_text(&text[..i])),
        None => escape_text(text),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 4 × 3 text map in metres.
    const MAP: &[u8] = b"1 2 3 4\n5 6 7 8\n9 1 2 3\n";

    fn options(dx: Option<f64>, dy: Option<f64>) -> ReadOptions {
        ReadOptions {
            dx,
            dy,
            ..ReadOptions::default()
        }
    }

    #[test]
    fn dy_defaults_to_dx_only_where_the_file_gives_none() {
        let read = |o: &ReadOptions| read_bytes(MAP, "map.txt", o);
        // A text matrix gives no intervals: dy = dx.
        let t = read(&options(Some(2e-6), None)).unwrap();
        assert_eq!((t.dx(), t.dy()), (2e-6, Some(2e-6)));
        // A dy given is kept.
        let t = read(&options(Some(2e-6), Some(3e-6))).unwrap();
        assert_eq!((t.dx(), t.dy()), (2e-6, Some(3e-6)));
        // Nothing given: the reader's own error naming dx.
        assert!(matches!(
            read(&options(None, None)),
            Err(ReadError::NeedInterval { name: "dx", .. })
        ));
        // An xyz file gives its own dy (2 m), which dx alone does not contradict.
        let xyz = b"0 0 1\n1 0 2\n0 2 3\n1 2 4\n";
        let t = read_bytes(xyz, "map.xyz", &options(Some(1.0), None));
        let t = t.unwrap();
        assert_eq!((t.dx(), t.dy()), (1.0, Some(2.0)));
    }
}
