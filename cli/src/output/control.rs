//! The writers as they were before the fast number formatting and the direct SVG writer:
//! numbers through the standard formatter, SVG elements built with the `svg` crate, JSON
//! through `serde_json`'s derive. Never used by the tool; kept as the control that
//! `cli/tests/writers.rs` compares the fast writers with, byte for byte, and that
//! `cargo bench --bench writing` times them against.

use crate::model::doc::FillDoc;
use crate::model::picture::Picture;
use crate::output::number::fixed_std;
use crate::output::svg::{self, Attributes, PLACES};
use ::svg as svg_crate;
use std::fmt::Write as _;
use svg_crate::node::element::{ClipPath, Definitions, Description, Element, Group, Rectangle, Title};
use svg_crate::node::Text;
use svg_crate::{Document, Node};

/// A number on the page through the standard formatter.
fn n(out: &mut String, v: f64) {
    out.push_str(&fixed_std(v, PLACES));
}

/// An `svg` crate node receiving attributes.
struct Crate<'a, N: Node>(&'a mut N);

impl<N: Node> Attributes for Crate<'_, N> {
    fn set(&mut self, name: &'static str, value: impl FnOnce(&mut String)) {
        let mut s = String::new();
        value(&mut s);
        self.0.assign(name, s);
    }
}

/// Attributes gathered before their element exists.
struct Pairs(Vec<(&'static str, String)>);

impl Attributes for Pairs {
    fn set(&mut self, name: &'static str, value: impl FnOnce(&mut String)) {
        let mut s = String::new();
        value(&mut s);
        self.0.push((name, s));
    }
}

/// Any picture as SVG, built as a tree of `svg` crate elements and printed by it.
pub fn svg(pic: &Picture) -> Vec<u8> {
    let f = pic.to_page();
    let (page_w, page_h) = pic.page_size();
    let element = |it, in_clip| {
        let mut pairs = Pairs(Vec::new());
        let mut e = Element::new(svg::item(&mut pairs, it, &f, in_clip, n));
        for (k, v) in pairs.0 {
            e.assign(k, v);
        }
        e
    };
    let mut d = Document::new();
    svg::page(&mut Crate(&mut d), page_w, page_h, n);
    d = d
        .add(Title::new("").add(Text::new(pic.title.as_str())))
        .add(Description::new().add(Text::new(pic.desc.as_str())));
    if let Some(bg) = &pic.background {
        let mut r = Rectangle::new();
        svg::background(&mut Crate(&mut r), bg, page_w, page_h, n);
        d = d.add(r);
    }
    if !pic.clips.is_empty() {
        let mut defs = Definitions::new();
        for c in &pic.clips {
            defs = defs.add(ClipPath::new().set("id", c.id.as_str()).add(element(&c.item, true)));
        }
        d = d.add(defs);
    }
    for layer in &pic.layers {
        if layer.bare {
            for item in &layer.items {
                d.append(element(item, false));
            }
            continue;
        }
        let mut g = Group::new();
        svg::group(&mut Crate(&mut g), layer, n);
        for item in &layer.items {
            g.append(element(item, false));
        }
        d = d.add(g);
    }
    let mut s = d.to_string();
    s.push('\n');
    s.into_bytes()
}

/// A fill as CSV, each number through `Display`.
pub fn csv(doc: &FillDoc) -> Vec<u8> {
    let mut s = String::from("index,kind,x,y,radius,angle,area,trials\n");
    let opt = |v: Option<f64>| v.map(|x| x.to_string()).unwrap_or_default();
    for sh in &doc.shapes {
        let _ = writeln!(
            s,
            "{},{},{},{},{},{},{},{}",
            sh.index,
            sh.kind,
            sh.center[0],
            sh.center[1],
            opt(sh.radius),
            opt(sh.angle),
            sh.area,
            sh.trials
        );
    }
    s.into_bytes()
}

/// A fill as JSON through `serde_json`'s derive.
pub fn json(doc: &FillDoc) -> Vec<u8> {
    let mut v = serde_json::to_vec(doc).unwrap_or_default();
    v.push(b'\n');
    v
}
