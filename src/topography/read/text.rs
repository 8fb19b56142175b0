//! Text: numbers separated by white space, commas or semicolons, one row
//! per line; blank lines and lines starting with `#` are skipped; `nan`
//! (any case) marks a missing point. By the number of columns: 1 = a
//! profile, 2 = `x z` pairs, 3 = `x y z` triples on a regular grid,
//! otherwise (or with [`Format::Matrix`](super::Format::Matrix)) a matrix,
//! rows = y. A single line is a profile.

use super::{clip, Ctx, ReadError, ReadOptions};
use crate::topography::Topography;

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
/// line each row comes from.
struct Table {
    values: Vec<f64>,
    cols: usize,
    lines: Vec<usize>,
}

impl Table {
    fn rows(&self) -> usize {
        self.lines.len()
    }

    fn column(&self, c: usize) -> Vec<f64> {
        self.values.iter().skip(c).step_by(self.cols).copied().collect()
    }
}

/// Reads a text file's content (`bytes`, the whole file); `matrix`: read a
/// matrix whatever the number of columns.
pub(super) fn read(cx: &Ctx, bytes: &[u8], options: &ReadOptions, matrix: bool) -> Result<Topography, ReadError> {
    let table = parse(cx, bytes)?;
    let z = options.z_unit;
    match table.cols {
        _ if matrix || table.cols > 3 || table.rows() == 1 => {
            let heights = table.values.iter().map(|h| z * h).collect();
            let (nx, ny) = (table.cols, table.rows());
            cx.make(heights, (nx, ny), (None, None), options, ny == 1)
        }
        1 => {
            let heights = table.values.iter().map(|h| z * h).collect();
            cx.make(heights, (table.rows(), 1), (None, None), options, true)
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

/// The numbers of the file, checked: UTF-8, numbers, no infinity, rows of
/// one length, at least one.
fn parse(cx: &Ctx, bytes: &[u8]) -> Result<Table, ReadError> {
    let text = std::str::from_utf8(bytes).map_err(|e| {
        let line = 1 + bytes[..e.valid_up_to()].iter().filter(|&&b| b == b'\n').count();
        text_err(cx, line, "not UTF-8 text")
    })?;
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut table = Table {
        values: Vec::new(),
        cols: 0,
        lines: Vec::new(),
    };
    for (i, line) in text.lines().enumerate() {
        let line_no = i + 1;
        let trimmed = line.trim();
        if trimmed.is_empty() || trimmed.starts_with('#') {
            continue;
        }
        let before = table.values.len();
        for field in trimmed
            .split(|c: char| c.is_whitespace() || c == ',' || c == ';')
            .filter(|f| !f.is_empty())
        {
            match field.parse::<f64>() {
                Ok(v) if v.is_infinite() => {
                    return Err(text_err(cx, line_no, format!("'{}' is infinite", clip(field, 40))))
                }
                Ok(v) => table.values.push(v),
                Err(_) => {
                    return Err(text_err(cx, line_no, format!("'{}' is not a number", clip(field, 40))));
                }
            }
        }
        let cols = table.values.len() - before;
        if cols == 0 {
            return Err(text_err(cx, line_no, "no numbers, only separators"));
        }
        if table.lines.is_empty() {
            table.cols = cols;
        } else if cols != table.cols {
            return Err(text_err(
                cx,
                line_no,
                format!("{cols} numbers, line {} has {}", table.lines[0], table.cols),
            ));
        }
        table.lines.push(line_no);
    }
    if table.lines.is_empty() {
        return Err(cx.size("the file holds no numbers"));
    }
    Ok(table)
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
