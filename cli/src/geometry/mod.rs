//! Plane geometry shared by the commands that draw cells: Delaunay triangulations, Voronoi
//! cells and exact clipping to a region (territories, tiles and cobblestones).

pub mod site;
pub mod voronoi;
