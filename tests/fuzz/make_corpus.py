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


def main():
    OUT.mkdir(exist_ok=True)
    for name, prog in seeds().items():
        (OUT / name).write_bytes(bytes(prog.b))
    print(f"wrote {len(seeds())} seeds to {OUT}", file=sys.stderr)


if __name__ == "__main__":
    main()
