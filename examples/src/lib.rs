//! Examples live in `examples/examples/`; parameter files and pictures in `examples/gallery/`.
