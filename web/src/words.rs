//! The page's reading of a command line, without an argument parser linked in: the words
//! split into flags and their values, then taken one flag at a time by the code that builds
//! each command's arguments ([`crate::flags`]), with the binary's rules (a flag at most once
//! unless it repeats, a value where one is due, conflicts and requirements) and the first
//! line of the binary's messages. The tests hold it to clap's reading of the same lines.

/// A message as the binary prints it: the first line of clap's, and its closing hint.
pub fn message(first: &str) -> String {
    format!("error: {first}\n\nFor more information, try '--help'.")
}

/// Marks a value clap would not take (see [`Words::new`]); no command line holds it.
const LOOSE: char = '\u{0}';

/// One flag as written: its long name (a short one is resolved), its value if one follows.
#[derive(Debug)]
struct Given {
    long: String,
    /// As written, for messages (`-o` or `--output`).
    written: String,
    value: Option<String>,
    taken: bool,
}

/// The flags of a command line, taken one by one.
#[derive(Debug)]
pub struct Words {
    given: Vec<Given>,
    /// A word that follows no flag, if any: refused once every flag is taken.
    stray: Option<String>,
    /// The long names asked for, in order (the tests compare them with clap's).
    asked: Vec<&'static str>,
}

/// Whether `w` is a value rather than a flag: `-` alone, or a negative number.
fn is_value(w: &str) -> bool {
    let mut c = w.chars();
    match (c.next(), c.next()) {
        (Some('-'), None) => true,
        (Some('-'), Some(d)) => d.is_ascii_digit() || d == '.',
        _ => true,
    }
}

/// `<NAME>` of a flag's value as clap shows it: the long name in capitals, or one given.
fn value_name(long: &str) -> String {
    match long {
        "max-output-size" => "BYTES".to_string(),
        "color" => "COLORS".to_string(),
        _ => long.to_ascii_uppercase().replace('-', "_"),
    }
}

/// clap's message for a flag with a value that must be given and is not.
fn not_provided(long: &str) -> String {
    message(&format!(
        "the following required arguments were not provided:\n  --{long} <{}>",
        value_name(long)
    ))
}

impl Words {
    /// Splits `argv` into flags and values; `shorts` maps each one-letter flag to its long
    /// name, and the flags in `plain` take no value that starts with `-`.
    pub fn new(argv: &[String], shorts: &[(char, &str)], plain: &[&str]) -> Result<Words, String> {
        let mut given: Vec<Given> = Vec::new();
        let mut stray = None;
        let mut words = argv.iter().peekable();
        while let Some(w) = words.next() {
            let (long, written, attached) = if let Some(rest) = w.strip_prefix("--").filter(|r| !r.is_empty()) {
                match rest.split_once('=') {
                    Some((name, value)) => (name.to_string(), format!("--{name}"), Some(value.to_string())),
                    None => (rest.to_string(), w.clone(), None),
                }
            } else if !is_value(w) {
                let mut c = w.chars().skip(1);
                let letter = c.next().unwrap_or('-');
                let rest: String = c.collect();
                let Some((_, long)) = shorts.iter().find(|(s, _)| *s == letter) else {
                    return Err(message(&format!("unexpected argument '-{letter}' found")));
                };
                let attached = (!rest.is_empty()).then(|| rest.strip_prefix('=').unwrap_or(&rest).to_string());
                (long.to_string(), format!("-{letter}"), attached)
            } else {
                stray.get_or_insert_with(|| w.clone());
                continue;
            };
            if long == "help" || long == "version" {
                return Err(message(&format!(
                    "the page has no '{written}'; every flag is described in docs/cli.md"
                )));
            }
            // A value in the next word that starts with `-` is another flag to clap, when the
            // flag takes no such values: marked, and refused when the flag is read.
            let value = match attached {
                Some(v) => Some(v),
                None => words
                    .next_if(|n| is_value(n))
                    .map(|n| match plain.contains(&long.as_str()) && n.len() > 1 && n.starts_with('-') {
                        true => format!("{LOOSE}{n}"),
                        false => n.clone(),
                    }),
            };
            given.push(Given {
                long,
                written,
                value,
                taken: false,
            });
        }
        Ok(Words {
            given,
            stray,
            asked: Vec::new(),
        })
    }

    /// The long names asked for so far.
    pub fn asked(&self) -> &[&'static str] {
        &self.asked
    }

    fn given(&self, long: &str) -> bool {
        self.given.iter().any(|g| g.long == long)
    }

    /// The values given for `long` (`None` for a use without one), marked as taken.
    fn take(&mut self, long: &'static str) -> Vec<Option<String>> {
        self.asked.push(long);
        let mut out = Vec::new();
        for g in self.given.iter_mut().filter(|g| g.long == long) {
            g.taken = true;
            out.push(g.value.clone());
        }
        out
    }

    /// A flag without a value: whether it was given.
    pub fn flag(&mut self, long: &'static str) -> Result<bool, String> {
        let uses = self.take(long);
        if uses.len() > 1 {
            return Err(message(&format!("the argument '--{long}' cannot be used multiple times")));
        }
        match uses.first() {
            Some(Some(v)) => Err(message(&format!(
                "unexpected value '{v}' for '--{long}' found; no more were expected"
            ))),
            Some(None) => Ok(true),
            None => Ok(false),
        }
    }

    /// The flag with its value, as messages show it: `'--long <LONG>'`.
    fn shown(long: &str) -> String {
        format!("'--{long} <{}>'", value_name(long))
    }

    /// The word of a value, or the message for a missing one or one clap takes for a flag.
    fn word<'a>(long: &str, v: Option<&'a str>) -> Result<&'a str, String> {
        let Some(v) = v else {
            return Err(message(&format!(
                "a value is required for {} but none was supplied",
                Self::shown(long)
            )));
        };
        match v.strip_prefix(LOOSE) {
            Some(word) => Err(message(&format!("unexpected argument '{word}' found"))),
            None => Ok(v),
        }
    }

    /// The message for a value its parser refuses with `e`.
    fn invalid(long: &str, v: &str, e: String) -> String {
        if e == MISSING {
            message(&format!("a value is required for {} but none was supplied", Self::shown(long)))
        } else if e.is_empty() {
            message(&format!("invalid value '{v}' for {}", Self::shown(long)))
        } else {
            message(&format!("invalid value '{v}' for {}: {e}", Self::shown(long)))
        }
    }

    /// `v` parsed (the one generic step, kept small: it is made once per flag).
    fn parsed<T>(long: &str, v: &str, parse: impl Fn(&str) -> Result<T, String>) -> Result<T, String> {
        parse(v).map_err(|e| Self::invalid(long, v, e))
    }

    /// The value of a flag given at most once, if given, and the message clap gives once it
    /// has read that value: the flag given again.
    fn once(&mut self, long: &'static str) -> Result<(Option<String>, Option<String>), String> {
        let uses = self.take(long);
        let first = uses.first().map(|v| Self::word(long, v.as_deref()).map(String::from)).transpose()?;
        // clap reads the first use's value, and of a second one whether it has a value,
        // before it finds the flag repeated.
        let again = uses.get(1).map(|second| match Self::word(long, second.as_deref()) {
            Err(e) => e,
            Ok(_) => message(&format!("the argument {} cannot be used multiple times", Self::shown(long))),
        });
        Ok((first, again))
    }

    /// A flag with a value, given at most once.
    pub fn opt<T>(&mut self, long: &'static str, parse: impl Fn(&str) -> Result<T, String>) -> Result<Option<T>, String> {
        let (first, again) = self.once(long)?;
        let value = first.map(|v| Self::parsed(long, &v, parse)).transpose()?;
        again.map_or(Ok(value), Err)
    }

    /// A flag with a value and a default (the text clap shows as the default).
    pub fn or<T>(&mut self, long: &'static str, default: &str, parse: impl Fn(&str) -> Result<T, String>) -> Result<T, String> {
        let (first, again) = self.once(long)?;
        let value = Self::parsed(long, first.as_deref().unwrap_or(default), parse)?;
        again.map_or(Ok(value), Err)
    }

    /// A flag with a value that must be given.
    pub fn required<T>(&mut self, long: &'static str, parse: impl Fn(&str) -> Result<T, String>) -> Result<T, String> {
        self.opt(long, parse)?.ok_or_else(|| not_provided(long))
    }

    /// A flag that may be given any number of times, its values in order.
    pub fn all<T>(&mut self, long: &'static str, parse: impl Fn(&str) -> Result<T, String>) -> Result<Vec<T>, String> {
        let uses = self.take(long);
        uses.iter()
            .map(|v| Self::parsed(long, Self::word(long, v.as_deref())?, &parse))
            .collect()
    }

    /// Refuses `a` and `b` together.
    // Out of line: a dozen flags call it, and each copy would cost the page's download.
    #[inline(never)]
    pub fn conflict(&self, a: &str, b: &str) -> Result<(), String> {
        let at = |name: &str| self.given.iter().position(|g| g.long == name);
        let (Some(i), Some(j)) = (at(a), at(b)) else { return Ok(()) };
        // clap names the earlier of the two first.
        let (first, second) = if i < j { (a, b) } else { (b, a) };
        Err(message(&format!(
            "the argument {} cannot be used with {}",
            self.display(first),
            self.display(second)
        )))
    }

    /// Refuses `a` without `b`.
    #[inline(never)]
    pub fn requires(&self, a: &str, b: &str) -> Result<(), String> {
        if self.given(a) && !self.given(b) {
            return Err(not_provided(b));
        }
        Ok(())
    }

    /// A given flag as messages show it: with `<NAME>` if it took a value.
    fn display(&self, long: &str) -> String {
        match self.given.iter().find(|g| g.long == long) {
            Some(g) if g.value.is_none() => format!("'--{long}'"),
            _ => Self::shown(long),
        }
    }

    /// Refuses any flag no one took, and a word that follows no flag.
    pub fn finish(self) -> Result<(), String> {
        if let Some(g) = self.given.iter().find(|g| !g.taken) {
            return Err(message(&format!("unexpected argument '{}' found", g.written)));
        }
        if let Some(w) = self.stray {
            return Err(message(&format!("unexpected argument '{w}' found")));
        }
        Ok(())
    }
}

/// A whole number in `lo..=hi` (`hi` `None`: no upper bound), with clap's messages for a
/// ranged flag: `wide` parses as a signed number first, as clap does for 32-bit flags.
pub fn ranged(s: &str, lo: u64, hi: Option<u64>, wide: bool) -> Result<u64, String> {
    let v: i128 = if wide {
        s.parse::<i64>().map_err(|e| e.to_string())?.into()
    } else {
        s.parse::<u64>().map_err(|e| e.to_string())?.into()
    };
    let inside = v >= i128::from(lo) && hi.is_none_or(|h| v <= i128::from(h));
    if !inside {
        let bound = match hi {
            Some(h) => format!("{lo}..={h}"),
            None if wide => format!("{lo}..={}", u32::MAX),
            None => format!("{lo}..{}", u64::MAX),
        };
        return Err(format!("{v} is not in {bound}"));
    }
    u64::try_from(v).map_err(|e| e.to_string())
}

/// What a parser says of an empty word that clap takes for a missing value (a choice, a
/// path).
pub const MISSING: &str = "\u{0}";

/// One of a flag's names; another word gets clap's bare "invalid value" message.
pub fn choice<T: Copy>(s: &str, names: &[(&str, T)]) -> Result<T, String> {
    if s.is_empty() {
        return Err(MISSING.to_string());
    }
    names.iter().find(|(n, _)| *n == s).map(|(_, v)| *v).ok_or_else(String::new)
}
