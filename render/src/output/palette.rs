//! Colour for screens and prints: a palette of hex colours given to the shapes by size band,
//! at random (fixed by the seed) or in turn, and a background colour.

use crate::model::doc::FillDoc;
use zetafill::internals::shape::mix64;

/// A colour as `#rrggbb` (lower case).
pub type Colour = String;

/// How shapes take their colours from a palette.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ColorBy {
    /// By size: K bands of equal width in log(area) for K colours, the largest shapes taking
    /// the first (the bands of `--layers size-bands:K`).
    Size,
    /// A pseudo-random colour per shape, fixed by the seed and the shape's index.
    Random,
    /// In turn: shape i takes colour i mod K.
    Cycle,
    /// By the shape's entry in a mix (`--shape mix:...`): entry j takes colour j mod K.
    Kind,
}

impl ColorBy {
    /// The name on the command line.
    pub fn name(self) -> &'static str {
        match self {
            ColorBy::Size => "size",
            ColorBy::Random => "random",
            ColorBy::Cycle => "cycle",
            ColorBy::Kind => "kind",
        }
    }
}

/// Parses one colour: `rgb` or `rrggbb` in hex, with or without a leading `#` (a shell reads
/// an unquoted ` #` as the start of a comment).
pub fn colour(s: &str) -> Result<Colour, String> {
    let h = s.strip_prefix('#').unwrap_or(s);
    if !((h.len() == 3 || h.len() == 6) && h.chars().all(|c| c.is_ascii_hexdigit())) {
        return Err(format!(
            "'{s}' is not a colour; write it as rrggbb or rgb in hex, for example 1d3557"
        ));
    }
    let hex = h.to_ascii_lowercase();
    Ok(if hex.len() == 3 {
        hex.chars().fold(String::from("#"), |mut out, c| {
            out.push(c);
            out.push(c);
            out
        })
    } else {
        format!("#{hex}")
    })
}

/// A list of colours.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Palette(pub Vec<Colour>);

impl Palette {
    /// As written on a command line: the colours without `#`, separated by commas.
    pub fn arg(&self) -> String {
        self.0.iter().map(|c| c.trim_start_matches('#')).collect::<Vec<_>>().join(",")
    }
}

/// Parses a palette: colours separated by commas, at most [`MAX_COLOURS`].
pub fn palette(s: &str) -> Result<Palette, String> {
    let list: Vec<Colour> = s.split(',').map(|c| colour(c.trim())).collect::<Result<_, _>>()?;
    if list.len() > MAX_COLOURS {
        return Err(format!("{} colours given; at most {MAX_COLOURS}", list.len()));
    }
    Ok(Palette(list))
}

/// The most colours a palette holds.
pub const MAX_COLOURS: usize = 64;

/// The palette index of shape `index` drawn at random for `seed`: `splitmix64(seed XOR
/// splitmix64(index)) mod k`, with SplitMix64's output function (the core's [`mix64`]).
pub fn random_pick(seed: u64, index: u64, k: usize) -> usize {
    (mix64(seed ^ mix64(index)) % k as u64) as usize
}

/// The band (0 = the largest) of each of `sizes` when their range is split into `k` bands of
/// equal width in log(size). When they are all equal, or one is zero, every one is band 0.
pub fn log_bands(sizes: &[f64], k: usize) -> Vec<usize> {
    let k = k.max(1);
    let (max, min) = sizes.iter().fold((0.0f64, f64::INFINITY), |(a, b), &v| (a.max(v), b.min(v)));
    let span = if min > 0.0 && max > min { libm::log(max / min) } else { 0.0 };
    sizes
        .iter()
        .map(|&v| {
            if span > 0.0 && v > 0.0 {
                ((k as f64 * libm::log(max / v) / span).floor() as usize).min(k - 1)
            } else {
                0
            }
        })
        .collect()
}

/// The colours of items known by an identity and a size: by size band, at random for `seed`
/// ([`random_pick`] of the identity), or in turn (identity mod K). [`ColorBy::Kind`] is the
/// caller's (`kind`): the entry of each item's kind.
pub fn assign_items(colours: &[Colour], by: ColorBy, seed: u64, items: &[(u64, f64)], kind: impl Fn(u64) -> usize) -> Vec<Colour> {
    let k = colours.len().max(1);
    let pick = |i: usize| colours.get(i % k).cloned().unwrap_or_default();
    match by {
        ColorBy::Size => {
            let sizes: Vec<f64> = items.iter().map(|it| it.1).collect();
            log_bands(&sizes, k).into_iter().map(pick).collect()
        }
        ColorBy::Random => items.iter().map(|it| pick(random_pick(seed, it.0, k))).collect(),
        ColorBy::Cycle => items.iter().map(|it| pick(it.0 as usize)).collect(),
        ColorBy::Kind => items.iter().map(|it| pick(kind(it.0))).collect(),
    }
}

/// Each shape of a fill's colour, its size being its area (so the size bands are those of
/// `--layers size-bands:K`); `entry` gives the mix entry of shape i (for [`ColorBy::Kind`]).
pub fn assign(doc: &FillDoc, colours: &[Colour], by: ColorBy, entry: impl Fn(u64) -> usize) -> Vec<Colour> {
    let items: Vec<(u64, f64)> = doc.shapes.iter().map(|s| (s.index, s.area)).collect();
    assign_items(colours, by, doc.params.seed, &items, entry)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn colours_parse_and_normalise() {
        assert_eq!(colour("#1D3557"), Ok("#1d3557".to_string()));
        assert_eq!(colour("#fA0"), Ok("#ffaa00".to_string()));
        assert_eq!(colour("1d3557"), Ok("#1d3557".to_string()));
        for bad in ["red", "#12", "#1234", "#ggg", "##123456", "#", ""] {
            assert!(colour(bad).is_err(), "{bad}");
        }
        assert_eq!(palette("#000, fff").map(|p| p.arg()), Ok("000000,ffffff".to_string()));
        assert!(palette("#000,,#fff").is_err());
        assert!(palette(&vec!["#000"; 65].join(",")).is_err());
    }

    #[test]
    fn log_bands_split_the_range_evenly() {
        assert_eq!(log_bands(&[8.0, 4.0, 2.0, 1.0, 5.0], 3), [0, 1, 2, 2, 0]);
        assert_eq!(log_bands(&[3.0, 3.0], 4), [0, 0]);
        // A size of zero leaves no range to split.
        assert_eq!(log_bands(&[2.0, 0.0, 1.0], 2), [0, 0, 0]);
        assert!(log_bands(&[], 2).is_empty());
    }

    #[test]
    fn the_mix_is_splitmix64() {
        // The first outputs of SplitMix64 seeded with 0 (the generator adds the constant
        // before mixing, as the README's formula does).
        assert_eq!(mix64(0), 0xe220_a839_7b1d_cdaf);
        assert_eq!(mix64(0x9e37_79b9_7f4a_7c15), 0x6e78_9e6a_a1b9_65f4);
    }
}
