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
//!
//! The table file does not store the integration grid: it is recomputed
//! from the build options the table records ([`BuildOptions::from_table`]).
//! [`write_npz`] and [`write_npy_dir`] write atomically (a temporary file
//! in the same directory, flushed, then renamed).

use crate::build::{params_of, BuildError, BuildOptions, Progress};
use crate::io::write_atomic_with;
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
        ("beta", arr0(d.beta).into_dyn()),
        ("nu", arr0(d.nu).into_dyn()),
        ("eps_star", arr0(d.eps_star).into_dyn()),
    ])
}

fn vector(v: Vec<f64>) -> ArrayD<f64> {
    ArrayD::from_shape_vec(IxDyn(&[v.len()]), v).expect("length matches")
}

fn cube(shape: [usize; 3], v: Vec<f64>) -> ArrayD<f64> {
    ArrayD::from_shape_vec(IxDyn(&shape), v).expect("row-major data of the shape")
}

/// Writes the arrays into one uncompressed `.npz` file (as `numpy.savez`
/// does), atomically.
pub fn write_npz(path: &Path, arrays: &[Named]) -> io::Result<()> {
    write_atomic_with(path, |file| {
        let mut npz = NpzWriter::new(BufWriter::new(file));
        for (name, array) in arrays {
            npz.add_array(*name, array).map_err(io::Error::other)?;
        }
        npz.finish()
            .map_err(io::Error::other)?
            .into_inner()
            .map_err(|e| e.into_error())?
            .sync_all()
    })
}

/// Writes each array to `DIR/NAME.npy`, each file atomically. `dir` is
/// created if missing (its parent must exist).
pub fn write_npy_dir(dir: &Path, arrays: &[Named]) -> io::Result<()> {
    if !dir.is_dir() {
        std::fs::create_dir(dir)?;
    }
    for (name, array) in arrays {
        write_atomic_with(&dir.join(format!("{name}.npy")), |file| {
            let mut out = BufWriter::new(file);
            array.write_npy(&mut out).map_err(io::Error::other)?;
            out.flush()?;
            out.into_inner().map_err(|e| e.into_error())?.sync_all()
        })?;
    }
    Ok(())
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
