//! The smallest use of the library: fill a 100 x 100 mm square with 300 circles and print
//! each one as it is placed, then the statistics.
//!
//! `cargo run -p zetafill-examples --example basic`

use zetafill::{index_words, Engine, Params, Placed, Region, Stop, Storage};

fn main() {
    const CAP: usize = 300;
    // The caller owns every buffer: here Vecs, on a microcontroller static arrays.
    let mut shapes = vec![Placed::<f64>::default(); CAP];
    let mut index = vec![0u32; index_words(CAP)];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let region = Region::Rect {
        width: 100.0,
        height: 100.0,
        periodic: false,
    };
    let mut engine = match Engine::<f64>::new(Params::circles(1.3, 1.0), region, storage) {
        Ok(e) => e,
        Err(e) => {
            eprintln!("bad parameters: {e}");
            std::process::exit(2);
        }
    };
    let mut rng = zetafill::rng_from_seed(7);
    let reason = engine.run(
        &mut rng,
        &Stop {
            count: Some(CAP as u64),
            ..Stop::default()
        },
        |p| {
            println!(
                "{:4} x={:8.3} y={:8.3} r={:7.4} trials={}",
                p.index, p.shape.x, p.shape.y, p.shape.scale, p.trials
            );
        },
    );
    let s = engine.stats();
    println!(
        "stopped: {reason:?}; {} shapes, {} trials, {:.1}% filled",
        s.placed,
        s.trials,
        100.0 * s.fill_fraction
    );
}
