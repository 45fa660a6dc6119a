//! Arrays in a profile. A position or a size has exactly the dimensions the machine has, so an
//! array with more or fewer numbers is refused where it is read, never cut to size or padded:
//! the TOML reader then names the line of its key, as for every other field it refuses.
//!
//! `park` is the array `[x, y]`: the writer moves in X and Y only (a pen's height belongs to
//! the blocks), so `park = [0.0, 0.0, 5.0]` is refused rather than parked at (0, 0) with the
//! 5.0 dropped. The tables `[bed]`, `[feed]` and `[power]` may also be written as arrays of
//! their fields in order (`bed = [300.0, 200.0]`, as serde reads a struct from a sequence);
//! those too must hold exactly their fields.

use super::{Bed, Feeds, Power};
use serde::de::{self, value::MapAccessDeserializer, Deserializer, MapAccess, SeqAccess, Visitor};
use serde::Deserialize;
use std::fmt;
use std::marker::PhantomData;

/// What a wrong count is refused with.
fn wrong_count(key: &str, what: &str, fields: &[&str], unit: &str, table: bool, n: usize) -> String {
    let or_table = if table { format!(", or a [{key}] table") } else { String::new() };
    format!(
        "{key}: {n} number{}; {what} {} numbers, [{}] in {unit}{or_table}",
        if n == 1 { "" } else { "s" },
        fields.len(),
        fields.join(", ")
    )
}

/// Every number of an array, however many.
fn numbers<'de, A: SeqAccess<'de>>(mut seq: A) -> Result<Vec<f64>, A::Error> {
    let mut v = Vec::new();
    while let Some(x) = seq.next_element::<f64>()? {
        v.push(x);
    }
    Ok(v)
}

/// `park`: exactly `[x, y]`.
pub fn park<'de, D: Deserializer<'de>>(d: D) -> Result<Option<[f64; 2]>, D::Error> {
    struct Park;
    impl<'de> Visitor<'de> for Park {
        type Value = [f64; 2];
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            f.write_str("an array [x, y] of two numbers (mm)")
        }
        fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<[f64; 2], A::Error> {
            let v = numbers(seq)?;
            match v[..] {
                [x, y] => Ok([x, y]),
                _ => Err(de::Error::custom(wrong_count(
                    "park",
                    "a park position has one number per axis the writer moves (a pen's height belongs to the blocks):",
                    &["x", "y"],
                    "mm",
                    false,
                    v.len(),
                ))),
            }
        }
    }
    d.deserialize_seq(Park).map(Some)
}

/// A table of numbers that may be written as an array of its fields in order.
pub trait Fields: Sized {
    /// The profile key.
    const KEY: &'static str;
    /// What the fields are, for the message.
    const WHAT: &'static str;
    /// The fields in order.
    const FIELDS: &'static [&'static str];
    /// Their unit.
    const UNIT: &'static str;
    /// The table from exactly [`Self::FIELDS`]`.len()` numbers.
    fn from_numbers(v: &[f64]) -> Self;
}

impl Fields for Bed {
    const KEY: &'static str = "bed";
    const WHAT: &'static str = "a bed has the machine's two sides:";
    const FIELDS: &'static [&'static str] = &["width", "height"];
    const UNIT: &'static str = "mm";
    fn from_numbers(v: &[f64]) -> Bed {
        Bed { width: v[0], height: v[1] }
    }
}

impl Fields for Feeds {
    const KEY: &'static str = "feed";
    const WHAT: &'static str = "the feeds are";
    const FIELDS: &'static [&'static str] = &["draw", "travel"];
    const UNIT: &'static str = "mm/min";
    fn from_numbers(v: &[f64]) -> Feeds {
        Feeds { draw: v[0], travel: v[1] }
    }
}

impl Fields for Power {
    const KEY: &'static str = "power";
    const WHAT: &'static str = "a power range is";
    const FIELDS: &'static [&'static str] = &["min", "max", "default"];
    const UNIT: &'static str = "S units";
    fn from_numbers(v: &[f64]) -> Power {
        Power {
            min: v[0],
            max: v[1],
            default: v[2],
        }
    }
}

/// A [`Fields`] table: read as a table by its own `Deserialize` (which names unknown and
/// missing keys), or from an array of exactly its fields.
pub fn table<'de, D: Deserializer<'de>, T: Fields + Deserialize<'de>>(d: D) -> Result<T, D::Error> {
    struct Table<T>(PhantomData<T>);
    impl<'de, T: Fields + Deserialize<'de>> Visitor<'de> for Table<T> {
        type Value = T;
        fn expecting(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
            write!(f, "a [{}] table with {}", T::KEY, T::FIELDS.join(", "))
        }
        fn visit_map<A: MapAccess<'de>>(self, map: A) -> Result<T, A::Error> {
            T::deserialize(MapAccessDeserializer::new(map))
        }
        fn visit_seq<A: SeqAccess<'de>>(self, seq: A) -> Result<T, A::Error> {
            let v = numbers(seq)?;
            if v.len() != T::FIELDS.len() {
                return Err(de::Error::custom(wrong_count(T::KEY, T::WHAT, T::FIELDS, T::UNIT, true, v.len())));
            }
            Ok(T::from_numbers(&v))
        }
    }
    d.deserialize_any(Table(PhantomData))
}

/// [`table`] for an optional table.
pub fn optional_table<'de, D: Deserializer<'de>, T: Fields + Deserialize<'de>>(d: D) -> Result<Option<T>, D::Error> {
    table(d).map(Some)
}

// The cases are TOML text: they need the TOML reader.
#[cfg(all(test, feature = "toml"))]
mod tests {
    use crate::output::machine::Machine;

    fn servo() -> String {
        Machine::builtin_text("grbl-servo-pen").unwrap_or("").to_string()
    }

    /// The line of `key` in `text` (1-based).
    fn line_of(text: &str, key: &str) -> usize {
        text.lines().position(|l| l.starts_with(key)).map_or(0, |i| i + 1)
    }

    /// Bug pinned here: `park = [0.0, 0.0, 5.0]` was read as (0, 0), the 5.0 dropped; so were
    /// a fourth number, and the extra numbers of a bed, feeds or power range given as an array.
    #[test]
    fn arrays_of_the_wrong_length_are_refused_on_their_line() {
        let good = servo();
        let bed = good.replace("[bed]\nwidth = 300.0\nheight = 300.0\n", "");
        let feed = good.replace("[feed]\ndraw = 3000.0\ntravel = 6000.0\n", "");
        let laser = Machine::builtin_text("grbl-laser").unwrap_or("").to_string();
        let power = laser.replace("[power]\nmin = 0.0\nmax = 1000.0      # GRBL $30\ndefault = 800.0\n", "");
        assert!(bed != good && feed != good && power != laser);
        let at_top = |t: &str, line: &str| t.replace("park = [0.0, 0.0]", &format!("park = [0.0, 0.0]\n{line}"));
        let cases = [
            (
                good.replace("park = [0.0, 0.0]", "park = [0.0, 0.0, 5.0]"),
                "park",
                "park: 3 numbers",
            ),
            (
                good.replace("park = [0.0, 0.0]", "park = [0.0, 0.0, 5.0, 1.0]"),
                "park",
                "park: 4 numbers",
            ),
            (good.replace("park = [0.0, 0.0]", "park = [0.0]"), "park", "park: 1 number;"),
            (good.replace("park = [0.0, 0.0]", "park = []"), "park", "park: 0 numbers"),
            (at_top(&bed, "bed = [300.0, 300.0, 50.0]"), "bed", "bed: 3 numbers"),
            (at_top(&bed, "bed = [300.0]"), "bed", "bed: 1 number;"),
            (at_top(&feed, "feed = [3000.0, 6000.0, 600.0]"), "feed", "feed: 3 numbers"),
            (at_top(&power, "power = [0.0, 1000.0, 800.0, 5.0]"), "power", "power: 4 numbers"),
            (at_top(&power, "power = [0.0, 1000.0]"), "power", "power: 2 numbers"),
        ];
        for (text, key, want) in cases {
            let e = Machine::parse(&text).err().unwrap_or_default();
            let line = format!("line {},", line_of(&text, &format!("{key} =")));
            assert!(e.contains(want) && e.contains(&line), "expected '{want}' at {line} got '{e}'");
        }
        // The right count still reads, as an array or (for tables) a table.
        for text in [
            good.replace("park = [0.0, 0.0]", "park = [10, 20.5]"),
            at_top(&bed, "bed = [300.0, 200.0]"),
            at_top(&feed, "feed = [3000.0, 6000.0]"),
        ] {
            let m = Machine::parse(&text).unwrap_or_else(|e| panic!("{e}\n{text}"));
            assert!(m.park == Some([0.0, 0.0]) || m.park == Some([10.0, 20.5]));
            assert!(m.bed.height == 300.0 || m.bed.height == 200.0);
        }
        let m = Machine::parse(&at_top(&power, "power = [0.0, 1000.0, 800.0]")).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(m.power.map(|p| p.default), Some(800.0));
        // Tables keep their own messages: an unknown or a missing key is named.
        let e = Machine::parse(&good.replace("height = 300.0", "height = 300.0\ndepth = 5.0"))
            .err()
            .unwrap_or_default();
        assert!(
            e.contains("depth") && e.contains(&format!("line {},", line_of(&good, "height") + 1)),
            "{e}"
        );
        let e = Machine::parse(&good.replace("height = 300.0\n", "")).err().unwrap_or_default();
        assert!(e.contains("height"), "{e}");
    }
}
