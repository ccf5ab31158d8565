"""The real-time path: LUTs baked from the physical model, a CPU real-time model, reference images.

The dissertation's real-time approximation of the sea (Eqs. 20–22) mixes a
reflected sky and the light from the water with a corrected Fresnel weight,
and builds the light from the water out of two lookup textures over depth
and path length. This package bakes those textures from the same optics,
sun and sky and vision model as the offline renderer, shades G-buffers with
them on the CPU, and measures the result against path-traced references:

* :mod:`.luts` — the textures as pure functions of spectra (T0, T1, Fresnel,
  sky map, ripple maps) and their axis conventions;
* :mod:`.bake` — a scene's LUT set (its water, sun and sky, Φ);
* :mod:`.sky` — the renderer's ``sunsky`` evaluated in given directions;
* :mod:`.gbuffer` — camera and per-pixel G-buffer by ray casting;
* :mod:`.model` — Eqs. 20 and 22 per pixel from the LUTs;
* :mod:`.compare` — CIEDE2000 maps and statistics;
* :mod:`.gamma_fit` — γ of F^γ fitted to references;
* :mod:`.reference` — reference frames and comparisons;
* :mod:`.files` — EXR/PNG/JSON files of LUTs and reference sets.

Command line: ``oceanrender bake-luts`` and ``oceanrender reference``
(docs/realtime.md).
"""
