//! The colour flags (`--palette`, `--color-by`, `--background`), one group flattened into
//! every command that paints a picture.

use crate::output::palette::{self, ColorBy, Colour, Palette};

/// `--color-by`: how shapes take their colours from a palette.
#[derive(Debug, Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
pub enum ColorByArg {
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

impl From<ColorByArg> for ColorBy {
    fn from(c: ColorByArg) -> ColorBy {
        match c {
            ColorByArg::Size => ColorBy::Size,
            ColorByArg::Random => ColorBy::Random,
            ColorByArg::Cycle => ColorBy::Cycle,
            ColorByArg::Kind => ColorBy::Kind,
        }
    }
}

/// `--palette`, `--color-by` and `--background`: colours for the shapes of a picture.
#[derive(Debug, Clone, Default, clap::Args)]
pub struct ColourArgs {
    /// SVG/PNG: colours for the shapes, hex rrggbb (or rgb, '#' optional) separated by
    /// commas; their fill, or their stroke with --style outline.
    #[arg(long, value_parser = palette::palette)]
    pub palette: Option<Palette>,
    /// SVG/PNG: how shapes take the palette's colours (default size; territory: cycle, by
    /// territory).
    #[arg(long = "color-by", value_enum, requires = "palette")]
    pub color_by: Option<ColorByArg>,
    /// SVG/PNG: a background colour (hex rrggbb or rgb) behind the drawing.
    #[arg(long, value_parser = palette::colour)]
    pub background: Option<Colour>,
}

impl ColourArgs {
    /// The first colour flag given, if any.
    pub fn given(&self) -> Option<&'static str> {
        if self.palette.is_some() {
            Some("--palette")
        } else {
            self.background.as_ref().map(|_| "--background")
        }
    }

    /// The rule that gives out the colours (`size` unless given).
    pub fn by(&self) -> ColorBy {
        self.by_or(ColorBy::Size)
    }

    /// The rule that gives out the colours, `default` unless given.
    pub fn by_or(&self, default: ColorBy) -> ColorBy {
        self.color_by.map_or(default, ColorBy::from)
    }

    /// The flags as a command that reproduces the picture writes them.
    pub fn flags(&self) -> String {
        self.flags_or(ColorBy::Size)
    }

    /// [`ColourArgs::flags`] where `--color-by` defaults to `default`.
    pub fn flags_or(&self, default: ColorBy) -> String {
        let mut s = String::new();
        if let Some(p) = &self.palette {
            s.push_str(&format!(" --palette {} --color-by {}", p.arg(), self.by_or(default).name()));
        }
        if let Some(bg) = &self.background {
            s.push_str(&format!(" --background {}", bg.trim_start_matches('#')));
        }
        s
    }
}
