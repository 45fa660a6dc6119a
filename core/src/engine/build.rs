//! Building an engine: the checks of the parameters, the region and the caller's storage.

use super::{Engine, ParamError, Params, Storage};
use crate::coverage::Coverage;
use crate::geom::Point;
use crate::region::Region;
use crate::scalar::Scalar;
use crate::shape::{Motif, ShapeKind};
use crate::spatial::SpatialHash;
use crate::AreaSequence;

impl<'a, S: Scalar> Engine<'a, S> {
    /// Validates the parameters and builds an engine over the caller's storage. A region
    /// larger than the scalar computes exactly ([`Scalar::MAX_EXTENT`]) is refused.
    pub fn new(params: Params, region: Region<'a>, storage: Storage<'a, S>) -> Result<Self, ParamError> {
        Self::with_motifs(params, region, storage, &[])
    }

    /// [`Engine::new`] with the table of motifs that the [`ShapeKind::Motif`] kinds of the
    /// parameters name: kind `id` is entry `id`, and must be that entry's
    /// [`Motif::kind`] (else [`ParamError::Shape`]).
    ///
    /// # Examples
    ///
    /// Thirty L-shaped motifs, each one the outline that was tested.
    ///
    /// ```
    /// use zetafill::{index_words, rng_from_seed, Engine, Geo, Motif, Params, Placed, Point, Region, Stop, StopReason, Storage};
    ///
    /// let p = Point::new;
    /// let mut ell = [p(0.0, 0.0), p(3.0, 0.0), p(3.0, 1.0), p(1.0, 1.0), p(1.0, 3.0), p(0.0, 3.0)];
    /// let motifs = [Motif::new(&mut ell, &[6])?];
    /// let params = Params { shape: motifs[0].kind(0).into(), rotate: true, ..Params::circles(1.3, 2.0) };
    /// let mut shapes = [Placed::<f64>::default(); 30];
    /// let mut index = [0u32; index_words(30)];
    /// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
    /// let region = Region::Rect { width: 100.0, height: 100.0, periodic: false };
    /// let mut engine = Engine::with_motifs(params, region, storage, &motifs)?;
    /// assert_eq!(engine.run(&mut rng_from_seed(3), &Stop { count: Some(30), ..Stop::default() }, |_| {}), StopReason::Count);
    /// for i in 0..30 {
    ///     let Some(g @ Geo::Motif { .. }) = engine.geo(i) else { panic!("a motif") };
    ///     assert!((g.poly_area2() / 2.0 - engine.area_of(i as u64)).abs() < 1e-9 * engine.area_of(i as u64));
    /// }
    /// // A kind that names no motif of the table is refused.
    /// let (mut shapes, mut index) = ([Placed::<f64>::default(); 30], [0u32; index_words(30)]);
    /// let storage = Storage { shapes: &mut shapes, index: &mut index, coverage: &mut [] };
    /// let params = Params { shape: motifs[0].kind(1).into(), ..Params::circles(1.3, 2.0) };
    /// assert!(Engine::with_motifs(params, region, storage, &motifs).is_err());
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    pub fn with_motifs(params: Params, region: Region<'a>, storage: Storage<'a, S>, motifs: &'a [Motif<'a>]) -> Result<Self, ParamError> {
        let Storage { shapes, index, coverage } = storage;
        crate::params::check_power_law(params.c, params.n_offset)?;
        if !params.shape.is_valid() {
            return Err(ParamError::Shape);
        }
        let named = |k: &ShapeKind| match *k {
            ShapeKind::Motif { id, .. } => motifs.get(usize::from(id)).is_some_and(|m| m.kind(id) == *k),
            _ => true,
        };
        if !params.shape.kinds().iter().all(named) {
            return Err(ParamError::Shape);
        }
        if !region.is_valid() {
            return Err(ParamError::Region);
        }
        if !region.within(S::MAX_EXTENT) {
            return Err(ParamError::Extent);
        }
        let (w, h) = region.extent();
        if !(params.gap.is_finite() && params.gap >= 0.0 && 2.0 * params.gap < w.min(h)) {
            return Err(ParamError::Gap);
        }
        if params.max_trials == 0 {
            return Err(ParamError::MaxTrials);
        }
        let images = region.wallpaper().map_or(1, |w| w.order());
        if shapes.len() < images || index.len() <= shapes.len() {
            return Err(ParamError::Storage);
        }
        // The coverage bitmap knows rectangular tori only.
        let coverage = if region.wallpaper().is_some() { &mut [] } else { coverage };
        let seq = AreaSequence::new(region.area(), params.c, params.n_offset).map_err(|_| ParamError::Zeta)?;
        let (next, heads) = index.split_at_mut(shapes.len());
        let hash = SpatialHash::new(heads, next, S::from_f64(w.max(h))).map_err(|_| ParamError::Storage)?;
        let (x0, y0, _, _) = region.bbox();
        let mut coverage = Coverage::new(
            coverage,
            Point::new(S::from_f64(x0), S::from_f64(y0)),
            S::from_f64(w),
            S::from_f64(h),
        );
        coverage.mark_outside(&region);
        let gap = S::from_f64(params.gap);
        Ok(Engine {
            params,
            region,
            shapes,
            len: 0,
            hash,
            coverage,
            seq,
            placed_area: 0.0,
            trials: 0,
            gap,
            period: (S::from_f64(w), S::from_f64(h)),
            min_size: crate::feasibility::min_size::<S>(&region),
            density: None,
            images: core::num::NonZeroU32::new(images as u32).unwrap_or(core::num::NonZeroU32::MIN),
            shear: S::from_f64(region.wallpaper().map_or(0.0, |w| w.lattice().1)),
            motifs,
        })
    }
}
