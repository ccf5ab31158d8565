"""Production: sequences on several processes or machines (:mod:`.distributed`, Dask) and
movies with contact sheets (:mod:`.movie`). Built on ``oceanrender.pipeline``.

Mitsuba is imported lazily inside the functions that need it, never at import time.
"""
