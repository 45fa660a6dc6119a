//! Streaming, as a display would do it: step the engine one shape at a time and draw each
//! shape into a small character framebuffer as soon as it is placed. A prefix of the
//! sequence is a level of detail: stopping early gives the same first shapes.
//!
//! `cargo run -p zetafill-examples --example stream`

use zetafill::{index_words, Engine, Geo, Params, Placed, Region, ShapeKind, Storage};

const W: usize = 72;
const H: usize = 36;

fn main() {
    const CAP: usize = 400;
    let mut shapes = [Placed::<f64>::default(); CAP];
    let mut index = [0u32; index_words(CAP)];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut params = Params::circles(1.25, 2.0);
    params.shape = ShapeKind::Square.into();
    params.rotate = true;
    let region = Region::Rect {
        width: 2.0 * H as f64,
        height: H as f64,
        periodic: true,
    };
    let Ok(mut engine) = Engine::<f64>::new(params, region, storage) else {
        return;
    };
    let mut rng = zetafill::rng_from_seed(3);
    let mut fb = [[b' '; W]; H];
    for _ in 0..CAP {
        let Ok(p) = engine.step(&mut rng) else { break };
        let Some(g) = engine.geo(p.index as usize) else { break };
        // Each cell is 1 mm wide and 1 mm tall (rows are printed top-down).
        for (row, line) in fb.iter_mut().enumerate() {
            for (col, cell) in line.iter_mut().enumerate() {
                let (x, y) = (col as f64 + 0.5, (H - 1 - row) as f64 + 0.5);
                if inside(&g, x, y) {
                    *cell = b"#@%*+=-:."[(p.index as usize).min(8)];
                }
            }
        }
    }
    for line in &fb {
        println!("{}", String::from_utf8_lossy(line));
    }
    let s = engine.stats();
    println!("{} shapes, {:.1}% filled", s.placed, 100.0 * s.fill_fraction);
}

/// Point-in-shape for drawing (no periodic images: this is a sketch).
fn inside(g: &Geo<f64>, x: f64, y: f64) -> bool {
    match g {
        Geo::Circle { c, r } => (x - c.x).powi(2) + (y - c.y).powi(2) <= r * r,
        Geo::Ring { c, r, inner } => {
            let d2 = (x - c.x).powi(2) + (y - c.y).powi(2);
            d2 <= r * r && d2 >= inner * inner
        }
        Geo::Poly { .. } => zetafill::internals::geom::point_in_poly(zetafill::Point::new(x, y), g.vertices()),
        // Even-odd over the rings.
        Geo::Motif { m, f } => {
            let ring_holds = |r: Vec<zetafill::Point<f64>>| zetafill::internals::geom::point_in_poly(zetafill::Point::new(x, y), &r);
            m.rings_at(f).map(|r| ring_holds(r.collect())).filter(|&h| h).count() % 2 == 1
        }
    }
}
