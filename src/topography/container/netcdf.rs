//! A bounded reader of the NetCDF-3 files SurfaceTopography writes for a
//! container's measurements (`squeezed-netcdf`, its `to_netcdf`: classic
//! or 64-bit offset format): a variable `heights` over dimensions `x` (a
//! profile), `x, y` (a map, indexed `[x, y]`) or `n` (a nonuniform profile
//! with positions in the variable `x`); the attributes `length`, `unit`
//! and `periodic` of `x` and `y`, `unit` of `heights`; an optional `mask`
//! variable (undefined points), `_FillValue` / `missing_value` of
//! `heights` (undefined points, as scipy's `maskandscale` reads them); the
//! global attribute `json` (SurfaceTopography's `info`, with the
//! instrument's parameters).
//!
//! Own code rather than the `netcdf3` crate: that crate (14 000 lines on
//! `nom`, marked experimental) allocates from the counts a header declares
//! before checking them against the file, and reads from paths; this one
//! is ~300 lines over the bytes of a zip member, every count bounded by
//! the bytes left and every offset by checked arithmetic. Record
//! variables, the 64-bit data format (CDF-5) and `scale_factor` /
//! `add_offset` are refused, not misread.

/// The most characters a name may have (NetCDF's `NC_MAX_NAME`).
const MAX_NAME: usize = 256;

/// An attribute's values.
#[derive(Debug, Clone)]
pub(super) enum Value {
    /// Characters (`NC_CHAR`), as bytes.
    Text(Vec<u8>),
    /// Numbers of any numeric type, as f64.
    Numbers(Vec<f64>),
}

impl Value {
    fn number(&self) -> Option<f64> {
        match self {
            Value::Numbers(v) if v.len() == 1 => Some(v[0]),
            _ => None,
        }
    }

    fn text(&self) -> Option<&str> {
        match self {
            Value::Text(t) => std::str::from_utf8(t).ok().map(|s| s.trim_end_matches('\0')),
            _ => None,
        }
    }
}

/// A variable of the header.
#[derive(Debug)]
struct Variable {
    name: String,
    dims: Vec<usize>,
    attributes: Vec<(String, Value)>,
    nc_type: u32,
    begin: u64,
}

impl Variable {
    fn attribute(&self, name: &str) -> Option<&Value> {
        self.attributes.iter().find(|(n, _)| n == name).map(|(_, v)| v)
    }
}

/// What a SurfaceTopography NetCDF file holds.
#[derive(Debug, Clone)]
pub(super) enum Grid {
    /// A map of `nx` × `ny` points, heights in rows of x (`h[j·nx + i]`).
    Map {
        /// Points along x.
        nx: usize,
        /// Points along y.
        ny: usize,
        /// The heights (file unit; NaN where undefined).
        heights: Vec<f64>,
    },
    /// A uniform profile.
    Profile(Vec<f64>),
    /// A nonuniform profile: positions and heights (file unit).
    Nonuniform {
        /// Positions.
        x: Vec<f64>,
        /// Heights.
        z: Vec<f64>,
    },
}

/// A read NetCDF measurement.
#[derive(Debug, Clone)]
pub(super) struct NcMeasurement {
    /// The heights.
    pub grid: Grid,
    /// The physical sizes along x (and y) from the `length` attributes, in
    /// the file's unit.
    pub lengths: Option<Vec<f64>>,
    /// The length unit of the positions (`x:unit`, else `heights:unit`).
    pub unit: Option<String>,
    /// `x:periodic` ≠ 0.
    pub periodic: bool,
    /// The global attribute `json` (SurfaceTopography's `info`).
    pub json: Option<String>,
}

/// A cursor over the header with checked reads.
struct Cursor<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl Cursor<'_> {
    fn take(&mut self, n: usize, what: &str) -> Result<&[u8], String> {
        let end = self
            .at
            .checked_add(n)
            .filter(|&e| e <= self.bytes.len())
            .ok_or_else(|| format!("the header ends inside {what}"))?;
        let out = &self.bytes[self.at..end];
        self.at = end;
        Ok(out)
    }

    fn u32(&mut self, what: &str) -> Result<u32, String> {
        let b = self.take(4, what)?;
        Ok(u32::from_be_bytes([b[0], b[1], b[2], b[3]]))
    }

    fn u64(&mut self, what: &str) -> Result<u64, String> {
        let b = self.take(8, what)?;
        let mut a = [0u8; 8];
        a.copy_from_slice(b);
        Ok(u64::from_be_bytes(a))
    }

    fn left(&self) -> usize {
        self.bytes.len() - self.at
    }

    /// A count of items each at least `min_bytes` long: at most what the
    /// bytes left can hold.
    fn count(&mut self, min_bytes: usize, what: &str) -> Result<usize, String> {
        let n = self.u32(what)? as usize;
        if n > self.left() / min_bytes.max(1) {
            return Err(format!("{what}: {n} declared, more than the file holds"));
        }
        Ok(n)
    }

    /// Skips the padding to a multiple of 4 after `n` bytes.
    fn pad(&mut self, n: usize, what: &str) -> Result<(), String> {
        self.take((4 - n % 4) % 4, what).map(|_| ())
    }

    fn name(&mut self, what: &str) -> Result<String, String> {
        let n = self.u32(what)? as usize;
        if n > MAX_NAME {
            return Err(format!("{what}: a name of {n} bytes, over {MAX_NAME}"));
        }
        let b = self.take(n, what)?.to_vec();
        self.pad(n, what)?;
        String::from_utf8(b).map_err(|_| format!("{what}: a name that is not UTF-8"))
    }
}

/// The size in bytes of a value of `nc_type`.
fn type_size(nc_type: u32) -> Result<usize, String> {
    match nc_type {
        1 | 2 => Ok(1),
        3 => Ok(2),
        4 | 5 => Ok(4),
        6 => Ok(8),
        t => Err(format!("data type {t} is not a NetCDF-3 type (1 to 6)")),
    }
}

/// Big-endian values of `nc_type` as f64.
fn numbers(bytes: &[u8], nc_type: u32) -> Vec<f64> {
    match nc_type {
        1 => bytes.iter().map(|&b| f64::from(b as i8)).collect(),
        2 => bytes.iter().map(|&b| f64::from(b)).collect(),
        3 => bytes
            .chunks_exact(2)
            .map(|c| f64::from(i16::from_be_bytes([c[0], c[1]])))
            .collect(),
        4 => bytes
            .chunks_exact(4)
            .map(|c| f64::from(i32::from_be_bytes([c[0], c[1], c[2], c[3]])))
            .collect(),
        5 => bytes
            .chunks_exact(4)
            .map(|c| f64::from(f32::from_be_bytes([c[0], c[1], c[2], c[3]])))
            .collect(),
        _ => bytes
            .chunks_exact(8)
            .map(|c| f64::from_be_bytes([c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]]))
            .collect(),
    }
}

/// An attribute list (`ABSENT` or `NC_ATTRIBUTE nelems [attr ...]`).
fn attributes(c: &mut Cursor, what: &str) -> Result<Vec<(String, Value)>, String> {
    let tag = c.u32(what)?;
    if tag == 0 {
        c.u32(what)?;
        return Ok(Vec::new());
    }
    if tag != 12 {
        return Err(format!("{what}: tag {tag}, not an attribute list (12)"));
    }
    let n = c.count(12, what)?;
    let mut out = Vec::with_capacity(n);
    for _ in 0..n {
        let name = c.name(what)?;
        let nc_type = c.u32(what)?;
        let size = type_size(nc_type).map_err(|e| format!("{what} {name}: {e}"))?;
        let count = c.u32(what)? as usize;
        let len = count
            .checked_mul(size)
            .filter(|&l| l <= c.left())
            .ok_or_else(|| format!("{what} {name}: {count} values, more than the file holds"))?;
        let bytes = c.take(len, what)?;
        let value = if nc_type == 2 {
            Value::Text(bytes.to_vec())
        } else {
            Value::Numbers(numbers(bytes, nc_type))
        };
        c.pad(len, what)?;
        out.push((name, value));
    }
    Ok(out)
}

/// Reads a NetCDF-3 file of SurfaceTopography's layout (see the module
/// docs), at most `max_points` heights. The errors say what is wrong
/// (the caller names the file).
pub(super) fn read(bytes: &[u8], max_points: u64) -> Result<NcMeasurement, String> {
    let mut c = Cursor { bytes, at: 0 };
    let magic = c.take(4, "the magic number")?;
    let wide = match magic {
        b"CDF\x01" => false,
        b"CDF\x02" => true,
        [b'C', b'D', b'F', 5] => {
            return Err("a NetCDF-3 64-bit data (CDF-5) file, not read (classic or 64-bit offset only)".into())
        }
        _ if magic.starts_with(b"\x89HDF") => return Err("a NetCDF-4 (HDF5) file, not read (NetCDF-3 only)".into()),
        _ => return Err("not a NetCDF-3 file (no CDF magic number)".into()),
    };
    c.u32("the record count")?;
    // Dimensions.
    let tag = c.u32("the dimension list")?;
    let mut dims: Vec<(String, usize)> = Vec::new();
    if tag == 10 {
        let n = c.count(8, "the dimensions")?;
        for _ in 0..n {
            let name = c.name("a dimension")?;
            let len = c.u32("a dimension's length")? as usize;
            dims.push((name, len));
        }
    } else if tag == 0 {
        c.u32("the dimension list")?;
    } else {
        return Err(format!("tag {tag} where the dimension list (10) is expected"));
    }
    let globals = attributes(&mut c, "the global attributes")?;
    // Variables.
    let tag = c.u32("the variable list")?;
    let mut vars: Vec<Variable> = Vec::new();
    if tag == 11 {
        let n = c.count(24, "the variables")?;
        for _ in 0..n {
            let name = c.name("a variable")?;
            let rank = c.count(4, "a variable's dimensions")?;
            let mut ids = Vec::with_capacity(rank);
            for _ in 0..rank {
                let id = c.u32("a dimension id")? as usize;
                if id >= dims.len() {
                    return Err(format!("variable {name}: dimension id {id} of {}", dims.len()));
                }
                ids.push(id);
            }
            let attributes = attributes(&mut c, "a variable's attributes")?;
            let nc_type = c.u32("a variable's type")?;
            type_size(nc_type).map_err(|e| format!("variable {name}: {e}"))?;
            c.u32("a variable's size")?;
            let begin = if wide {
                c.u64("a variable's offset")?
            } else {
                u64::from(c.u32("a variable's offset")?)
            };
            vars.push(Variable {
                name,
                dims: ids,
                attributes,
                nc_type,
                begin,
            });
        }
    } else if tag == 0 {
        c.u32("the variable list")?;
    } else {
        return Err(format!("tag {tag} where the variable list (11) is expected"));
    }
    let var = |name: &str| vars.iter().find(|v| v.name == name);
    let heights = var("heights").ok_or("no variable `heights`")?;
    // A variable's values, every offset and length checked.
    let values = |v: &Variable| -> Result<Vec<f64>, String> {
        let mut count = 1usize;
        for &d in &v.dims {
            let (name, len) = &dims[d];
            if *len == 0 {
                return Err(format!(
                    "variable {}: over the record dimension {name}, not read",
                    v.name
                ));
            }
            count = count
                .checked_mul(*len)
                .filter(|&n| n as u64 <= max_points)
                .ok_or_else(|| format!("variable {}: more than {max_points} values", v.name))?;
        }
        let size = type_size(v.nc_type)?;
        let start = usize::try_from(v.begin).map_err(|_| format!("variable {}: offset past the file", v.name))?;
        let end = count
            .checked_mul(size)
            .and_then(|l| start.checked_add(l))
            .filter(|&e| e <= bytes.len())
            .ok_or_else(|| format!("variable {}: its data lie past the end of the file", v.name))?;
        Ok(numbers(&bytes[start..end], v.nc_type))
    };
    for refused in ["scale_factor", "add_offset"] {
        if heights.attribute(refused).is_some() {
            return Err(format!("heights: attribute {refused} (packed data) is not read"));
        }
    }
    let mut z = values(heights)?;
    // Undefined points: the fill value (scipy's maskandscale) and the mask.
    for key in ["_FillValue", "missing_value"] {
        if let Some(fill) = heights.attribute(key).and_then(Value::number) {
            z.iter_mut().filter(|v| **v == fill).for_each(|v| *v = f64::NAN);
        }
    }
    if let Some(mask) = var("mask") {
        if mask.dims != heights.dims {
            return Err("variable mask: not over the dimensions of heights".into());
        }
        for (v, m) in z.iter_mut().zip(values(mask)?) {
            if m != 0.0 {
                *v = f64::NAN;
            }
        }
    }
    let dim_name = |k: usize| dims[heights.dims[k]].0.as_str();
    let x_var = var("x");
    let y_var = var("y");
    let length = |v: Option<&Variable>| v.and_then(|v| v.attribute("length")).and_then(Value::number);
    let grid = match heights.dims.len() {
        2 if dim_name(0) == "x" && dim_name(1) == "y" => {
            let (nx, ny) = (dims[heights.dims[0]].1, dims[heights.dims[1]].1);
            // Stored [x][y]: rows of x for the library.
            let mut h = Vec::with_capacity(z.len());
            for j in 0..ny {
                for i in 0..nx {
                    h.push(z[i * ny + j]);
                }
            }
            Grid::Map { nx, ny, heights: h }
        }
        1 if dim_name(0) == "x" => Grid::Profile(z),
        1 if dim_name(0) == "n" => {
            let x_var = x_var.ok_or("a nonuniform profile (dimension n) without the variable x")?;
            if x_var.dims != heights.dims {
                return Err("variable x: not over the dimension n of heights".into());
            }
            Grid::Nonuniform { x: values(x_var)?, z }
        }
        _ => {
            let names: Vec<&str> = (0..heights.dims.len()).map(dim_name).collect();
            return Err(format!(
                "heights over ({}): (x), (x, y) or (n) expected",
                names.join(", ")
            ));
        }
    };
    let lengths = match (&grid, length(x_var), length(y_var)) {
        (Grid::Map { .. }, Some(lx), Some(ly)) => Some(vec![lx, ly]),
        (Grid::Profile(_), Some(lx), _) => Some(vec![lx]),
        _ => None,
    };
    let text = |v: Option<&Variable>, key: &str| {
        v.and_then(|v| v.attribute(key))
            .and_then(Value::text)
            .map(str::to_string)
    };
    let unit = text(x_var, "unit").or_else(|| text(Some(heights), "unit"));
    let periodic = x_var
        .and_then(|v| v.attribute("periodic"))
        .and_then(Value::number)
        .is_some_and(|p| p != 0.0);
    let json = globals
        .iter()
        .find(|(n, _)| n == "json")
        .and_then(|(_, v)| v.text())
        .map(str::to_string);
    Ok(NcMeasurement {
        grid,
        lengths,
        unit,
        periodic,
        json,
    })
}
