//! A G-code program ready to be streamed: its paths checked and put in drawing order once,
//! its moves written a first time into a [`Counter`](crate::output::stream::Counter) to work out
//! the figures the header states and the exact size, then written again, a few paths at a
//! time, into the destination. Both passes write the same moves (nothing in them depends on
//! the sink), so the file holds the figures of its own moves.

use super::{check_options, comment, int, order, path_finite, Figures, GcodeOptions, Writer};
use crate::error::CliError;
use crate::model::Drawing;
use crate::model::Path;
use crate::output::machine::{Machine, Units};
use crate::output::stream::{io_error, TextSink};

/// A program ready to be written: the paths checked and ordered, the figures worked out and
/// the bytes counted (the moves are written once into a [`Counter`](crate::output::stream::Counter)
/// for that, since the header that opens the file states the figures of all of them).
#[derive(Debug, Clone)]
pub struct Program {
    m: Machine,
    o: GcodeOptions,
    /// Each pen's name and paths in drawing order.
    pens: Vec<(String, Vec<Path>)>,
    head: String,
    body: u64,
    /// What the program does.
    pub figures: Figures,
}

/// Checks and orders `pens` for machine `m` (see [`super::write_pens`]) and counts the program.
pub fn program(pens: &[(String, Drawing)], m: &Machine, o: &GcodeOptions) -> Result<Program, String> {
    m.validate()?;
    check_options(m, o)?;
    let area = m.usable_area(o.margin);
    let (b, finite) = {
        let all = Drawing {
            paths: pens.iter().flat_map(|(_, d)| d.paths.iter().cloned()).collect(),
        };
        (all.bounds(), all.paths.iter().all(path_finite))
    };
    if !b.inside(&area, 1e-6) {
        return Err(format!(
            "the drawing (x {:.3}..{:.3}, y {:.3}..{:.3} mm) does not fit the bed less margin (x {:.3}..{:.3}, y {:.3}..{:.3} mm)",
            b.x0, b.x1, b.y0, b.y1, area.x0, area.x1, area.y0, area.y1
        ));
    }
    if !finite {
        return Err("the drawing has a non-finite coordinate".into());
    }
    let pens = pens
        .iter()
        .filter(|(_, d)| !d.paths.is_empty())
        .map(|(name, d)| (name.clone(), order(&d.paths, m.home_in_bed(), o.order)))
        .collect();
    let mut p = Program {
        m: m.clone(),
        o: o.clone(),
        pens,
        head: String::new(),
        body: 0,
        figures: Figures {
            paths: 0,
            tool_ons: 0,
            pen_down_mm: 0.0,
            travel_mm: 0.0,
            seconds: 0.0,
        },
    };
    let mut counter = crate::output::stream::Counter(0);
    let fig = p.moves(&mut counter).map_err(|e| e.to_string())?;
    p.body = counter.0;
    p.head = head(m, o, &fig);
    p.figures = fig;
    Ok(p)
}

impl Program {
    /// The program's size in bytes.
    pub fn len(&self) -> u64 {
        self.head.len() as u64 + self.body
    }

    /// Whether the program is empty (never: it has a header).
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Writes the program into `out`, a few paths at a time.
    pub fn write_to(&self, out: &mut dyn std::io::Write) -> Result<(), CliError> {
        out.write_all(self.head.as_bytes()).map_err(io_error)?;
        self.moves(out).map(drop)
    }

    /// Writes everything after the header into `out` and returns the figures.
    fn moves(&self, out: &mut dyn std::io::Write) -> Result<Figures, CliError> {
        let (m, o) = (&self.m, &self.o);
        let dec = m.units.decimals();
        let k = m.units.per_mm() * 10f64.powi(dec as i32);
        let mb = m.machine_bounds_mm();
        let lo = [(mb.x0 * k - 1e-6).ceil() as i64, (mb.y0 * k - 1e-6).ceil() as i64];
        let hi = [(mb.x1 * k + 1e-6).floor() as i64, (mb.y1 * k + 1e-6).floor() as i64];
        let mut w = Writer {
            m,
            o,
            out: TextSink::new(out),
            dec,
            k,
            lo,
            hi,
            pos: None,
            tool_on: false,
            feed_stated: false,
            fig: Figures {
                paths: 0,
                tool_ons: 0,
                pen_down_mm: 0.0,
                travel_mm: 0.0,
                seconds: 0.0,
            },
        };
        w.line("G90");
        w.line(if m.units == Units::Mm { "G21" } else { "G20" });
        w.line("G17");
        w.block(&m.start);
        // The tool is off whatever the start block did.
        w.tool_on = true;
        w.tool(false);
        w.fig.tool_ons = 0;
        let used = &self.pens;
        for (i, (name, paths)) in used.iter().enumerate() {
            if used.len() > 1 {
                if i > 0 {
                    w.tool(false);
                    w.park();
                }
                let s = format!("; pen {} of {}: {name}", i + 1, used.len());
                w.line(&s);
                if i > 0 {
                    w.block(&m.pen_change);
                }
            }
            for _ in 0..o.passes {
                for p in paths {
                    w.path(p);
                    w.out.maybe_flush()?;
                }
            }
        }
        w.tool(false);
        w.park();
        w.block(&m.end);
        w.out.flush()?;
        let dwell = Machine::dwell_seconds(&m.tool_on) + Machine::dwell_seconds(&m.tool_off);
        let mut fig = w.fig;
        fig.seconds = fig.pen_down_mm / o.feed * 60.0 + fig.travel_mm / o.travel_feed * 60.0 + fig.tool_ons as f64 * dwell;
        Ok(fig)
    }
}

/// The comment lines that open a program: machine, settings and figures.
fn head(m: &Machine, o: &GcodeOptions, fig: &Figures) -> String {
    let dec = m.units.decimals();
    let mut head = String::new();
    comment(&mut head, &format!("zetafill G-code for machine '{}': {}", m.name, m.description));
    for h in &o.header {
        comment(&mut head, h);
    }
    let unit = if m.units == Units::Mm { "mm" } else { "inch" };
    comment(
        &mut head,
        &format!(
            "bed {} x {} mm, origin {:?}, units {unit} ({} decimals), margin {} mm",
            m.bed.width, m.bed.height, m.origin, dec, o.margin
        ),
    );
    comment(
        &mut head,
        &format!(
            "feed {} mm/min, travel {} mm/min ({:?}), power {}, passes {}, arcs {}, chord tolerance {} mm, order {:?}",
            o.feed,
            o.travel_feed,
            m.travel,
            o.power.map(|p| int(p, 0)).unwrap_or_else(|| "-".into()),
            o.passes,
            if o.arcs { "G2/G3" } else { "no (polylines)" },
            o.chord_tolerance,
            o.order
        ),
    );
    comment(&mut head, &format!("figures: {fig}"));
    head
}
