//! Text: numbers separated by white space, commas or semicolons, one row
//! per line; blank lines and lines starting with `#` are skipped; `nan`
//! (any case) marks a missing point. By the number of columns: 1 = a
//! profile, 2 = `x z` pairs, 3 = `x y z` triples on a regular grid,
//! otherwise (or with [`Format::MATRIX`](super::Format::MATRIX)) a matrix,
//! rows = y. A single line is a profile.

use super::{clip, Ctx, Entry, ReadError, ReadOptions, Source, CHUNK};
use crate::topography::Topography;

/// The registry's entry: text by its number of columns.
pub(super) const ENTRY: Entry = Entry {
    name: "text",
    description: "text: a column, x z pairs, x y z triples or a matrix",
    extensions: &["txt", "csv", "asc", "xyz", "dat"],
    sniff: None,
    read: |cx, source, _, options| read(cx, source, options, false),
};

/// The registry's entry: text read as a matrix whatever its columns.
pub(super) const MATRIX: Entry = Entry {
    name: "matrix",
    description: "text read as a matrix (rows = y) whatever its columns",
    extensions: &[],
    sniff: None,
    read: |cx, source, _, options| read(cx, source, options, true),
};

/// A grid position is off by more than this fraction of the interval:
/// the grid is irregular.
const GRID_TOL: f64 = 0.01;

fn text_err(cx: &Ctx, line: usize, detail: impl Into<String>) -> ReadError {
    ReadError::Text {
        path: cx.path(),
        line,
        detail: detail.into(),
    }
}

fn irregular(cx: &Ctx, detail: impl Into<String>) -> ReadError {
    ReadError::Irregular {
        path: cx.path(),
        detail: detail.into(),
    }
}

/// The numbers of a text file: `rows` rows of `cols`, row-major, with the
/// line each row comes from (kept only for `x z` and `x y z` files, whose
/// grid errors name lines).
struct Table {
    values: Vec<f64>,
    cols: usize,
    rows: usize,
    lines: Vec<usize>,
}

impl Table {
    fn rows(&self) -> usize {
        self.rows
    }

    fn column(&self, c: usize) -> Vec<f64> {
        self.values.iter().skip(c).step_by(self.cols).copied().collect()
    }
}

/// Reads a text file from `source`; `matrix`: read a matrix whatever the
/// number of columns.
pub(super) fn read(
    cx: &Ctx,
    source: &mut dyn Source,
    options: &ReadOptions,
    matrix: bool,
) -> Result<Topography, ReadError> {
    let mut table = parse(cx, source, options, matrix)?;
    let z = options.z_unit;
    match table.cols {
        _ if matrix || table.cols > 3 || table.rows() == 1 => {
            table.values.iter_mut().for_each(|h| *h *= z);
            let (nx, ny) = (table.cols, table.rows());
            cx.make(table.values, (nx, ny), (None, None), options, ny == 1)
        }
        1 => {
            table.values.iter_mut().for_each(|h| *h *= z);
            let n = table.rows();
            cx.make(table.values, (n, 1), (None, None), options, true)
        }
        2 => {
            let x = Axis::regular(cx, "x", &table.column(0), &table.lines)?;
            if x.n != table.rows() {
                return Err(irregular(
                    cx,
                    format!(
                        "{} points on {} x positions (a profile has one point per x)",
                        table.rows(),
                        x.n
                    ),
                ));
            }
            // As many positions as points: one point at each.
            let mut heights = vec![f64::NAN; x.n];
            for (&i, h) in x.index.iter().zip(table.column(1)) {
                heights[i] = z * h;
            }
            cx.make(heights, (x.n, 1), (x.interval(options), None), options, true)
        }
        _ => {
            let x = Axis::regular(cx, "x", &table.column(0), &table.lines)?;
            let y = Axis::regular(cx, "y", &table.column(1), &table.lines)?;
            let n = table.rows();
            if x.n.checked_mul(y.n) != Some(n) {
                return Err(irregular(
                    cx,
                    format!(
                        "{n} points do not fill the grid of {} x positions by {} y positions",
                        x.n, y.n
                    ),
                ));
            }
            let mut heights = vec![f64::NAN; n];
            let mut line_at = vec![0; n];
            for (k, h) in table.column(2).into_iter().enumerate() {
                let at = y.index[k] * x.n + x.index[k];
                if line_at[at] != 0 {
                    return Err(irregular(
                        cx,
                        format!("lines {} and {} are the same grid point", line_at[at], table.lines[k]),
                    ));
                }
                line_at[at] = table.lines[k];
                heights[at] = z * h;
            }
            cx.make(
                heights,
                (x.n, y.n),
                (x.interval(options), y.interval(options)),
                options,
                false,
            )
        }
    }
}

/// The numbers of the file, checked: numbers, no infinity, rows of one
/// length, at least one. Two passes over the file: the first checks it
/// and counts, the second fills a vector of exactly the size counted (the
/// peak memory is the numbers, not the text nor a growing vector's slack).
fn parse(cx: &Ctx, source: &mut dyn Source, options: &ReadOptions, matrix: bool) -> Result<Table, ReadError> {
    let mut cols = 0;
    let mut first_line = 0;
    let mut rows = 0u64;
    scan(
        cx,
        source,
        |_| {},
        |n, line| {
            if rows == 0 {
                (cols, first_line) = (n, line);
            } else if n != cols {
                return Err(text_err(cx, line, format!("{n} numbers, line {first_line} has {cols}")));
            }
            rows += 1;
            Ok(())
        },
    )?;
    if rows == 0 {
        return Err(cx.size("the file holds no numbers"));
    }
    // Points: a row of an `x z` or `x y z` file is one point; every
    // number of a matrix (or of a single line) is one.
    let coordinates = !matrix && rows > 1 && (2..=3).contains(&cols);
    let points = if coordinates { rows } else { rows * cols as u64 };
    let what = || format!("{rows} rows of {cols} numbers");
    cx.check_points(what, points, options)?;
    let mut values = cx.vec(rows * cols as u64)?;
    let mut lines = cx.vec(if coordinates { rows } else { 0 })?;
    source.rewind().map_err(|e| cx.io(e))?;
    scan(
        cx,
        source,
        |v| {
            if values.len() < values.capacity() {
                values.push(v);
            }
        },
        |_, line| {
            if lines.len() < lines.capacity() {
                lines.push(line);
            }
            Ok(())
        },
    )?;
    if values.len() as u64 != rows * cols as u64 {
        return Err(cx.size("the file changed while it was read"));
    }
    Ok(Table {
        values,
        cols,
        rows: rows as usize,
        lines,
    })
}

/// The longest field read as a number (bytes): longer is an error.
const MAX_FIELD: usize = 1024;

/// Reads the text of `source` as numbers: `value` for each number, then
/// `row(count, line)` at the end of each line that holds numbers. Lines
/// end with LF, CR or CR LF; blank lines and lines starting with `#` are
/// skipped; a UTF-8 byte-order mark at the start is ignored. Nothing but
/// the field being read is held.
fn scan(
    cx: &Ctx,
    source: &mut dyn Source,
    mut value: impl FnMut(f64),
    mut row: impl FnMut(usize, usize) -> Result<(), ReadError>,
) -> Result<(), ReadError> {
    let mut buf = vec![0u8; CHUNK];
    let mut field: Vec<u8> = Vec::with_capacity(64);
    let (mut line, mut count) = (1usize, 0usize);
    let (mut comment, mut punct, mut after_cr, mut first) = (false, false, false, true);
    let mut end_field = |field: &mut Vec<u8>, line: usize, count: &mut usize| -> Result<(), ReadError> {
        if field.is_empty() {
            return Ok(());
        }
        let text = std::str::from_utf8(field).map_err(|_| text_err(cx, line, "not UTF-8 text"))?;
        match text.parse::<f64>() {
            Ok(v) if v.is_infinite() => return Err(text_err(cx, line, format!("'{}' is infinite", clip(text, 40)))),
            Ok(v) => value(v),
            Err(_) => return Err(text_err(cx, line, format!("'{}' is not a number", clip(text, 40)))),
        }
        *count += 1;
        field.clear();
        Ok(())
    };
    loop {
        let got = match source.read(&mut buf) {
            Ok(0) => break,
            Ok(got) => got,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(cx.io(e)),
        };
        let mut bytes = &buf[..got];
        if first {
            first = false;
            // A byte-order mark split over two reads is not looked for: a
            // read of a file or of memory gives at least 3 bytes here.
            bytes = bytes.strip_prefix(b"\xEF\xBB\xBF").unwrap_or(bytes);
        }
        for &b in bytes {
            if after_cr {
                after_cr = false;
                if b == b'\n' {
                    continue;
                }
            }
            match b {
                b'\n' | b'\r' => {
                    end_field(&mut field, line, &mut count)?;
                    if count > 0 {
                        row(count, line)?;
                    } else if punct && !comment {
                        return Err(text_err(cx, line, "no numbers, only separators"));
                    }
                    (count, comment, punct) = (0, false, false);
                    after_cr = b == b'\r';
                    line += 1;
                }
                _ if comment => {}
                b' ' | b'\t' | 0x0b | 0x0c => end_field(&mut field, line, &mut count)?,
                b',' | b';' => {
                    end_field(&mut field, line, &mut count)?;
                    punct = true;
                }
                b'#' if count == 0 && field.is_empty() && !punct => comment = true,
                _ => {
                    if field.len() == MAX_FIELD {
                        let shown = String::from_utf8_lossy(&field);
                        return Err(text_err(
                            cx,
                            line,
                            format!("'{}' is not a number (over {MAX_FIELD} bytes)", clip(&shown, 40)),
                        ));
                    }
                    field.push(b);
                }
            }
        }
    }
    end_field(&mut field, line, &mut count)?;
    if count > 0 {
        row(count, line)?;
    } else if punct && !comment {
        return Err(text_err(cx, line, "no numbers, only separators"));
    }
    Ok(())
}

/// Coordinates (x or y) on a regular axis.
struct Axis {
    /// The position of each point on the axis (0 = the lowest coordinate).
    index: Vec<usize>,
    /// The number of positions.
    n: usize,
    /// The interval in the file's units (`None` with one position).
    step: Option<f64>,
}

impl Axis {
    /// Groups the coordinates `values` into positions and checks that they
    /// are evenly spaced (within [`GRID_TOL`] of the interval); `lines`:
    /// each value's line, for errors.
    fn regular(cx: &Ctx, name: &str, values: &[f64], lines: &[usize]) -> Result<Axis, ReadError> {
        if let Some(k) = values.iter().position(|v| v.is_nan()) {
            return Err(text_err(cx, lines[k], format!("{name} is NaN")));
        }
        let mut order: Vec<usize> = (0..values.len()).collect();
        order.sort_by(|&a, &b| values[a].total_cmp(&values[b]));
        let max_gap = order
            .windows(2)
            .map(|w| values[w[1]] - values[w[0]])
            .fold(0.0, f64::max);
        // Coordinates closer than a tenth of the largest gap are one
        // position (text rounding); distinct positions are at least an
        // interval apart, and the largest gap at most two of them on a
        // regular grid that passes the check below.
        let mut index = vec![0; values.len()];
        let mut n = 1;
        for w in order.windows(2) {
            if values[w[1]] - values[w[0]] > 0.1 * max_gap {
                n += 1;
            }
            index[w[1]] = n - 1;
        }
        let (first, last) = match (order.first(), order.last()) {
            (Some(&a), Some(&b)) => (values[a], values[b]),
            _ => {
                return Ok(Axis {
                    index,
                    n: 0,
                    step: None,
                })
            }
        };
        if n == 1 {
            return Ok(Axis { index, n, step: None });
        }
        let step = (last - first) / (n - 1) as f64;
        for (k, &v) in values.iter().enumerate() {
            let grid = first + index[k] as f64 * step;
            if (v - grid).abs() > GRID_TOL * step {
                return Err(irregular(
                    cx,
                    format!(
                        "{name} = {v} (line {}) is off the evenly spaced {name} positions ({n} from {first} to \
                         {last}, every {step})",
                        lines[k]
                    ),
                ));
            }
        }
        Ok(Axis {
            index,
            n,
            step: Some(step),
        })
    }

    /// The interval in metres, if the file gives one.
    fn interval(&self, options: &ReadOptions) -> Option<f64> {
        self.step.map(|s| s * options.xy_unit)
    }
}
