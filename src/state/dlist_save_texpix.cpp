// Display-list savers (GL 2.1 §5.4) for the texture, fog, point-parameter and pixel commands
// whose arguments point at data of computed size (gl.xml len="COMPSIZE(...)"): the values or
// the client image are copied when the command is compiled, so the list keeps working after
// the application reuses its memory.
//
// Images (TexImage*, TexSubImage*, DrawPixels, Bitmap, PolygonStipple) are unpacked with the
// pixel-store state of compile time (§5.4: "the client state ... is taken at the time the list
// is compiled"). The list keeps the client bytes the unpack state spans together with that
// state, and at execution unpacks them under it: the same result, without a second pixel
// format. Pixel transfer operations apply at execution, as for any other compiled command.
// Proxy texture images are not compiled but executed at once (§5.4).
#include <algorithm>
#include <cstring>
#include <memory>
#include <new>
#include <vector>

#include "state/api_util.h"
#include "dispatch.h"
#include "pixel/unpack.h"
#include "state/dlist_internal.h"
#include "state/pixel_buffer.h"
#include "state/texture_internal.h"

namespace pineda {

namespace {

// Records `head` followed by `size` bytes of `data` (a header and its array or image);
// returns whether the command must also execute now (dlist_record).
bool record_with_data(void (*replay)(const void*), const void* head, size_t head_size,
                      const void* data, size_t size) {
  const auto buf = std::make_unique<char[]>(head_size + size);
  std::memcpy(buf.get(), head, head_size);
  if (size != 0) std::memcpy(buf.get() + head_size, data, size);
  return dlist_record(replay, buf.get(), head_size + size);
}

// ---- parameter vectors --------------------------------------------------------------------

template <typename T> struct Vec4Args {
  GLenum a, b; // target or coordinate, and pname (unused leading fields stay 0)
  T v[4];
};

// Number of values each command's parameter vector holds for `pname` (GL 2.1 §3.8.13,
// §2.11.4, §3.8.4, §3.10, §3.3): a vector is read only as far as its command reads it, so that
// a pname another command takes four values for (TEXTURE_ENV_COLOR given to TexParameterfv)
// does not read past a one-value array.
int env_count(GLenum pname) {
  return pname == GL_TEXTURE_ENV_COLOR ? 4 : 1;
}
int gen_count(GLenum pname) {
  if (pname == GL_OBJECT_PLANE || pname == GL_EYE_PLANE) return 4;
  return pname == GL_TEXTURE_GEN_MODE ? 1 : 0;
}
int tex_param_count(GLenum pname) {
  return pname == GL_TEXTURE_BORDER_COLOR ? 4 : 1;
}
int fog_count(GLenum pname) {
  return pname == GL_FOG_COLOR ? 4 : 1;
}
int point_count(GLenum pname) {
  return pname == GL_POINT_DISTANCE_ATTENUATION ? 3 : 1;
}

template <typename T, void(GLAPIENTRY* Fn)(GLenum, GLenum, const T*)> void replay2(const void* p) {
  Vec4Args<T> a;
  std::memcpy(&a, p, sizeof a);
  Fn(a.a, a.b, a.v);
}

template <typename T, void(GLAPIENTRY* Fn)(GLenum, const T*)> void replay1(const void* p) {
  Vec4Args<T> a;
  std::memcpy(&a, p, sizeof a);
  Fn(a.b, a.v);
}

// Compiles a (a, pname, params) command; returns whether it must also execute now. A null
// pointer compiles nothing (the command then does nothing, as pineda::exec treats it).
template <typename T>
bool save_vec(void (*replay)(const void*), int (*count)(GLenum), GLenum a, GLenum pname,
              const T* params) {
  if (compiling_list() == nullptr) return true;
  if (params == nullptr) return false;
  Vec4Args<T> args{a, pname, {}};
  std::copy(params, params + count(pname), args.v);
  return dlist_record(replay, &args, sizeof args);
}

// ---- arrays of values ---------------------------------------------------------------------

// Larger than any texture-name array a valid call can pass; a larger count is
// an error of the command, generated when the list executes.
constexpr GLsizei kMaxCopiedValues = 1 << 16;

struct alignas(16) PixelMapHeader {
  GLenum map;
  GLsizei mapsize;
  GLsizei copied;
};

template <typename T, void(GLAPIENTRY* Fn)(GLenum, GLsizei, const T*)>
void replay_pixel_map(const void* p) {
  PixelMapHeader h;
  std::memcpy(&h, p, sizeof h);
  std::vector<T> values(static_cast<size_t>(h.copied));
  // memcpy of nothing still needs valid pointers, which an empty vector has not.
  if (!values.empty())
    std::memcpy(values.data(), static_cast<const char*>(p) + sizeof h, values.size() * sizeof(T));
  // The values are in the list, whatever buffer is bound to PIXEL_UNPACK_BUFFER now.
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  const GLuint saved_buffer = ctx->pixel_store.unpack_buffer;
  ctx->pixel_store.unpack_buffer = 0;
  Fn(h.map, h.mapsize, h.copied > 0 ? values.data() : nullptr);
  ctx->pixel_store.unpack_buffer = saved_buffer;
}

template <typename T, void(GLAPIENTRY* Fn)(GLenum, GLsizei, const T*)>
bool save_pixel_map(GLenum map, GLsizei mapsize, const T* values, const char* func) {
  Context* ctx = compiling_list();
  if (ctx == nullptr) return true;
  // A size beyond MAX_PIXEL_MAP_TABLE is an error when the list executes (§3.6.3), so the
  // values are not read: the array may well be shorter than the size.
  const bool sized = mapsize <= kMaxPixelMapTable;
  const GLsizei count = sized ? std::max<GLsizei>(mapsize, 0) : 0;
  // With a pixel unpack buffer bound the list keeps the buffer's values of compile time.
  if (sized && unpack_buffer_bound(ctx)) {
    const void* src = nullptr;
    if (!unpack_memory_quiet(ctx, values, size_t(count) * sizeof(T), sizeof(T), &src)) {
      record_error_at_execution(ctx, GL_INVALID_OPERATION, func);
      return list_executes(ctx);
    }
    values = static_cast<const T*>(src);
  }
  const GLsizei copied = values == nullptr ? 0 : count;
  const PixelMapHeader h{map, mapsize, copied};
  return record_with_data(&replay_pixel_map<T, Fn>, &h, sizeof h, values,
                          static_cast<size_t>(copied) * sizeof(T));
}

void GLAPIENTRY draw_buffers_call(GLenum, GLsizei n, const GLenum* bufs) {
  exec::DrawBuffers(n, bufs);
}

struct alignas(16) PrioritizeHeader {
  GLsizei n;
  GLsizei copied;
};

void replay_prioritize(const void* p) {
  PrioritizeHeader h;
  std::memcpy(&h, p, sizeof h);
  const size_t n = static_cast<size_t>(h.copied);
  std::vector<GLuint> names(n);
  std::vector<GLfloat> priorities(n);
  const char* data = static_cast<const char*>(p) + sizeof h;
  if (n != 0) {
    std::memcpy(names.data(), data, n * sizeof(GLuint));
    std::memcpy(priorities.data(), data + n * sizeof(GLuint), n * sizeof(GLfloat));
  }
  exec::PrioritizeTextures(h.n, names.data(), priorities.data());
}

// ---- images -------------------------------------------------------------------------------

// Every image command's scalar arguments, the unpack state of compile time and the size of
// the client bytes that follow the header in the record (0: the command had no data).
struct alignas(16) ImageHeader {
  GLenum target = 0, format = 0, type = 0;
  GLint level = 0, internal_format = 0, border = 0;
  GLint x = 0, y = 0, z = 0;
  GLsizei w = 0, h = 0, d = 0;
  GLfloat f[4] = {}; // Bitmap: xorig, yorig, xmove, ymove
  PixelStore unpack;
  size_t bytes = 0;
};

using ImageCall = void (*)(const ImageHeader& h, const void* pixels);

// Executes `call` on the data that follows the header, unpacked with the compile-time unpack
// state, which is put back afterwards.
template <ImageCall Call> void replay_image(const void* p) {
  ImageHeader h;
  std::memcpy(&h, p, sizeof h);
  Context* ctx = current_context();
  if (ctx == nullptr) return;
  // The image is in the list, whatever buffer is bound to PIXEL_UNPACK_BUFFER now.
  const PixelStore saved = ctx->pixel_store.unpack;
  const GLuint saved_buffer = ctx->pixel_store.unpack_buffer;
  ctx->pixel_store.unpack = h.unpack;
  ctx->pixel_store.unpack_buffer = 0;
  Call(h, h.bytes != 0 ? static_cast<const char*>(p) + sizeof h : nullptr);
  ctx->pixel_store.unpack = saved;
  ctx->pixel_store.unpack_buffer = saved_buffer;
}

// Compiles an image command whose client image spans client_image_bytes(w, h, d, format,
// type) under the current unpack state; returns whether it must also execute now.
template <ImageCall Call>
bool save_image(ImageHeader h, const void* pixels, const char* func, bool three_d = false) {
  Context* ctx = compiling_list();
  if (ctx == nullptr) return true;
  // IMAGE_HEIGHT and SKIP_IMAGES apply to 3D images only (§3.8.1): a 1D or 2D image spans
  // no more than its rows.
  h.unpack = three_d ? ctx->pixel_store.unpack : store_2d(ctx->pixel_store.unpack);
  const size_t span = client_image_bytes(h.w, h.h, h.d, h.format, h.type, h.unpack);
  // With a pixel unpack buffer bound the list keeps the buffer's bytes of compile time; an
  // access the buffer cannot satisfy is the command's error when the list executes.
  if (unpack_buffer_bound(ctx) &&
      !unpack_memory_quiet(ctx, pixels, span, pixel_type_unit(h.type), &pixels)) {
    record_error_at_execution(ctx, GL_INVALID_OPERATION, func);
    return list_executes(ctx);
  }
  h.bytes = pixels == nullptr ? 0 : span;
  try {
    return record_with_data(&replay_image<Call>, &h, sizeof h, pixels, h.bytes);
  } catch (const std::bad_alloc&) {
    record_error_at_execution(ctx, GL_OUT_OF_MEMORY, "glNewList");
    return list_executes(ctx);
  }
}

void call_tex_image_1d(const ImageHeader& h, const void* px) {
  exec::TexImage1D(h.target, h.level, h.internal_format, h.w, h.border, h.format, h.type, px);
}
void call_tex_image_2d(const ImageHeader& h, const void* px) {
  exec::TexImage2D(h.target, h.level, h.internal_format, h.w, h.h, h.border, h.format, h.type, px);
}
void call_tex_image_3d(const ImageHeader& h, const void* px) {
  exec::TexImage3D(h.target, h.level, h.internal_format, h.w, h.h, h.d, h.border, h.format, h.type,
                   px);
}
void call_tex_sub_image_1d(const ImageHeader& h, const void* px) {
  exec::TexSubImage1D(h.target, h.level, h.x, h.w, h.format, h.type, px);
}
void call_tex_sub_image_2d(const ImageHeader& h, const void* px) {
  exec::TexSubImage2D(h.target, h.level, h.x, h.y, h.w, h.h, h.format, h.type, px);
}
void call_tex_sub_image_3d(const ImageHeader& h, const void* px) {
  exec::TexSubImage3D(h.target, h.level, h.x, h.y, h.z, h.w, h.h, h.d, h.format, h.type, px);
}
void call_draw_pixels(const ImageHeader& h, const void* px) {
  exec::DrawPixels(h.w, h.h, h.format, h.type, px);
}
void call_bitmap(const ImageHeader& h, const void* px) {
  exec::Bitmap(h.w, h.h, h.f[0], h.f[1], h.f[2], h.f[3], static_cast<const GLubyte*>(px));
}
void call_polygon_stipple(const ImageHeader&, const void* px) {
  exec::PolygonStipple(static_cast<const GLubyte*>(px));
}

} // namespace

namespace saver {

void GLAPIENTRY TexEnvfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (save_vec(&replay2<GLfloat, &exec::TexEnvfv>, &env_count, target, pname, params))
    exec::TexEnvfv(target, pname, params);
}
void GLAPIENTRY TexEnviv(GLenum target, GLenum pname, const GLint* params) {
  if (save_vec(&replay2<GLint, &exec::TexEnviv>, &env_count, target, pname, params))
    exec::TexEnviv(target, pname, params);
}
void GLAPIENTRY TexGeniv(GLenum coord, GLenum pname, const GLint* params) {
  if (save_vec(&replay2<GLint, &exec::TexGeniv>, &gen_count, coord, pname, params))
    exec::TexGeniv(coord, pname, params);
}
void GLAPIENTRY TexGenfv(GLenum coord, GLenum pname, const GLfloat* params) {
  if (save_vec(&replay2<GLfloat, &exec::TexGenfv>, &gen_count, coord, pname, params))
    exec::TexGenfv(coord, pname, params);
}
void GLAPIENTRY TexGendv(GLenum coord, GLenum pname, const GLdouble* params) {
  if (save_vec(&replay2<GLdouble, &exec::TexGendv>, &gen_count, coord, pname, params))
    exec::TexGendv(coord, pname, params);
}
void GLAPIENTRY TexParameterfv(GLenum target, GLenum pname, const GLfloat* params) {
  if (save_vec(&replay2<GLfloat, &exec::TexParameterfv>, &tex_param_count, target, pname, params))
    exec::TexParameterfv(target, pname, params);
}
void GLAPIENTRY TexParameteriv(GLenum target, GLenum pname, const GLint* params) {
  if (save_vec(&replay2<GLint, &exec::TexParameteriv>, &tex_param_count, target, pname, params))
    exec::TexParameteriv(target, pname, params);
}
void GLAPIENTRY Fogfv(GLenum pname, const GLfloat* params) {
  if (save_vec(&replay1<GLfloat, &exec::Fogfv>, &fog_count, 0, pname, params))
    exec::Fogfv(pname, params);
}
void GLAPIENTRY Fogiv(GLenum pname, const GLint* params) {
  if (save_vec(&replay1<GLint, &exec::Fogiv>, &fog_count, 0, pname, params))
    exec::Fogiv(pname, params);
}
void GLAPIENTRY PointParameterfv(GLenum pname, const GLfloat* params) {
  if (save_vec(&replay1<GLfloat, &exec::PointParameterfv>, &point_count, 0, pname, params))
    exec::PointParameterfv(pname, params);
}
void GLAPIENTRY PointParameteriv(GLenum pname, const GLint* params) {
  if (save_vec(&replay1<GLint, &exec::PointParameteriv>, &point_count, 0, pname, params))
    exec::PointParameteriv(pname, params);
}

void GLAPIENTRY PixelMapfv(GLenum map, GLsizei mapsize, const GLfloat* values) {
  if (save_pixel_map<GLfloat, &exec::PixelMapfv>(map, mapsize, values, "glPixelMapfv"))
    exec::PixelMapfv(map, mapsize, values);
}
void GLAPIENTRY PixelMapuiv(GLenum map, GLsizei mapsize, const GLuint* values) {
  if (save_pixel_map<GLuint, &exec::PixelMapuiv>(map, mapsize, values, "glPixelMapuiv"))
    exec::PixelMapuiv(map, mapsize, values);
}
void GLAPIENTRY PixelMapusv(GLenum map, GLsizei mapsize, const GLushort* values) {
  if (save_pixel_map<GLushort, &exec::PixelMapusv>(map, mapsize, values, "glPixelMapusv"))
    exec::PixelMapusv(map, mapsize, values);
}

// GL 2.0 §5.4: DrawBuffers is compiled with its array (at most MAX_DRAW_BUFFERS values; a
// larger n is INVALID_VALUE when the list executes and its array is not read).
void GLAPIENTRY DrawBuffers(GLsizei n, const GLenum* bufs) {
  const GLsizei copied = bufs == nullptr || n > kMaxDrawBuffers ? 0 : std::max<GLsizei>(n, 0);
  const PixelMapHeader h{GL_NONE, n, copied};
  if (compiling_list() == nullptr ||
      record_with_data(&replay_pixel_map<GLenum, &draw_buffers_call>, &h, sizeof h, bufs,
                       static_cast<size_t>(copied) * sizeof(GLenum)))
    exec::DrawBuffers(n, bufs);
}

void GLAPIENTRY PrioritizeTextures(GLsizei n, const GLuint* textures, const GLfloat* priorities) {
  if (compiling_list() == nullptr) return exec::PrioritizeTextures(n, textures, priorities);
  const GLsizei copied = (textures == nullptr || priorities == nullptr)
                             ? 0
                             : std::clamp<GLsizei>(n, 0, kMaxCopiedValues);
  const size_t k = static_cast<size_t>(copied);
  const PrioritizeHeader h{n, copied};
  std::vector<char> data(k * (sizeof(GLuint) + sizeof(GLfloat)) + 1);
  if (k > 0) {
    std::memcpy(&data[0], textures, k * sizeof(GLuint));
    std::memcpy(&data[k * sizeof(GLuint)], priorities, k * sizeof(GLfloat));
  }
  if (record_with_data(&replay_prioritize, &h, sizeof h, &data[0], data.size() - 1))
    exec::PrioritizeTextures(n, textures, priorities);
}

void GLAPIENTRY TexImage1D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLint border, GLenum format, GLenum type, const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.internal_format = internalformat;
  h.w = width, h.h = 1, h.d = 1, h.border = border, h.format = format, h.type = type;
  if (is_proxy_texture_target(target) || save_image<&call_tex_image_1d>(h, pixels, "glTexImage1D"))
    exec::TexImage1D(target, level, internalformat, width, border, format, type, pixels);
}
void GLAPIENTRY TexImage2D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLsizei height, GLint border, GLenum format, GLenum type,
                           const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.internal_format = internalformat;
  h.w = width, h.h = height, h.d = 1, h.border = border, h.format = format, h.type = type;
  if (is_proxy_texture_target(target) || save_image<&call_tex_image_2d>(h, pixels, "glTexImage2D"))
    exec::TexImage2D(target, level, internalformat, width, height, border, format, type, pixels);
}
void GLAPIENTRY TexImage3D(GLenum target, GLint level, GLint internalformat, GLsizei width,
                           GLsizei height, GLsizei depth, GLint border, GLenum format, GLenum type,
                           const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.internal_format = internalformat;
  h.w = width, h.h = height, h.d = depth, h.border = border, h.format = format, h.type = type;
  if (is_proxy_texture_target(target) ||
      save_image<&call_tex_image_3d>(h, pixels, "glTexImage3D", true))
    exec::TexImage3D(target, level, internalformat, width, height, depth, border, format, type,
                     pixels);
}
void GLAPIENTRY TexSubImage1D(GLenum target, GLint level, GLint xoffset, GLsizei width,
                              GLenum format, GLenum type, const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.x = xoffset;
  h.w = width, h.h = 1, h.d = 1, h.format = format, h.type = type;
  if (save_image<&call_tex_sub_image_1d>(h, pixels, "glTexSubImage1D"))
    exec::TexSubImage1D(target, level, xoffset, width, format, type, pixels);
}
void GLAPIENTRY TexSubImage2D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                              GLsizei width, GLsizei height, GLenum format, GLenum type,
                              const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.x = xoffset, h.y = yoffset;
  h.w = width, h.h = height, h.d = 1, h.format = format, h.type = type;
  if (save_image<&call_tex_sub_image_2d>(h, pixels, "glTexSubImage2D"))
    exec::TexSubImage2D(target, level, xoffset, yoffset, width, height, format, type, pixels);
}
void GLAPIENTRY TexSubImage3D(GLenum target, GLint level, GLint xoffset, GLint yoffset,
                              GLint zoffset, GLsizei width, GLsizei height, GLsizei depth,
                              GLenum format, GLenum type, const void* pixels) {
  ImageHeader h;
  h.target = target, h.level = level, h.x = xoffset, h.y = yoffset, h.z = zoffset;
  h.w = width, h.h = height, h.d = depth, h.format = format, h.type = type;
  if (save_image<&call_tex_sub_image_3d>(h, pixels, "glTexSubImage3D", true))
    exec::TexSubImage3D(target, level, xoffset, yoffset, zoffset, width, height, depth, format,
                        type, pixels);
}
void GLAPIENTRY DrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                           const void* pixels) {
  ImageHeader h;
  h.w = width, h.h = height, h.d = 1, h.format = format, h.type = type;
  if (save_image<&call_draw_pixels>(h, pixels, "glDrawPixels"))
    exec::DrawPixels(width, height, format, type, pixels);
}
void GLAPIENTRY Bitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                       GLfloat ymove, const GLubyte* bitmap) {
  ImageHeader h;
  h.w = width, h.h = height, h.d = 1, h.format = GL_COLOR_INDEX, h.type = GL_BITMAP;
  h.f[0] = xorig, h.f[1] = yorig, h.f[2] = xmove, h.f[3] = ymove;
  if (save_image<&call_bitmap>(h, bitmap, "glBitmap"))
    exec::Bitmap(width, height, xorig, yorig, xmove, ymove, bitmap);
}
void GLAPIENTRY PolygonStipple(const GLubyte* mask) {
  ImageHeader h;
  h.w = 32, h.h = 32, h.d = 1, h.format = GL_COLOR_INDEX, h.type = GL_BITMAP;
  if (save_image<&call_polygon_stipple>(h, mask, "glPolygonStipple")) exec::PolygonStipple(mask);
}

} // namespace saver

} // namespace pineda
