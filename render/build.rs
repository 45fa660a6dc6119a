//! The built-in machine profiles, `machines/*.toml`, as JSON: each file is read as a TOML value
//! here and written to `$OUT_DIR/machines/NAME.json`, and `$OUT_DIR/machines.rs` lists them
//! (with their TOML text) for `output::machine`. A build without the `toml` feature then reads
//! the built-ins with serde_json through the same `Deserialize` as the TOML files, without
//! linking a TOML parser; the names come from the file names only, sorted.

use std::fmt::Write as _;
use std::path::Path;

fn main() {
    let dir = Path::new(&env("CARGO_MANIFEST_DIR")).join("machines");
    let out = Path::new(&env("OUT_DIR")).join("machines");
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut names = Vec::new();
    for entry in std::fs::read_dir(&dir).unwrap_or_else(|e| fail(&dir, &e.to_string())) {
        let path = entry.unwrap_or_else(|e| fail(&dir, &e.to_string())).path();
        if path.extension().is_some_and(|x| x == "toml") {
            println!("cargo:rerun-if-changed={}", path.display());
            let name = path.file_stem().and_then(|s| s.to_str()).unwrap_or_default();
            if name.is_empty() || !name.bytes().all(|b| b.is_ascii_alphanumeric() || b == b'-' || b == b'_') {
                fail(&path, "a built-in's name is its file name: ASCII letters, digits, '-' and '_'");
            }
            names.push(name.to_string());
        }
    }
    // Byte order of the names, as `Machine::builtin_names` lists them.
    names.sort();
    std::fs::create_dir_all(&out).unwrap_or_else(|e| fail(&out, &e.to_string()));
    for name in &names {
        let path = dir.join(format!("{name}.toml"));
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| fail(&path, &e.to_string()));
        let value: toml::Table = toml::from_str(&text).unwrap_or_else(|e| fail(&path, &e.to_string()));
        let json = to_json(&toml::Value::Table(value)).unwrap_or_else(|e| fail(&path, &e));
        let target = out.join(format!("{name}.json"));
        std::fs::write(&target, json.to_string()).unwrap_or_else(|e| fail(&target, &e.to_string()));
    }
    let mut rs = String::new();
    // Each file by its path under the folder `dir_var` names: `include_str!` then also
    // rebuilds the crate when the file changes.
    let list = |rs: &mut String, dir_var: &str, ext: &str| {
        for name in &names {
            let _ = writeln!(
                rs,
                "    (\"{name}\", include_str!(concat!(env!(\"{dir_var}\"), \"/machines/{name}.{ext}\"))),"
            );
        }
    };
    rs.push_str("/// Names of the built-in profiles: the file names of `machines/*.toml`, sorted.\n");
    rs.push_str("const BUILTIN_NAMES: &[&str] = &[\n");
    for name in &names {
        let _ = writeln!(rs, "    \"{name}\",");
    }
    rs.push_str("];\n\n");
    rs.push_str("/// The built-in profiles: name and TOML text, sorted by name.\n");
    rs.push_str("pub const BUILTINS: &[(&str, &str)] = &[\n");
    list(&mut rs, "CARGO_MANIFEST_DIR", "toml");
    rs.push_str("];\n\n");
    rs.push_str("/// The built-in profiles as JSON (written by the build script from the TOML), in the\n");
    rs.push_str("/// order of [`BUILTINS`].\n");
    rs.push_str("#[cfg(any(test, not(feature = \"toml\")))]\n");
    rs.push_str("const BUILTIN_JSON: &[(&str, &str)] = &[\n");
    list(&mut rs, "OUT_DIR", "json");
    rs.push_str("];\n");
    let target = Path::new(&env("OUT_DIR")).join("machines.rs");
    std::fs::write(&target, rs).unwrap_or_else(|e| fail(&target, &e.to_string()));
}

/// A TOML value as JSON. A profile holds strings, numbers, booleans, arrays and tables only;
/// a date, or a number JSON cannot hold (inf, nan), is refused here rather than written as
/// something the TOML reader would not have given.
fn to_json(v: &toml::Value) -> Result<serde_json::Value, String> {
    Ok(match v {
        toml::Value::String(s) => serde_json::Value::String(s.clone()),
        toml::Value::Integer(i) => serde_json::Value::from(*i),
        toml::Value::Float(f) => serde_json::Number::from_f64(*f)
            .map(serde_json::Value::Number)
            .ok_or_else(|| format!("{f}: a built-in's numbers must be finite"))?,
        toml::Value::Boolean(b) => serde_json::Value::Bool(*b),
        toml::Value::Datetime(d) => return Err(format!("{d}: a built-in holds no dates")),
        toml::Value::Array(a) => serde_json::Value::Array(a.iter().map(to_json).collect::<Result<_, _>>()?),
        toml::Value::Table(t) => {
            serde_json::Value::Object(t.iter().map(|(k, v)| Ok((k.clone(), to_json(v)?))).collect::<Result<_, String>>()?)
        }
    })
}

fn env(key: &str) -> String {
    std::env::var(key).unwrap_or_else(|_| panic!("cargo sets {key} for build scripts"))
}

fn fail(path: &Path, why: &str) -> ! {
    panic!("{}: {why}", path.display())
}
