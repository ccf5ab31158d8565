"""Production rendering (issue 7): movies and contact sheets, denoising, animation.

* :mod:`.movie` — an H.264 MP4 and a contact sheet from a finished sequence folder.
* :mod:`.denoise` — Intel Open Image Denoise with albedo and normal AOVs from Mitsuba.
* :mod:`.animation` — keyframed camera paths and sun motion (keyframes or a solar clock).

Mitsuba is imported lazily inside the functions that need it, never at import time.
"""
