//! Plane geometry shared by the commands that draw cells: Delaunay triangulations, Voronoi
//! cells and exact clipping to a region (territories, tiles and cobblestones), and the rings
//! traced from a picture (masks).

pub mod simplify;
pub mod site;
pub mod trace;
pub mod voronoi;
