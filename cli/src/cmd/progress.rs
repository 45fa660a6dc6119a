//! The progress bar of a long run: on standard error when it is a terminal and `--quiet` is
//! not given. Built with the `progress` feature (on by default, through indicatif); the
//! browser page builds without it, and then no bar is ever shown.

/// A progress bar (indicatif's).
#[cfg(feature = "progress")]
pub type Bar = indicatif::ProgressBar;

/// A progress bar that is never made: the build has no `progress` feature.
#[cfg(not(feature = "progress"))]
#[derive(Debug)]
pub enum Bar {}

#[cfg(not(feature = "progress"))]
impl Bar {
    /// Counts `_n` more.
    pub fn inc(&self, _n: u64) {
        match *self {}
    }

    /// Sets the count to `_n`.
    pub fn set_position(&self, _n: u64) {
        match *self {}
    }

    /// Sets the count back to 0.
    pub fn reset(&self) {
        match *self {}
    }

    /// Removes the bar.
    pub fn finish_and_clear(&self) {
        match *self {}
    }
}

/// A bar counting to `total` (a spinner if `None`), its count followed by `what` ("shapes",
/// "tries"), unless `quiet` or standard error is not a terminal.
pub fn bar(quiet: bool, total: Option<u64>, what: &str) -> Option<Bar> {
    #[cfg(feature = "progress")]
    {
        use std::io::IsTerminal;
        if quiet || !std::io::stderr().is_terminal() {
            return None;
        }
        let b = match total {
            Some(k) => indicatif::ProgressBar::new(k),
            None => indicatif::ProgressBar::new_spinner(),
        };
        let template = format!("{{bar:40}} {{pos}}/{{len}} {what}, {{elapsed}} (eta {{eta}})");
        if let Ok(style) = indicatif::ProgressStyle::with_template(&template) {
            b.set_style(style);
        }
        Some(b)
    }
    #[cfg(not(feature = "progress"))]
    {
        let _ = (quiet, total, what);
        None
    }
}
