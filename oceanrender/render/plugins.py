"""Registering the project's Python plugins with Mitsuba, once per variant."""

from __future__ import annotations

from collections.abc import Callable

__all__ = ["register_once"]


def register_once(registered: set[str], kind: str, name: str, make_class: Callable[[], type]) -> None:
    """Register plugin ``name`` of ``kind`` ("integrator", "phase", …) for the active variant, once.

    ``make_class()`` builds the class (it may need the variant); ``registered`` holds the
    variants done. Mitsuba keeps Python plugins per variant, so this is called again
    after switching variants.
    """
    import mitsuba as mi  # noqa: PLC0415

    variant = mi.variant()
    if variant is None:
        raise RuntimeError(f"set a Mitsuba variant (oceanrender.runtime.activate_variant) before registering {name}")
    if variant in registered:
        return
    cls = make_class()
    getattr(mi, f"register_{kind}")(name, lambda props: cls(props))
    registered.add(variant)
