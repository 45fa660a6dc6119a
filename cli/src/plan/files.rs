//! The files every command names, each with its flag: the one list that the rule "no output
//! is ever an input" ([`crate::io::inputs::refuse_overwrites`]) is checked against, before
//! anything is read or computed. A new flag that reads a file adds it here; an input missed
//! here is still caught when the output is put in place, since every read is noted
//! ([`crate::io::inputs::was_read`]).

use crate::args::plot::PlotArgs;
use crate::args::stats::StatsCommand;
use crate::args::Command;
use crate::io::inputs::Files;
use crate::model::density::DensitySpec;
use crate::model::region::RegionSpec;

/// Every output and input `cmd` names.
pub fn of(cmd: &Command) -> Files<'_> {
    let mut f = Files::default();
    match cmd {
        Command::Fill(a) => {
            f.output("--output", &a.output.output);
            if let Some(r) = &a.region {
                region(&mut f, r);
            }
            if let Some(p) = &a.input.font {
                f.input("--font", p);
            }
            if let Some(DensitySpec::Image { path, .. }) = &a.density {
                f.input("--density", path);
            }
            machine(&mut f, &a.plot);
        }
        Command::Line(a) => {
            f.output("--output", &a.output.output);
            machine(&mut f, &a.plot);
        }
        Command::Space(a) => f.output("--output", &a.output.output),
        Command::Territory(a) => {
            f.output("--output", &a.output.output);
            region(&mut f, &a.region);
            if let Some(p) = &a.sites_from {
                f.input("--sites-from", p);
            }
            machine(&mut f, &a.plot);
        }
        Command::Tile(a) => {
            f.output("--output", &a.output.output);
            machine(&mut f, &a.plot);
        }
        Command::Stats(s) => match s {
            StatsCommand::Trials(a) => chart(&mut f, a.chart.output.as_deref()),
            StatsCommand::Halting(a) => chart(&mut f, a.chart.output.as_deref()),
            StatsCommand::Dimension(a) => f.input("FILE", &a.input),
            StatsCommand::Zeta(_) | StatsCommand::Gasket(_) => {}
        },
        // Reads a profile and prints it: nothing is written.
        Command::Machines(_) => {}
        // Print to standard output only.
        Command::Completions(_) | Command::Man(_) => {}
    }
    f
}

fn region<'a>(f: &mut Files<'a>, spec: &'a RegionSpec) {
    if let RegionSpec::Svg(p) | RegionSpec::Mask { path: p, .. } = spec {
        f.input("--region", p);
    }
}

fn machine<'a>(f: &mut Files<'a>, plot: &'a PlotArgs) {
    if let Some(p) = plot.machine_file() {
        f.input("--machine", p);
    }
}

fn chart<'a>(f: &mut Files<'a>, output: Option<&'a std::path::Path>) {
    if let Some(p) = output {
        f.output("--output", p);
    }
}
