#!/usr/bin/env python3
"""Writes the seed corpus of gl_fuzzer (tests/fuzz/corpus/): small GL programs in the byte
encoding that fuzz_input.h and gl_fuzzer.cpp decode. Each seed reaches one area (immediate
mode, arrays, buffers, clipping, read-back, OSMesa layout) so that fuzzing starts from inputs
that already draw something. Enum values come from the Khronos registry (the one the build's
generator reads); the OSMesa format byte is the harness's own encoding. The regress_* files
next to the seeds are not made here: they are crash inputs the fuzzer found, kept so that
the corpus replay guards their fixes."""
import pathlib
import re
import struct
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]
OUT = pathlib.Path(__file__).resolve().parent / "corpus"

REGISTRY = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "/usr/share/khronos-api/gl.xml")
GL = {}
for m in re.finditer(r'<enum value="(0x[0-9A-Fa-f]+|\d+)" name="(GL_\w+)"', REGISTRY.read_text()):
    GL.setdefault(m.group(2), int(m.group(1), 0))

# Opcodes of the main loop (gl_fuzzer.cpp, LLVMFuzzerTestOneInput).
BEGIN, END, VERTEX, ATTRIB, RECT, MATRIX, STATE, QUERY = 0, 1, 2, 4, 5, 6, 7, 9
READ, ARRAYS, FILL, DRAW, BUFFERS, OSMESA = 10, 11, 12, 13, 14, 15
# The later families (fuzz_ops_pixel.cpp, fuzz_ops_state.cpp); each takes a sub-op byte.
PIXELS, TEXIMG, TEXSTATE, LISTS, SELFB, EVAL, LIGHT, FRAG, ATTRIB2, QUERIES2, RASTER = (
    16, 18, 20, 22, 24, 25, 26, 27, 28, 29, 30)

SPECIAL = {"nan": 5, "inf": 6, "-inf": 7, 1e30: 8, -1e30: 9, 1e-30: 10, "max": 11, "-max": 12,
           "min": 13, "denorm": 14, 16384.0: 15, -16384.0: 16, 1e9: 17, 1e-9: 18}


class Prog:
    def __init__(self, fmt=0x18, w=32, h=32):
        self.b = bytearray([fmt, w - 1, h - 1])

    def u8(self, v):
        self.b.append(v & 0xFF)
        return self

    def u16(self, v):
        self.b += struct.pack("<H", v & 0xFFFF)
        return self

    def u32(self, v):
        self.b += struct.pack("<I", v & 0xFFFFFFFF)
        return self

    def f(self, v):
        if isinstance(v, str) or v in SPECIAL and v not in (0, 1, -1):
            return self.u8(SPECIAL[v])
        eighths = v * 8
        if eighths == int(eighths) and 24 <= int(eighths) + 100 < 200 and v != 0:
            return self.u8(int(eighths) + 100)
        if v == 0:
            return self.u8(0)
        self.u8(200)
        self.b += struct.pack("<f", v)
        return self

    def i(self, v):
        if -16 <= v < 144:
            return self.u8(v + 16)
        self.u8(255)
        return self.u32(v)

    def e(self, name):
        self.u8(250)
        return self.u32(GL[name] if isinstance(name, str) else name)

    # Operations.
    def begin(self, mode):
        return self.u8(BEGIN).e(mode)

    def end(self):
        return self.u8(END)

    def v2(self, x, y):
        return self.u8(VERTEX).u8(0).f(x).f(y)

    def v3(self, x, y, z):
        return self.u8(VERTEX).u8(1).f(x).f(y).f(z)

    def v4(self, x, y, z, w):
        return self.u8(VERTEX).u8(2).f(x).f(y).f(z).f(w)

    def color(self, r, g, b, a):
        return self.u8(ATTRIB).u8(1).f(r).f(g).f(b).f(a)

    def normal(self, x, y, z):
        return self.u8(ATTRIB).u8(7).f(x).f(y).f(z)

    def texcoord(self, s, t):
        return self.u8(ATTRIB).u8(10).f(s).f(t)

    def edge(self, flag):
        return self.u8(ATTRIB).u8(12).u8(flag)

    def rectf(self, *v):
        self.u8(RECT).u8(0)
        for x in v:
            self.f(x)
        return self

    def matrix_mode(self, m):
        return self.u8(MATRIX).u8(0).e(m)

    def load_identity(self):
        return self.u8(MATRIX).u8(1)

    def load_matrix(self, m):
        self.u8(MATRIX).u8(2)
        for x in m:
            self.f(x)
        return self

    def rotate(self, a, x, y, z):
        return self.u8(MATRIX).u8(4).f(a).f(x).f(y).f(z)

    def frustum(self, *v):
        self.u8(MATRIX).u8(7)
        for x in v:
            self.f(x)
        return self

    def ortho(self, *v):
        self.u8(MATRIX).u8(8)
        for x in v:
            self.f(x)
        return self

    def state(self, sub, *args):
        self.u8(STATE).u8(sub)
        for kind, v in args:
            getattr(self, kind)(v)
        return self

    def enable(self, cap):
        return self.state(0, ("e", cap))

    def viewport(self, x, y, w, h):
        return self.state(2, ("i", x), ("i", y), ("i", w), ("i", h))

    def clip_plane(self, plane, a, b, c, d):
        return self.state(4, ("f", a), ("f", b), ("f", c), ("f", d), ("e", plane))

    def clear(self, mask):
        return self.state(17, ("u32", mask))

    def query(self, sub, pname):
        return self.u8(QUERY).u8(sub).e(pname)

    def read(self, x, y, w, h, fmt, typ):
        return self.u8(READ).i(x).i(y).i(w).i(h).e(fmt).e(typ)

    def pointer(self, sub, *args, offset=0):
        self.u8(ARRAYS).u8(sub)
        for kind, v in args:
            getattr(self, kind)(v)
        return self.u16(offset)

    def client_state(self, enable, array):
        return self.u8(ARRAYS).u8(5 if enable else 6).e(array)

    def fill_floats(self, offset, values):
        self.u8(FILL).u16(offset).u8(len(values)).u8(1)
        for v in values:
            self.f(v)
        return self

    def fill_bytes(self, offset, values):
        self.u8(FILL).u16(offset).u8(len(values)).u8(0)
        for v in values:
            self.u8(v)
        return self

    def draw_arrays(self, mode, first, count):
        return self.u8(DRAW).u8(0).e(mode).i(first).i(count)

    def draw_elements(self, mode, count, typ, offset):
        return self.u8(DRAW).u8(1).e(mode).i(count).e(typ).u16(offset).u32(0).u32(0)

    def buffers(self, sub, *args):
        self.u8(BUFFERS).u8(sub)
        for kind, v in args:
            getattr(self, kind)(v)
        return self

    def osmesa(self, sub, *args):
        self.u8(OSMESA).u8(sub)
        for kind, v in args:
            getattr(self, kind)(v)
        return self

    def op(self, code, sub, *args):
        """A later-family operation: opcode, sub-op, then (kind, value) arguments in the
        order the harness decodes them."""
        self.u8(code).u8(sub)
        for kind, v in args:
            getattr(self, kind)(v)
        return self

    # Texture helpers (fuzz_ops_pixel.cpp op_tex_image: target, level, internal format,
    # sizes, border byte (value % 4 - 1), format, type, data byte; 1 = data from the arena).
    def tex_image_2d(self, target, level, internal, w, h, fmt, typ, border=0, data=1):
        return self.op(TEXIMG, 1, ("e", target), ("i", level), ("e", internal), ("i", w),
                       ("i", h), ("u8", border + 1), ("e", fmt), ("e", typ), ("u8", data))

    def tex_param(self, target, pname, value):
        return self.op(TEXSTATE, 7, ("e", target), ("e", pname), ("e", value))

    def bind_texture(self, target, name):
        return self.op(TEXSTATE, 2, ("e", target), ("u8", name))

    def pixel_store(self, pname, value):
        return self.op(PIXELS, 10, ("e", pname), ("i", value))

    def draw_pixels(self, w, h, fmt, typ, offset=0):
        return self.op(PIXELS, 1, ("i", w), ("i", h), ("e", fmt), ("e", typ), ("u16", offset))

    def raster_pos(self, x, y):
        return self.op(RASTER, 0, ("f", x), ("f", y))

    def tex_quad(self):
        self.begin("GL_QUADS")
        for s_, t_, x, y in ((0, 0, -1, -1), (1, 0, 1, -1), (1, 1, 1, 1), (0, 1, -1, 1)):
            self.texcoord(s_, t_).v2(x, y)
        return self.end()


def triangle(p, pts, mode="GL_TRIANGLES"):
    p.begin(mode)
    for pt in pts:
        if len(pt) == 2:
            p.v2(*pt)
        elif len(pt) == 3:
            p.v3(*pt)
        else:
            p.v4(*pt)
    return p.end()


def seeds():
    s = {}
    p = Prog()
    s["tri_basic"] = triangle(p.color(1, 0, 0, 1), [(-1, -1), (1, -1), (0, 1)])

    p = Prog(fmt=0x1F, w=48, h=40)  # RGB, 32-bit depth, stencil
    p.enable("GL_DEPTH_TEST").clear(0x4100)
    p.begin("GL_QUADS").color(0, 1, 0, 1).v3(-1, -1, 0.5).color(0, 0, 1, 1).v3(1, -1, -0.5)
    p.v3(1, 1, 0.25).v3(-1, 1, 0).end()
    s["quad_depth_rgb"] = p

    p = Prog().matrix_mode("GL_PROJECTION").frustum(-1, 1, -1, 1, 1e-9, 1e9)
    s["frustum_extreme"] = triangle(p, [(-2, -2, -0.5), (2, -2, -5), (0, 3, 2)])

    p = Prog().clip_plane("GL_CLIP_PLANE0", 1, 0.5, 0, 0).enable("GL_CLIP_PLANE0")
    p.clip_plane("GL_CLIP_PLANE3", 0, -1, 0.25, 0.5).enable("GL_CLIP_PLANE3")
    s["clip_planes"] = triangle(p, [(-1, -1), (1, -1), (1, 1), (-1, 1)], "GL_POLYGON")

    p = Prog()
    s["nan_vertices"] = triangle(p, [(0, 0), ("nan", 1), (1, "inf")], "GL_TRIANGLE_STRIP")
    p = Prog().color("nan", "inf", -1, 2).normal("nan", 0, 0).texcoord("inf", "nan")
    s["nan_attribs"] = triangle(p, [(0, 0, 0, "nan"), (1, 0, 0, 0), (0, 1, 0, -1), (0.5, 0.5)])
    p = Prog().load_matrix(["nan"] * 4 + [1] * 12)
    s["nan_matrix"] = triangle(p, [(0, 0), (1, 0), (0, 1)])
    p = Prog().load_matrix([1e30, 0, 0, 0, 0, 1e30, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1e-30])
    s["huge_matrix"] = triangle(p, [(0, 0), (1, 0), (0, 1)], "GL_TRIANGLE_FAN")

    p = Prog().v4(0, 0, 0, 0)
    s["w_zero"] = triangle(p, [(0, 0, 0, 0), (1, 0, 0, 1e-30), (0, 1, 0, -1e-30)])

    verts = [-1, -1, 1, -1, 1, 1, -1, 1, 0, 0, 0.5, -0.75]
    p = Prog().fill_floats(0, verts).pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.client_state(True, "GL_VERTEX_ARRAY")
    for mode in ("GL_TRIANGLES", "GL_TRIANGLE_STRIP", "GL_LINE_LOOP", "GL_POINTS", "GL_QUADS"):
        p.draw_arrays(mode, 0, 6)
    s["arrays_client"] = p

    p = Prog().fill_floats(0, verts).pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 8), offset=0)
    p.fill_bytes(1024, [0, 1, 2, 2, 3, 0, 4, 5, 1]).client_state(True, "GL_VERTEX_ARRAY")
    p.draw_elements("GL_TRIANGLES", 9, "GL_UNSIGNED_BYTE", 1024)
    p.fill_bytes(1100, [0, 0, 1, 0, 2, 0, 3, 0]).draw_elements("GL_LINE_STRIP", 4,
                                                              "GL_UNSIGNED_SHORT", 1100)
    s["elements_client"] = p

    p = Prog().fill_floats(0, verts + [0.25] * 20)
    p.buffers(0, ("u8", 2)).buffers(2, ("e", "GL_ARRAY_BUFFER"), ("u8", 1))
    p.buffers(4, ("e", "GL_ARRAY_BUFFER"), ("i", 96), ("e", "GL_STATIC_DRAW"))
    p.pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.pointer(1, ("i", 3), ("e", "GL_FLOAT"), ("i", 0), offset=48)
    p.client_state(True, "GL_VERTEX_ARRAY").client_state(True, "GL_COLOR_ARRAY")
    p.draw_arrays("GL_TRIANGLES", 0, 6).draw_arrays("GL_TRIANGLES", 0, 60)
    p.fill_bytes(2000, [0, 1, 2, 3, 4, 5, 200])
    p.buffers(2, ("e", "GL_ELEMENT_ARRAY_BUFFER"), ("u8", 2))
    p.buffers(4, ("e", "GL_ELEMENT_ARRAY_BUFFER"), ("i", 7), ("e", "GL_STATIC_DRAW"))
    p.draw_elements("GL_TRIANGLE_FAN", 6, "GL_UNSIGNED_BYTE", 0)
    p.buffers(1, ("u8", 1), ("u8", 2), ("u8", 1)).draw_arrays("GL_TRIANGLES", 0, 6)
    s["buffers_arrays"] = p

    p = Prog().buffers(2, ("e", "GL_ARRAY_BUFFER"), ("u8", 3))
    p.buffers(4, ("e", "GL_ARRAY_BUFFER"), ("i", 64), ("e", "GL_STATIC_DRAW"))
    p.buffers(7, ("e", "GL_ARRAY_BUFFER"), ("e", "GL_WRITE_ONLY"), ("u8", 0x3F))
    p.pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.client_state(True, "GL_VERTEX_ARRAY").draw_arrays("GL_TRIANGLES", 0, 3)
    p.buffers(8, ("e", "GL_ARRAY_BUFFER")).draw_arrays("GL_TRIANGLES", 0, 3)
    p.buffers(5, ("e", "GL_ARRAY_BUFFER"), ("i", 8), ("i", 16))
    p.buffers(6, ("e", "GL_ARRAY_BUFFER"), ("i", 0), ("i", 64))
    s["map_buffer"] = p

    p = Prog(w=20, h=17)
    p.state(18, ("f", 0.25), ("f", 0.5), ("f", 0.75), ("f", 1)).clear(0x4000)
    triangle(p, [(-1, -1), (1, -1), (0, 1)])
    formats = [("GL_RGBA", "GL_UNSIGNED_BYTE"), ("GL_BGR", "GL_FLOAT"),
               ("GL_LUMINANCE_ALPHA", "GL_SHORT"), ("GL_RGB", "GL_UNSIGNED_SHORT_5_6_5"),
               ("GL_BGRA", "GL_UNSIGNED_INT_8_8_8_8_REV"), ("GL_DEPTH_COMPONENT", "GL_UNSIGNED_INT"),
               ("GL_STENCIL_INDEX", "GL_BITMAP"), ("GL_ALPHA", "GL_DOUBLE")]
    for fmt, typ in formats:
        p.read(-3, -2, 25, 19, fmt, typ)
    p.state(21, ("e", "GL_PACK_ROW_LENGTH"), ("i", 40)).state(21, ("e", "GL_PACK_SKIP_ROWS"), ("i", 3))
    p.state(21, ("e", "GL_PACK_SKIP_PIXELS"), ("i", 5)).state(21, ("e", "GL_PACK_ALIGNMENT"), ("i", 8))
    for fmt, typ in formats:
        p.read(2, 1, 7, 9, fmt, typ)
    s["read_pixels"] = p

    p = Prog().state(8, ("e", "GL_FRONT"), ("e", "GL_LINE")).state(8, ("e", "GL_BACK"), ("e", "GL_POINT"))
    p.edge(0)
    triangle(p, [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, 2)], "GL_POLYGON")
    p.enable("GL_CULL_FACE")
    triangle(p, [(-1, -1), (1, -1), (1, 1), (-1, 1), (0, 2), (2, 0)], "GL_QUAD_STRIP")
    s["polygon_modes"] = p

    p = Prog().fill_floats(0, [0, 0, 1, 1, 0, 0, 0, 1, 0, -1, -1, 0] * 4)
    p.pointer(7, ("e", "GL_T2F_C4F_N3F_V3F"), ("i", 0), offset=0).draw_arrays("GL_TRIANGLES", 0, 3)
    p.pointer(7, ("e", "GL_C4UB_V3F"), ("i", 0), offset=0).draw_arrays("GL_LINES", 0, 4)
    s["interleaved"] = p

    p = Prog().viewport(-8000, -8000, 16384, 16384)
    triangle(p, [(-1, -1), (1, -1), (0, 1)])
    p.viewport(5, 5, 1, 1)
    triangle(p, [(-1, -1), (1, -1), (0, 1)])
    p.viewport(0, 0, 0x7FFFFFFF, 0x7FFFFFFF)
    s["viewports"] = triangle(p, [(-1, -1), (1, -1), (0, 1)], "GL_LINE_STRIP")

    p = Prog(fmt=0x05, w=13, h=9).osmesa(1, ("u8", 40)).osmesa(2, ("u8", 0))
    triangle(p, [(-1, -1), (1, -1), (0, 1)]).clear(0x4000)
    p.osmesa(0, ("u8", 63), ("u8", 2)).osmesa(1, ("u8", 3))
    s["osmesa_layout"] = triangle(p, [(-1, -1), (1, -1), (0, 1)], "GL_TRIANGLE_FAN")

    p = Prog().begin("GL_TRIANGLES").v2(0, 0).viewport(0, 0, 5, 5).query(1, "GL_VIEWPORT")
    p.read(0, 0, 1, 1, "GL_RGBA", "GL_UNSIGNED_BYTE").pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0))
    p.begin("GL_POINTS").v2(1, 0).v2(0, 1).end().end()
    s["inside_begin"] = p

    p = Prog().fill_floats(0, verts).pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.client_state(True, "GL_VERTEX_ARRAY").begin("GL_TRIANGLES")
    for k in (0, 1, 2, 3, 4, 5):
        p.u8(DRAW).u8(5).e("GL_POINTS").i(k)
    s["array_element"] = p.end()

    p = Prog().fill_floats(0, verts).pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.client_state(True, "GL_VERTEX_ARRAY").u8(DRAW).u8(3).e("GL_TRIANGLES").u8(2)
    p.i(0).i(3).i(3).i(3)
    s["multi_draw"] = p

    p = Prog()
    p.state(0, ("e", "GL_BLEND")).state(14, ("e", "GL_CONSTANT_COLOR"), ("e", "GL_ONE"),
                                         ("e", "GL_SRC_ALPHA_SATURATE"), ("e", "GL_ZERO"))
    p.state(15, ("e", "GL_FUNC_SUBTRACT")).state(16, ("f", "nan"), ("f", 2), ("f", -1), ("f", 0.5))
    s["blend_nan"] = triangle(p, [(-1, -1), (1, -1), (0, 1)])

    p = Prog()
    s["zero_area"] = triangle(p, [(0, 0), (0, 0), (0, 0), (0, 0), (1, 1), (2, 2), (0.5, 0.5),
                                  (-1, 0.5), (1, 0.5)])
    p = Prog().begin("GL_LINES").v2(0.1, 0.1).v2(0.1, 0.1).v2(-1e30, 0).v2(1e30, 0).end()
    s["lines_degenerate"] = p

    p = Prog().rectf(-1e30, -1e30, 1e30, 1e30).rectf("nan", 0, 1, 1).rectf(-0.5, -0.5, 0.5, 0.5)
    s["rects"] = p

    p = Prog(w=64, h=64).matrix_mode("GL_PROJECTION").frustum(-0.1, 0.1, -0.1, 0.1, 0.1, 100)
    p.matrix_mode("GL_MODELVIEW").rotate(30, 1, 1, 0)
    s["near_crossing"] = triangle(p, [(-1, -1, 5), (1, -1, -5), (0, 1, -0.09), (0.2, 0.3, -0.1),
                                      (0, 0, 0), (1, 1, 1)], "GL_TRIANGLE_STRIP")

    p = Prog().u8(ARRAYS).u8(8).u32(0xFFFFFFFF).u8(ARRAYS).u8(9).u8(ARRAYS).u8(9)
    p.u8(MATRIX).u8(9).u8(MATRIX).u8(10).u8(MATRIX).u8(10)
    s["stacks"] = p

    p = Prog(fmt=0x11)  # BGRA with stencil, no depth
    for q in ("GL_VERSION", "GL_EXTENSIONS", "GL_MAX_VIEWPORT_DIMS", "GL_MODELVIEW_MATRIX",
              "GL_POLYGON_MODE", "GL_COLOR_CLEAR_VALUE"):
        for sub in range(5):
            p.query(sub, q)
    s["queries"] = p

    p = Prog(fmt=0x0A).osmesa(5, ("u8", 0x1F), ("u8", 7), ("u8", 9))
    s["recreate"] = triangle(p, [(-1, -1), (1, -1), (0, 1)])

    s.update(later_seeds())

    rng = 12345
    for k in range(8):
        p = Prog(fmt=k, w=8 + 7 * k, h=5 + 9 * k)
        p.begin("GL_TRIANGLE_STRIP")
        for _ in range(12):
            rng = (rng * 1103515245 + 12345) & 0x7FFFFFFF
            x = ((rng >> 8) % 41 - 20) / 8
            rng = (rng * 1103515245 + 12345) & 0x7FFFFFFF
            y = ((rng >> 8) % 41 - 20) / 8
            p.color(x / 3, y / 3, 0.5, 1).v2(x, y)
        s[f"strip_{k}"] = p.end()
    return s


def later_seeds():
    """Seeds of the command families added after the first harness: textures, pixel paths,
    display lists, selection/feedback, evaluators, lighting and fog, accumulation, queries,
    stipples, attribute stacks."""
    s = {}
    ramp = (list(range(0, 256, 3)) * 3)[:240]

    p = Prog().fill_bytes(0, ramp).op(TEXSTATE, 0, ("u8", 2)).bind_texture("GL_TEXTURE_2D", 1)
    p.tex_image_2d("GL_TEXTURE_2D", 0, "GL_RGBA", 8, 8, "GL_RGBA", "GL_UNSIGNED_BYTE")
    p.tex_param("GL_TEXTURE_2D", "GL_TEXTURE_MIN_FILTER", "GL_NEAREST")
    p.enable("GL_TEXTURE_2D").tex_quad()
    p.op(TEXIMG, 5, ("e", "GL_TEXTURE_2D"), ("i", 0), ("i", 2), ("i", 3), ("i", 4), ("i", 3),
         ("e", "GL_BGR"), ("e", "GL_UNSIGNED_SHORT_5_6_5_REV"), ("u8", 1))
    p.op(TEXIMG, 7, ("e", "GL_TEXTURE_2D"), ("i", 0), ("i", 1), ("i", 2), ("i", 5), ("i", 6),
         ("u8", 3), ("i", 1), ("i", 1))
    p.op(TEXIMG, 8, ("e", "GL_TEXTURE_2D"), ("i", 0), ("e", "GL_RGBA"), ("e", "GL_FLOAT"))
    p.op(TEXIMG, 7, ("e", "GL_TEXTURE_2D"), ("i", 1), ("i", 0), ("i", 0), ("i", 4), ("i", 4),
         ("u8", 1), ("e", "GL_LUMINANCE8"), ("u8", 1))
    p.op(TEXIMG, 10, ("e", "GL_TEXTURE_2D"), ("i", 0), ("e", "GL_TEXTURE_WIDTH")).tex_quad()
    s["tex_2d"] = p

    p = Prog().fill_floats(0, [0.25, 0.5, 1, 0.75] * 40).bind_texture("GL_TEXTURE_1D", 3)
    p.op(TEXIMG, 0, ("e", "GL_TEXTURE_1D"), ("i", 0), ("e", "GL_LUMINANCE_ALPHA"), ("i", 16),
         ("u8", 1), ("e", "GL_LUMINANCE_ALPHA"), ("e", "GL_FLOAT"), ("u8", 1))
    p.tex_param("GL_TEXTURE_1D", "GL_GENERATE_MIPMAP", "GL_TRUE")
    p.op(TEXIMG, 4, ("e", "GL_TEXTURE_1D"), ("i", 0), ("i", 4), ("i", 8), ("e", "GL_RGBA"),
         ("e", "GL_FLOAT"), ("u8", 1))
    p.tex_param("GL_TEXTURE_1D", "GL_TEXTURE_WRAP_S", "GL_MIRRORED_REPEAT")
    p.enable("GL_TEXTURE_1D").tex_quad()
    p.bind_texture("GL_TEXTURE_3D", 4)
    p.op(TEXIMG, 3, ("e", "GL_TEXTURE_3D"), ("i", 0), ("e", "GL_RGB5_A1"), ("i", 4), ("i", 4),
         ("i", 4), ("u8", 1), ("e", "GL_RGBA"), ("e", "GL_UNSIGNED_SHORT_4_4_4_4"), ("u8", 1))
    p.op(TEXIMG, 6, ("e", "GL_TEXTURE_3D"), ("i", 0), ("i", 1), ("i", 1), ("i", 1), ("i", 2),
         ("i", 2), ("i", 2), ("e", "GL_LUMINANCE"), ("e", "GL_UNSIGNED_BYTE"), ("u8", 1))
    p.enable("GL_TEXTURE_3D").tex_quad()
    p.op(TEXIMG, 8, ("e", "GL_TEXTURE_3D"), ("i", 0), ("e", "GL_BGRA"),
         ("e", "GL_UNSIGNED_INT_8_8_8_8_REV"))
    p.bind_texture("GL_TEXTURE_CUBE_MAP", 5)
    for face in ("POSITIVE_X", "NEGATIVE_X", "POSITIVE_Y", "NEGATIVE_Y", "POSITIVE_Z",
                 "NEGATIVE_Z"):
        p.tex_image_2d("GL_TEXTURE_CUBE_MAP_" + face, 0, "GL_RGB", 4, 4, "GL_RGB",
                       "GL_UNSIGNED_BYTE")
    p.op(TEXSTATE, 14, ("e", "GL_S"), ("e", "GL_TEXTURE_GEN_MODE"), ("u8", 0),
         ("e", "GL_REFLECTION_MAP"))
    p.enable("GL_TEXTURE_GEN_S").enable("GL_TEXTURE_CUBE_MAP").tex_quad()
    p.op(TEXIMG, 9, ("e", "GL_TEXTURE_2D"), ("i", 0), ("e", "GL_COMPRESSED_RGB_S3TC_DXT1_EXT"),
         ("i", 4), ("i", 4), ("i", 1), ("i", 8), ("i", 0), ("i", 0), ("i", 0), ("u8", 1),
         ("u16", 0))
    s["tex_1d_3d_cube"] = p

    p = Prog().fill_bytes(0, ramp).op(TEXSTATE, 15, ("e", "GL_TEXTURE1"))
    p.bind_texture("GL_TEXTURE_2D", 2)
    p.tex_image_2d("GL_TEXTURE_2D", 0, "GL_ALPHA", 4, 4, "GL_ALPHA", "GL_UNSIGNED_BYTE")
    p.enable("GL_TEXTURE_2D")
    p.op(TEXSTATE, 12, ("e", "GL_TEXTURE_ENV"), ("e", "GL_TEXTURE_ENV_MODE"), ("e", "GL_COMBINE"))
    p.op(TEXSTATE, 12, ("e", "GL_TEXTURE_ENV"), ("e", "GL_COMBINE_RGB"), ("e", "GL_DOT3_RGB"))
    p.op(TEXSTATE, 12, ("e", "GL_TEXTURE_ENV"), ("e", "GL_SOURCE1_RGB"), ("e", "GL_CONSTANT"))
    p.op(TEXSTATE, 13, ("e", "GL_TEXTURE_ENV"), ("e", "GL_TEXTURE_ENV_COLOR"), ("u8", 1),
         ("f", 0.5), ("f", 1), ("f", 0.25), ("f", 1))
    p.op(TEXSTATE, 14, ("e", "GL_T"), ("e", "GL_EYE_PLANE"), ("u8", 3), ("f", 1), ("f", 0.5),
         ("f", 0), ("f", 0.25))
    p.op(TEXSTATE, 14, ("e", "GL_T"), ("e", "GL_TEXTURE_GEN_MODE"), ("u8", 0),
         ("e", "GL_EYE_LINEAR"))
    p.enable("GL_TEXTURE_GEN_T")
    p.begin("GL_TRIANGLES")
    for x, y in ((-1, -1), (1, -1), (0, 1)):
        p.op(TEXSTATE, 17, ("e", "GL_TEXTURE1"), ("u8", 1), ("f", x), ("f", y)).v2(x, y)
    p.end()
    p.op(TEXSTATE, 16, ("e", "GL_TEXTURE1")).fill_floats(4096, [0, 0, 1, 0, 1, 1, 0, 1] * 2)
    p.op(TEXSTATE, 18, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), ("u16", 4096))
    p.client_state(True, "GL_TEXTURE_COORD_ARRAY").fill_floats(0, [-1, -1, 1, -1, 1, 1, -1, 1])
    p.pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=0)
    p.client_state(True, "GL_VERTEX_ARRAY").draw_arrays("GL_QUADS", 0, 4)
    s["tex_env_multitexture"] = p

    p = Prog(w=40, h=30).fill_bytes(0, ramp).raster_pos(-0.5, -0.5)
    for fmt, typ in (("GL_RGBA", "GL_UNSIGNED_BYTE"), ("GL_LUMINANCE", "GL_FLOAT"),
                     ("GL_DEPTH_COMPONENT", "GL_UNSIGNED_SHORT"), ("GL_STENCIL_INDEX", "GL_BITMAP"),
                     ("GL_COLOR_INDEX", "GL_UNSIGNED_BYTE"),
                     ("GL_BGRA", "GL_UNSIGNED_INT_2_10_10_10_REV")):
        p.draw_pixels(7, 5, fmt, typ)
    p.op(PIXELS, 9, ("f", 2), ("f", -1.5)).draw_pixels(6, 6, "GL_RGB", "GL_UNSIGNED_BYTE")
    p.op(PIXELS, 7, ("e", "GL_RED_SCALE"), ("f", 0.5)).op(PIXELS, 7, ("e", "GL_GREEN_BIAS"), ("f", 0.25))
    p.op(PIXELS, 5, ("e", "GL_PIXEL_MAP_I_TO_R"), ("i", 8), ("u16", 0), ("u8", 1))
    p.op(PIXELS, 8, ("e", "GL_MAP_COLOR"), ("i", 1))
    p.op(PIXELS, 5, ("e", "GL_PIXEL_MAP_R_TO_R"), ("i", 16), ("u16", 0), ("u8", 0))
    p.draw_pixels(5, 4, "GL_RGBA", "GL_UNSIGNED_BYTE").draw_pixels(5, 4, "GL_COLOR_INDEX", "GL_SHORT")
    p.op(PIXELS, 6, ("e", "GL_PIXEL_MAP_I_TO_R"), ("u8", 0))
    p.op(PIXELS, 3, ("i", 13), ("i", 9), ("f", 1), ("f", 2), ("f", 3), ("f", -1), ("u16", 100),
         ("u8", 1))
    p.op(PIXELS, 4, ("i", 0), ("i", 0), ("i", 10), ("i", 10), ("e", "GL_COLOR"))
    p.op(RASTER, 7, ("f", 3), ("f", 4)).op(PIXELS, 4, ("i", 2), ("i", 2), ("i", 12), ("i", 9),
                                            ("e", "GL_DEPTH"))
    p.pixel_store("GL_UNPACK_ROW_LENGTH", 11).pixel_store("GL_UNPACK_SKIP_ROWS", 2)
    p.pixel_store("GL_UNPACK_SKIP_PIXELS", 3).pixel_store("GL_UNPACK_ALIGNMENT", 8)
    p.pixel_store("GL_UNPACK_LSB_FIRST", 1).pixel_store("GL_UNPACK_SWAP_BYTES", 1)
    p.draw_pixels(5, 6, "GL_RGB", "GL_SHORT").draw_pixels(9, 3, "GL_STENCIL_INDEX", "GL_BITMAP")
    p.op(PIXELS, 3, ("i", 17), ("i", 5), ("f", 0), ("f", 0), ("f", 1), ("f", 1), ("u16", 0),
         ("u8", 1))
    p.op(PIXELS, 12, ("u8", 0), ("u16", 8)).op(PIXELS, 12, ("u8", 1), ("u16", 0))
    p.pixel_store("GL_PACK_ROW_LENGTH", 13).pixel_store("GL_PACK_SKIP_PIXELS", 1)
    p.op(PIXELS, 0, ("i", 0), ("i", 0), ("i", 9), ("i", 7), ("e", "GL_LUMINANCE_ALPHA"),
         ("e", "GL_UNSIGNED_SHORT"))
    s["pixel_paths"] = p

    p = Prog().fill_bytes(0, ramp).op(LISTS, 6, ("u8", 5))
    p.op(LISTS, 0, ("u8", 1), ("e", "GL_COMPILE"))
    triangle(p.color(1, 0.5, 0, 1), [(-1, -1), (1, -1), (0, 1)])
    p.tex_image_2d("GL_TEXTURE_2D", 0, "GL_RGB", 4, 4, "GL_RGB", "GL_UNSIGNED_BYTE")
    p.raster_pos(0, 0).draw_pixels(3, 3, "GL_RGBA", "GL_UNSIGNED_BYTE")
    p.op(PIXELS, 3, ("i", 8), ("i", 8), ("f", 0), ("f", 0), ("f", 1), ("f", 1), ("u16", 0),
         ("u8", 1))
    p.op(LIGHT, 0, ("e", "GL_LIGHT0"), ("e", "GL_SPOT_EXPONENT"), ("f", 2))
    p.op(TEXSTATE, 7, ("e", "GL_TEXTURE_2D"), ("e", "GL_TEXTURE_MAG_FILTER"), ("e", "GL_LINEAR"))
    p.op(LISTS, 1)
    p.op(LISTS, 0, ("u8", 2), ("e", "GL_COMPILE_AND_EXECUTE")).op(LISTS, 2, ("u8", 1))
    p.rectf(-0.5, -0.5, 0.5, 0.5).op(LISTS, 1)
    p.op(LISTS, 2, ("u8", 2)).op(LISTS, 5, ("u8", 1))
    # CallLists: type, count, then count * (bytes per name) name bytes.
    for typ, per, names in (("GL_UNSIGNED_BYTE", 1, [0, 1]), ("GL_2_BYTES", 2, [0, 0, 0, 1]),
                            ("GL_3_BYTES", 3, [0, 0, 1]), ("GL_4_BYTES", 4, [0, 0, 0, 0]),
                            ("GL_FLOAT", 4, [0, 0, 0, 0]), ("GL_SHORT", 2, [1, 0])):
        p.op(LISTS, 4, ("e", typ), ("u8", len(names) // per))
        for b in names:
            p.u8(b)
    p.op(LISTS, 8, ("u8", 2)).op(LISTS, 7, ("u8", 1), ("u8", 0), ("u8", 3)).op(LISTS, 2, ("u8", 2))
    s["display_lists"] = p

    p = Prog().op(SELFB, 0, ("i", 64)).op(SELFB, 2, ("e", "GL_SELECT")).op(SELFB, 3)
    p.op(SELFB, 4, ("u8", 7))
    triangle(p, [(-1, -1), (1, -1), (0, 1)])
    p.op(SELFB, 6, ("u8", 3)).rectf(-2, -2, -1.5, -1.5).op(SELFB, 5).op(SELFB, 2, ("e", "GL_RENDER"))
    p.op(SELFB, 1, ("i", 200), ("e", "GL_4D_COLOR_TEXTURE")).op(SELFB, 2, ("e", "GL_FEEDBACK"))
    p.op(SELFB, 7, ("f", 3))
    triangle(p, [(-1, -1), (1, -1), (0, 1)], "GL_LINE_LOOP")
    triangle(p, [(0.5, 0.5), (0.25, 0)], "GL_POINTS")
    p.raster_pos(0, 0).draw_pixels(2, 2, "GL_RGBA", "GL_UNSIGNED_BYTE")
    p.op(PIXELS, 3, ("i", 0), ("i", 0), ("f", 0), ("f", 0), ("f", 1), ("f", 1), ("u16", 0),
         ("u8", 1))
    p.state(8, ("e", "GL_FRONT_AND_BACK"), ("e", "GL_LINE"))
    triangle(p, [(-1, -1), (1, -1), (0, 1)]).op(SELFB, 2, ("e", "GL_RENDER"))
    p.op(SELFB, 1, ("i", 3), ("e", "GL_3D")).op(SELFB, 2, ("e", "GL_FEEDBACK"))
    triangle(p, [(-1, -1), (1, -1), (0, 1)]).op(SELFB, 2, ("e", "GL_RENDER"))
    s["select_feedback"] = p

    ctrl = [-1, -1, 0, -0.5, 1, 0, 0.5, -1, 0, 1, 1, 0.5] * 4
    p = Prog().fill_floats(0, ctrl)
    p.op(EVAL, 0, ("e", "GL_MAP1_VERTEX_3"), ("f", 0), ("f", 1), ("u8", 5), ("u8", 6), ("u16", 0))
    p.enable("GL_MAP1_VERTEX_3").op(EVAL, 5, ("u8", 18), ("f", 0), ("f", 1))
    p.op(EVAL, 12, ("e", "GL_LINE_STRIP"), ("u8", 8), ("u8", 18))
    p.begin("GL_POINTS").op(EVAL, 7, ("f", 0.5)).op(EVAL, 10, ("u8", 12)).end()
    p.op(EVAL, 2, ("e", "GL_MAP2_VERTEX_3"), ("f", 0), ("f", 1), ("u8", 5), ("u8", 4), ("f", 0),
         ("f", 1), ("u8", 14), ("u8", 4), ("u16", 0))
    p.op(EVAL, 3, ("e", "GL_MAP2_COLOR_4"), ("f", 0), ("f", 1), ("u8", 6), ("u8", 3), ("f", 0),
         ("f", 1), ("u8", 14), ("u8", 3), ("u16", 0))
    p.enable("GL_MAP2_VERTEX_3").enable("GL_MAP2_COLOR_4").enable("GL_AUTO_NORMAL")
    p.op(EVAL, 6, ("u8", 12), ("f", 0), ("f", 1), ("u8", 12), ("f", 0), ("f", 1))
    p.op(EVAL, 13, ("e", "GL_FILL"), ("u8", 8), ("u8", 16), ("u8", 8), ("u8", 16))
    p.op(EVAL, 13, ("e", "GL_LINE"), ("u8", 8), ("u8", 12), ("u8", 8), ("u8", 12))
    p.op(EVAL, 4, ("u8", 0), ("e", "GL_MAP2_VERTEX_3"), ("e", "GL_COEFF"), ("u8", 0))
    p.op(EVAL, 4, ("u8", 1), ("e", "GL_MAP1_VERTEX_3"), ("e", "GL_DOMAIN"), ("u8", 1))
    s["evaluators"] = p

    p = Prog(fmt=0x08).enable("GL_LIGHTING").enable("GL_LIGHT0").enable("GL_DEPTH_TEST")
    p.op(LIGHT, 2, ("e", "GL_LIGHT0"), ("e", "GL_POSITION"), ("f", 1), ("f", 1), ("f", 2), ("f", 0))
    p.op(LIGHT, 2, ("e", "GL_LIGHT0"), ("e", "GL_SPOT_DIRECTION"), ("f", 0), ("f", 0), ("f", -1))
    p.op(LIGHT, 6, ("e", "GL_FRONT_AND_BACK"), ("e", "GL_SPECULAR"), ("f", 1), ("f", 1), ("f", 1),
         ("f", 1))
    p.op(LIGHT, 5, ("e", "GL_FRONT"), ("e", "GL_SHININESS"), ("f", 16))
    p.op(LIGHT, 9, ("e", "GL_LIGHT_MODEL_TWO_SIDE"), ("u8", 1), ("i", 1))
    p.op(LIGHT, 10, ("e", "GL_FRONT"), ("e", "GL_DIFFUSE")).enable("GL_COLOR_MATERIAL")
    p.enable("GL_FOG").op(LIGHT, 11, ("e", "GL_FOG_MODE"), ("u8", 1), ("e", "GL_EXP2"))
    p.op(LIGHT, 11, ("e", "GL_FOG_COORD_SRC"), ("u8", 1), ("e", "GL_FOG_COORD"))
    p.op(LIGHT, 11, ("e", "GL_FOG_COLOR"), ("u8", 2), ("f", 0.5), ("f", 0.5), ("f", 1), ("f", 1))
    p.enable("GL_COLOR_SUM").op(FRAG, 20, ("u8", 0), ("f", 0.25), ("f", 0), ("f", 0.5))
    p.begin("GL_TRIANGLES")
    for x, y, fc in ((-1, -1, 0), (1, -1, 0.5), (0, 1, 1)):
        p.normal(0, 0, 1).op(LIGHT, 11, ("e", 0), ("u8", 4), ("f", fc)).v3(x, y, -0.5)
    p.end()
    p.op(LIGHT, 11, ("e", 0), ("u8", 8), ("e", "GL_FLOAT"), ("i", 0), ("u16", 0))
    p.client_state(True, "GL_FOG_COORD_ARRAY").fill_floats(64, [-1, -1, 1, -1, 0, 1])
    p.op(FRAG, 21, ("i", 3), ("e", "GL_UNSIGNED_BYTE"), ("i", 0), ("u16", 200))
    p.client_state(True, "GL_SECONDARY_COLOR_ARRAY")
    p.pointer(0, ("i", 2), ("e", "GL_FLOAT"), ("i", 0), offset=64)
    p.client_state(True, "GL_VERTEX_ARRAY").draw_arrays("GL_TRIANGLES", 0, 3)
    p.op(LIGHT, 4, ("e", "GL_LIGHT0"), ("e", "GL_SPOT_DIRECTION"), ("u8", 1))
    p.op(LIGHT, 8, ("e", "GL_BACK"), ("e", "GL_COLOR_INDEXES"), ("u8", 0))
    s["lighting_fog"] = p

    p = Prog(fmt=0x28).state(18, ("f", 0.5), ("f", 0), ("f", 0), ("f", 1)).clear(0x4000)
    p.op(FRAG, 13, ("e", "GL_LOAD"), ("f", 0.5))
    triangle(p.color(0, 1, 0, 1), [(-1, -1), (1, -1), (0, 1)])
    p.op(FRAG, 13, ("e", "GL_ACCUM"), ("f", 0.5)).op(FRAG, 13, ("e", "GL_MULT"), ("f", 1.5))
    p.op(FRAG, 13, ("e", "GL_ADD"), ("f", -0.25)).op(FRAG, 13, ("e", "GL_RETURN"), ("f", 1))
    p.op(FRAG, 14, ("f", 0.25), ("f", 0.25), ("f", 0.25), ("f", 1)).clear(0x200)
    p.op(QUERIES2, 0, ("u8", 2)).op(QUERIES2, 3, ("e", "GL_SAMPLES_PASSED"), ("u8", 1))
    triangle(p, [(-1, -1), (1, -1), (0, 1)]).op(QUERIES2, 4, ("e", "GL_SAMPLES_PASSED"))
    p.op(QUERIES2, 7, ("u8", 1), ("e", "GL_QUERY_RESULT"))
    p.op(QUERIES2, 5, ("e", "GL_SAMPLES_PASSED"), ("e", "GL_QUERY_COUNTER_BITS"))
    s["accum_queries"] = p

    p = Prog(fmt=0x1C).fill_bytes(0, [0xAA, 0x55, 0xF0, 0x0F] * 40)
    p.op(PIXELS, 12, ("u8", 0), ("u16", 0)).enable("GL_POLYGON_STIPPLE")
    p.op(FRAG, 11, ("i", 3), ("u16", 0xF0F0)).enable("GL_LINE_STIPPLE")
    p.op(FRAG, 10, ("f", 3)).op(FRAG, 8, ("f", 5))
    p.op(FRAG, 9, ("e", "GL_POINT_DISTANCE_ATTENUATION"), ("u8", 2), ("f", 1), ("f", 0.5), ("f", 0))
    p.op(FRAG, 9, ("e", "GL_POINT_SIZE_MAX"), ("u8", 0), ("f", 4))
    p.op(FRAG, 1, ("e", "GL_GREATER"), ("f", 0.25)).enable("GL_ALPHA_TEST")
    p.op(FRAG, 2, ("e", "GL_EQUAL"), ("i", 0), ("u32", 0xFF)).enable("GL_STENCIL_TEST")
    p.op(FRAG, 3, ("e", "GL_KEEP"), ("e", "GL_INCR_WRAP"), ("e", "GL_INVERT"))
    p.op(FRAG, 0, ("i", 2), ("i", 2), ("i", 20), ("i", 20)).enable("GL_SCISSOR_TEST")
    p.op(FRAG, 5, ("e", "GL_XOR")).enable("GL_COLOR_LOGIC_OP")
    triangle(p, [(-1, -1), (1, -1), (0, 1)])
    triangle(p, [(-1, -1), (1, 1), (1, -1), (-1, 1)], "GL_LINES")
    triangle(p, [(0, 0), (0.5, 0.5)], "GL_POINTS")
    p.op(FRAG, 12, ("f", 1), ("f", 2)).enable("GL_POLYGON_OFFSET_FILL")
    p.op(FRAG, 6, ("e", "GL_NONE")).rectf(-1, -1, 1, 1).op(FRAG, 6, ("e", "GL_FRONT"))
    s["fragment_stipple_points"] = p

    p = Prog().op(ATTRIB2, 0, ("u8", 21)).enable("GL_LIGHTING").state(16, ("f", 1), ("f", 0),
                                                                       ("f", 0), ("f", 1))
    p.op(PIXELS, 9, ("f", 2), ("f", 2)).op(FRAG, 8, ("f", 7)).op(ATTRIB2, 0, ("u8", 18))
    p.op(TEXSTATE, 15, ("e", "GL_TEXTURE2")).op(ATTRIB2, 1).op(ATTRIB2, 1).op(ATTRIB2, 1)
    p.op(ATTRIB2, 2, ("u8", 2)).pixel_store("GL_UNPACK_ALIGNMENT", 1)
    p.op(TEXSTATE, 16, ("e", "GL_TEXTURE3")).op(ATTRIB2, 3).op(ATTRIB2, 3)
    for q in ("GL_ATTRIB_STACK_DEPTH", "GL_CURRENT_RASTER_POSITION", "GL_ZOOM_X",
              "GL_LIST_INDEX", "GL_FOG_COLOR", "GL_TEXTURE_MATRIX"):
        for sub in range(4):
            p.query(sub, q)
    s["attrib_stacks"] = p
    return s


def main():
    OUT.mkdir(exist_ok=True)
    for name, prog in seeds().items():
        (OUT / name).write_bytes(bytes(prog.b))
    print(f"wrote {len(seeds())} seeds to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
