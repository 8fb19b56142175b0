//! The memory a read, the filters, the power spectra and a scan hold
//! (issue 46), measured exactly: a counting global allocator records the
//! peak of the bytes allocated while each runs, over what was allocated
//! before it (the topography itself). The bounds are docs/RELIABILITY.md's,
//! as multiples of the heights (H = 8 bytes a point) plus a small constant
//! for the per-line buffers. Its own test binary (the allocator is global)
//! with one test, so that nothing else allocates while it measures.

use ke_friction::topography::{
    psd_all, read_file, scan, ReadOptions, ScanRange, StatsOptions, Surface, Topography, Window,
};
use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

#[path = "npy.rs"]
mod npy;

struct Counting;

static CURRENT: AtomicUsize = AtomicUsize::new(0);
static PEAK: AtomicUsize = AtomicUsize::new(0);

// SAFETY: forwards to the system allocator, only counting.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        let p = System.alloc(layout);
        if !p.is_null() {
            let now = CURRENT.fetch_add(layout.size(), Ordering::Relaxed) + layout.size();
            PEAK.fetch_max(now, Ordering::Relaxed);
        }
        p
    }

    unsafe fn dealloc(&self, p: *mut u8, layout: Layout) {
        System.dealloc(p, layout);
        CURRENT.fetch_sub(layout.size(), Ordering::Relaxed);
    }

    unsafe fn realloc(&self, p: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        let q = System.realloc(p, layout, new_size);
        if !q.is_null() {
            if new_size >= layout.size() {
                let now = CURRENT.fetch_add(new_size - layout.size(), Ordering::Relaxed) + new_size - layout.size();
                PEAK.fetch_max(now, Ordering::Relaxed);
            } else {
                CURRENT.fetch_sub(layout.size() - new_size, Ordering::Relaxed);
            }
        }
        q
    }
}

#[global_allocator]
static ALLOCATOR: Counting = Counting;

/// The peak bytes allocated while `f` runs, over those allocated before,
/// and its result.
fn peak_of<T>(f: impl FnOnce() -> T) -> (usize, T) {
    let before = CURRENT.load(Ordering::Relaxed);
    PEAK.store(before, Ordering::Relaxed);
    let out = f();
    (PEAK.load(Ordering::Relaxed) - before, out)
}

/// Side of the map: 1024² points, 8 MiB of heights (the multiples are
/// those of 2048² and 8192² maps too: the buffers beyond them are lines;
/// measured at 2048²: 1.004, 1.003, 1.016, 2.016, 1.007, 1.015 for the
/// read, S-filter, L-filter, both, PSD and scan). Small: the tests run
/// unoptimised.
const N: usize = 1024;
const MIB: usize = 1 << 20;

fn rough(n: usize) -> Vec<f64> {
    (0..n * n)
        .map(|k| {
            let (x, y) = ((k % n) as f64, (k / n) as f64);
            1e-7 * ((x * 0.7).sin() + (y * 0.9).cos() + (x * 0.031 + y * 0.027).sin() + (x * 0.13 - y * 0.41).cos())
                + 1e-9 * x
        })
        .collect()
}

#[test]
fn reads_filters_spectra_and_scans_hold_bounded_memory() {
    let heights = rough(N);
    let h = 8 * heights.len();
    let dx = 1e-6;
    let size = N as f64 * dx;
    let mut report = vec![];
    let mut check = |what: &str, peak: usize, times: f64| {
        let bound = (times * h as f64) as usize + MIB;
        report.push(format!(
            "{what}: {:.3} x heights (bound {times} x + 1 MiB)",
            peak as f64 / h as f64
        ));
        assert!(
            peak <= bound,
            "{what}: peak {:.1} MiB = {:.3} x the {} MiB of heights, over {times} x + 1 MiB",
            peak as f64 / MIB as f64,
            peak as f64 / h as f64,
            h / MIB
        );
    };

    // A read of a .npy: the heights themselves (1 x) and what the reader
    // holds besides.
    let dir = std::env::temp_dir().join(format!("kef-memory-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("map.npy");
    let bytes: Vec<u8> = heights.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write(&path, npy::npy("<f8", false, &[N, N], &bytes)).unwrap();
    drop(bytes);
    let options = ReadOptions {
        dx: Some(dx),
        dy: Some(dx),
        ..ReadOptions::default()
    };
    let (peak, t) = peak_of(|| read_file(&path, &options).unwrap());
    std::fs::remove_dir_all(&dir).unwrap();
    check("read (.npy)", peak, 1.5);
    drop(t);

    let t = Topography::map(heights, N, N, dx, dx).unwrap();
    let stats = |lambda_s: Option<f64>, lambda_c: Option<f64>| {
        let options = StatsOptions {
            lambda_s,
            lambda_c,
            ..StatsOptions::default()
        };
        peak_of(|| t.stats(&options).unwrap()).0
    };
    check("statistics, no filter", stats(None, None), 0.0);
    check("S-filter (lambda_s)", stats(Some(5e-6), None), 1.0);
    check("L-filter (lambda_c)", stats(None, Some(size / 5.0)), 1.0);
    check("S- and L-filter", stats(Some(5e-6), Some(size / 5.0)), 2.0);
    for window in [Window::None, Window::Hann] {
        let (peak, spectra) = peak_of(|| psd_all(&t, window).unwrap());
        assert_eq!(spectra.len(), 3);
        check(&format!("PSD (x, y, area; {window:?})"), peak, 1.05);
    }
    // A scan: one row's working copy at a time; the rows share the heights.
    let range = ScanRange {
        from: 2e-6,
        to: 2e-5,
        per_decade: 3,
    };
    let (peak, rows) = peak_of(|| scan(&t, &StatsOptions::default(), &range, None, |_, _| {}).unwrap());
    assert!(rows.len() == 4 && rows.iter().all(|r| r.surface.is_ok()));
    check(&format!("scan of {} rows", rows.len()), peak, 1.0);
    let (held, _) = peak_of(|| rows.clone());
    assert!(held < MIB, "{} rows hold {held} bytes", rows.len());
    let (peak, _) = peak_of(|| Surface::new(t.clone(), StatsOptions::default()).unwrap());
    check("a surface (shares the heights)", peak, 0.0);
    eprintln!("{}", report.join("\n"));
}
