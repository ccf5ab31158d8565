"""Numpy arrays handed to Dr.Jit, 64-byte aligned: a kernel's code never depends on where numpy put them.

Dr.Jit (1.5, LLVM backend) maps a C-contiguous numpy array's memory without
copying it, and writes that memory's alignment into the kernels that read it:
an input of the kernel's width is loaded with ``align 64`` when its address is
a multiple of 64 bytes and ``align 1`` otherwise, and a mesh's vertex buffers
are read with packet gathers only when aligned. numpy's allocator gives 16-byte
aligned addresses, sometimes on a 64-byte boundary and sometimes not, so the
same trace hashed to a new kernel at random, and each new kernel was compiled
again (measured, default scene on a cold kernel cache: the meter's kernel of
frame 2 differed from frame 0's in that alignment only, and compiled again;
with ``PacketOps`` on, frame 1's four kernels also differed, through the mesh's
packet gathers). Every array passed from here starts on a 64-byte boundary, so
a trace gives one kernel.
"""

from __future__ import annotations

import numpy as np

#: Alignment of the arrays handed to Dr.Jit [bytes]: a cache line, the widest (AVX-512) vector load.
ALIGNMENT = 64


def aligned(array, dtype) -> np.ndarray:
    """``array`` as a C-contiguous ``dtype`` array whose data start on a multiple of :data:`ALIGNMENT` bytes.

    The input itself when it already is one; else one copy, converted on the way, into a fresh buffer.
    """
    source = np.asarray(array)
    dtype = np.dtype(dtype)
    if source.dtype == dtype and source.flags.c_contiguous and source.ctypes.data % ALIGNMENT == 0:
        return source
    nbytes = source.size * dtype.itemsize
    raw = np.empty(nbytes + ALIGNMENT, dtype=np.uint8)
    start = -raw.ctypes.data % ALIGNMENT
    out = raw[start:start + nbytes].view(dtype).reshape(source.shape)
    out[...] = source
    return out


def jit_floats(array):
    """A flat ``mi.Float`` (float32) of ``array``, read from aligned memory (Mitsuba's vertex buffers too)."""
    import mitsuba as mi  # noqa: PLC0415

    return mi.Float(aligned(array, np.float32).reshape(-1))


def jit_uints(array):
    """A flat ``mi.UInt32`` of ``array``, read from aligned memory (mesh faces, pixel indices)."""
    import mitsuba as mi  # noqa: PLC0415

    return mi.UInt32(aligned(array, np.uint32).reshape(-1))


def jit_bools(array):
    """A flat ``mi.Bool`` of ``array``, read from aligned memory (per-lane masks)."""
    import mitsuba as mi  # noqa: PLC0415

    return mi.Bool(aligned(array, np.bool_).reshape(-1))
