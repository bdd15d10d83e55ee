// libFuzzer harness: the input bytes are a program of GL and OSMesa calls with arbitrary
// arguments (fuzz_input.h decodes them), run against a fresh context each time.
//
// The harness owns every piece of client memory it hands to Pineda and sizes it from what
// the call may legally read or write (GL 2.1 §2.8 for arrays, §3.6.4 and §4.3.2 for images,
// fuzz_harness.h), so AddressSanitizer reports an access outside it as Pineda's bug, not the
// harness's. Memory is allocated with exact sizes so that the heap redzones sit right at its
// ends; the colour buffer's row gaps (OSMESA_ROW_LENGTH > width) are checked by pattern.
// Draws whose element ranges the harness memory cannot back, and very large draws, are
// skipped: the goal is to explore Pineda, not to time out on the harness.
//
// Arguments are decoded inside call expressions; the harness is built by clang only, which
// evaluates them left to right, and make_corpus.py writes its seeds in that order.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "fuzz_harness.h"

namespace pineda::fuzz {

Harness::~Harness() {
  if (ctx != nullptr) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }
  check_gaps();
  std::free(color);
  std::free(client);
  for (void* p : keep)
    std::free(p);
}

// Bytes between rows that no pixel occupies must keep the pattern written at allocation.
bool Harness::gaps_intact() const {
  if (color == nullptr) return true;
  const size_t row_bytes = static_cast<size_t>(row_pixels()) * bpp;
  const size_t used = static_cast<size_t>(width) * bpp;
  for (int y = 0; y < height; ++y)
    for (size_t b = used; b < row_bytes; ++b)
      if (color[y * row_bytes + b] != kGapPattern) return false;
  return true;
}

void Harness::check_gaps() const {
  if (!gaps_intact()) std::abort();
}

// (Re)attach a drawable of the given size and row length, checking and dropping the
// previous one.
void Harness::make_current(int w, int h, int row_len) {
  check_gaps();
  row_length = row_len;
  width = w;
  height = h;
  std::free(color);
  color_bytes = static_cast<size_t>(row_pixels()) * h * bpp;
  color = static_cast<uint8_t*>(std::malloc(color_bytes));
  std::memset(color, kGapPattern, color_bytes);
  if (!OSMesaMakeCurrent(ctx, color, GL_UNSIGNED_BYTE, w, h)) std::abort();
}

void Harness::create(Input& in) {
  static constexpr GLenum kFormats[] = {OSMESA_RGBA, OSMESA_BGRA, OSMESA_ARGB, OSMESA_RGB};
  // The old drawable is checked with its own layout before the format changes.
  check_gaps();
  std::free(color);
  color = nullptr;
  const uint8_t sel = in.u8();
  format = kFormats[sel & 3];
  bpp = format == OSMESA_RGB ? 3 : 4;
  static constexpr GLint kDepth[] = {0, 16, 24, 32};
  if (ctx != nullptr) {
    OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
    OSMesaDestroyContext(ctx);
  }
  // Bit 5 of the selector asks for an accumulation buffer.
  ctx = OSMesaCreateContextExt(format, kDepth[(sel >> 2) & 3], (sel & 16) ? 8 : 0,
                               (sel & 32) ? 16 : 0, nullptr);
  if (ctx == nullptr) std::abort();
  compiling = false;
  make_current(1 + in.u8() % kMaxSurface, 1 + in.u8() % kMaxSurface, 0);
  tex_coords = get_int(GL_MAX_TEXTURE_COORDS);
  if (tex_coords < 1) tex_coords = 1;
}

namespace {

struct Arr {
  GLenum cap, ptr, size, type, stride, binding;
  int default_size; // when the array has no SIZE query
};
constexpr Arr kArrays[] = {
    {GL_VERTEX_ARRAY, GL_VERTEX_ARRAY_POINTER, GL_VERTEX_ARRAY_SIZE, GL_VERTEX_ARRAY_TYPE,
     GL_VERTEX_ARRAY_STRIDE, GL_VERTEX_ARRAY_BUFFER_BINDING, 0},
    {GL_COLOR_ARRAY, GL_COLOR_ARRAY_POINTER, GL_COLOR_ARRAY_SIZE, GL_COLOR_ARRAY_TYPE,
     GL_COLOR_ARRAY_STRIDE, GL_COLOR_ARRAY_BUFFER_BINDING, 0},
    {GL_NORMAL_ARRAY, GL_NORMAL_ARRAY_POINTER, 0, GL_NORMAL_ARRAY_TYPE, GL_NORMAL_ARRAY_STRIDE,
     GL_NORMAL_ARRAY_BUFFER_BINDING, 3},
    {GL_EDGE_FLAG_ARRAY, GL_EDGE_FLAG_ARRAY_POINTER, 0, 0, GL_EDGE_FLAG_ARRAY_STRIDE,
     GL_EDGE_FLAG_ARRAY_BUFFER_BINDING, 1},
    {GL_INDEX_ARRAY, GL_INDEX_ARRAY_POINTER, 0, GL_INDEX_ARRAY_TYPE, GL_INDEX_ARRAY_STRIDE,
     GL_INDEX_ARRAY_BUFFER_BINDING, 1},
    {GL_SECONDARY_COLOR_ARRAY, GL_SECONDARY_COLOR_ARRAY_POINTER, GL_SECONDARY_COLOR_ARRAY_SIZE,
     GL_SECONDARY_COLOR_ARRAY_TYPE, GL_SECONDARY_COLOR_ARRAY_STRIDE,
     GL_SECONDARY_COLOR_ARRAY_BUFFER_BINDING, 0},
    {GL_FOG_COORD_ARRAY, GL_FOG_COORD_ARRAY_POINTER, 0, GL_FOG_COORD_ARRAY_TYPE,
     GL_FOG_COORD_ARRAY_STRIDE, GL_FOG_COORD_ARRAY_BUFFER_BINDING, 1},
    // Texture coordinates last: one per unit (client_limit selects each).
    {GL_TEXTURE_COORD_ARRAY, GL_TEXTURE_COORD_ARRAY_POINTER, GL_TEXTURE_COORD_ARRAY_SIZE,
     GL_TEXTURE_COORD_ARRAY_TYPE, GL_TEXTURE_COORD_ARRAY_STRIDE,
     GL_TEXTURE_COORD_ARRAY_BUFFER_BINDING, 0},
};

// The largest index one array can supply; INT64_MAX when it does not read client memory.
int64_t array_limit(const Harness& h, const Arr& a) {
  if (!glIsEnabled(a.cap) || get_int(a.binding) != 0) return INT64_MAX;
  void* p = nullptr;
  glGetPointerv(a.ptr, &p);
  const int64_t size = a.size ? get_int(a.size) : a.default_size;
  const int64_t tb = a.type ? type_bytes(static_cast<GLenum>(get_int(a.type))) : 1;
  const int64_t elem = size * tb;
  const int64_t stride_set = get_int(a.stride);
  const int64_t stride = stride_set != 0 ? stride_set : elem;
  const auto* u = static_cast<const uint8_t*>(p);
  // An array whose pointer is not in harness memory (an offset left behind by a deleted
  // buffer, or null) is the application's error in real GL: never draw with it.
  if (u < h.client || u >= h.client + kClientBytes || elem <= 0) return -1;
  const int64_t room = (h.client + kClientBytes) - u;
  if (room < elem) return -1;
  return stride > 0 ? (room - elem) / stride : INT64_MAX;
}

} // namespace

// The largest element index every enabled client-memory array can supply, -1 when one cannot
// supply any, INT64_MAX when no array reads client memory (Pineda bounds buffer-backed arrays
// itself, GL 1.5 §2.9). Reads Pineda's own array state so that PushClientAttrib and
// InterleavedArrays are followed exactly; texture coordinate arrays of every unit count.
int64_t client_limit(const Harness& h) {
  // Inside Begin/End queries return nothing, but a COMPILE_AND_EXECUTE list still compiles
  // draws (reading the arrays): the limit taken before the primitive holds until End.
  if (inside_begin()) return h.begin_limit;
  int64_t limit = INT64_MAX;
  constexpr size_t kTexArray = sizeof(kArrays) / sizeof(kArrays[0]) - 1;
  for (size_t k = 0; k < kTexArray; ++k)
    limit = std::min(limit, array_limit(h, kArrays[k]));
  const GLint active = get_int(GL_CLIENT_ACTIVE_TEXTURE);
  for (int u = 0; u < h.tex_coords; ++u) {
    glClientActiveTexture(GL_TEXTURE0 + u);
    limit = std::min(limit, array_limit(h, kArrays[kTexArray]));
  }
  glClientActiveTexture(static_cast<GLenum>(active));
  return limit;
}

// Pointer argument for a *Pointer call: an offset when an array buffer is bound (Pineda
// bounds it), otherwise a place in harness memory, or null.
const void* array_pointer(Harness& h, Input& in) {
  const uint16_t off = in.u16();
  if (get_int(GL_ARRAY_BUFFER_BINDING) != 0) return reinterpret_cast<const void*>(uintptr_t{off});
  if (off == 0xffff) return nullptr;
  return h.client + off % kClientBytes;
}

namespace {

void op_vertex(Input& in) {
  switch (in.u8() % 10) {
  case 0:
    glVertex2f(in.f(), in.f());
    break;
  case 1:
    glVertex3f(in.f(), in.f(), in.f());
    break;
  case 2:
    glVertex4f(in.f(), in.f(), in.f(), in.f());
    break;
  case 3:
    glVertex3d(in.d(), in.d(), in.d());
    break;
  case 4:
    glVertex2i(in.i(), in.i());
    break;
  case 5:
    glVertex4s(static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()),
               static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i()));
    break;
  case 6: {
    const GLfloat v[3] = {in.f(), in.f(), in.f()};
    glVertex3fv(v);
    break;
  }
  case 7: {
    const GLdouble v[4] = {in.d(), in.d(), in.d(), in.d()};
    glVertex4dv(v);
    break;
  }
  case 8: {
    const GLint v[3] = {in.i(), in.i(), in.i()};
    glVertex3iv(v);
    break;
  }
  default:
    glVertex2d(in.d(), in.d());
    break;
  }
}

void op_attrib(Input& in) {
  switch (in.u8() % 14) {
  case 0:
    glColor3f(in.f(), in.f(), in.f());
    break;
  case 1:
    glColor4f(in.f(), in.f(), in.f(), in.f());
    break;
  case 2:
    glColor4ub(in.u8(), in.u8(), in.u8(), in.u8());
    break;
  case 3:
    glColor3d(in.d(), in.d(), in.d());
    break;
  case 4:
    glColor4i(in.i(), in.i(), in.i(), in.i());
    break;
  case 5:
    glColor4us(in.u16(), in.u16(), in.u16(), in.u16());
    break;
  case 6:
    glColor3b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
              static_cast<GLbyte>(in.u8()));
    break;
  case 7:
    glNormal3f(in.f(), in.f(), in.f());
    break;
  case 8:
    glNormal3b(static_cast<GLbyte>(in.u8()), static_cast<GLbyte>(in.u8()),
               static_cast<GLbyte>(in.u8()));
    break;
  case 9:
    glTexCoord1f(in.f());
    break;
  case 10:
    glTexCoord2f(in.f(), in.f());
    break;
  case 11:
    glTexCoord4d(in.d(), in.d(), in.d(), in.d());
    break;
  case 12:
    glEdgeFlag(in.u8() & 1);
    break;
  default: {
    const GLuint v[4] = {in.u32(), in.u32(), in.u32(), in.u32()};
    glColor4uiv(v);
    break;
  }
  }
}

void op_rect(Input& in) {
  switch (in.u8() % 4) {
  case 0:
    glRectf(in.f(), in.f(), in.f(), in.f());
    break;
  case 1:
    glRecti(in.i(), in.i(), in.i(), in.i());
    break;
  case 2:
    glRectd(in.d(), in.d(), in.d(), in.d());
    break;
  default: {
    const GLshort a[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    const GLshort b[2] = {static_cast<GLshort>(in.i()), static_cast<GLshort>(in.i())};
    glRectsv(a, b);
    break;
  }
  }
}

void op_matrix(Input& in) {
  switch (in.u8() % 12) {
  case 0:
    glMatrixMode(in.e());
    break;
  case 1:
    glLoadIdentity();
    break;
  case 2: {
    GLfloat m[16];
    for (float& v : m)
      v = in.f();
    glLoadMatrixf(m);
    break;
  }
  case 3: {
    GLdouble m[16];
    for (double& v : m)
      v = in.d();
    glMultTransposeMatrixd(m);
    break;
  }
  case 4:
    glRotatef(in.f(), in.f(), in.f(), in.f());
    break;
  case 5:
    glTranslated(in.d(), in.d(), in.d());
    break;
  case 6:
    glScalef(in.f(), in.f(), in.f());
    break;
  case 7:
    glFrustum(in.d(), in.d(), in.d(), in.d(), in.d(), in.d());
    break;
  case 8:
    glOrtho(in.d(), in.d(), in.d(), in.d(), in.d(), in.d());
    break;
  case 9:
    glPushMatrix();
    break;
  case 10:
    glPopMatrix();
    break;
  default: {
    GLfloat m[16];
    for (float& v : m)
      v = in.f();
    glMultMatrixf(m);
    break;
  }
  }
}

void op_state(Input& in) {
  switch (in.u8() % 24) {
  case 0:
    glEnable(in.e());
    break;
  case 1:
    glDisable(in.e());
    break;
  case 2:
    glViewport(in.i(), in.i(), in.i(), in.i());
    break;
  case 3:
    glDepthRange(in.d(), in.d());
    break;
  case 4: {
    const GLdouble eq[4] = {in.d(), in.d(), in.d(), in.d()};
    glClipPlane(in.e(), eq);
    break;
  }
  case 5: {
    GLdouble eq[4];
    glGetClipPlane(in.e(), eq);
    break;
  }
  case 6:
    glFrontFace(in.e());
    break;
  case 7:
    glCullFace(in.e());
    break;
  case 8:
    glPolygonMode(in.e(), in.e());
    break;
  case 9:
    glShadeModel(in.e());
    break;
  case 10:
    glDepthFunc(in.e());
    break;
  case 11:
    glDepthMask(in.u8() & 1);
    break;
  case 12:
    glClearDepth(in.d());
    break;
  case 13:
    glBlendFunc(in.e(), in.e());
    break;
  case 14:
    glBlendFuncSeparate(in.e(), in.e(), in.e(), in.e());
    break;
  case 15:
    glBlendEquation(in.e());
    break;
  case 16:
    glBlendColor(in.f(), in.f(), in.f(), in.f());
    break;
  case 17:
    glClear(in.u32());
    break;
  case 18:
    glClearColor(in.f(), in.f(), in.f(), in.f());
    break;
  case 19:
    glClearStencil(in.i());
    break;
  case 20:
    glColorMask(in.u8() & 1, in.u8() & 1, in.u8() & 1, in.u8() & 1);
    break;
  case 21:
    glPixelStorei(in.e(), in.i());
    break;
  case 22:
    glPixelStoref(in.e(), in.f());
    break;
  default:
    glHint(in.e(), in.e());
    break;
  }
}

void op_query(Input& in) {
  switch (in.u8() % 8) {
  case 0: {
    GLboolean v[16];
    glGetBooleanv(in.e(), v);
    break;
  }
  case 1: {
    GLint v[16];
    glGetIntegerv(in.e(), v);
    break;
  }
  case 2: {
    GLfloat v[16];
    glGetFloatv(in.e(), v);
    break;
  }
  case 3: {
    GLdouble v[16];
    glGetDoublev(in.e(), v);
    break;
  }
  case 4: {
    const GLubyte* s = glGetString(in.e());
    if (s != nullptr && std::strlen(reinterpret_cast<const char*>(s)) > 100000) std::abort();
    break;
  }
  case 5:
    glIsEnabled(in.e());
    break;
  case 6: {
    void* p = nullptr;
    glGetPointerv(in.e(), &p);
    break;
  }
  default:
    glGetError();
    break;
  }
}

void op_arrays(Harness& h, Input& in) {
  switch (in.u8() % 10) {
  case 0: {
    const GLint size = in.i();
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glVertexPointer(size, type, stride, array_pointer(h, in));
    break;
  }
  case 1: {
    const GLint size = in.i();
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glColorPointer(size, type, stride, array_pointer(h, in));
    break;
  }
  case 2: {
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glNormalPointer(type, stride, array_pointer(h, in));
    break;
  }
  case 3: {
    const GLint size = in.i();
    const GLenum type = in.e();
    const GLsizei stride = in.i();
    glTexCoordPointer(size, type, stride, array_pointer(h, in));
    break;
  }
  case 4: {
    const GLsizei stride = in.i();
    glEdgeFlagPointer(stride, array_pointer(h, in));
    break;
  }
  case 5:
    glEnableClientState(in.e());
    break;
  case 6:
    glDisableClientState(in.e());
    break;
  case 7: {
    const GLenum fmt = in.e();
    const GLsizei stride = in.i();
    glInterleavedArrays(fmt, stride, array_pointer(h, in));
    break;
  }
  case 8:
    glPushClientAttrib(in.u32());
    break;
  default:
    glPopClientAttrib();
    break;
  }
}

// Client memory contents: a run of floats (the common vertex type) or raw bytes.
void op_fill_client(Harness& h, Input& in) {
  const size_t off = in.u16() % kClientBytes;
  const size_t n = in.u8();
  if (in.u8() & 1) {
    for (size_t k = 0; k < n && off + 4 * k + 4 <= kClientBytes; ++k) {
      const float v = in.f();
      std::memcpy(h.client + off + 4 * k, &v, 4);
    }
  } else {
    for (size_t k = 0; k < n && off + k < kClientBytes; ++k)
      h.client[off + k] = in.u8();
  }
}

// Largest index in `count` client indices of `type` at p, or -1 when they do not fit.
int64_t max_client_index(const Harness& h, const void* p, int64_t count, GLenum type) {
  const int64_t tb = type_bytes(type);
  const auto* u = static_cast<const uint8_t*>(p);
  if (tb == 0 || count <= 0) return 0;
  if (u < h.client || u + count * tb > h.client + kClientBytes) return -1;
  int64_t mx = 0;
  for (int64_t k = 0; k < count; ++k) {
    uint32_t v = 0;
    if (tb == 1)
      v = u[k];
    else if (tb == 2) {
      uint16_t s;
      std::memcpy(&s, u + 2 * k, 2);
      v = s;
    } else
      std::memcpy(&v, u + 4 * k, 4);
    if (v > mx) mx = v;
  }
  return mx;
}

// May Pineda be asked to draw `count` indices read from `indices`? With an element buffer,
// Pineda bounds the index read; the largest index is then read back through the GL.
bool elements_ok(const Harness& h, int64_t count, GLenum type, const void* indices) {
  if (count > kMaxDrawCount) return false;
  if (count <= 0) return true;
  const int64_t limit = client_limit(h);
  if (get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING) == 0) {
    const int64_t mx = max_client_index(h, indices, count, type);
    return mx >= 0 && mx <= limit;
  }
  if (limit == INT64_MAX) return true;
  const int64_t tb = type_bytes(type);
  const auto off = static_cast<int64_t>(reinterpret_cast<uintptr_t>(indices));
  GLint mapped = 0, have = 0;
  glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_MAPPED, &mapped);
  glGetBufferParameteriv(GL_ELEMENT_ARRAY_BUFFER, GL_BUFFER_SIZE, &have);
  // Unknown types and mapped buffers are refused by Pineda before any index is read.
  if (tb == 0 || mapped) return true;
  if (off + count * tb > have) return true; // Pineda refuses the out-of-range read
  std::vector<uint8_t> copy(static_cast<size_t>(count * tb));
  glGetBufferSubData(GL_ELEMENT_ARRAY_BUFFER, off, count * tb, copy.data());
  int64_t mx = 0;
  for (int64_t k = 0; k < count; ++k) {
    uint32_t v = 0;
    std::memcpy(&v, copy.data() + k * tb, static_cast<size_t>(tb));
    if (tb == 1) v &= 0xff;
    if (tb == 2) v &= 0xffff;
    if (v > mx) mx = v;
  }
  return mx <= limit && limit >= 0;
}

// An index pointer: an offset into the bound element buffer, or harness memory.
const void* index_pointer(Harness& h, Input& in) {
  const uint16_t off = in.u16();
  if (get_int(GL_ELEMENT_ARRAY_BUFFER_BINDING) != 0)
    return reinterpret_cast<const void*>(uintptr_t{off});
  return h.client + off % kClientBytes;
}

void op_draw(Harness& h, Input& in) {
  const uint8_t kind = in.u8() % 6;
  const GLenum mode = in.e();
  switch (kind) {
  case 0: {
    const GLint first = in.i();
    const GLsizei count = in.i();
    const int64_t limit = client_limit(h);
    if (count > kMaxDrawCount) return;
    if (count > 0 && first >= 0 && int64_t{first} + count - 1 > limit) return;
    glDrawArrays(mode, first, count);
    break;
  }
  case 1:
  case 2: {
    const GLsizei count = in.i();
    const GLenum type = in.e();
    const void* idx = index_pointer(h, in);
    const GLuint start = in.u32(), end = in.u32();
    if (!elements_ok(h, count, type, idx)) return;
    if (kind == 1)
      glDrawElements(mode, count, type, idx);
    else
      glDrawRangeElements(mode, start, end, count, type, idx);
    break;
  }
  case 3: {
    GLint first[4];
    GLsizei count[4];
    const GLsizei n = in.u8() % 5;
    const int64_t limit = client_limit(h);
    for (int k = 0; k < n; ++k) {
      first[k] = in.i();
      count[k] = in.i();
      if (count[k] > kMaxDrawCount) return;
      if (count[k] > 0 && first[k] >= 0 && int64_t{first[k]} + count[k] - 1 > limit) return;
    }
    glMultiDrawArrays(mode, first, count, n);
    break;
  }
  case 4: {
    GLsizei count[4];
    const void* idx[4];
    const GLsizei n = in.u8() % 5;
    const GLenum type = in.e();
    for (int k = 0; k < n; ++k) {
      count[k] = in.i();
      idx[k] = index_pointer(h, in);
      if (!elements_ok(h, count[k], type, idx[k])) return;
    }
    glMultiDrawElements(mode, count, type, idx, n);
    break;
  }
  default: {
    const GLint i = in.i();
    if (i >= 0 && i > client_limit(h)) return;
    glArrayElement(i);
    break;
  }
  }
}

void op_buffers(Harness& h, Input& in) {
  switch (in.u8() % 10) {
  case 0: {
    GLuint names[4] = {};
    const GLsizei n = in.u8() % 5;
    glGenBuffers(n, names);
    break;
  }
  case 1: {
    const GLuint names[2] = {in.u8() % 8u, in.u8() % 8u};
    glDeleteBuffers(1 + (in.u8() & 1), names);
    break;
  }
  case 2:
    glBindBuffer(in.e(), in.u8() % 8u);
    break;
  case 3:
    glIsBuffer(in.u8() % 8u);
    break;
  case 4: {
    const GLenum target = in.e();
    const int64_t size = in.i();
    const GLenum usage = in.e();
    if (size > kMaxBufferBytes) return;
    // Data from harness memory when it holds that much, otherwise an uninitialized store.
    const void* data =
        (size > 0 && size <= static_cast<int64_t>(kClientBytes)) ? h.client : nullptr;
    glBufferData(target, static_cast<GLsizeiptr>(size), data, usage);
    break;
  }
  case 5: {
    const GLenum target = in.e();
    const GLintptr off = in.i();
    const int64_t size = in.i();
    // Source bytes only where harness memory backs them; larger sizes get null (no read).
    const void* data =
        (size > 0 && size <= static_cast<int64_t>(kClientBytes)) ? h.client : nullptr;
    glBufferSubData(target, off, static_cast<GLsizeiptr>(size), data);
    break;
  }
  case 6: {
    const GLenum target = in.e();
    const GLintptr off = in.i();
    const int64_t size = in.i();
    GLint have = 0;
    glGetBufferParameteriv(target, GL_BUFFER_SIZE, &have);
    glGetError();
    // A legal range gets exactly its size; an illegal one a single byte Pineda must not touch.
    const bool legal = off >= 0 && size >= 0 && off + size <= have;
    void* dst = std::malloc(legal && size > 0 ? static_cast<size_t>(size) : 1);
    glGetBufferSubData(target, off, static_cast<GLsizeiptr>(size), dst);
    std::free(dst);
    break;
  }
  case 7: {
    const GLenum target = in.e();
    void* p = glMapBuffer(target, in.e());
    GLint size = 0;
    glGetBufferParameteriv(target, GL_BUFFER_SIZE, &size);
    if (p != nullptr && size > 0) std::memset(p, in.u8(), static_cast<size_t>(size));
    break;
  }
  case 8:
    glUnmapBuffer(in.e());
    break;
  default: {
    GLint v = 0;
    void* p = nullptr;
    const GLenum target = in.e();
    glGetBufferParameteriv(target, in.e(), &v);
    glGetBufferPointerv(target, in.e(), &p);
    break;
  }
  }
}

void op_osmesa(Harness& h, Input& in) {
  switch (in.u8() % 6) {
  case 0: {
    const int w = 1 + in.u8() % kMaxSurface;
    h.make_current(w, 1 + in.u8() % kMaxSurface, h.row_length);
    break;
  }
  case 1: {
    // Row length: new memory laid out for the new rows first, then the new row length.
    const int v = in.u8() % (2 * kMaxSurface);
    h.make_current(h.width, h.height, v);
    OSMesaPixelStore(OSMESA_ROW_LENGTH, v);
    break;
  }
  case 2:
    OSMesaPixelStore(OSMESA_Y_UP, in.u8() & 1);
    break;
  case 3: {
    GLint v = 0;
    OSMesaGetIntegerv(in.e(), &v);
    break;
  }
  case 4: {
    GLint w = 0, hh = 0, fmt = 0;
    void* p = nullptr;
    OSMesaGetColorBuffer(h.ctx, &w, &hh, &fmt, &p);
    OSMesaGetDepthBuffer(h.ctx, &w, &hh, &fmt, &p);
    break;
  }
  default:
    h.create(in);
    break;
  }
}

} // namespace
} // namespace pineda::fuzz

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace pineda::fuzz;
  Input in(data, size);
  Harness h;
  h.client = static_cast<uint8_t*>(std::calloc(kClientBytes, 1));
  h.create(in);
  // Bounded work per input: each op costs at most one draw of kMaxDrawCount vertices, one
  // image of kMaxImageBytes or one evaluator mesh.
  // GL_FUZZER_TRACE=1 prints each opcode and its first argument byte, to read a crash input.
  static const bool trace = std::getenv("GL_FUZZER_TRACE") != nullptr;
  for (int steps = 0; steps < 512 && !in.empty(); ++steps) {
    const int op = in.u8() % 32;
    if (trace)
      std::fprintf(stderr, "step %d op %d next byte %d gaps %s\n", steps, op, in.peek(),
                   h.gaps_intact() ? "intact" : "BROKEN");
    switch (op) {
    case 0: {
      const GLenum mode = in.e();
      before_begin(h);
      glBegin(mode);
      break;
    }
    case 1:
      glEnd();
      break;
    case 2:
      op_vertex(in);
      break;
    case 3:
      op_vertex_variants(h, in);
      break;
    case 4:
      op_attrib(in);
      break;
    case 5:
      op_rect(in);
      break;
    case 6:
      op_matrix(in);
      break;
    case 7:
    case 8:
      op_state(in);
      break;
    case 9:
      op_query(in);
      break;
    case 10:
      op_read_pixels(h, in);
      break;
    case 11:
      op_arrays(h, in);
      break;
    case 12:
      op_fill_client(h, in);
      break;
    case 13:
      op_draw(h, in);
      break;
    case 14:
      op_buffers(h, in);
      break;
    case 15:
      op_osmesa(h, in);
      break;
    case 16:
    case 17:
      op_pixels(h, in);
      break;
    case 18:
    case 19:
      op_texture_image(h, in);
      break;
    case 20:
    case 21:
      op_texture_state(h, in);
      break;
    case 22:
    case 23:
      op_lists(h, in);
      break;
    case 24:
      op_select_feedback(h, in);
      break;
    case 25:
      op_eval(h, in);
      break;
    case 26:
      op_lighting(h, in);
      break;
    case 27:
      op_fragment_misc(h, in);
      break;
    case 28:
      op_attrib2(h, in);
      break;
    case 29:
      op_queries2(h, in);
      break;
    case 30:
      op_raster_pos(h, in);
      break;
    default:
      op_other_variants(h, in);
      break;
    }
  }
  return 0;
}
