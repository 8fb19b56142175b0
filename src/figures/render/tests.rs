//! The drawing's tests: every text inside the image at every scale, the
//! wrapped titles, the legends' corners.

use super::error_map::ring_centre;
use super::*;
use plotters_backend::{BackendColor, BackendCoord, BackendStyle, BackendTextStyle, DrawingErrorKind};

/// A backend that draws nothing and records where each text would go
/// (its box, rotation included, in pixels): the measuring hook of
/// [`every_text_lies_inside_the_image`]. Text outside the canvas is
/// what the real backends silently clip.
struct Extents {
    size: (u32, u32),
    texts: Texts,
}

/// The texts drawn and their boxes (x0, y0, x1, y1), shared with the
/// test (the drawing area owns the backend).
type Texts = std::rc::Rc<std::cell::RefCell<Vec<(String, (i32, i32, i32, i32))>>>;

impl DrawingBackend for Extents {
    type ErrorType = std::convert::Infallible;
    fn get_size(&self) -> (u32, u32) {
        self.size
    }
    fn ensure_prepared(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn present(&mut self) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn draw_pixel(&mut self, _: BackendCoord, _: BackendColor) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn draw_line<S: BackendStyle>(
        &mut self,
        _: BackendCoord,
        _: BackendCoord,
        _: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn draw_rect<S: BackendStyle>(
        &mut self,
        _: BackendCoord,
        _: BackendCoord,
        _: &S,
        _: bool,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn draw_path<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        _: I,
        _: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    fn fill_polygon<S: BackendStyle, I: IntoIterator<Item = BackendCoord>>(
        &mut self,
        _: I,
        _: &S,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        Ok(())
    }
    /// The box the default `draw_text` fills, by the same arithmetic
    /// (plotters-backend's): the layout box moved to the anchor, then
    /// rotated about the anchor point.
    fn draw_text<T: BackendTextStyle>(
        &mut self,
        text: &str,
        style: &T,
        pos: BackendCoord,
    ) -> Result<(), DrawingErrorKind<Self::ErrorType>> {
        let ((x0, y0), (x1, y1)) = style.layout_box(text).expect("the embedded font lays out");
        let (w, h) = (x1 - x0, y1 - y0);
        let dx = match style.anchor().h_pos {
            HPos::Left => 0,
            HPos::Right => -w,
            HPos::Center => -w / 2,
        };
        let dy = match style.anchor().v_pos {
            VPos::Top => 0,
            VPos::Center => -h / 2,
            VPos::Bottom => -h,
        };
        let t = style.transform();
        let (a, b) = (t.transform(dx, dy), t.transform(dx + w, dy + h));
        self.texts.borrow_mut().push((
            text.to_string(),
            (
                pos.0 + a.0.min(b.0),
                pos.1 + a.1.min(b.1),
                pos.0 + a.0.max(b.0),
                pos.1 + a.1.max(b.1),
            ),
        ));
        Ok(())
    }
}

/// The texts of `what` drawn at `scale` as the PNG is (supersampled)
/// that reach outside the canvas, and how many texts there were.
fn clipped(what: &impl Render, scale: u32) -> (Vec<String>, usize) {
    fonts().unwrap();
    let k = supersample(scale);
    let (w, h) = size_at(scale).unwrap();
    let texts = Texts::default();
    let backend = Extents {
        size: (w * k, h * k),
        texts: std::rc::Rc::clone(&texts),
    };
    what.render(&backend.into_drawing_area(), scale * k).unwrap();
    let (w, h) = ((w * k) as i32, (h * k) as i32);
    let texts = texts.borrow();
    let out = texts
        .iter()
        .filter(|(_, (x0, y0, x1, y1))| *x0 < 0 || *y0 < 0 || *x1 > w || *y1 > h)
        .map(|(t, b)| format!("{t:?} at {b:?} in {w}x{h}"))
        .collect();
    (out, texts.len())
}

/// A surface page with the longest title the CLI writes: two long file
/// names, both intervals and both filters.
fn long_surface_page(pair: bool) -> Page {
    use crate::{HeightDistribution, Model, Params};
    let gauss = Model::new(Params::new(5.0, 0.001)).unwrap();
    let pearson =
        Model::new(Params::new(5.0, 0.001).distribution(HeightDistribution::pearson(0.3, 3.4).unwrap())).unwrap();
    let fits = vec![
        ("gaussian".to_string(), gauss),
        ("pearson (Ssk 0.3, Sku 3.4)".to_string(), pearson),
    ];
    let heights: Vec<f64> = (0..4000).map(|i| ((i as f64) * 0.618034).fract() * 6.0 - 3.0).collect();
    crate::figures::surface_page(
        "instrument_export_2024-05-17_sample-03_area-2.x3p + counterface_disk_2024-05-17.x3p",
        "at dx = 1.23457e-6 m, dy = 2.46914e-6 m, lambda_s = 4.5e-6 m, lambda_c = 0.000123457 m",
        (!pair).then_some(&heights[..]),
        &fits,
        None,
    )
    .unwrap()
}

/// Every plot kind of `kefric plot`, at scale 1 and 2: no text (title,
/// axis title, tick label, legend) reaches outside the image, where it
/// would be cut.
#[test]
fn every_text_lies_inside_the_image() {
    use crate::figures::{curve_page, distributions_page, scan_page, table_error, Figure, ScanPoint};
    use crate::{Model, Params, Table};
    let mut pages: Vec<(&str, Page)> = Vec::new();
    for fig in [Figure::Fig3, Figure::Fig4, Figure::Fig5, Figure::Fig6] {
        pages.push((fig.name(), fig.page().unwrap()));
    }
    let model = Model::new(Params::new(1.0, 0.003)).unwrap();
    pages.push(("curve", curve_page(&model, Some(Table::embedded()), None).unwrap()));
    pages.push(("distributions", distributions_page(1.0, 0.001).unwrap()));
    pages.push(("surface", long_surface_page(false)));
    pages.push(("surface (pair)", long_surface_page(true)));
    let points: Vec<ScanPoint> = (0..12)
        .map(|i| ScanPoint {
            lambda_s: 2e-6 * 1.5f64.powi(i),
            mu: Some(0.01 * 1.2f64.powi(i)),
            psi: Some(5.0 / 1.3f64.powi(i)),
            beta: 0.04 + 0.001 * f64::from(i),
        })
        .collect();
    pages.push((
        "surface --scan",
        scan_page("instrument_export_2024-05-17_sample-03_area-2.x3p", &points, Some(5e-6)).unwrap(),
    ));
    #[cfg(feature = "topography")]
    {
        let q: Vec<f64> = (0..200).map(|i| 1e4 * 1.05f64.powi(i)).collect();
        let psd = crate::topography::Psd {
            c: q.iter().map(|q| 1e-30 * q.powf(-3.2)).collect(),
            q,
        };
        let spectra = [("along x", &psd), ("along y", &psd), ("area (radial)", &psd)];
        pages.push((
            "surface --psd",
            crate::figures::psd_page(
                "instrument_export_2024-05-17_sample-03_area-2.x3p",
                &spectra,
                Some(4.5e-6),
                Some(1.2e-4),
            )
            .unwrap(),
        ));
    }
    #[cfg(feature = "topography")]
    pages.extend(container_pages());
    let map = table_error(Table::embedded(), 0.003, 8, 12).unwrap();
    for scale in [1, 2] {
        for (name, page) in &pages {
            let (out, n) = clipped(page, scale);
            assert!(n >= 10, "{name}: only {n} texts drawn");
            assert!(
                out.is_empty(),
                "{name} at scale {scale}: texts cut at the image's edge: {out:#?}"
            );
        }
        let (out, n) = clipped(&map, scale);
        assert!(n >= 10 && out.is_empty(), "table-error at scale {scale}: {out:#?}");
    }
    // The check sees a cut: the surface page's title on one line, as
    // plotters' caption would draw it unwrapped, is wider than the image.
    let (title_w, _) = {
        fonts().unwrap();
        let backend = Extents {
            size: BASE_SIZE,
            texts: std::rc::Rc::default(),
        };
        let font: TextStyle = (FAMILY, CAPTION_PX).into_font().into();
        let title = long_surface_page(false).top.title.unwrap();
        backend.estimate_text_size(&title, &font).unwrap()
    };
    assert!(
        title_w > BASE_SIZE.0,
        "the long title ({title_w} px) would fit unwrapped"
    );
}

/// `plot surface CONTAINER --psd` and `--scan` of the synthetic container
/// (tests/data/container/uniform.zip), its measurements given long names.
#[cfg(feature = "topography")]
fn container_pages() -> Vec<(&'static str, Page)> {
    use crate::topography::container::{
        combined_psd, container_scan, measurement_spectra, read_container, ContainerOptions, Resolved,
        COMBINED_POINTS_PER_DECADE,
    };
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/container/uniform.zip");
    let s = read_container(&path, &ContainerOptions::default()).unwrap().remove(0);
    let spectra = measurement_spectra(&s.measurements);
    let names: Vec<String> = s
        .measurements
        .iter()
        .map(|m| format!("instrument_export_2024-05-17_{} (512-point profile)", m.name))
        .collect();
    let combined = combined_psd(&spectra, COMBINED_POINTS_PER_DECADE).unwrap();
    let labelled: Vec<(String, &_)> = names.iter().cloned().zip(&spectra).collect();
    let title = "instrument_export_2024-05-17_sample-03_container.zip";
    let psd =
        crate::figures::container_psd_page(title, &labelled, Some(&combined.psd), Some(1e-6), Some(1e-4)).unwrap();
    let how = crate::topography::SurfaceModel::new(crate::Materials::from_array([
        70e9, 0.33, 200e9, 0.31, 1e9, 0.5, 0.4e-9,
    ]));
    let rows = container_scan(&s.measurements, &spectra, None, 5, &how, &[crate::Load::Pressure(1e6)]).unwrap();
    let scan = crate::figures::container_scan_page(title, &names, &Resolved::of(&spectra).ranges, &rows).unwrap();
    vec![("surface CONTAINER --psd", psd), ("surface CONTAINER --scan", scan)]
}

/// A title is broken after commas where it can be, between words
/// where it must, and a word wider than the room is shortened.
#[test]
fn titles_wrap_after_commas_then_between_words() {
    let width = |t: &str| 10 * t.chars().count() as i32;
    assert_eq!(wrap("a short one", 200, width), ["a short one"]);
    assert_eq!(
        wrap("psi = 5.06, theta = 0.001, beta = 0.1 at dx = 1e-6 m", 260, width),
        ["psi = 5.06, theta = 0.001,", "beta = 0.1 at dx = 1e-6 m"]
    );
    assert_eq!(wrap("aaaa bbbb cccc", 90, width), ["aaaa bbbb", "cccc"]);
    // "=" keeps its sides together.
    assert_eq!(
        wrap("mu against F* for heights: psi = 1, theta = 0.001", 300, width),
        ["mu against F* for heights:", "psi = 1, theta = 0.001"]
    );
    let cut = wrap("averyveryverylongword x", 100, width);
    assert!(cut.iter().all(|l| width(l) <= 100) && cut[0].ends_with('…'), "{cut:?}");
}

/// The clear corner is the one the lines do not pass through.
#[test]
fn the_legend_goes_where_the_lines_are_not() {
    // A line along the top from left to right and down the right edge:
    // only the lower left corner is clear.
    let lines = vec![vec![(0, 10), (980, 10), (980, 700)]];
    let size = (300, 100);
    let corners = [(690, 12), (12, 12), (690, 588), (12, 588)];
    let n: Vec<usize> = corners.iter().map(|&at| covered(&lines, at, size, 1)).collect();
    assert!(n[0] > 0 && n[1] > 0 && n[2] > 0 && n[3] == 0, "{n:?}");
}

#[test]
fn rings_stay_inside_the_frame() {
    // A cell at the right edge (the default table's largest error at
    // θ = 0.003 sits there) and one in a corner.
    assert_eq!(ring_centre((1299, 500), (1300, 1100), 28), (1271, 500));
    assert_eq!(ring_centre((2, 1098), (1300, 1100), 28), (28, 1071));
    assert_eq!(ring_centre((600, 500), (1300, 1100), 28), (600, 500));
}

#[test]
fn markers_of_different_phases_never_share_an_x() {
    let line: Vec<(f64, f64)> = (0..=100).map(|i| (i as f64 / 100.0, 2.0)).collect();
    let at = |phase| {
        marker_positions(
            &line,
            Markers {
                shape: Shape::Circle,
                phase,
            },
            (0.0, 1.0),
        )
    };
    let (a, b, c) = (at(0.0), at(1.0 / 3.0), at(2.0 / 3.0));
    assert_eq!(a.len(), Markers::PER_AXIS);
    for p in a.iter().chain(&b).chain(&c) {
        assert!((p.1 - 2.0).abs() < 1e-12 && (0.0..=1.0).contains(&p.0), "{p:?}");
    }
    for (p, q) in a.iter().zip(&b).chain(b.iter().zip(&c)) {
        assert!(q.0 - p.0 > 0.02, "{p:?} {q:?}");
    }
}

#[test]
fn tick_labels_suit_the_step() {
    assert_eq!(tick_label(0.5, 0.5), "0.5");
    assert_eq!(tick_label(0.25, 0.25), "0.25");
    assert_eq!(tick_label(2.0, 0.5), "2.0");
    assert_eq!(tick_label(1e-19, 0.5), "0");
    assert_eq!(tick_label(-2e-5, 1e-5), "−2×10⁻⁵");
    assert_eq!(tick_label(4.02e-5, 4.02e-5), "4.02×10⁻⁵");
}
