//! The JSON Schema of the documents every command writes (`docs/zetafill.schema.json`), and
//! the check each test's parsed document goes through: a document that the schema does not
//! describe fails the test that read it, whatever that test was about.

use serde_json::Value;
use std::sync::OnceLock;

/// The schema file, from the repository's root.
pub fn schema_path() -> std::path::PathBuf {
    std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../docs/zetafill.schema.json")
}

/// The schema as JSON.
pub fn schema_value() -> Value {
    let path = schema_path();
    let bytes = std::fs::read(&path).unwrap_or_else(|e| panic!("cannot read {}: {e}", path.display()));
    serde_json::from_slice(&bytes).unwrap_or_else(|e| panic!("{} is not JSON: {e}", path.display()))
}

/// The compiled schema, built once per test binary.
fn validator() -> &'static jsonschema::Validator {
    static VALIDATOR: OnceLock<jsonschema::Validator> = OnceLock::new();
    VALIDATOR.get_or_init(|| jsonschema::validator_for(&schema_value()).unwrap_or_else(|e| panic!("the schema does not compile: {e}")))
}

/// Whether `v` is one of the tool's documents (an object with `version` and `mode`), which
/// the schema describes; other JSON (a glTF file's, a test's own) is not checked.
pub fn is_document(v: &Value) -> bool {
    v.get("version").is_some() && v.get("mode").is_some()
}

/// Every way `doc` departs from the schema, one line each (empty when it follows it).
pub fn schema_errors(doc: &Value) -> Vec<String> {
    validator()
        .iter_errors(doc)
        .map(|e| format!("{}: {e}", e.instance_path()))
        .collect()
}

/// Panics with every departure when `v` is a document the schema does not describe.
pub fn check_document(v: &Value) {
    if !is_document(v) {
        return;
    }
    let errors = schema_errors(v);
    assert!(
        errors.is_empty(),
        "the document does not follow docs/zetafill.schema.json:\n{}",
        errors.iter().take(20).cloned().collect::<Vec<_>>().join("\n")
    );
}
