//! An encoder for table files written independently of the library's
//! (from the format's description in `src/table/format.rs` and postcard's
//! wire format), so that tests and the fuzz targets can craft any file a
//! hostile author could: valid checksum, any axes, any coefficients.
//!
//! Shared by path (`#[path = …] mod forge;`) by the library's tests, the
//! CLI's, the C ABI's and the fuzz targets; it depends on `crc32fast` only.

#![allow(dead_code)]

/// The format's magic bytes and version.
const MAGIC: &[u8; 8] = b"KEFRICTB";
const VERSION: u32 = 1;

/// Axis scale codes (`Scale::code`).
pub const LOG: u8 = 0;
/// √ map.
pub const SQRT: u8 = 1;

/// One stored axis: scale code, first node coordinate, step, node count
/// (ghosts included), domain.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Axis {
    /// Scale code.
    pub scale: u8,
    /// Coordinate of node 0.
    pub first: f64,
    /// Coordinate spacing.
    pub step: f64,
    /// Nodes, ghost nodes included.
    pub nodes: u32,
    /// Domain, lower end.
    pub lo: f64,
    /// Domain, upper end.
    pub hi: f64,
}

impl Axis {
    /// An axis over `[lo, hi]` with `nodes` nodes, one ghost node beyond
    /// each end.
    pub fn over(scale: u8, lo: f64, hi: f64, nodes: u32) -> Axis {
        let map = |v: f64| if scale == LOG { v.ln() } else { v.sqrt() };
        let step = (map(hi) - map(lo)) / (nodes - 3) as f64;
        Axis {
            scale,
            first: map(lo) - step,
            step,
            nodes,
            lo,
            hi,
        }
    }
}

/// Everything a table file holds, as plain numbers.
#[derive(Debug, Clone, PartialEq)]
pub struct Spec {
    /// β, ν, ε*.
    pub constants: [f64; 3],
    /// Fit code, model code.
    pub codes: [u8; 2],
    /// ψ, θ, F* axes.
    pub axes: [Axis; 3],
    /// Store the coefficients in f32 (else f64).
    pub f32: bool,
    /// ln μ coefficients, F* fastest.
    pub ln_mu: Vec<f64>,
    /// h* coefficients.
    pub h_star: Vec<f64>,
    /// The generator string.
    pub generator: String,
    /// tolerance, max_rel, p99_rel.
    pub accuracy: [f64; 3],
    /// The worst point.
    pub worst: [f64; 3],
    /// h* from, to.
    pub h_range: [f64; 2],
}

impl Spec {
    /// A small, valid table over ψ [0.5, 8], θ [0, 0.01], F* [1e-5, 0.1]
    /// whose ln μ coefficients are all `ln_mu` (so μ = e^ln_mu everywhere:
    /// the B-spline weights sum to one) and h* coefficients all 1.
    pub fn uniform(ln_mu: f64, f32: bool) -> Spec {
        let axes = [
            Axis::over(LOG, 0.5, 8.0, 7),
            Axis::over(SQRT, 0.0, 0.01, 6),
            Axis::over(LOG, 1e-5, 0.1, 9),
        ];
        let n = axes.iter().map(|a| a.nodes as usize + 2).product();
        Spec {
            constants: [0.04, 0.3, 0.004],
            codes: [0, 0],
            axes,
            f32,
            ln_mu: vec![ln_mu; n],
            h_star: vec![1.0; n],
            generator: "forge".into(),
            accuracy: [1e-3, 1e-4, 1e-5],
            worst: [1.0, 0.001, 0.01],
            h_range: [-1.0, 5.0],
        }
    }

    /// `c` as the file stores it (rounded to f32 in an f32 table).
    pub fn stored(&self, c: f64) -> f64 {
        if self.f32 {
            c as f32 as f64
        } else {
            c
        }
    }

    /// The number of coefficients the axes need.
    pub fn coefficients(&self) -> usize {
        self.axes.iter().map(|a| a.nodes as usize + 2).product()
    }

    /// The complete file: header, postcard payload, CRC-32.
    pub fn encode(&self) -> Vec<u8> {
        let mut p = Vec::new();
        for c in self.constants {
            f64le(&mut p, c);
        }
        p.extend_from_slice(&self.codes);
        for a in &self.axes {
            p.push(a.scale);
            f64le(&mut p, a.first);
            f64le(&mut p, a.step);
            varint(&mut p, a.nodes as u64);
            f64le(&mut p, a.lo);
            f64le(&mut p, a.hi);
        }
        for coefs in [&self.ln_mu, &self.h_star] {
            varint(&mut p, if self.f32 { 0 } else { 1 });
            varint(&mut p, coefs.len() as u64);
            for &c in coefs {
                if self.f32 {
                    p.extend_from_slice(&(c as f32).to_le_bytes());
                } else {
                    f64le(&mut p, c);
                }
            }
        }
        // The build record: nodes, ghosts, h* range and points, samples,
        // seed, generator.
        for a in &self.axes {
            varint(&mut p, a.nodes.saturating_sub(2) as u64);
        }
        varint(&mut p, 1);
        f64le(&mut p, self.h_range[0]);
        f64le(&mut p, self.h_range[1]);
        varint(&mut p, 100);
        varint(&mut p, 1000);
        varint(&mut p, 42);
        varint(&mut p, self.generator.len() as u64);
        p.extend_from_slice(self.generator.as_bytes());
        // The accuracy record.
        for v in self.accuracy {
            f64le(&mut p, v);
        }
        varint(&mut p, 1000);
        for v in self.worst {
            f64le(&mut p, v);
        }
        frame(&p)
    }
}

/// A file with the right magic, version, length and checksum around `payload`.
pub fn frame(payload: &[u8]) -> Vec<u8> {
    let mut out = Vec::with_capacity(payload.len() + 24);
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&VERSION.to_le_bytes());
    out.extend_from_slice(&(payload.len() as u64).to_le_bytes());
    out.extend_from_slice(payload);
    let crc = crc32fast::hash(&out);
    out.extend_from_slice(&crc.to_le_bytes());
    out
}

fn f64le(out: &mut Vec<u8>, v: f64) {
    out.extend_from_slice(&v.to_le_bytes());
}

/// postcard's unsigned varint (LEB128).
fn varint(out: &mut Vec<u8>, mut v: u64) {
    loop {
        let byte = (v & 0x7f) as u8;
        v >>= 7;
        if v == 0 {
            out.push(byte);
            return;
        }
        out.push(byte | 0x80);
    }
}

/// The crafted files of issue 23's attack, each with a name and whether a
/// loader must refuse it (`Some(field named in the error)`) or may load it
/// (`None`: then it must answer μ = e^c for its uniform coefficient c).
pub fn crafted() -> Vec<(&'static str, Spec, Option<&'static str>)> {
    let mut v = vec![];
    // 1. A tiny F* step at ln 0.01: the cell index of an in-domain query
    // went negative and the portable kernel read before the array.
    let mut s = Spec::uniform(0.5f64.ln(), false);
    s.axes[2] = Axis {
        scale: LOG,
        first: 0.01f64.ln(),
        step: 1e-17,
        nodes: 9,
        lo: 0.01,
        // The next float: a domain of one ulp, inside the nodes.
        hi: f64::from_bits(0.01f64.to_bits() + 1),
    };
    v.push(("tiny F* step (f64)", s.clone(), Some("f_star axis")));
    s.f32 = true;
    v.push(("tiny F* step (f32)", s, Some("f_star axis")));
    // The same with a domain of some width but an origin far from zero.
    let mut s = Spec::uniform(0.0, false);
    s.axes[0].first = -1e15;
    v.push(("psi axis far from its domain", s, Some("psi axis")));
    // 2. ln μ of 3e38 in an f32 table: the f32 exponential gave NaN.
    v.push(("f32 ln_mu 3e38", Spec::uniform(3e38, true), Some("ln_mu")));
    v.push(("f32 ln_mu 701", Spec::uniform(701.0, true), Some("ln_mu")));
    // 3. ln μ of -1000 in an f64 table gave μ = -1.6e182.
    v.push(("f64 ln_mu -1000", Spec::uniform(-1000.0, false), Some("ln_mu")));
    v.push(("f64 ln_mu 701", Spec::uniform(701.0, false), Some("ln_mu")));
    // Within the exponentials' range, but the slope would overflow.
    v.push(("f64 ln_mu 690", Spec::uniform(690.0, false), Some("dmu/dF*")));
    let mut s = Spec::uniform(0.0, false);
    s.ln_mu[17] = f64::NAN;
    v.push(("a NaN ln_mu coefficient", s, Some("ln_mu")));
    let mut s = Spec::uniform(0.0, true);
    s.h_star[3] = f64::INFINITY;
    v.push(("an infinite h_star coefficient", s, Some("h_star")));
    let mut s = Spec::uniform(0.0, false);
    s.h_star[3] = 1e300;
    v.push(("a huge h_star coefficient", s, Some("h_star")));
    // Lengths that disagree with the axes.
    let mut s = Spec::uniform(0.0, false);
    s.ln_mu.pop();
    v.push(("one ln_mu coefficient short", s, Some("ln_mu")));
    let mut s = Spec::uniform(0.0, false);
    s.axes[1].nodes += 1;
    v.push(("theta axis one node long", s, Some("coefficients")));
    let mut s = Spec::uniform(0.0, false);
    s.worst[1] = f64::NAN;
    v.push(("a NaN worst point", s, Some("worst")));
    let mut s = Spec::uniform(0.0, false);
    s.generator = "x".repeat(5000);
    v.push(("a 5000-byte generator", s, Some("generator")));
    // Loadable: extreme but representable values answer μ = e^c.
    v.push(("f32 ln_mu 86", Spec::uniform(86.0, true), None));
    v.push(("f32 ln_mu -86", Spec::uniform(-86.0, true), None));
    // Beyond the f32 kernel's exponential: the portable kernel answers.
    v.push(("f32 ln_mu -87", Spec::uniform(-87.0, true), None));
    v.push(("f32 ln_mu 300", Spec::uniform(300.0, true), None));
    v.push(("f64 ln_mu -700", Spec::uniform(-700.0, false), None));
    v.push(("f64 ln_mu 64.7", Spec::uniform(64.7, false), None));
    let mut s = Spec::uniform(0.0, true);
    s.generator = "ok\n\x1b[32mverdict: OK\x1b[0m\r\u{202e}".into();
    v.push(("escape sequences in the generator", s, None));
    v
}
