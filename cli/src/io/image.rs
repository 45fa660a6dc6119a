//! Pictures read as luminance (`--density image:FILE`, `--region mask:FILE`): PNG through the `png` crate (grey or
//! colour, with or without alpha, palette, 1 to 16 bits) and JPEG through `zune-jpeg`.
//!
//! A pixel's luminance is `0.2126 R + 0.7152 G + 0.0722 B` of its stored (gamma-encoded)
//! values, in `[0, 1]`; a transparent pixel is composited over white, so it reads as light.

use std::path::Path;

/// The largest picture file read.
pub const MAX_IMAGE_BYTES: u64 = 64 << 20;
/// The most pixels a picture may have (a 8,000 x 8,000 image).
pub const MAX_PIXELS: u64 = 64_000_000;

/// A picture as luminance, row by row from the top.
#[derive(Debug, Clone, PartialEq)]
pub struct Grey {
    /// Width in pixels.
    pub width: usize,
    /// Height in pixels.
    pub height: usize,
    /// `width * height` values in `[0, 1]`.
    pub luma: Vec<f32>,
    /// The SHA-256 of the file, in hex.
    pub sha256: String,
}

/// Reads `path` as luminance, or says what is wrong with it.
pub fn read_grey(path: &Path) -> Result<Grey, String> {
    let bytes =
        crate::io::read::read_limited(path, MAX_IMAGE_BYTES, "a picture").map_err(|e| format!("cannot read {}: {e}", path.display()))?;
    let sha256 = crate::io::read::sha256_hex(&bytes);
    let (width, height, luma) = if bytes.starts_with(b"\x89PNG\r\n\x1a\n") {
        png_luma(&bytes)?
    } else if bytes.starts_with(&[0xff, 0xd8, 0xff]) {
        jpeg_luma(&bytes)?
    } else if bytes.is_empty() {
        return Err(format!("{} is empty: give a PNG or JPEG picture", path.display()));
    } else {
        return Err(format!("{} is not a PNG or JPEG picture", path.display()));
    };
    if width == 0 || height == 0 || luma.len() != width * height {
        return Err(format!("{} holds no pixels", path.display()));
    }
    Ok(Grey {
        width,
        height,
        luma,
        sha256,
    })
}

fn check_size(w: u64, h: u64) -> Result<(), String> {
    if w.saturating_mul(h) > MAX_PIXELS {
        return Err(format!(
            "the picture is {w} x {h} pixels, more than the {MAX_PIXELS} a picture may have: scale it down"
        ));
    }
    Ok(())
}

fn luminance(r: f32, g: f32, b: f32) -> f32 {
    0.2126 * r + 0.7152 * g + 0.0722 * b
}

fn png_luma(bytes: &[u8]) -> Result<(usize, usize, Vec<f32>), String> {
    let mut dec = png::Decoder::new(std::io::Cursor::new(bytes));
    dec.set_transformations(png::Transformations::EXPAND);
    let mut reader = dec.read_info().map_err(|e| format!("not a readable PNG: {e}"))?;
    let info = reader.info();
    check_size(u64::from(info.width), u64::from(info.height))?;
    let mut buf = vec![0u8; reader.output_buffer_size()];
    let frame = reader.next_frame(&mut buf).map_err(|e| format!("not a readable PNG: {e}"))?;
    let (w, h) = (frame.width as usize, frame.height as usize);
    let channels = frame.color_type.samples();
    let wide = frame.bit_depth == png::BitDepth::Sixteen;
    let max = if wide { 65535.0 } else { 255.0 };
    let sample = |i: usize| -> f32 {
        let v = if wide {
            u16::from_be_bytes([buf.get(i * 2).copied().unwrap_or(0), buf.get(i * 2 + 1).copied().unwrap_or(0)])
        } else {
            u16::from(buf.get(i).copied().unwrap_or(0))
        };
        f32::from(v) / max
    };
    let mut luma = Vec::with_capacity(w * h);
    for y in 0..h {
        for x in 0..w {
            let base = y * (frame.line_size / if wide { 2 } else { 1 }) + x * channels;
            let (l, a) = match channels {
                1 => (sample(base), 1.0),
                2 => (sample(base), sample(base + 1)),
                3 => (luminance(sample(base), sample(base + 1), sample(base + 2)), 1.0),
                _ => (luminance(sample(base), sample(base + 1), sample(base + 2)), sample(base + 3)),
            };
            luma.push(l * a + (1.0 - a));
        }
    }
    Ok((w, h, luma))
}

fn jpeg_luma(bytes: &[u8]) -> Result<(usize, usize, Vec<f32>), String> {
    use zune_jpeg::zune_core::colorspace::ColorSpace;
    use zune_jpeg::zune_core::options::DecoderOptions;
    let options = DecoderOptions::default()
        .jpeg_set_out_colorspace(ColorSpace::Luma)
        .set_max_width(usize::MAX >> 1)
        .set_max_height(usize::MAX >> 1);
    let mut dec = zune_jpeg::JpegDecoder::new_with_options(bytes, options);
    dec.decode_headers().map_err(|e| format!("not a readable JPEG: {e:?}"))?;
    let (w, h) = dec.dimensions().ok_or("not a readable JPEG: no size")?;
    check_size(w as u64, h as u64)?;
    let pixels = dec.decode().map_err(|e| format!("not a readable JPEG: {e:?}"))?;
    if pixels.len() != w * h {
        return Err(format!("not a readable JPEG: {} values for {w} x {h} pixels", pixels.len()));
    }
    Ok((w, h, pixels.iter().map(|&v| f32::from(v) / 255.0).collect()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A PNG of `w x h` pixels of `color` and `depth` from the samples `data`.
    fn png_file(dir: &Path, name: &str, w: u32, h: u32, color: png::ColorType, depth: png::BitDepth, data: &[u8]) -> std::path::PathBuf {
        let path = dir.join(name);
        let file = std::fs::File::create(&path).unwrap_or_else(|e| panic!("{e}"));
        let mut enc = png::Encoder::new(file, w, h);
        enc.set_color(color);
        enc.set_depth(depth);
        let mut wr = enc.write_header().unwrap_or_else(|e| panic!("{e}"));
        wr.write_image_data(data).unwrap_or_else(|e| panic!("{e}"));
        path
    }

    #[test]
    fn every_png_layout_reads_as_luminance() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let d = dir.path();
        let close = |a: &[f32], b: &[f32]| a.len() == b.len() && a.iter().zip(b).all(|(x, y)| (x - y).abs() < 1e-3);
        let g8 = png_file(d, "g8.png", 2, 1, png::ColorType::Grayscale, png::BitDepth::Eight, &[0, 255]);
        assert!(close(&read_grey(&g8).map(|g| g.luma).unwrap_or_default(), &[0.0, 1.0]));
        let g16 = png_file(
            d,
            "g16.png",
            2,
            1,
            png::ColorType::Grayscale,
            png::BitDepth::Sixteen,
            &[0x80, 0x00, 0xff, 0xff],
        );
        assert!(close(
            &read_grey(&g16).map(|g| g.luma).unwrap_or_default(),
            &[32768.0 / 65535.0, 1.0]
        ));
        // Pure red, green and blue: the Rec. 709 weights.
        let rgb = png_file(
            d,
            "rgb.png",
            3,
            1,
            png::ColorType::Rgb,
            png::BitDepth::Eight,
            &[255, 0, 0, 0, 255, 0, 0, 0, 255],
        );
        assert!(close(
            &read_grey(&rgb).map(|g| g.luma).unwrap_or_default(),
            &[0.2126, 0.7152, 0.0722]
        ));
        // Black, fully transparent and half transparent: over white.
        let ga = png_file(
            d,
            "ga.png",
            3,
            1,
            png::ColorType::GrayscaleAlpha,
            png::BitDepth::Eight,
            &[0, 255, 0, 0, 0, 128],
        );
        assert!(close(
            &read_grey(&ga).map(|g| g.luma).unwrap_or_default(),
            &[0.0, 1.0, 1.0 - 128.0 / 255.0]
        ));
        // Two rows, one bit a pixel, expanded.
        let bits = png_file(
            d,
            "b1.png",
            3,
            2,
            png::ColorType::Grayscale,
            png::BitDepth::One,
            &[0b1010_0000, 0b0100_0000],
        );
        assert!(close(
            &read_grey(&bits).map(|g| g.luma).unwrap_or_default(),
            &[1.0, 0.0, 1.0, 0.0, 1.0, 0.0]
        ));
        let g = read_grey(&g8).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!((g.width, g.height, g.sha256.len()), (2, 1, 64));
    }

    #[test]
    fn bad_pictures_say_what_is_wrong() {
        let dir = tempfile::tempdir().unwrap_or_else(|e| panic!("{e}"));
        let d = dir.path();
        let empty = d.join("empty.png");
        std::fs::write(&empty, b"").unwrap_or_else(|e| panic!("{e}"));
        let text = d.join("notes.png");
        std::fs::write(&text, b"hello").unwrap_or_else(|e| panic!("{e}"));
        let cut = d.join("cut.png");
        let whole = std::fs::read(png_file(
            d,
            "whole.png",
            4,
            4,
            png::ColorType::Grayscale,
            png::BitDepth::Eight,
            &[7; 16],
        ))
        .unwrap_or_default();
        std::fs::write(&cut, &whole[..whole.len() - 20]).unwrap_or_else(|e| panic!("{e}"));
        for (path, says) in [
            (d.join("missing.png"), "cannot read"),
            (empty, "is empty"),
            (text, "not a PNG or JPEG"),
            (cut, "not a readable PNG"),
            (Path::new("/dev/zero").to_path_buf(), "more than 64 MiB"),
        ] {
            let e = read_grey(&path).err().unwrap_or_default();
            assert!(e.contains(says), "{}: {e}", path.display());
        }
        // A header that claims 10,000 x 10,000 pixels is refused before they are read.
        let mut huge = whole.clone();
        huge[16..24].copy_from_slice(&[0, 0, 0x27, 0x10, 0, 0, 0x27, 0x10]);
        let crc = crc32(&huge[12..29]);
        huge[29..33].copy_from_slice(&crc.to_be_bytes());
        let big = d.join("big.png");
        std::fs::write(&big, &huge).unwrap_or_else(|e| panic!("{e}"));
        let e = read_grey(&big).err().unwrap_or_default();
        assert!(e.contains("10000 x 10000"), "{e}");
    }

    /// The CRC-32 of PNG chunks.
    fn crc32(bytes: &[u8]) -> u32 {
        let mut c = 0xffff_ffffu32;
        for &b in bytes {
            c ^= u32::from(b);
            for _ in 0..8 {
                c = if c & 1 != 0 { 0xedb8_8320 ^ (c >> 1) } else { c >> 1 };
            }
        }
        !c
    }
}
