"""The headless OpenGL harness (oceanrender.realtime.glsl) on a real OpenGL implementation (Mesa's llvmpipe in CI)."""

import numpy as np
import pytest

from oceanrender.realtime.glsl import GLContext, ShaderError, Texture, compile_messages, shipped_shader
from oceanrender.realtime.ripples import mip_pyramid, sample_trilinear

ECHO = """#version 330 core
uniform sampler2D g_position;
uniform float u_scale;
out vec4 frag_colour;
void main() {
    vec4 p = texelFetch(g_position, ivec2(gl_FragCoord.xy), 0);
    frag_colour = vec4(p.xyz * u_scale, isinf(p.w) ? -1.0 : gl_FragCoord.x + 1000.0 * gl_FragCoord.y);
}
"""

TRILINEAR = """#version 330 core
uniform sampler2D g_position;
uniform sampler2D ripple_moments;
out vec4 frag_colour;
void main() {
    vec4 p = texelFetch(g_position, ivec2(gl_FragCoord.xy), 0);
    frag_colour = textureLod(ripple_moments, p.xy, p.z);
}
"""


@pytest.fixture(scope="module")
def gl():
    context = GLContext()
    yield context
    context.release()


def test_context_is_a_real_opengl_implementation(gl):
    assert "OpenGL" in gl.renderer and gl.ctx.version_code >= 330


def test_gbuffer_texel_ij_is_pixel_ij_and_inf_survives(gl, rng):
    """Row j of the uploaded G-buffer comes back as row j of the image: no flips, float32 exact."""
    height, width = 5, 7
    data = rng.uniform(-100, 100, (height, width, 4)).astype(np.float32)
    data[2, 3, 3] = np.inf
    program = gl.program(ECHO, "echo.frag")
    out = gl.render(program, (width, height), {"g_position": Texture(data, linear=False)}, {"u_scale": 2.0})
    np.testing.assert_array_equal(out[..., :3], 2.0 * data[..., :3])
    j, i = np.mgrid[0:height, 0:width]
    expected = np.where(np.isinf(data[..., 3]), -1.0, (i + 0.5) + 1000.0 * (j + 0.5))
    np.testing.assert_array_equal(out[..., 3], expected.astype(np.float32))


def test_uploaded_mip_levels_sample_like_the_numpy_model(gl, rng):
    """textureLod with LINEAR_MIPMAP_LINEAR on our levels = :func:`sample_trilinear` (hardware filter weights)."""
    level0 = rng.uniform(-1, 1, (16, 16, 4)).astype(np.float32)
    levels = mip_pyramid(level0)
    count = 400
    st = rng.uniform(-2.0, 3.0, (count, 2))
    lod = rng.uniform(0.0, 4.0, count)
    lod[:20] = np.floor(lod[:20])  # whole levels too
    queries = np.zeros((1, count, 4), np.float32)
    queries[0, :, :2], queries[0, :, 2] = st, lod
    program = gl.program(TRILINEAR, "trilinear.frag")
    textures = {"g_position": Texture(queries, linear=False),
                "ripple_moments": Texture(levels[0], repeat=(True, True), levels=tuple(levels[1:]))}
    out = gl.render(program, (count, 1), textures, {})[0]
    expected = sample_trilinear(levels, st, lod)
    # Rasterisers interpolate with fixed-point weights (llvmpipe and most GPUs: 8 fractional bits), so
    # a sample may differ by up to 2^-8 of the difference between neighbouring texels (here ≤ 2).
    np.testing.assert_allclose(out, expected, atol=2.0 * 2.0**-8)
    assert np.mean(np.abs(out - expected)) < 2.0 * 2.0**-10


def test_compile_errors_are_one_line_each_with_the_file_and_line(gl):
    broken = ECHO.replace("frag_colour = vec4(", "frag_colour = vec3(undeclared_name, ")  # line 7
    with pytest.raises(ShaderError) as info:
        gl.program(broken, "mine.frag")
    messages = info.value.messages
    assert messages and all(m.startswith("mine.frag:7:") and ": error: " in m for m in messages)
    assert any("undeclared_name" in m for m in messages)


def test_compiler_log_formats():
    mesa = "GLSL Compiler failed\n\nfragment_shader\n===============\n0:12(5): error: `x' undeclared\n" \
           "0:13(1): warning: unused\n"
    assert compile_messages(mesa, "a.frag") == ["a.frag:12:5: error: `x' undeclared"]
    nvidia = "0(7) : error C1008: undefined variable \"x\"\n0(9) : warning C7022: unrecognized profile\n"
    assert compile_messages(nvidia, "a.frag") == ["a.frag:7: error: undefined variable \"x\""]
    amd = "ERROR: 0:4: 'x' : undeclared identifier\n"
    assert compile_messages(amd, "a.frag") == ["a.frag:4: error: 'x' : undeclared identifier"]


def test_the_shipped_shader_compiles(gl):
    program = gl.program(shipped_shader().read_text(), "water.frag")
    for name in ("g_position", "lut_T1", "ripple_moments", "u_gamma", "u_ripple_strength"):
        assert name in program
