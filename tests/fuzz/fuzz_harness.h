// The state the libFuzzer harness keeps across the calls of one input, and the helpers its
// operation files share (gl_fuzzer.cpp: geometry, arrays, buffers, OSMesa; fuzz_ops_pixel.cpp:
// pixel paths and texture images; fuzz_ops_state.cpp: everything else of GL 1.5).
//
// The harness owns all client memory it hands to Pineda. A pointer argument gets a heap block
// of exactly the bytes GL may read or write for the call's arguments (computed here from the
// spec, never from Pineda), so that AddressSanitizer's redzones sit at its ends; memory GL keeps
// using after the call (select and feedback buffers, array pointers) lives as long as the input.
#pragma once

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "fuzz_input.h"

namespace pineda::fuzz {

constexpr size_t kClientBytes = 1 << 16;     // vertex array memory ("arena")
constexpr int64_t kMaxDrawCount = 4096;      // vertices per draw the harness lets through
constexpr int64_t kMaxBufferBytes = 1 << 20; // buffer objects the harness lets Pineda allocate
constexpr int64_t kMaxImageBytes = 1 << 20;  // client images handed to pixel commands
constexpr int kMaxSurface = 64;              // drawable width and height
constexpr uint8_t kGapPattern = 0xA5;

// The pixel-store state one direction (pack or unpack) of a call uses (GL 2.1 Tables 3.1,
// 4.5).
struct Store {
  int64_t row_length = 0, skip_rows = 0, skip_pixels = 0, alignment = 4;
  int64_t image_height = 0, skip_images = 0;
};

struct Harness {
  OSMesaContext ctx = nullptr;
  GLenum format = OSMESA_RGBA;
  int bpp = 4;
  // The drawable: exact-size heap block so that ASan sees any write past either end.
  uint8_t* color = nullptr;
  size_t color_bytes = 0;
  int width = 0, height = 0;
  int row_length = 0; // OSMESA_ROW_LENGTH as last set by the harness
  uint8_t* client = nullptr;
  // Inside glBegin queries are errors, so the array limit that ArrayElement needs is taken
  // just before anything that may begin a primitive (Begin, CallList, CallLists); array state
  // cannot change until End (GL 2.1 §2.6.3).
  // The same holds for the pixel-store state (unpack, pack), which image commands compiled
  // into a COMPILE_AND_EXECUTE list inside Begin/End still use.
  int64_t begin_limit = -1;
  Store begin_store[2];
  // Display lists: calls recorded into the list being compiled. One per list at most, so that
  // executing lists is a chain, not a tree (a tree of nested CallLists grows exponentially
  // with MAX_LIST_NESTING: legal GL, but no execution would finish).
  // Whether a list is being compiled (queries fail inside a Begin that COMPILE_AND_EXECUTE
  // executed, so the harness follows NewList/EndList itself).
  bool compiling = false;
  int list_calls = 0;
  // Select and feedback buffers: GL writes them until RenderMode returns to RENDER, maybe
  // after another SelectBuffer/FeedbackBuffer call failed, so they live until the input ends.
  std::vector<void*> keep;
  // GL_MAX_TEXTURE_SIZE etc., read at context creation to keep texture sizes small.
  int max_tex = 0, max_3d = 0, max_cube = 0, tex_coords = 1;

  ~Harness();
  int row_pixels() const { return row_length > width ? row_length : width; }
  bool gaps_intact() const;
  void check_gaps() const;
  void make_current(int w, int h, int row_len);
  void create(Input& in);
};

inline GLint get_int(GLenum pname) {
  GLint v[16] = {};
  glGetIntegerv(pname, v);
  return v[0];
}

// GL_FUZZER_TRACE=1: print each operation (and image extents) to read a crash input.
inline bool tracing() {
  static const bool on = std::getenv("GL_FUZZER_TRACE") != nullptr;
  return on;
}

// True between a successful glBegin and glEnd, which a display list may also contain: every
// query then fails without writing its result.
inline bool inside_begin() {
  GLint v[16] = {-12345};
  glGetIntegerv(GL_MATRIX_MODE, v);
  return v[0] == -12345;
}

inline int64_t type_bytes(GLenum type) {
  switch (type) {
  case GL_BYTE:
  case GL_UNSIGNED_BYTE:
    return 1;
  case GL_SHORT:
  case GL_UNSIGNED_SHORT:
    return 2;
  case GL_INT:
  case GL_UNSIGNED_INT:
  case GL_FLOAT:
    return 4;
  case GL_DOUBLE:
    return 8;
  default:
    return 0;
  }
}

// An exact-size heap block for one call, its bytes copied from the arena (the fuzzer fills
// the arena with op_fill_client) so that the data GL reads are under the fuzzer's control.
class Block {
public:
  Block(const Harness& h, int64_t bytes, size_t arena_offset = 0)
      : size_(bytes > 0 ? static_cast<size_t>(bytes) : 1) {
    p_ = static_cast<uint8_t*>(std::malloc(size_));
    for (size_t k = 0; k < size_; ++k)
      p_[k] = h.client[(arena_offset + k) % kClientBytes];
  }
  ~Block() { std::free(p_); }
  Block(const Block&) = delete;
  Block& operator=(const Block&) = delete;
  template <typename T> T* as() { return reinterpret_cast<T*>(p_); }
  void* get() { return p_; }

private:
  size_t size_;
  uint8_t* p_;
};

// Values of a `count`-value vector argument, exact size, from the input.
struct Floats {
  Floats(const Harness& h, Input& in, int64_t count) : b(h, count * 4) {
    for (int64_t k = 0; k < count; ++k)
      b.as<GLfloat>()[k] = in.f();
  }
  GLfloat* get() { return b.as<GLfloat>(); }
  Block b;
};
struct Ints {
  Ints(const Harness& h, Input& in, int64_t count) : b(h, count * 4) {
    for (int64_t k = 0; k < count; ++k)
      b.as<GLint>()[k] = in.i();
  }
  GLint* get() { return b.as<GLint>(); }
  Block b;
};

// The six commands of a two-enum parameter family: glFoo{f,i}, glFoo{f,i}v and glGetFoo{f,i}v
// (Light, TexParameter, TexEnv).
struct ParamFamily {
  void(GLAPIENTRY* f)(GLenum, GLenum, GLfloat);
  void(GLAPIENTRY* i)(GLenum, GLenum, GLint);
  void(GLAPIENTRY* fv)(GLenum, GLenum, const GLfloat*);
  void(GLAPIENTRY* iv)(GLenum, GLenum, const GLint*);
  void(GLAPIENTRY* get_fv)(GLenum, GLenum, GLfloat*);
  void(GLAPIENTRY* get_iv)(GLenum, GLenum, GLint*);
};

// One call of `fam` for target t and pname p, chosen by the input: the scalar forms take a
// float from the input or `int_value`, the vector and query forms exactly `count` values.
inline void call_param(const Harness& h, Input& in, const ParamFamily& fam, GLenum t, GLenum p,
                       int64_t count, GLint int_value) {
  switch (in.u8() % 5) {
  case 0:
    fam.f(t, p, in.f());
    break;
  case 1:
    fam.i(t, p, int_value);
    break;
  case 2: {
    Floats v(h, in, count);
    fam.fv(t, p, v.get());
    break;
  }
  case 3: {
    Ints v(h, in, count);
    fam.iv(t, p, v.get());
    break;
  }
  default: {
    Block v(h, count * 4);
    if (in.u8() & 1)
      fam.get_fv(t, p, v.as<GLfloat>());
    else
      fam.get_iv(t, p, v.as<GLint>());
    break;
  }
  }
}

// A count of names (Gen*/Delete*/Prioritize...): small, sometimes negative.
inline GLsizei name_count(Input& in) {
  const uint8_t v = in.u8();
  return v >= 250 ? -static_cast<GLsizei>(v - 249) : v % 9;
}

// A list/texture/query name: small most of the time, sometimes any 32-bit value.
inline GLuint name(Input& in) {
  const uint8_t v = in.u8();
  return v < 240 ? v % 12 : in.u32();
}

// `n` names from the input, exact size (Delete*, PrioritizeTextures, AreTexturesResident).
struct Names {
  Names(const Harness& h, Input& in, GLsizei n) : b(h, n > 0 ? n * 4 : 0) {
    for (GLsizei k = 0; k < n; ++k)
      b.as<GLuint>()[k] = name(in);
  }
  GLuint* get() { return b.as<GLuint>(); }
  Block b;
};

// The largest element index every enabled client-memory array can supply (gl_fuzzer.cpp).
int64_t client_limit(const Harness& h);
// The pixel-store state of one direction, read back from the GL (fuzz_ops_pixel.cpp).
Store read_store(bool pack);
// Takes what the harness needs to know inside a primitive, before a command that may begin
// one (Begin, CallList, CallLists) when none is under way.
inline void before_begin(Harness& h) {
  if (inside_begin()) return;
  h.begin_limit = client_limit(h);
  h.begin_store[0] = read_store(false);
  h.begin_store[1] = read_store(true);
}
// Pointer argument for a *Pointer call (gl_fuzzer.cpp).
const void* array_pointer(Harness& h, Input& in);

// Operation groups of the other files, each decoding one sub-operation.
void op_read_pixels(Harness& h, Input& in);
void op_pixels(Harness& h, Input& in);
void op_texture_image(Harness& h, Input& in);
void op_texture_state(Harness& h, Input& in);
void op_lists(Harness& h, Input& in);
void op_select_feedback(Harness& h, Input& in);
void op_eval(Harness& h, Input& in);
void op_lighting(Harness& h, Input& in);
void op_fragment_misc(Harness& h, Input& in);
void op_attrib2(Harness& h, Input& in);
void op_queries2(Harness& h, Input& in);
void op_raster_pos(Harness& h, Input& in);
void op_vertex_variants(Harness& h, Input& in);
void op_other_variants(Harness& h, Input& in);

} // namespace pineda::fuzz
