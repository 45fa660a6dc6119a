//! Charts of the statistics as SVG, drawn with `plotters` (SVG back end only, text as SVG
//! `<text>`): cumulative trials against placements on log-log axes (the paper's Figure 5), and
//! the halting fraction against c (Figure 6). The same data give the same bytes.

use crate::error::CliError;
use plotters::prelude::*;

/// Chart size in pixels (the SVG's user units).
const SIZE: (u32, u32) = (800, 560);

/// A fixed palette, so colours do not depend on anything but the series order.
const PALETTE: [RGBColor; 8] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(140, 86, 75),
    RGBColor(227, 119, 194),
    RGBColor(23, 190, 207),
];

fn color(i: usize) -> RGBColor {
    PALETTE.get(i % PALETTE.len()).copied().unwrap_or(BLACK)
}

fn chart_error(e: impl std::fmt::Display) -> CliError {
    CliError::Io(format!("cannot draw the chart: {e}"))
}

/// The series' legend in the upper left, then the drawing finished.
fn legend_and_present<'a, DB: DrawingBackend + 'a, CT: plotters::coord::CoordTranslate>(
    chart: &mut ChartContext<'a, DB, CT>,
    root: &DrawingArea<DB, plotters::coord::Shift>,
) -> Result<(), CliError> {
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(chart_error)?;
    root.present().map_err(chart_error)
}

/// One curve of cumulative trials.
#[derive(Debug, Clone)]
pub struct TrialsSeries {
    /// Legend text.
    pub label: String,
    /// `(placements n, cumulative trials)`, n from 1.
    pub points: Vec<(f64, f64)>,
    /// The fitted power law `trials = a n^k` and the n range it was fitted on.
    pub fit: Option<(f64, f64, f64, f64)>,
}

/// The points worth drawing on a log x axis: at most about 400 per decade (the first point
/// of each step of 1/400 decade, and the last point).
fn thin_log(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out: Vec<(f64, f64)> = Vec::new();
    let mut last_step = i64::MIN;
    for &p in points {
        let step = (libm::log10(p.0) * 400.0).floor() as i64;
        if step != last_step {
            out.push(p);
            last_step = step;
        }
    }
    if let (Some(&l), Some(&o)) = (points.last(), out.last()) {
        if l != o {
            out.push(l);
        }
    }
    out
}

/// Log-log chart of cumulative trials against placements.
pub fn trials_chart(series: &[TrialsSeries], title: &str) -> Result<Vec<u8>, CliError> {
    let mut out = String::new();
    let xmax = series.iter().flat_map(|s| s.points.iter().map(|p| p.0)).fold(10.0f64, f64::max);
    let ymax = series.iter().flat_map(|s| s.points.iter().map(|p| p.1)).fold(10.0f64, f64::max);
    {
        let root = SVGBackend::with_string(&mut out, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(chart_error)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(72)
            .build_cartesian_2d((1f64..xmax * 1.2).log_scale(), (1f64..ymax * 1.5).log_scale())
            .map_err(chart_error)?;
        chart
            .configure_mesh()
            .x_desc("placements n")
            .y_desc("cumulative trials")
            .x_label_formatter(&|v| format!("{v:.0e}"))
            .y_label_formatter(&|v| format!("{v:.0e}"))
            .draw()
            .map_err(chart_error)?;
        for (i, s) in series.iter().enumerate() {
            let col = color(i);
            chart
                .draw_series(LineSeries::new(thin_log(&s.points), col.stroke_width(2)))
                .map_err(chart_error)?
                .label(s.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2)));
            if let Some((k, a, n0, n1)) = s.fit {
                let line = [(n0, a * libm::pow(n0, k)), (n1, a * libm::pow(n1, k))];
                chart
                    .draw_series(LineSeries::new(line, BLACK.stroke_width(1)))
                    .map_err(chart_error)?;
            }
        }
        legend_and_present(&mut chart, &root)?;
    }
    out.push('\n');
    Ok(out.into_bytes())
}

/// One curve of halting fractions.
#[derive(Debug, Clone)]
pub struct HaltingSeries {
    /// Legend text.
    pub label: String,
    /// `(c, fraction of runs that halted)`.
    pub points: Vec<(f64, f64)>,
}

/// Chart of the halting fraction against c.
pub fn halting_chart(series: &[HaltingSeries], title: &str) -> Result<Vec<u8>, CliError> {
    let mut out = String::new();
    let cs = series.iter().flat_map(|s| s.points.iter().map(|p| p.0));
    let (cmin, cmax) = cs.fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), c| (a.min(c), b.max(c)));
    let (cmin, cmax) = if cmin.is_finite() && cmax > cmin {
        (cmin, cmax)
    } else {
        (cmin - 0.05, cmin + 0.05)
    };
    let pad = (cmax - cmin) * 0.04;
    {
        let root = SVGBackend::with_string(&mut out, SIZE).into_drawing_area();
        root.fill(&WHITE).map_err(chart_error)?;
        let mut chart = ChartBuilder::on(&root)
            .caption(title, ("sans-serif", 22))
            .margin(16)
            .x_label_area_size(48)
            .y_label_area_size(64)
            .build_cartesian_2d((cmin - pad)..(cmax + pad), -0.02f64..1.02)
            .map_err(chart_error)?;
        chart
            .configure_mesh()
            .x_desc("c")
            .y_desc("fraction of runs that halted")
            .x_label_formatter(&|v| format!("{v:.3}"))
            .y_label_formatter(&|v| format!("{v:.1}"))
            .draw()
            .map_err(chart_error)?;
        for (i, s) in series.iter().enumerate() {
            let col = color(i);
            chart
                .draw_series(LineSeries::new(s.points.iter().copied(), col.stroke_width(2)))
                .map_err(chart_error)?
                .label(s.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], col.stroke_width(2)));
            chart
                .draw_series(s.points.iter().map(|&p| Circle::new(p, 4, col.filled())))
                .map_err(chart_error)?;
        }
        legend_and_present(&mut chart, &root)?;
    }
    out.push('\n');
    Ok(out.into_bytes())
}
