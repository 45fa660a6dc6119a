//! One module per subcommand: each turns its parsed arguments into a run of the core and
//! hands the result to the writers of [`crate::output`].

pub mod cobble;
pub mod fill;
pub mod line;
pub mod machines;
pub mod plot;
pub mod space;
pub mod stats;
pub mod stopping;
pub mod territory;
pub mod tile;
