//! Output formats: one file per format, each turning a [`crate::model::doc::FillDoc`] or a
//! [`crate::model::Drawing`] into bytes. Writers take plain options (no clap), touch no files
//! and never exit the process: the commands decide where the bytes go.
//!
//! The 3D writers ([`mesh`], [`stl`], [`obj`], [`glb`], [`render3d`]) take solids
//! ([`crate::model::solid`]); the `space` command will call them.

#[doc(hidden)]
pub mod control;
pub mod csv;
pub mod curves;
pub mod digest;
pub mod gcode;
pub mod glb;
pub mod height;
pub mod json;
pub mod machine;
pub mod mesh;
pub mod number;
pub mod obj;
pub mod order;
pub mod palette;
pub mod png;
pub mod render3d;
pub mod space;
pub mod stl;
pub mod stream;
pub mod svg;

/// A number in mm with at most `places` decimals, no trailing zeros, never `-0`.
pub fn num(v: f64, places: usize) -> String {
    let mut s = String::with_capacity(12);
    number::push_fixed(&mut s, v, places);
    s
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_plain_and_short() {
        assert_eq!(num(1.5, 4), "1.5");
        assert_eq!(num(2.0, 4), "2");
        assert_eq!(num(-0.00001, 4), "0");
        assert_eq!(num(1e-7, 4), "0");
        assert_eq!(num(123.456789, 4), "123.4568");
    }
}
