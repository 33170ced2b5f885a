"""Rolling bearings as built: geometry, materials, the ball set, the catalogue, hybrids, duplex sets, ratings.

* :mod:`~auxbearing.bearings.geometry`: one bearing's dimensions and internal geometry (SI);
* :mod:`~auxbearing.bearings.materials`: ring and ball materials with their sources;
* :mod:`~auxbearing.bearings.ballset`: the ball set's array face over the compiled kernel;
* :mod:`~auxbearing.bearings.series`: the sizes of the catalogue with the rule for their internal geometry;
* :mod:`~auxbearing.bearings.catalogue`: names as makers write them ("6205", "7208 BECBP", "QJ208 hybrid",
  "7208 DB medium");
* :mod:`~auxbearing.bearings.hybrid`: silicon-nitride balls in any bearing;
* :mod:`~auxbearing.bearings.duplex` and :mod:`~auxbearing.bearings.duplex_statics`: matched pairs (DB, DF,
  DT) with preload and spacer, and their statics through the one ball-set kernel;
* :mod:`~auxbearing.bearings.ratings`: ISO 281 C, ISO 76 C0 and the static safety factor s0, hybrids and
  matched sets.
"""
