//! Drawing the table's error map (`kefric plot table-error`): the colour
//! map, the worst points ringed.

use super::*;

/// The centre of a ring of outer radius `r` around the pixel `(x, y)`,
/// moved just enough to keep the whole ring inside a plotting area of
/// `(w, h)` pixels.
pub(super) fn ring_centre((x, y): (i32, i32), (w, h): (u32, u32), r: i32) -> (i32, i32) {
    let inside = |v: i32, n: u32| v.clamp(r, (n as i32 - 1 - r).max(r));
    (inside(x, w), inside(y, h))
}

/// Viridis, sampled at five points and interpolated linearly.
fn viridis(t: f64) -> RGBColor {
    const STOPS: [(f64, f64, f64); 5] = [
        (68.0, 1.0, 84.0),
        (59.0, 82.0, 139.0),
        (33.0, 145.0, 140.0),
        (94.0, 201.0, 98.0),
        (253.0, 231.0, 37.0),
    ];
    let t = t.clamp(0.0, 1.0) * 4.0;
    let i = (t.floor() as usize).min(3);
    let f = t - i as f64;
    let (a, b) = (STOPS[i], STOPS[i + 1]);
    let mix = |x: f64, y: f64| (x + (y - x) * f).round() as u8;
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

impl ErrorMap {
    /// The colour scale's decades (log10 of the error): whole decades
    /// covering the errors and, not at the very top, the tolerance; at
    /// most 6 of them.
    fn scale(&self) -> (f64, f64) {
        let max = self.rel.iter().copied().fold(0.0, f64::max);
        let min = self
            .rel
            .iter()
            .copied()
            .filter(|&r| r > 0.0)
            .fold(f64::INFINITY, f64::min);
        let hi = (max.max(self.tolerance).log10() + 0.3).ceil();
        let lo = if min.is_finite() { min.log10().floor() } else { hi - 6.0 };
        (lo.max(hi - 6.0), hi)
    }
}

impl Render for ErrorMap {
    fn render<DB: DrawingBackend>(&self, root: &DrawingArea<DB, Shift>, s: u32) -> Result<(), String> {
        root.fill(&WHITE).map_err(err)?;
        let (main, bar) = root.split_horizontally((BASE_SIZE.0 - COLOUR_BAR_PX) * s);
        let (lo, hi) = self.scale();
        let colour = |r: f64| viridis((r.max(1e-300).log10() - lo) / (hi - lo));
        let (psi_lo, psi_hi) = (self.psi[0], self.psi[self.psi.len() - 1]);
        let x = ChartAxis {
            title: "F*".into(),
            log: true,
            range: (self.f_star[0], self.f_star[self.f_star.len() - 1]),
            ticks: None,
        };
        let psi_ticks: Vec<f64> = [0.25, 0.5, 1.0, 2.0, 4.0, 8.0, 16.0, 32.0]
            .into_iter()
            .filter(|&v| v >= psi_lo * (1.0 - 1e-9) && v <= psi_hi * (1.0 + 1e-9))
            .collect();
        let y = ChartAxis {
            title: "ψ".into(),
            log: true,
            range: (psi_lo, psi_hi),
            ticks: (psi_ticks.len() >= 2).then_some(psi_ticks),
        };
        let (max, at_psi, at_f) = self.max();
        let title = format!(
            "Table error, θ = {} (max {}, ringed)",
            num(self.theta),
            tick_label(max, max)
        );
        let width = y_area(&main, &y, s)?;
        let mut chart = frame(&main, Some(&title), &x, &y, false, width, s)?;
        let cols = self.f_star.len() - 1;
        chart
            .draw_series(self.rel.iter().enumerate().map(|(i, &r)| {
                let (row, col) = (i / cols, i % cols);
                Rectangle::new(
                    [
                        (x.to_plot(self.f_star[col]), y.to_plot(self.psi[row + 1])),
                        (x.to_plot(self.f_star[col + 1]), y.to_plot(self.psi[row])),
                    ],
                    colour(r).filled(),
                )
            }))
            .map_err(err)?;
        // The largest error: its cell outlined and a ring around it, moved
        // inside the frame where the cell lies at an edge.
        let (r, c) = {
            let at = self.rel.iter().position(|&v| v == max).unwrap_or(0);
            (at / cols, at % cols)
        };
        let ring = ShapeStyle::from(&WHITE).stroke_width(3 * s);
        let (w, h) = chart.plotting_area().dim_in_pixel();
        let px = |f: f64, p: f64| pixel(&chart, x.to_plot(f), y.to_plot(p));
        let pixels = chart.plotting_area().strip_coord_spec();
        let (c0, c1) = (px(self.f_star[c], self.psi[r + 1]), px(self.f_star[c + 1], self.psi[r]));
        pixels
            .draw(&Rectangle::new([c0, c1], ShapeStyle::from(&WHITE).stroke_width(2 * s)))
            .map_err(err)?;
        let centre = ring_centre(px(at_f, at_psi), (w, h), ((RING_PX + 2) * s) as i32);
        pixels.draw(&Circle::new(centre, RING_PX * s, ring)).map_err(err)?;
        border(&chart, s)?;

        // The colour bar: the same caption and x-label space as the map,
        // so that the two line up.
        let mut builder = ChartBuilder::on(&bar);
        builder
            .margin(MARGIN_PX * s)
            .margin_right(10 * s)
            .caption(" ", (FAMILY, CAPTION_PX * s))
            .x_label_area_size(X_AREA_PX * s)
            .y_label_area_size(0)
            .right_y_label_area_size(95 * s);
        let cb = ChartAxis {
            title: "|μ_table/μ − 1|   (red: tolerance)".into(),
            log: true,
            range: (10f64.powf(lo), 10f64.powf(hi)),
            ticks: None,
        };
        let unit = ChartAxis {
            title: String::new(),
            log: false,
            range: (0.0, 1.0),
            ticks: Some(vec![]),
        };
        let mut bar_chart = builder.build_cartesian_2d(unit.coord(), cb.coord()).map_err(err)?;
        let fy = |u: &f64| cb.label(*u);
        bar_chart
            .configure_mesh()
            .disable_mesh()
            .disable_x_axis()
            .y_label_formatter(&fy)
            .y_desc(cb.title.as_str())
            .axis_desc_style((FAMILY, DESC_PX * s))
            .label_style((FAMILY, LABEL_PX * s))
            .axis_style(BLACK.stroke_width(s))
            .set_all_tick_mark_size(TICK_PX * s)
            .draw()
            .map_err(err)?;
        let steps = 120;
        bar_chart
            .draw_series((0..steps).map(|i| {
                let a = lo + (hi - lo) * i as f64 / steps as f64;
                let b = lo + (hi - lo) * (i + 1) as f64 / steps as f64;
                Rectangle::new([(0.0, b), (1.0, a)], viridis((i as f64 + 0.5) / steps as f64).filled())
            }))
            .map_err(err)?;
        // The tolerance the table promises, as a line across the bar.
        let t = self.tolerance.log10();
        if t >= lo && t <= hi {
            bar_chart
                .draw_series(LineSeries::new(vec![(0.0, t), (1.0, t)], RED.stroke_width(3 * s)))
                .map_err(err)?;
        }
        border(&bar_chart, s)?;
        Ok(())
    }
}
