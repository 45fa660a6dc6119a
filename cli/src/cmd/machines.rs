//! `zetafill machines`: lists the built-in machine profiles; `zetafill machines show NAME`
//! prints one as TOML, ready to copy, edit and pass back with `--machine FILE.toml`.

use crate::error::CliError;
use crate::output::machine::Machine;
use crate::plan::machines::{profile_error, MachinesPlan};

/// The listing: one line per built-in, name then description.
pub fn listing() -> String {
    let mut s = String::new();
    for name in Machine::builtin_names() {
        let m = Machine::builtin(name);
        let (d, w, h) = m.map(|m| (m.description, m.bed.width, m.bed.height)).unwrap_or_default();
        s.push_str(&format!("{name:<16} {w} x {h} mm  {d}\n"));
    }
    s.push_str("\n`zetafill machines show NAME` prints one as TOML; edit a copy and use --machine FILE.toml.\n");
    s
}

/// `zetafill machines`.
pub fn run(plan: &MachinesPlan) -> Result<(), CliError> {
    let text = match plan {
        MachinesPlan::List => listing(),
        MachinesPlan::Show(name) => match Machine::builtin_text(name) {
            Some(t) => t.to_string(),
            None => {
                // A file: check it, then print it normalised (a build without profile files
                // refuses it in `load`).
                let m = Machine::load(name, crate::plan::plot::profile_text).map_err(profile_error)?;
                normalised(&m)?
            }
        },
    };
    print!("{text}");
    Ok(())
}

/// A profile as TOML text.
#[cfg(feature = "profile-files")]
fn normalised(m: &Machine) -> Result<String, CliError> {
    toml::to_string(m).map_err(|e| CliError::Io(format!("cannot encode TOML: {e}")))
}

/// A profile as TOML text: a build without profile files has no TOML writer, and no file
/// profile reaches here.
#[cfg(not(feature = "profile-files"))]
fn normalised(_: &Machine) -> Result<String, CliError> {
    Err(CliError::Io("this build reads and writes no machine profile files".into()))
}
