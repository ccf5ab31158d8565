"""Run a fragment shader over a G-buffer on a real OpenGL implementation (headless), and read its image back.

The harness of ``oceanrender validate-shader``: an OpenGL 3.3 core context
without a window (``moderngl`` over EGL: Mesa's llvmpipe software rasteriser
on a machine without a GPU, the GPU's driver where there is one), one
full-screen triangle, the G-buffer and the LUTs as float textures, and the
framebuffer read back as float32.

Conventions (the shader's side is documented in ``shaders/water.frag`` and
docs/realtime.md):

* G-buffer row j (from the top of the reference image) is uploaded as texture
  row j, and the framebuffer is read back bottom row first, so pixel (i, j)
  is shaded by the fragment at ``gl_FragCoord.xy = (i + ½, j + ½)`` and lands
  in row j of the result: no flips anywhere.
* A LUT's first row is texture row 0 (v = 0), as its sidecar states.
* The ripple textures are uploaded with every mip level computed in numpy
  (:mod:`.ripples`), so the GL and numpy models sample the same texels.

Why moderngl: a maintained Python binding (PyPI wheels) that creates a
headless EGL context, compiles GLSL and moves numpy arrays to and from
textures in a few calls; PyOpenGL would need the context code written here.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from importlib import resources
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

__all__ = ["VERTEX_SHADER", "shipped_shader", "ShaderError", "compile_messages", "GLContext", "Texture",
           "gbuffer_textures"]

#: The harness's vertex stage: one triangle covering the viewport (no vertex buffers).
VERTEX_SHADER = """#version 330 core
void main() {
    vec2 corner = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));
    gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
}
"""

#: Mesa: "0:12(5): error: message"; NVIDIA/AMD: "0(12) : error C1008: message"; "ERROR: 0:12: message".
_MESSAGE_PATTERNS = (
    re.compile(r"^\s*\d+:(?P<line>\d+)\((?P<column>\d+)\):\s*(?P<kind>error|warning):\s*(?P<text>.*)$", re.I),
    re.compile(r"^\s*\d+\((?P<line>\d+)\)\s*:\s*(?P<kind>error|warning)\s*\w*:\s*(?P<text>.*)$", re.I),
    re.compile(r"^\s*(?P<kind>error|warning):\s*\d+:(?P<line>\d+):\s*(?P<text>.*)$", re.I),
)


def shipped_shader() -> Path:
    """Path of the reference fragment shader shipped with the package (``realtime/shaders/water.frag``)."""
    return Path(str(resources.files(__package__).joinpath("shaders", "water.frag")))


class ShaderError(ValueError):
    """A shader that does not compile or link; ``messages`` holds one line per compiler error."""

    def __init__(self, messages: list[str]):
        super().__init__("\n".join(messages))
        self.messages = messages


def compile_messages(log: str, source_name: str) -> list[str]:
    """The errors of a GLSL compiler log as ``NAME:LINE[:COLUMN]: error: text`` lines, one per error.

    Lines of the log that match no known compiler format but say "error" are
    kept as they are (prefixed with the name), so nothing is lost.
    """
    out = []
    for raw in log.splitlines():
        for pattern in _MESSAGE_PATTERNS:
            match = pattern.match(raw)
            if match:
                if match.group("kind").lower() == "error":
                    where = match.group("line") + (f":{match.group('column')}" if "column" in match.groupdict()
                                                   and match.group("column") else "")
                    out.append(f"{source_name}:{where}: error: {match.group('text').strip()}")
                break
        else:
            if "error" in raw.lower() and raw.strip() and "compiler failed" not in raw.lower():
                out.append(f"{source_name}: {raw.strip()}")
    return out or [f"{source_name}: error: {line.strip()}" for line in log.splitlines() if line.strip()][:20]


@dataclass(frozen=True)
class Texture:
    """A texture to bind: data (rows, columns, channels) float32, and how it is filtered.

    ``levels``: further mip levels (each (rows/2ᵏ, columns/2ᵏ, channels)); ``repeat``: (x, y) wrapping;
    ``linear``: bilinear (else nearest).
    """

    data: NDArray[np.float32]
    linear: bool = True
    repeat: tuple[bool, bool] = (False, False)
    levels: tuple[NDArray[np.float32], ...] = ()


def gbuffer_textures(gbuffer) -> dict[str, Texture]:
    """The five RGBA G-buffer textures of the interface (``g_position`` …) from a :class:`~.gbuffer.GBuffer`."""

    def rgba(xyz, w) -> Texture:
        data = np.concatenate([np.asarray(xyz, dtype=np.float32), np.asarray(w, dtype=np.float32)[..., None]], -1)
        return Texture(np.ascontiguousarray(data), linear=False)

    water = np.stack([gbuffer.depth, gbuffer.path_length, gbuffer.rock], axis=-1)
    return {"g_position": rgba(gbuffer.position, gbuffer.kind), "g_normal": rgba(gbuffer.normal, gbuffer.cos_view),
            "g_view": rgba(gbuffer.ray, gbuffer.distance), "g_water": rgba(water, gbuffer.roughness),
            "g_refracted": rgba(gbuffer.refracted, gbuffer.foam)}


class GLContext:
    """A headless OpenGL context (EGL) that renders fragment shaders into float32 images.

    Raises RuntimeError (with the reason) when no OpenGL 3.3 context can be made.
    """

    def __init__(self):
        try:
            import moderngl  # noqa: PLC0415
        except ImportError as exc:  # pragma: no cover (a dependency of the project)
            raise RuntimeError(f"moderngl is not installed ({exc}); run `make setup`") from None
        self._gl = moderngl
        try:
            self.ctx = moderngl.create_standalone_context(backend="egl", require=330)
        except Exception as exc:  # noqa: BLE001 (every backend failure is the same for the user)
            raise RuntimeError(f"no headless OpenGL 3.3 context (EGL): {exc}. On Debian: apt-get install "
                               "libegl1 libegl-mesa0 libgl1-mesa-dri") from None

    @property
    def renderer(self) -> str:
        """``GL_RENDERER, GL_VERSION`` of the context (e.g. llvmpipe, Mesa)."""
        info = self.ctx.info
        return f"{info['GL_RENDERER']}, OpenGL {info['GL_VERSION']}"

    def program(self, source: str, source_name: str):
        """Compile and link the fragment shader with the harness's vertex stage; :class:`ShaderError` if it fails."""
        try:
            return self.ctx.program(vertex_shader=VERTEX_SHADER, fragment_shader=source)
        except self._gl.Error as exc:
            raise ShaderError(compile_messages(str(exc), source_name)) from None

    def upload(self, texture: Texture):
        """A GL texture of ``texture`` (its levels, filter and wrapping), to pass to :meth:`render` many times."""
        gl = self._gl
        data = np.ascontiguousarray(texture.data, dtype=np.float32)
        rows, columns, channels = data.shape
        tex = self.ctx.texture((columns, rows), channels, data.tobytes(), dtype="f4")
        if texture.levels:
            tex.build_mipmaps(0, len(texture.levels))
            for level, values in enumerate(texture.levels, start=1):
                tex.write(np.ascontiguousarray(values, dtype=np.float32).tobytes(), level=level)
            tex.filter = (gl.LINEAR_MIPMAP_LINEAR, gl.LINEAR)
        else:
            tex.filter = (gl.LINEAR, gl.LINEAR) if texture.linear else (gl.NEAREST, gl.NEAREST)
        tex.repeat_x, tex.repeat_y = texture.repeat
        return tex

    def render(self, program, size: tuple[int, int], textures: dict, uniforms: dict) -> NDArray[np.float32]:
        """Draw the full-screen triangle with ``program`` into a (height, width) RGBA32F target → (H, W, 4).

        ``textures``: :class:`Texture` s (uploaded for this draw and released
        after it) or GL textures from :meth:`upload` (bound as they are).
        Textures and uniforms the program does not declare are skipped.
        """
        width, height = size
        bound = []
        try:
            for unit, (name, texture) in enumerate((n, t) for n, t in textures.items() if n in program):
                if isinstance(texture, Texture):
                    texture = self.upload(texture)
                    bound.append(texture)
                texture.use(location=unit)
                program[name].value = unit
            for name, value in uniforms.items():
                if name in program:
                    program[name].value = value
            target = self.ctx.texture((width, height), 4, dtype="f4")
            fbo = self.ctx.framebuffer(color_attachments=[target])
            fbo.use()
            fbo.clear(0.0, 0.0, 0.0, 0.0)
            vao = self.ctx.vertex_array(program, [])
            vao.render(self._gl.TRIANGLES, vertices=3)
            image = np.frombuffer(fbo.read(components=4, dtype="f4"), dtype=np.float32)
            vao.release()
            fbo.release()
            target.release()
            return image.reshape(height, width, 4).copy()
        finally:
            for tex in bound:
                tex.release()

    def release(self) -> None:
        self.ctx.release()
