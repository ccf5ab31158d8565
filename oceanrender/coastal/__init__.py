"""Coastal water: a two-dimensional shallow-water solver with wetting and drying.

:mod:`~oceanrender.coastal.swe` holds the state, the flux and the time stepping,
:mod:`~oceanrender.coastal.boundaries` the wall, transmissive and incident-wave
sides, and :mod:`~oceanrender.coastal.analytic` the closed-form dam-break and bore
solutions the solver is validated against (see docs/coastal.md, section "Solver").
Units: lengths in m, time in s; axis 0 of every grid is y (south → north), axis 1
is x (west → east).
"""
