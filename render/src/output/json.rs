//! JSON output: the [`FillDoc`] as docs/cli.md (Outputs) specifies, numbers in shortest
//! round-trip form (full f64 precision), on one line with a trailing newline.
//!
//! The shapes, nearly all of the bytes, are written directly into a buffer handed on every
//! 64 KiB; the small parts
//! (parameters, region, statistics) through their `serde` derive. The bytes are those of
//! `serde_json::to_vec(doc)`: the same number formatter ([`push_json`]), the same
//! field order and omissions (`cli/tests/writers.rs` compares the two on every shape kind).

use crate::error::CliError;
use crate::model::doc::{FillDoc, ShapeDoc};
use crate::output::number::{push_int, push_json};
use crate::output::stream::{TextSink, MAX_JSON_NUMBER, MAX_U64};
use serde::Serialize;

/// Serialises a fill.
pub fn render(doc: &FillDoc) -> Result<Vec<u8>, CliError> {
    let mut v = Vec::new();
    write(doc, &mut v)?;
    Ok(v)
}

/// What comes before the shapes and after them, each as one string.
fn frame(doc: &FillDoc) -> Result<(String, String), CliError> {
    let mut s = String::with_capacity(1024);
    s.push_str("{\"version\":");
    push_int(&mut s, u64::from(doc.version));
    s.push_str(",\"mode\":");
    part(&mut s, &doc.mode)?;
    s.push_str(",\"params\":");
    part(&mut s, &doc.params)?;
    s.push_str(",\"region\":");
    part(&mut s, &doc.region)?;
    s.push_str(",\"area\":");
    push_json(&mut s, doc.area);
    s.push_str(",\"zeta\":");
    push_json(&mut s, doc.zeta);
    s.push_str(",\"shapes\":[");
    let mut tail = String::from("],\"stats\":");
    part(&mut tail, &doc.stats)?;
    tail.push_str("}\n");
    Ok((s, tail))
}

/// Writes a fill into `out`, a few shapes at a time.
pub fn write(doc: &FillDoc, out: &mut dyn std::io::Write) -> Result<(), CliError> {
    let (head, tail) = frame(doc)?;
    let mut sink = TextSink::new(out);
    sink.buf.push_str(&head);
    for (i, sh) in doc.shapes.iter().enumerate() {
        if i > 0 {
            sink.buf.push(',');
        }
        shape(&mut sink.buf, sh)?;
        sink.maybe_flush()?;
    }
    sink.buf.push_str(&tail);
    sink.flush()
}

/// An upper bound on the size of [`write`](fn@write)'s bytes: all but the shapes exactly, and each
/// shape with its keys, a comma, two `u64` and every number at [`MAX_JSON_NUMBER`] bytes (its
/// kind escaped at worst six bytes a byte).
pub fn max_size(doc: &FillDoc) -> Result<u64, CliError> {
    let (head, tail) = frame(doc)?;
    let keys = "{\"index\":,\"kind\":\"\",\"center\":[,],\"radius\":,\"inner_radius\":,\"angle\":,\"area\":,\"trials\":},";
    let shapes: u64 = doc
        .shapes
        .iter()
        .map(|sh| {
            let vertices = sh.vertices.as_ref().map_or(0, |v| v.len() as u64);
            let list = if vertices > 0 {
                ",\"vertices\":[]".len() as u64 + vertices * (2 * MAX_JSON_NUMBER + 4)
            } else {
                0
            };
            let lines = |key: &str, r: &Option<Vec<Vec<[f64; 2]>>>| {
                r.as_ref().map_or(0, |r| {
                    let points: u64 = r.iter().map(|v| v.len() as u64).sum();
                    key.len() as u64 + 6 + r.len() as u64 * 3 + points * (2 * MAX_JSON_NUMBER + 4)
                })
            };
            let list = list + lines("outlines", &sh.outlines) + lines("decorations", &sh.decorations);
            keys.len() as u64 + 6 * sh.kind.len() as u64 + 2 * MAX_U64 + 6 * MAX_JSON_NUMBER + list
        })
        .sum();
    Ok(head.len() as u64 + tail.len() as u64 + shapes)
}

/// Appends a value through its `serde` derive.
fn part<T: Serialize + ?Sized>(s: &mut String, v: &T) -> Result<(), CliError> {
    s.push_str(&serde_json::to_string(v).map_err(|e| CliError::Io(format!("cannot encode JSON: {e}")))?);
    Ok(())
}

/// Appends `[x,y]`.
fn pair(s: &mut String, v: [f64; 2]) {
    s.push('[');
    push_json(s, v[0]);
    s.push(',');
    push_json(s, v[1]);
    s.push(']');
}

/// Appends `[[x,y],...]`.
fn points(s: &mut String, vs: &[[f64; 2]]) {
    s.push('[');
    for (i, v) in vs.iter().enumerate() {
        if i > 0 {
            s.push(',');
        }
        pair(s, *v);
    }
    s.push(']');
}

/// Appends one shape, its fields in the order of [`ShapeDoc`] and absent ones left out.
fn shape(s: &mut String, sh: &ShapeDoc) -> Result<(), CliError> {
    s.push_str("{\"index\":");
    push_int(s, sh.index);
    s.push_str(",\"kind\":");
    if sh.kind.bytes().all(|b| b.is_ascii_alphanumeric()) {
        s.push('"');
        s.push_str(sh.kind);
        s.push('"');
    } else {
        part(s, sh.kind)?;
    }
    s.push_str(",\"center\":");
    pair(s, sh.center);
    for (key, v) in [
        (",\"radius\":", sh.radius),
        (",\"inner_radius\":", sh.inner_radius),
        (",\"angle\":", sh.angle),
        (",\"area\":", Some(sh.area)),
    ] {
        if let Some(v) = v {
            s.push_str(key);
            push_json(s, v);
        }
    }
    s.push_str(",\"trials\":");
    push_int(s, sh.trials);
    if let Some(vs) = &sh.vertices {
        s.push_str(",\"vertices\":");
        points(s, vs);
    }
    for (key, lines) in [(",\"outlines\":[", &sh.outlines), (",\"decorations\":[", &sh.decorations)] {
        let Some(lines) = lines else { continue };
        s.push_str(key);
        for (k, line) in lines.iter().enumerate() {
            if k > 0 {
                s.push(',');
            }
            points(s, line);
        }
        s.push(']');
    }
    s.push('}');
    Ok(())
}
