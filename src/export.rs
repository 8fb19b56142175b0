//! Export of a table to NumPy `.npz` / `.npy` files.
//!
//! [`arrays`] produces the named arrays (all `f64`):
//!
//! | name | shape | content |
//! |---|---|---|
//! | `psi`, `theta`, `f_star` | (nψ), (nθ), (nF) | the lookup table's nodes inside its domain, natural units |
//! | `mu`, `h_star` | (nψ, nθ, nF) | the table's μ and h* at those nodes |
//! | `grid_psi`, `grid_theta`, `grid_h_star` | (mψ), (mθ), (mh) | the build's integration grid (ghost nodes included) |
//! | `grid_p_star`, `grid_fs_star`, `grid_q_star`, `grid_f_star`, `grid_mu` | (mψ, mθ, mh) | the model on that grid; `grid_mu` is NaN where F* ≤ 0 |
//! | `beta`, `nu`, `eps_star` | () | the model constants |
//! | `spline_ln_mu` | (mψ+2, mθ+2, mF+2) | the table's own interpolant: B-spline coefficients of ln μ (ghost nodes included) |
//! | `knots_psi`, `knots_theta`, `knots_f_star` | (mψ), (mθ), (mF) | its knots in the interpolation coordinates ln ψ, √θ, ln F* |
//! | `metadata` | (bytes,) `uint8` | UTF-8 JSON: the table's record ([`metadata`]) |
//! | `interpolant` | (bytes,) `uint8` | UTF-8 JSON: how to evaluate `spline_ln_mu` ([`interpolant`]) |
//!
//! The interpolant: along each axis, with `s = (x − first)/step` in the
//! axis's coordinate x (ln ψ, √θ, ln F*), cell `i = clamp(⌊s⌋, 0, nodes − 2)`
//! and `f = s − i`, ln μ = Σ w_a(f_ψ)·w_b(f_θ)·w_c(f_F)·c[iψ+a, iθ+b, iF+c]
//! over a, b, c in 0..4, with the uniform cubic B-spline weights
//! w = ((1−f)³, 3f³−6f²+4, −3f³+3f²+3f+1, f³)/6. `tools/spline_eval.py`
//! does it in a few lines of NumPy.
//!
//! The table file does not store the integration grid: it is recomputed
//! from the build options the table records ([`BuildOptions::from_table`]).
//! [`write_npz`] and [`write_npy_dir`] write atomically (a temporary file
//! in the same directory, flushed, then renamed).

use crate::build::{params_of, BuildError, BuildOptions, Progress};
use crate::io::{write_atomic_with, write_dir_atomic, WriteFile};
use crate::model::Model;
use crate::spline::Axis;
use crate::table::Table;
use ndarray::{arr0, ArrayD, IxDyn};
use ndarray_npy::{NpzWriter, WriteNpyExt};
use rayon::prelude::*;
use std::io::{self, BufWriter, Write};
use std::path::Path;

/// A named array, as it will appear in the `.npz` file (or as `NAME.npy`).
pub type Named = (&'static str, ArrayD<f64>);

/// The model evaluated on the integration grid (shape ψ × θ × h*, h* fastest).
#[derive(Debug, Clone, PartialEq)]
pub struct Grid {
    /// ψ nodes.
    pub psi: Vec<f64>,
    /// θ nodes.
    pub theta: Vec<f64>,
    /// h* nodes.
    pub h_star: Vec<f64>,
    /// P*.
    pub p_star: Vec<f64>,
    /// Fs*.
    pub fs_star: Vec<f64>,
    /// Q*.
    pub q_star: Vec<f64>,
    /// F*.
    pub f_star: Vec<f64>,
    /// μ, NaN where F* ≤ 0.
    pub mu: Vec<f64>,
}

/// Integrates the model on the (ψ, θ, h*) grid of the options' axes.
pub fn integrate_grid(o: &BuildOptions, progress: &dyn Progress) -> Result<Grid, BuildError> {
    o.validate()?;
    let [ax_p, ax_t, _] = o.axes();
    let psi: Vec<f64> = (0..ax_p.nodes).map(|i| ax_p.value(i)).collect();
    let theta: Vec<f64> = (0..ax_t.nodes).map(|j| ax_t.value(j)).collect();
    let h = o.h_nodes();
    progress.stage(
        "integrating the (psi, theta, h*) grid",
        (psi.len() * theta.len()) as u64,
    );
    let columns: Vec<Result<Vec<[f64; 5]>, BuildError>> = (0..psi.len() * theta.len())
        .into_par_iter()
        .map(|ij| {
            let (p, t) = (psi[ij / theta.len()], theta[ij % theta.len()]);
            let model = Model::new(params_of(o, p, t))?;
            let col = h
                .iter()
                .map(|&h| {
                    let c = model.at_h_star(h).map_err(|error| BuildError::Eval {
                        psi: p,
                        theta: t,
                        error,
                    })?;
                    Ok([c.p_star, c.fs_star, c.q_star, c.f_star, c.mu.unwrap_or(f64::NAN)])
                })
                .collect();
            progress.advance(1);
            col
        })
        .collect();
    let mut grid = Grid {
        psi,
        theta,
        h_star: h,
        p_star: vec![],
        fs_star: vec![],
        q_star: vec![],
        f_star: vec![],
        mu: vec![],
    };
    for col in columns {
        for [p, fs, q, f, mu] in col? {
            grid.p_star.push(p);
            grid.fs_star.push(fs);
            grid.q_star.push(q);
            grid.f_star.push(f);
            grid.mu.push(mu);
        }
    }
    Ok(grid)
}

/// The lookup table's nodes inside its domain on each axis (ψ, θ, F*), in
/// natural units, ghost nodes excluded. Node values are clamped into the
/// domain, and a node within rounding of a domain end is that end exactly,
/// so every value is a valid lookup argument.
pub fn table_nodes(table: &Table) -> [Vec<f64>; 3] {
    let d = table.domain();
    let ranges = d.ranges();
    let axes = table.axes();
    std::array::from_fn(|k| domain_nodes(&axes[k], ranges[k]))
}

fn domain_nodes(axis: &Axis, (lo, hi): (f64, f64)) -> Vec<f64> {
    let (c_lo, c_hi) = (axis.scale.forward(lo), axis.scale.forward(hi));
    // Node positions of the domain's ends (whole numbers for a built table;
    // a hand-made file whose ends fall between nodes gets the nodes inside).
    let slack = 1e-9;
    let s_lo = (c_lo - axis.first) / axis.step;
    let s_hi = (c_hi - axis.first) / axis.step;
    let first = (s_lo - slack).ceil().max(0.0) as usize;
    let last = ((s_hi + slack).floor().max(0.0) as usize).min(axis.nodes - 1);
    (first..=last)
        .map(|k| {
            let c = axis.coord(k);
            if (c - c_lo).abs() <= slack * axis.step {
                lo
            } else if (c - c_hi).abs() <= slack * axis.step {
                hi
            } else {
                axis.scale.inverse(c).clamp(lo, hi)
            }
        })
        .collect()
}

/// Every exported array, in a fixed order (see the module documentation).
/// Integrates the model on the build grid (about a second for the default
/// table on two cores), reporting to `progress`.
///
/// Fails if the table's recorded build options are invalid or the model
/// cannot be evaluated on the grid.
pub fn arrays(table: &Table, progress: &dyn Progress) -> Result<Vec<Named>, BuildError> {
    let axes = table.axes();
    let coef_shape = axes.map(|a| a.nodes + 2);
    let knots = |k: usize| vector((0..axes[k].nodes).map(|i| axes[k].coord(i)).collect());
    let [psi, theta, f_star] = table_nodes(table);
    let shape = [psi.len(), theta.len(), f_star.len()];
    let mut mu = Vec::with_capacity(shape.iter().product());
    let mut h_star = Vec::with_capacity(mu.capacity());
    for &p in &psi {
        for &t in &theta {
            for &f in &f_star {
                let lookup = |r: Result<f64, _>| r.expect("node values lie in the domain");
                mu.push(lookup(table.mu(p, t, f)));
                h_star.push(lookup(table.h_star(p, t, f)));
            }
        }
    }
    let options = BuildOptions::from_table(table);
    let grid = integrate_grid(&options, progress)?;
    let g_shape = [grid.psi.len(), grid.theta.len(), grid.h_star.len()];
    let d = table.domain();
    Ok(vec![
        ("psi", vector(psi)),
        ("theta", vector(theta)),
        ("f_star", vector(f_star)),
        ("mu", cube(shape, mu)),
        ("h_star", cube(shape, h_star)),
        ("grid_psi", vector(grid.psi)),
        ("grid_theta", vector(grid.theta)),
        ("grid_h_star", vector(grid.h_star)),
        ("grid_p_star", cube(g_shape, grid.p_star)),
        ("grid_fs_star", cube(g_shape, grid.fs_star)),
        ("grid_q_star", cube(g_shape, grid.q_star)),
        ("grid_f_star", cube(g_shape, grid.f_star)),
        ("grid_mu", cube(g_shape, grid.mu)),
        ("beta", arr0(d.constants.beta).into_dyn()),
        ("nu", arr0(d.constants.nu).into_dyn()),
        ("eps_star", arr0(d.constants.eps_star).into_dyn()),
        ("spline_ln_mu", cube(coef_shape, table.ln_mu_coefficients().to_vec())),
        ("knots_psi", knots(0)),
        ("knots_theta", knots(1)),
        ("knots_f_star", knots(2)),
    ])
}

/// The table's record, JSON (stored as the `uint8` array `metadata`:
/// `json.loads(z["metadata"].tobytes())`): exactly [`TableInfo`](crate::TableInfo)'s
/// serialisation, the names `kefric info --json` and Python's
/// `Table.info` use too.
pub fn metadata(table: &Table) -> String {
    serde_json::to_string(table.info()).expect("a table's record serialises")
}

/// How to evaluate the exported interpolant, JSON (stored as the `uint8`
/// array `interpolant`): the quantity (`"ln(mu)"`), its kind, the
/// coefficients' array name, the cell and weight formulas, and per axis
/// its name, coordinate (`"ln(psi)"`, `"sqrt(theta)"`, `"ln(f_star)"`),
/// `first`, `step`, `nodes` and knots' array name (numbers exact in
/// shortest round-trip form).
pub fn interpolant(table: &Table) -> String {
    let axis = |k: usize, name: &str, coordinate: &str| {
        let a = table.axes()[k];
        serde_json::json!({
            "name": name,
            "coordinate": coordinate,
            "first": a.first,
            "step": a.step,
            "nodes": a.nodes,
            "knots": format!("knots_{name}"),
        })
    };
    serde_json::json!({
        "quantity": "ln(mu)",
        "kind": "tensor-product uniform cubic B-spline",
        "coefficients": "spline_ln_mu",
        "cell": "s = (x - first)/step, i = clamp(floor(s), 0, nodes - 2), f = s - i; coefficients i..i+3",
        "weights": "((1-f)^3, 3f^3-6f^2+4, -3f^3+3f^2+3f+1, f^3)/6",
        "node_values": "mu and h_star are the table's lookups at its nodes inside the domain",
        "axes": [axis(0, "psi", "ln(psi)"), axis(1, "theta", "sqrt(theta)"), axis(2, "f_star", "ln(f_star)")],
    })
    .to_string()
}

/// The JSON texts of an export, by array name: `metadata` and
/// `interpolant` (see [`metadata`], [`interpolant`]).
pub fn texts(table: &Table) -> [(&'static str, String); 2] {
    [("metadata", metadata(table)), ("interpolant", interpolant(table))]
}

fn vector(v: Vec<f64>) -> ArrayD<f64> {
    ArrayD::from_shape_vec(IxDyn(&[v.len()]), v).expect("length matches")
}

fn cube(shape: [usize; 3], v: Vec<f64>) -> ArrayD<f64> {
    ArrayD::from_shape_vec(IxDyn(&shape), v).expect("row-major data of the shape")
}

/// Writes the arrays and the JSON `texts` (each as a `uint8` array of its
/// UTF-8 bytes, see [`texts`]) into one uncompressed `.npz` file (as
/// `numpy.savez` does), atomically.
pub fn write_npz(path: &Path, arrays: &[Named], texts: &[(&str, String)]) -> io::Result<()> {
    write_atomic_with(path, |file| {
        let mut npz = NpzWriter::new(BufWriter::new(file));
        for (name, array) in arrays {
            npz.add_array(*name, array).map_err(io::Error::other)?;
        }
        for (name, text) in texts {
            npz.add_array(*name, &text_bytes(text)).map_err(io::Error::other)?;
        }
        npz.finish()
            .map_err(io::Error::other)?
            .into_inner()
            .map_err(|e| e.into_error())?
            .sync_all()
    })
}

/// Writes each array to `DIR/NAME.npy`, and each JSON text to
/// `DIR/NAME.npy` (`uint8`), all or nothing (into a temporary directory beside it, moved in when all are written):
/// after a failure (a full disk) no new file is in `dir`. `dir` is created
/// if missing (its parent must exist).
pub fn write_npy_dir(dir: &Path, arrays: &[Named], texts: &[(&str, String)]) -> io::Result<()> {
    let npy = |write: &dyn Fn(&mut BufWriter<std::fs::File>) -> io::Result<()>, file: std::fs::File| {
        let mut out = BufWriter::new(file);
        write(&mut out)?;
        out.flush()?;
        out.into_inner().map_err(|e| e.into_error())?.sync_all()
    };
    let names: Vec<String> = arrays
        .iter()
        .map(|(name, _)| *name)
        .chain(texts.iter().map(|(name, _)| *name))
        .map(|name| format!("{name}.npy"))
        .collect();
    let writers: Vec<Box<WriteFile>> = arrays
        .iter()
        .map(|(_, array)| {
            Box::new(move |file| npy(&|out| array.write_npy(out).map_err(io::Error::other), file)) as Box<WriteFile>
        })
        .chain(texts.iter().map(|(_, text)| {
            Box::new(move |file| npy(&|out| text_bytes(text).write_npy(out).map_err(io::Error::other), file))
                as Box<WriteFile>
        }))
        .collect();
    let files: Vec<(&str, &WriteFile)> = names
        .iter()
        .map(String::as_str)
        .zip(writers.iter().map(|w| w.as_ref()))
        .collect();
    write_dir_atomic(dir, &files)
}

fn text_bytes(text: &str) -> ndarray::Array1<u8> {
    ndarray::Array1::from(text.as_bytes().to_vec())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn build_options_of_the_embedded_table_are_the_defaults() {
        let table = Table::embedded();
        let options = BuildOptions::from_table(table);
        assert_eq!(options, BuildOptions::default());
        // The reconstructed options reproduce the table's lookup axes.
        assert_eq!(&options.axes(), table.axes());
    }

    #[test]
    fn table_nodes_span_the_domain_on_the_nodes() {
        let table = Table::embedded();
        let d = table.domain();
        let nodes = table_nodes(table);
        let spec = &table.info().build;
        for (k, (values, (lo, hi))) in nodes.iter().zip(d.ranges()).enumerate() {
            assert_eq!(values.len(), spec.nodes[k]);
            assert_eq!((values[0], values[values.len() - 1]), (lo, hi));
            assert!(values.windows(2).all(|w| w[0] < w[1]));
            // Each value is a node of the table's axis (ghost nodes skipped).
            let axis = table.axes()[k];
            let offset = if k == 1 { 0 } else { spec.ghosts };
            for (i, &v) in values.iter().enumerate() {
                let want = axis.value(i + offset);
                assert!((v - want).abs() <= 1e-14 * want.abs(), "{k} {i}: {v} {want}");
            }
        }
    }
}
