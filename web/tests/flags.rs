//! The page reads a command line as the binary does: every flag of `fill`, `line`,
//! `territory` and `tile`, its default, its parser, its rules and the first line of every
//! message are held to clap's reading of the same words (the binary's parser, which the page
//! does not link).

use clap::{CommandFactory, Parser, ValueEnum};
use std::collections::BTreeSet;
use zetafill_cli::args::{Cli, Command};
use zetafill_web::flags::{self, names};
use zetafill_web::words::Words;

const COMMANDS: [&str; 4] = ["fill", "line", "territory", "tile"];

/// What clap makes of `zetafill COMMAND ARGV`: the arguments (Debug) or the message's first line.
fn clap_reads(command: &str, argv: &[String]) -> Result<String, String> {
    let words = ["zetafill", command].into_iter().map(String::from).chain(argv.iter().cloned());
    match Cli::try_parse_from(words) {
        Ok(Cli { command: Command::Fill(a) }) => Ok(format!("{a:?}")),
        Ok(Cli { command: Command::Line(a) }) => Ok(format!("{a:?}")),
        Ok(Cli {
            command: Command::Territory(a),
        }) => Ok(format!("{a:?}")),
        Ok(Cli { command: Command::Tile(a) }) => Ok(format!("{a:?}")),
        Ok(_) => panic!("not a page command"),
        Err(e) => Err(e.to_string().lines().next().unwrap_or_default().to_string()),
    }
}

/// What the page makes of the same words.
fn page_reads(command: &str, argv: &[String]) -> Result<String, String> {
    let first = |e: String| e.lines().next().unwrap_or_default().to_string();
    let mut w = Words::new(argv, &flags::SHORTS, flags::PLAIN).map_err(first)?;
    let debug = match command {
        "fill" => flags::fill(&mut w).map(|a| format!("{a:?}")),
        "line" => flags::line(&mut w).map(|a| format!("{a:?}")),
        "territory" => flags::territory(&mut w).map(|a| format!("{a:?}")),
        "tile" => flags::tile(&mut w).map(|a| format!("{a:?}")),
        _ => panic!("not a page command"),
    }
    .map_err(first)?;
    w.finish().map_err(first)?;
    Ok(debug)
}

fn words(line: &str) -> Vec<String> {
    line.split_whitespace().map(String::from).collect()
}

/// Both read `argv` alike; the outcome, for the caller to look at.
fn alike(command: &str, argv: &[String]) -> Result<String, String> {
    let line = format!("zetafill {command} {}", argv.join(" "));
    same(clap_reads(command, argv), page_reads(command, argv), &line)
}

/// Panics unless the page's outcome is clap's.
fn same(clap: Result<String, String>, page: Result<String, String>, line: &str) -> Result<String, String> {
    assert_eq!(page, clap, "{line}");
    clap
}

/// The long names of a command's flags, as clap defines them.
fn clap_flags(command: &str) -> Vec<clap::Arg> {
    let cli = Cli::command();
    let sub = cli.find_subcommand(command).expect("a subcommand");
    sub.get_arguments().filter(|a| a.get_id() != "help").cloned().collect()
}

fn takes_value(a: &clap::Arg) -> bool {
    a.get_action().takes_values()
}

#[test]
fn every_flag_is_read_and_no_other() {
    for command in COMMANDS {
        let clap: BTreeSet<String> = clap_flags(command).iter().filter_map(|a| a.get_long().map(String::from)).collect();
        let mut w = Words::new(&words("-o x.svg"), &flags::SHORTS, flags::PLAIN).expect("a good line");
        match command {
            "fill" => drop(flags::fill(&mut w)),
            "line" => drop(flags::line(&mut w)),
            "territory" => drop(flags::territory(&mut w)),
            _ => drop(flags::tile(&mut w)),
        }
        let page: BTreeSet<String> = w.asked().iter().map(|s| s.to_string()).collect();
        assert_eq!(page, clap, "{command}");
        for a in clap_flags(command) {
            if let Some(s) = a.get_short() {
                assert!(
                    flags::SHORTS.contains(&(s, a.get_long().expect("every flag has a long name"))),
                    "{command}: -{s}"
                );
            }
            let plain = takes_value(&a) && !a.is_allow_hyphen_values_set();
            assert_eq!(
                flags::PLAIN.contains(&a.get_long().expect("every flag has a long name")),
                plain,
                "{command}: --{} and PLAIN",
                a.get_long().expect("every flag has a long name")
            );
        }
    }
}

fn clap_names<T: ValueEnum>() -> Vec<String> {
    T::value_variants()
        .iter()
        .map(|v| v.to_possible_value().expect("a named value").get_name().to_string())
        .collect()
}

fn page_names<T>(table: &[(&str, T)]) -> Vec<String> {
    table.iter().map(|(n, _)| n.to_string()).collect()
}

#[test]
fn choices_have_the_names_clap_gives() {
    use zetafill_cli::args::{colour, fill, format, line, plot, raster, style, territory, tile};
    assert_eq!(page_names(&names::ROTATE), clap_names::<fill::Rotate>());
    assert_eq!(page_names(&names::MIX), clap_names::<fill::MixArg>());
    assert_eq!(page_names(&names::SAMPLER), clap_names::<fill::Sampler>());
    assert_eq!(page_names(&names::SCALAR), clap_names::<fill::ScalarArg>());
    assert_eq!(
        page_names(&names::SYMMETRY),
        clap_names::<zetafill_cli::args::symmetry::SymmetryArg>()
    );
    assert_eq!(page_names(&names::FORMAT), clap_names::<format::FormatArg>());
    assert_eq!(page_names(&names::STYLE), clap_names::<style::StyleArg>());
    assert_eq!(page_names(&names::RELIEF), clap_names::<raster::ReliefArg>());
    assert_eq!(page_names(&names::COLOR_BY), clap_names::<colour::ColorByArg>());
    assert_eq!(page_names(&names::ORDER), clap_names::<plot::OrderArg>());
    assert_eq!(page_names(&names::LINE_RENDER), clap_names::<line::RenderArg>());
    assert_eq!(page_names(&names::TERRITORY_RENDER), clap_names::<territory::RenderArg>());
    assert_eq!(page_names(&names::TERRITORY_FORMAT), clap_names::<territory::TerritoryFormatArg>());
    assert_eq!(page_names(&names::TILE_RENDER), clap_names::<tile::RenderArg>());
    assert_eq!(page_names(&names::TILE_STYLE), clap_names::<tile::StyleArg>());
    assert_eq!(page_names(&names::LAYOUT), clap_names::<tile::LayoutArg>());
    assert_eq!(page_names(&names::TILE_FORMAT), clap_names::<tile::TileFormatArg>());
    for (name, order) in names::ORDER {
        assert_eq!(order.name(), name);
    }
}

/// A value each flag accepts, and for choices each of its names.
fn samples(long: &str) -> Vec<&'static str> {
    match long {
        "shape" => vec!["ring:0.5", "mix:circle,square", "noisy:0.2"],
        "mix-order" | "rotate" => vec!["random", "none", "cycle"],
        "region" => vec!["circle:50", "annulus:50:20", "polygon:0,0,10,0,0,10", "text:ZF", "rect:300:100"],
        "sampler" => vec!["fast", "reference", "batched"],
        "scalar" => vec!["f64", "fixed"],
        "symmetry" => vec!["p4m", "p31m", "cm", "p1", "p7"],
        "lattice" => vec!["40", "40:30", "40:30:70", "40:30:180", "1:2:3:4", "0:1"],
        "repeat" => vec!["3:3", "2", "0:1", "101:1", "3:x", "2:7"],
        "format" => vec!["svg", "json", "csv", "png", "digest", "gcode"],
        "style" => vec!["outline", "filled"],
        "relief" => vec!["dome", "cone", "flat"],
        "color-by" => vec!["size", "random", "cycle", "kind"],
        "order" => vec!["none", "greedy", "improved"],
        "render" => vec![
            "dashes",
            "circles",
            "bars",
            "zoom",
            "boundaries",
            "cells",
            "filled",
            "shapes",
            "discs",
            "voronoi",
        ],
        "layout" => vec!["tile", "mosaic", "planet"],
        "density" => vec!["noise:value:10", "noise:gradient:20:3:0.5:1.5", "image:pic.png,invert"],
        "max-output-size" => vec!["1M", "4096"],
        "palette" => vec!["ff0000,00ff00", "abc"],
        "background" => vec!["fff", "#102030"],
        "page" => vec!["a4", "a3-landscape", "300x200"],
        "layers" => vec!["size-bands:3", "colours", "none"],
        "hatch" => vec!["1:30", "2"],
        "machine" => vec!["grbl-laser", "m.toml"],
        "site" => vec!["10,10"],
        "color" => vec!["0.5,0.5,0.5", "0.1,0.9,0.5:0.01,0,0"],
        "font" | "sites-from" | "output" => vec!["f.ttf"],
        "region-sha256" | "font-sha256" | "density-sha256" => vec!["abc"],
        "c" => vec!["1.25"],
        "dimension" => vec!["0.5", "1.5"],
        "fill" | "zoom-fraction" => vec!["0.3"],
        "count" | "max-trials" | "cells" | "tries" | "points" | "n0" => vec!["100", "20000001"],
        "threads" | "batch" | "passes" | "rows" | "columns" | "zoom-rows" | "pixels" | "sites" => vec!["3", "1025"],
        "seed" => vec!["7", "18446744073709551615"],
        _ => vec!["2", "0.5"],
    }
}

#[test]
fn every_flag_reads_alike_with_good_and_bad_values() {
    let base = words("-o x.svg");
    for command in COMMANDS {
        // The defaults.
        assert!(alike(command, &base).is_ok(), "{command}: the defaults");
        for a in clap_flags(command) {
            let long = a.get_long().expect("every flag has a long name");
            let flag = format!("--{long}");
            let mut lines: Vec<Vec<String>> = Vec::new();
            if takes_value(&a) {
                for v in samples(long).into_iter().chain(["@@", "-5", "-", "0", "nan", "1e999", ""]) {
                    lines.push([flag.clone(), v.to_string()].into());
                    lines.push([format!("{flag}={v}")].into());
                }
                lines.push([flag.clone()].into());
                // Twice: refused unless the flag repeats.
                let v = samples(long)[0];
                lines.push([flag.clone(), v.into(), flag.clone(), v.into()].into());
            } else {
                lines.push([flag.clone()].into());
                lines.push([flag.clone(), flag.clone()].into());
                lines.push([format!("{flag}=yes")].into());
            }
            for line in lines {
                let argv: Vec<String> = base.iter().cloned().chain(line).collect();
                alike(command, &argv).ok();
            }
        }
    }
}

#[test]
fn rules_and_malformed_lines_read_alike() {
    let lines = [
        ("fill", "-o x.svg --c 1.3 --dimension 1.5"),
        ("fill", "-o x.svg --dimension 1.5 --c 1.3"),
        ("fill", "--pixels 5 --dpi 3 -o x.svg"),
        ("fill", "--dpi 3 --pixels 5 -o x.svg"),
        ("fill", "-o x.svg --color-by size"),
        ("fill", "-o x.svg --color-by size --palette fff"),
        ("fill", "-o x.svg --hatch-only"),
        ("fill", "-o x.svg --cross-hatch --hatch 1"),
        ("fill", "-o x.svg --arcs --no-arcs"),
        ("fill", "-o x.svg --symmetry p4m"),
        ("fill", "-o x.svg --lattice 40"),
        ("fill", "-o x.svg --repeat 2:2 --symmetry p4m --lattice 40"),
        ("fill", "-o x.svg --repeat 2:2"),
        ("fill", "-o x.svg --symmetry p4m --lattice 40 --region circle:50"),
        ("fill", "-o x.svg --symmetry p4m --lattice 40 --repeat 2:2 --region circle:50"),
        ("fill", "-o x.svg --region rect:90:90 --repeat 2:2 --symmetry p4m --lattice 40"),
        ("fill", "-o x.svg --periodic --symmetry p6m --lattice 40"),
        ("fill", "-o x.svg --symmetry pgg --lattice 40:30 --density noise:value:10"),
        ("fill", "-o x.svg --voronoi --symmetry p2 --lattice 40:30:70"),
        ("fill", "-o x.svg --symmetry p4m --lattice 40:30"),
        ("fill", "-o x.svg --bogus"),
        ("fill", "-o x.svg stray"),
        ("fill", "-o"),
        ("fill", "-o -q"),
        ("fill", ""),
        ("fill", "--seed 3"),
        ("fill", "-ox.svg -q"),
        ("fill", "-o - --format digest --count 10"),
        ("fill", "--output=x.svg --quiet --seed=4 --gap -1"),
        ("fill", "-o x.svg --palette -1"),
        ("fill", "-o x.svg -x"),
        ("fill", "-o x.svg --shape star:5:0.5 --rotate none --region circle:80 --c 1.2 --n-offset 3 --count 500 --gap 0.2 --seed 9 --style filled --palette 264653,2a9d8f --color-by random --background fefae0"),
        ("line", "--count 400 --render bars --bar-height 40 --palette 264653,2a9d8f,e9c46a,f4a261,e76f51 --background fefae0 -o l.svg"),
        ("line", "-o l.svg --dimension 0.5"),
        ("line", "-o l.svg --count 10000001"),
        ("territory", "--sites 3 --points 7000 --seed 3 --render filled -o t.svg"),
        ("territory", "-o t.svg --sites 3 --site 1,1"),
        ("territory", "-o t.svg --site 1,1 --site 5,5 --color 0.5,0.5,0.5 --color 0.1,0.2,0.3"),
        ("territory", "-o t.svg --sites-from f.json --points 10"),
        ("territory", "-o t.svg --region circle:40 --sites-from f.json"),
        ("tile", "--seed 2 --radius 8 --spacing 2 --tries 3000 --style filled -o t.svg"),
        ("tile", "-o t.svg --layout planet --planet-radius 30 --relief dome"),
    ];
    let mut refused = 0;
    for (command, line) in lines {
        refused += alike(command, &words(line)).is_err() as usize;
    }
    assert!(refused >= 15, "{refused} refused");
}

/// The comparison itself fails on a difference: a changed default, a changed parser.
#[test]
fn the_checker_sees_a_difference() {
    let differs =
        |a: &str, b: &str| std::panic::catch_unwind(|| same(clap_reads("fill", &words(a)), page_reads("fill", &words(b)), a)).is_err();
    assert!(!differs("-o x.svg", "-o x.svg"));
    assert!(differs("-o x.svg --seed 2", "-o x.svg"));
    assert!(differs("-o x.svg --c 0.6", "-o x.svg --c 0.5"));
    assert!(differs("-o x.svg --bogus", "-o x.svg --c 0.5"));
}
