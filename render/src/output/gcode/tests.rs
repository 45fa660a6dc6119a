//! The writer's own checks: drawings at and off the bed's edge (its numbers are checked in
//! `words.rs`).

use super::*;

#[test]
fn a_circle_on_the_bed_edge_falls_back_to_chords_inside() {
    let m = Machine::builtin("grbl-servo-pen").unwrap_or_else(|| panic!("built-in"));
    // Touching x = 0 exactly: the rounded circle could poke out; it must not.
    let d = Drawing {
        paths: vec![Path::circle([1.0004, 50.0], 1.0004)],
    };
    let o = GcodeOptions::new(&m);
    let out = write(&d, &m, &o).unwrap_or_else(|e| panic!("{e}"));
    let text = String::from_utf8_lossy(&out.bytes);
    assert!(!text.contains("X-"), "{text}");
}

#[test]
fn refuses_what_is_off_the_bed() {
    let m = Machine::builtin("grbl-laser").unwrap_or_else(|| panic!("built-in"));
    let d = Drawing {
        paths: vec![Path::circle([399.0, 50.0], 2.0)],
    };
    assert!(write(&d, &m, &GcodeOptions::new(&m)).is_err());
}
