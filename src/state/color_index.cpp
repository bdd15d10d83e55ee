// Colour-index state in an RGBA-only GL: the current index (GL 2.1 §2.7), the index array
// (§2.8), the index write mask (§4.2.2) and clear value (§4.2.3). Pineda has no colour-index
// visuals, so these commands only set state: "the current index is used only in color index
// mode" (§2.7), and the index mask and clear value apply to colour-index buffers only
// (§4.2.2-§4.2.3). Their display-list savers are here too (src/api/dlist_savers.txt).
#include <cmath>
#include <cstring>

#include "state/api_util.h"
#include "dispatch.h"

namespace pineda {

namespace {

// §2.7: Index may be called at any time, also between Begin and End, and converts its
// argument to floating point without normalization (Mesa llvmpipe keeps e.g. Indexub(200) as
// 200.0).
void set_index(float index) {
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  ctx->current.index = index;
}

void replay_index(const void* p) {
  float index;
  std::memcpy(&index, p, sizeof index);
  set_index(index);
}

// §5.4: Index is compiled as an ordinary command (the current index is not one of the
// attributes compiled vertex blocks carry), so a list sets it in order when it executes.
void save_index(float index) {
  if (dlist_record(&replay_index, &index, sizeof index)) set_index(index);
}

} // namespace

namespace exec {

void GLAPIENTRY Indexs(GLshort c) {
  set_index(float(c));
}
void GLAPIENTRY Indexi(GLint c) {
  set_index(float(c));
}
void GLAPIENTRY Indexf(GLfloat c) {
  set_index(c);
}
void GLAPIENTRY Indexd(GLdouble c) {
  set_index(float(c));
}
void GLAPIENTRY Indexub(GLubyte c) {
  set_index(float(c));
}
// A null vector is ignored, as everywhere in Pineda.
void GLAPIENTRY Indexsv(const GLshort* c) {
  if (c != nullptr) set_index(float(*c));
}
void GLAPIENTRY Indexiv(const GLint* c) {
  if (c != nullptr) set_index(float(*c));
}
void GLAPIENTRY Indexfv(const GLfloat* c) {
  if (c != nullptr) set_index(*c);
}
void GLAPIENTRY Indexdv(const GLdouble* c) {
  if (c != nullptr) set_index(float(*c));
}
void GLAPIENTRY Indexubv(const GLubyte* c) {
  if (c != nullptr) set_index(float(*c));
}

// §2.8: type UNSIGNED_BYTE, SHORT, INT, FLOAT or DOUBLE (Table 2.4), a negative stride is
// INVALID_VALUE. The array is never read: indices have no effect in RGBA mode.
void GLAPIENTRY IndexPointer(GLenum type, GLsizei stride, const void* pointer) {
  PINEDA_CTX_OUTSIDE("glIndexPointer");
  if (type != GL_UNSIGNED_BYTE && type != GL_SHORT && type != GL_INT && type != GL_FLOAT &&
      type != GL_DOUBLE)
    return record_error(ctx, GL_INVALID_ENUM, "glIndexPointer", type);
  if (stride < 0) return record_error(ctx, GL_INVALID_VALUE, "glIndexPointer");
  ClientArray& a = ctx->arrays.index;
  a.size = 1;
  a.type = type;
  a.stride = stride;
  a.pointer = pointer;
  a.buffer = ctx->arrays.array_buffer;
}

// §4.2.2: the low bits of the mask apply to index buffers, of which there are none; all 32
// bits are kept for the query (Mesa llvmpipe returns them as given).
void GLAPIENTRY IndexMask(GLuint mask) {
  PINEDA_CTX_OUTSIDE("glIndexMask");
  ctx->color_buffer.index_writemask = mask;
}

// §4.2.3: the index is converted to fixed point and its integer part masked to the index
// buffer's bits; with no index buffer Pineda keeps the integer part (truncated toward zero as
// Mesa llvmpipe does), clamped to the int range so that the conversion is defined.
void GLAPIENTRY ClearIndex(GLfloat c) {
  PINEDA_CTX_OUTSIDE("glClearIndex");
  const double t = std::trunc(double(c));
  int32_t v = 0;
  if (t >= 2147483647.0)
    v = 2147483647;
  else if (t <= -2147483648.0)
    v = -2147483647 - 1;
  else if (t == t)
    v = int32_t(t);
  ctx->color_buffer.index_clear = v;
}

} // namespace exec

namespace saver {

void GLAPIENTRY Indexs(GLshort c) {
  save_index(float(c));
}
void GLAPIENTRY Indexi(GLint c) {
  save_index(float(c));
}
void GLAPIENTRY Indexf(GLfloat c) {
  save_index(c);
}
void GLAPIENTRY Indexd(GLdouble c) {
  save_index(float(c));
}
void GLAPIENTRY Indexub(GLubyte c) {
  save_index(float(c));
}
void GLAPIENTRY Indexsv(const GLshort* c) {
  if (c != nullptr) save_index(float(*c));
}
void GLAPIENTRY Indexiv(const GLint* c) {
  if (c != nullptr) save_index(float(*c));
}
void GLAPIENTRY Indexfv(const GLfloat* c) {
  if (c != nullptr) save_index(*c);
}
void GLAPIENTRY Indexdv(const GLdouble* c) {
  if (c != nullptr) save_index(float(*c));
}
void GLAPIENTRY Indexubv(const GLubyte* c) {
  if (c != nullptr) save_index(float(*c));
}

} // namespace saver
} // namespace pineda
