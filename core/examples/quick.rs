use zetafill::*;
fn main() {
    let n: usize = std::env::args().nth(1).and_then(|s| s.parse().ok()).unwrap_or(10000);
    let shape = match std::env::args().nth(2).as_deref() { Some("square") => ShapeKind::Square, _ => ShapeKind::Circle };
    let periodic = std::env::args().nth(3).is_some();
    let mut shapes = vec![Placed { x: 0.0, y: 0.0, scale: 0.0, angle: 0.0, kind: 0 }; n];
    let mut index = vec![0u32; index_words(n)];
    let mut cov = vec![0u64; if std::env::args().nth(4).is_some() { 0 } else { 1 << 18 }];
    let mut p = Params::circles(1.3, 1.0);
    p.shape = shape; p.rotate = true;
    let mut e = Engine::<f64>::new(p, Region::Rect { width: 200.0, height: 200.0, periodic }, Storage { shapes: &mut shapes, index: &mut index, coverage: &mut cov }).unwrap();
    let mut rng = rng_from_seed(1);
    let t = std::time::Instant::now();
    let r = e.run(&mut rng, &Stop { count: Some(n as u64), ..Default::default() }, |_| {});
    let el = t.elapsed().as_secs_f64();
    let s = e.stats();
    println!("cov {:.4} {r:?} placed {} trials {} fill {:.4} time {:.3}s  {:.1} ns/trial", e.coverage_fraction(), s.placed, s.trials, s.fill_fraction, el, el * 1e9 / s.trials as f64);
}
