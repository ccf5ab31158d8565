"""Numpy arrays handed to Dr.Jit: aligned, so a kernel's code never depends on where numpy put them."""

import numpy as np
import pytest

from oceanrender.render.buffers import ALIGNMENT, aligned, jit_uints


@pytest.mark.parametrize("dtype", [np.float32, np.uint32, np.bool_])
def test_aligned_arrays_start_on_a_cache_line_and_keep_their_values(dtype):
    base = (np.arange(1000) % 7).astype(dtype)
    for offset in range(17):  # views at every element step: most addresses off a 64-byte boundary
        view = base[offset:offset + 501]
        out = aligned(view, dtype)
        assert out.ctypes.data % ALIGNMENT == 0 and out.dtype == dtype and out.flags.c_contiguous
        np.testing.assert_array_equal(out, view)
    ready = aligned(base, dtype)
    assert aligned(ready, dtype) is ready  # already aligned and contiguous: no copy
    two_d = aligned(np.arange(12.0).reshape(3, 4)[:, 1:], np.float32)
    assert two_d.shape == (3, 3) and two_d.ctypes.data % ALIGNMENT == 0


def test_a_kernel_does_not_change_with_where_numpy_put_its_input(variant):
    # Dr.Jit 1.5 maps a numpy array's memory and writes its alignment into the kernel that reads it (a load
    # "align 64" against "align 1"): the same computation on buffers at other addresses hashes to other
    # kernels, each compiled anew. Through jit_uints every address gives the one kernel.
    import drjit as dr
    import mitsuba as mi

    buffer = np.zeros(4096 + 64, np.uint32)
    views = [buffer[k:k + 4096] for k in range(16)]  # start addresses 4 bytes apart: 64-aligned once in 16

    def kernels(convert) -> set:
        with dr.scoped_set_flag(dr.JitFlag.KernelHistory, True):
            dr.kernel_history()  # (emptied)
            for view in views:
                dr.eval(convert(view) * 3 + 1)
            return {k["hash"] for k in dr.kernel_history() if k["type"] == dr.KernelType.JIT}

    assert len(kernels(mi.UInt32)) > 1  # what the helper is for: mapped as they are, the views compile apart
    assert len(kernels(jit_uints)) == 1
