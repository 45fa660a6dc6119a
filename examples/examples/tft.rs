//! A fill on a colour display: 300 stars on a torus, each filled in a colour of its size
//! band, drawn shape by shape onto a 160 x 128 `Rgb565` framebuffer (an ST7735 TFT's) with
//! `zetafill_display::View::fill`, then written as a PPM picture. On a board the framebuffer
//! is the display driver's `DrawTarget`; nothing else changes.
//!
//! `cargo run -p zetafill-examples --example tft > tft.ppm`

use embedded_graphics::framebuffer::{buffer_size, Framebuffer};
use embedded_graphics::geometry::Point as Px;
use embedded_graphics::image::GetPixel;
use embedded_graphics::pixelcolor::raw::{LittleEndian, RawU16};
use embedded_graphics::pixelcolor::{Rgb565, RgbColor};
use std::io::Write;
use zetafill::{index_words, Engine, Params, Placed, Region, ShapeKind, Storage};
use zetafill_display::View;

const W: usize = 160;
const H: usize = 128;
type Tft = Framebuffer<Rgb565, RawU16, LittleEndian, W, H, { buffer_size::<Rgb565>(W, H) }>;

fn main() -> std::io::Result<()> {
    const CAP: usize = 300;
    let mut shapes = [Placed::<f64>::default(); CAP];
    let mut index = [0u32; index_words(CAP)];
    let storage = Storage {
        shapes: &mut shapes,
        index: &mut index,
        coverage: &mut [],
    };
    let mut params = Params::circles(1.25, 3.0);
    params.shape = ShapeKind::Star { points: 5, inner: 0.45 }.into();
    params.rotate = true;
    let region = Region::Rect {
        width: 100.0,
        height: 80.0,
        periodic: true,
    };
    let Ok(mut engine) = Engine::<f64>::new(params, region, storage) else {
        return Ok(());
    };
    // Five colours, largest shapes first, each band a fifth of the shapes' indices in log
    // scale (the areas fall as a power of the index).
    let palette = [
        Rgb565::new(4, 17, 10),
        Rgb565::new(5, 39, 17),
        Rgb565::new(29, 49, 13),
        Rgb565::new(30, 40, 12),
        Rgb565::new(29, 27, 10),
    ];
    let band = |i: u64| ((libm::log((i + 1) as f64) / libm::log(CAP as f64) * 5.0) as usize).min(4);
    let mut tft = Tft::new();
    let view = View::new(&region, W as u32, H as u32);
    let mut rng = zetafill::rng_from_seed(5);
    for _ in 0..CAP {
        let Ok(p) = engine.step(&mut rng) else { break };
        if let Some(g) = engine.geo(p.index as usize) {
            // A framebuffer's drawing never fails.
            let Ok(()) = view.fill(&g, palette[band(p.index)], &mut tft);
        }
    }
    let mut out = format!("P6\n{W} {H}\n255\n").into_bytes();
    for y in 0..H as i32 {
        for x in 0..W as i32 {
            let c = tft.pixel(Px::new(x, y)).unwrap_or(Rgb565::BLACK);
            // 5-6-5 bits to 8-8-8.
            out.extend_from_slice(&[c.r() << 3 | c.r() >> 2, c.g() << 2 | c.g() >> 4, c.b() << 3 | c.b() >> 2]);
        }
    }
    std::io::stdout().write_all(&out)
}
