"""Surface: waves or a coastal state turned into closed water-body and terrain meshes.

The camera-following radial mesh and the periodic patch of the open sea
(:mod:`.open_sea`), the coastal water body and its terrain (:mod:`.coastal_body`),
and the one interface both give the renderer (:mod:`.frame`): per-frame vertex
positions [m], normals and per-vertex attributes, the surface roughness inputs and
the terrain. Plain arrays: nothing here knows Mitsuba.
"""
