// glDrawPixels (GL 2.1 §3.6.4, §4.3.1), glBitmap (§3.7), glCopyPixels (§4.3.3), and glReadPixels
// when pixel transfer operations are active (§4.3.2; buffers.cpp keeps the direct path).
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "state/api_util.h"
#include "dispatch.h"
#include "framebuffer/read_pixels.h"
#include "state/draw_call.h"
#include "state/program_draw.h"
#include "state/validate.h"
#include "pixel/pixel_draw.h"
#include "pixel/unpack.h"
#include "draw/draw_buffers.h"
#include "state/draw_read_buffer.h"
#include "state/pixel_buffer.h"
#include "state/select.h"

namespace pineda {

namespace {

// Validation before pixel fragments are drawn: a fragment shader shades them too (§3.11), so
// its uniforms and built-in state are brought up to date as for a draw.
void validate_pixel_draw(Context* ctx) {
  check_program_link(ctx);
  validate_state(ctx);
  if (ctx->program_draw->has_fragment) refresh_program(ctx);
}

// Groups converted per step, so that huge images do not need a float copy of themselves.
constexpr size_t kStripGroups = size_t{1} << 16;

// GL 2.1 §3.6.4 places group (n, m) at (x_rp + z_x n, y_rp + z_y m). The raster position is
// rounded to the nearest integer first, as SGI's implementation did and Mesa does "to satisfy
// conformance tests": a position like 60.5 puts the image at 61, and reductions sample the
// groups Mesa samples. For positions off the half-integers and integral zooms this is exactly
// the spec's placement.
float round_raster(float v) {
  return std::isfinite(v) ? static_cast<float>(std::floor(static_cast<double>(v) + 0.5)) : v;
}

PixelPlacement placement_at(const Context* ctx, int w, int h) {
  PixelPlacement p;
  p.w = w;
  p.h = h;
  p.x = round_raster(ctx->current.raster_pos.win[0]);
  p.y = round_raster(ctx->current.raster_pos.win[1]);
  p.zoom_x = ctx->pixel.zoom_x;
  p.zoom_y = ctx->pixel.zoom_y;
  return p;
}

// The window pixels the groups of `p` can reach (§3.6.4): for FRONT_AND_BACK, whose first pass
// keeps their depth and stencil values (draw/draw_buffers.h). A pixel more on each side.
DrawRegion placement_region(const PixelPlacement& p) {
  const double x0 = p.x + double(p.zoom_x) * double(p.col0);
  const double x1 = p.x + double(p.zoom_x) * double(p.col0 + p.w);
  const double y0 = p.y + double(p.zoom_y) * double(p.row0);
  const double y1 = p.y + double(p.zoom_y) * double(p.row0 + p.h);
  if (!std::isfinite(x0) || !std::isfinite(x1) || !std::isfinite(y0) || !std::isfinite(y1))
    return {INT32_MIN, INT32_MIN, INT32_MAX, INT32_MAX};
  const auto to_int = [](double v) { return static_cast<int>(std::clamp(v, -1e9, 1e9)); };
  return {to_int(std::floor(std::min(x0, x1)) - 1), to_int(std::floor(std::min(y0, y1)) - 1),
          to_int(std::ceil(std::max(x0, x1)) + 1), to_int(std::ceil(std::max(y0, y1)) + 1)};
}

// Runs draw() (which returns the samples that passed) once per draw buffer (GL 2.1 §4.2.1);
// occlusion queries count the primary pass.
template <typename Draw> void each_draw_buffer(Context* ctx, const DrawRegion& region, Draw draw) {
  for_each_draw_buffer(ctx->fb, ctx->raster, region, [&](bool primary) {
    const uint64_t samples = draw();
    if (primary) ctx->queries.samples_passed += samples;
  });
}

// Draws `h` rows of `w` groups in strips of rows; unpack(rows, row_count, out) fills one strip
// of colours, depths or indices and draw(placement, data) sends it on.
template <typename T, typename Unpack, typename Draw>
void in_strips(PixelPlacement p, size_t per_group, Unpack unpack, Draw draw) {
  const int h = p.h;
  const int rows = static_cast<int>(std::max<size_t>(1, kStripGroups / static_cast<size_t>(p.w)));
  std::vector<T> buf(static_cast<size_t>(std::min(rows, h)) * static_cast<size_t>(p.w) * per_group);
  const int64_t row0 = p.row0;
  for (int m = 0; m < h; m += rows) {
    const int n = std::min(rows, h - m);
    unpack(m, n, buf.data());
    p.row0 = row0 + m;
    p.h = n;
    draw(p, buf.data());
  }
}

// The fragment colour of depth groups and the depth of colour groups (§3.6.4).
void draw_color_strip(Context* ctx, const PixelPlacement& p, const float* rgba) {
  PixelRect r;
  r.place = p;
  r.rgba = rgba;
  r.z = ctx->current.raster_pos.win[2];
  r.raster = &ctx->current.raster_pos;
  each_draw_buffer(ctx, placement_region(p),
                   [&] { return draw_pixel_rect(ctx->raster, ctx->fb, r); });
}

void draw_depth_strip(Context* ctx, const PixelPlacement& p, const float* depth) {
  PixelRect r;
  r.place = p;
  r.depth = depth;
  std::copy(ctx->current.raster_pos.color, ctx->current.raster_pos.color + 4, r.color);
  r.raster = &ctx->current.raster_pos;
  each_draw_buffer(ctx, placement_region(p),
                   [&] { return draw_pixel_rect(ctx->raster, ctx->fb, r); });
}

// The part of the w x h rectangle at (x, y) inside the framebuffer.
struct Inside {
  int x0, y0, x1, y1;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

Inside inside_fb(const Framebuffer& fb, int x, int y, int w, int h) {
  return Inside{static_cast<int>(std::max<int64_t>(x, 0)),
                static_cast<int>(std::max<int64_t>(y, 0)),
                static_cast<int>(std::min<int64_t>(int64_t{x} + w, fb.width)),
                static_cast<int>(std::min<int64_t>(int64_t{y} + h, fb.height))};
}

PixelStore tight_store() {
  PixelStore st;
  st.alignment = 1;
  return st;
}

// SELECT and FEEDBACK render modes: a pixel rectangle or bitmap at a valid raster position
// becomes `token` and that position in the feedback buffer (§5.3), and nothing else.
void raster_token(Context* ctx, GLenum token) {
  const RasterPos& rp = ctx->current.raster_pos;
  if (rp.valid) feedback_raster_token(ctx, token, rp.win, rp.color, rp.tex[0]);
}

} // namespace

// GL 2.1 §4.3.2 with pixel transfer operations that can change the result: the framebuffer
// values are read as floats, transformed, and packed per the pack state. False when the
// direct path (read_pixels) gives the same result. The caller has checked the arguments.
bool read_pixels_transfer(Context* ctx, int x, int y, int w, int h, GLenum format, GLenum type,
                          void* pixels) {
  const PixelTransferView xfer = pixel_transfer_view(ctx);
  const bool depth = format == GL_DEPTH_COMPONENT, stencil = format == GL_STENCIL_INDEX;
  const bool both = format == GL_DEPTH_STENCIL;
  if (both      ? !depth_transfer_active(xfer) && !stencil_transfer_active(xfer)
      : depth   ? !depth_transfer_active(xfer)
      : stencil ? !stencil_transfer_active(xfer)
                : !rgba_transfer_active(xfer))
    return false;
  const Inside in = inside_fb(ctx->read_fb, x, y, w, h);
  if (in.empty()) return true;
  const int iw = in.x1 - in.x0, ih = in.y1 - in.y0;
  // Pack only the groups inside the framebuffer: same rows as the full image, skipping the
  // groups before them (pixels outside the window are undefined, §4.3.2, and left untouched).
  PixelStore st = store_2d(ctx->pixel_store.pack);
  if (st.row_length == 0) st.row_length = w;
  const int64_t skip_pixels = int64_t{st.skip_pixels} + in.x0 - x;
  const int64_t skip_rows = int64_t{st.skip_rows} + in.y0 - y;
  // Offsets beyond the int range address no client memory there could be.
  if (skip_pixels > INT32_MAX || skip_rows > INT32_MAX) return true;
  st.skip_pixels = static_cast<int>(skip_pixels);
  st.skip_rows = static_cast<int>(skip_rows);
  const size_t n = static_cast<size_t>(iw) * static_cast<size_t>(ih);
  const PixelStore tight = tight_store();
  if (both) {
    std::vector<float> z(n);
    std::vector<uint32_t> s(n);
    read_pixels(ctx->read_fb, in.x0, in.y0, iw, ih, GL_DEPTH_COMPONENT, GL_FLOAT, tight, z.data());
    read_pixels(ctx->read_fb, in.x0, in.y0, iw, ih, GL_STENCIL_INDEX, GL_UNSIGNED_INT, tight,
                s.data());
    transfer_depth(xfer, z.data(), n);
    transfer_stencil(xfer, s.data(), n);
    pack_depth_stencil(z.data(), s.data(), iw, ih, 1, st, pixels);
  } else if (depth) {
    std::vector<float> z(n);
    read_pixels(ctx->read_fb, in.x0, in.y0, iw, ih, GL_DEPTH_COMPONENT, GL_FLOAT, tight, z.data());
    transfer_depth(xfer, z.data(), n);
    pack_depth(z.data(), iw, ih, 1, type, st, pixels);
  } else if (stencil) {
    std::vector<uint32_t> s(n);
    read_pixels(ctx->read_fb, in.x0, in.y0, iw, ih, GL_STENCIL_INDEX, GL_UNSIGNED_INT, tight,
                s.data());
    transfer_stencil(xfer, s.data(), n);
    pack_index(s.data(), iw, ih, 1, type, st, pixels);
  } else {
    std::vector<float> c(n * 4);
    read_pixels(ctx->read_fb, in.x0, in.y0, iw, ih, GL_RGBA, GL_FLOAT, tight, c.data());
    transfer_rgba(xfer, c.data(), n);
    pack_rgba(c.data(), iw, ih, 1, format, type, st, pixels);
  }
  return true;
}

namespace exec {

void GLAPIENTRY DrawPixels(GLsizei width, GLsizei height, GLenum format, GLenum type,
                           const void* pixels) {
  PINEDA_CTX_OUTSIDE("glDrawPixels");
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE, "glDrawPixels");
  const GLenum err = check_pixel_format_type(format, type);
  if (err != GL_NO_ERROR) return record_error(ctx, err, "glDrawPixels", format);
  // ARB_framebuffer_object §4.4.4: nothing is drawn into an incomplete framebuffer.
  if (!draw_framebuffer_ready(ctx, "glDrawPixels")) return;
  // §4.3.1 (and Mesa for depth): drawing into a buffer that does not exist.
  if ((format == GL_STENCIL_INDEX && ctx->fb.stencil == nullptr) ||
      (format == GL_DEPTH_COMPONENT && ctx->fb.depth == nullptr) ||
      (format == GL_DEPTH_STENCIL && (ctx->fb.depth == nullptr || ctx->fb.stencil == nullptr)))
    return record_error(ctx, GL_INVALID_OPERATION, "glDrawPixels");
  // §5.3: in feedback mode a valid raster position writes a DRAW_PIXEL_TOKEN; in selection and
  // feedback mode no fragments are made (§5.2).
  if (!render_mode_is_render(ctx)) return raster_token(ctx, GL_DRAW_PIXEL_TOKEN);
  // §3.6.4: with an invalid raster position DrawPixels is ignored.
  if (!ctx->current.raster_pos.valid || width == 0 || height == 0) return;
  const PixelStore st = store_2d(ctx->pixel_store.unpack);
  // §3.6.4: from the pixel unpack buffer when one is bound.
  if (!unpack_memory(ctx, pixels, client_image_bytes(width, height, 1, format, type, st),
                     pixel_type_unit(type), "glDrawPixels", &pixels))
    return;
  if (pixels == nullptr || !ctx->fb.present()) return;
  validate_pixel_draw(ctx);
  const PixelTransferView xfer = pixel_transfer_view(ctx);
  const PixelPlacement p = placement_at(ctx, width, height);
  // Each strip unpacks `rows` rows starting at row `m` of the client image.
  const auto strip_store = [&](int m) {
    PixelStore s = st;
    if (s.row_length == 0) s.row_length = width;
    s.skip_rows = static_cast<int>(std::min<int64_t>(INT32_MAX, int64_t{s.skip_rows} + m));
    return s;
  };
  if (format == GL_DEPTH_STENCIL) {
    // EXT_packed_depth_stencil: the depths as DEPTH_COMPONENT fragments, the stencil indices
    // as STENCIL_INDEX writes, strip by strip.
    std::vector<uint32_t> s;
    in_strips<float>(
        p, 1,
        [&](int m, int rows, float* out) {
          s.resize(size_t(rows) * size_t(width));
          unpack_depth_stencil(pixels, width, rows, 1, strip_store(m), xfer, out, s.data());
        },
        [&](const PixelPlacement& q, const float* z) {
          draw_depth_strip(ctx, q, z);
          draw_stencil_rect(ctx->raster, ctx->fb, q, s.data(), nullptr);
        });
  } else if (format == GL_STENCIL_INDEX) {
    in_strips<uint32_t>(
        p, 1,
        [&](int m, int rows, uint32_t* out) {
          unpack_index(pixels, width, rows, 1, format, type, strip_store(m), xfer, out);
        },
        [&](const PixelPlacement& q, const uint32_t* idx) {
          draw_stencil_rect(ctx->raster, ctx->fb, q, idx, nullptr);
        });
  } else if (format == GL_DEPTH_COMPONENT) {
    in_strips<float>(
        p, 1,
        [&](int m, int rows, float* out) {
          unpack_depth(pixels, width, rows, 1, type, strip_store(m), xfer, out);
        },
        [&](const PixelPlacement& q, const float* z) { draw_depth_strip(ctx, q, z); });
  } else {
    in_strips<float>(
        p, 4,
        [&](int m, int rows, float* out) {
          unpack_rgba(pixels, width, rows, 1, format, type, strip_store(m), xfer, out);
        },
        [&](const PixelPlacement& q, const float* rgba) { draw_color_strip(ctx, q, rgba); });
  }
}

void GLAPIENTRY Bitmap(GLsizei width, GLsizei height, GLfloat xorig, GLfloat yorig, GLfloat xmove,
                       GLfloat ymove, const GLubyte* bitmap) {
  PINEDA_CTX_OUTSIDE("glBitmap");
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE, "glBitmap");
  RasterPos& rp = ctx->current.raster_pos;
  // §3.7: with an invalid raster position the bitmap is ignored, the position not moved.
  if (!rp.valid) return;
  // ARB_framebuffer_object §4.4.4: nothing is drawn into an incomplete framebuffer.
  if (!draw_framebuffer_ready(ctx, "glBitmap")) return;
  // §3.7: from the pixel unpack buffer when one is bound (an error moves nothing).
  if (render_mode_is_render(ctx) && width > 0 && height > 0) {
    const void* src = nullptr;
    if (!unpack_memory(ctx, bitmap,
                       client_image_bytes(width, height, 1, GL_COLOR_INDEX, GL_BITMAP,
                                          store_2d(ctx->pixel_store.unpack)),
                       1, "glBitmap", &src))
      return;
    bitmap = static_cast<const GLubyte*>(src);
  }
  if (!render_mode_is_render(ctx)) {
    raster_token(ctx, GL_BITMAP_TOKEN); // §5.3; the raster position still moves
  } else if (bitmap != nullptr && width > 0 && height > 0 && ctx->fb.present()) {
    validate_pixel_draw(ctx);
    // Unpacked like DrawPixels of COLOR_INDEX / BITMAP, before any conversion (§3.7).
    const size_t n = static_cast<size_t>(width) * static_cast<size_t>(height);
    std::vector<uint32_t> idx(n);
    static const PixelTransfer kNoTransfer;
    static const PixelMaps kNoMaps;
    unpack_index(bitmap, width, height, 1, GL_COLOR_INDEX, GL_BITMAP,
                 store_2d(ctx->pixel_store.unpack), PixelTransferView{kNoTransfer, kNoMaps},
                 idx.data());
    std::vector<uint8_t> bits(n);
    for (size_t i = 0; i < n; ++i)
      bits[i] = static_cast<uint8_t>(idx[i] & 1u);
    // (x_ll, y_ll) = (floor(x_rp - x_bo), floor(y_rp - y_bo)). A raster position that should
    // be an integer often arrives a rounding error below it; like Mesa, a small epsilon keeps
    // it on that integer.
    constexpr float kEps = 1e-4f;
    const auto corner = [](float v) {
      if (std::isnan(v)) return -1073741824; // off any window
      const double f = std::floor(static_cast<double>(v));
      return static_cast<int>(std::clamp(f, -1073741824.0, 1073741824.0));
    };
    // §3.9: the colour sum (on with COLOR_SUM or lighting) adds the raster position's
    // secondary colour to bitmap fragments. llvmpipe does so for bitmaps, not for DrawPixels.
    // With texturing or fog on, draw_bitmap adds it after texturing instead.
    float color[4] = {rp.color[0], rp.color[1], rp.color[2], rp.color[3]};
    if ((ctx->lighting.enabled || ctx->fog.color_sum) && ctx->raster.shade == nullptr)
      for (int c = 0; c < 3; ++c)
        color[c] += rp.color2[c];
    // Occlusion queries count bitmap fragments too (GL 2.1 §4.1.7).
    const int x = corner(rp.win[0] - xorig + kEps), y = corner(rp.win[1] - yorig + kEps);
    const DrawRegion region{
        static_cast<int>(std::max<int64_t>(int64_t{x} - 1, INT32_MIN)),
        static_cast<int>(std::max<int64_t>(int64_t{y} - 1, INT32_MIN)),
        static_cast<int>(std::min<int64_t>(int64_t{x} + width + 1, INT32_MAX)),
        static_cast<int>(std::min<int64_t>(int64_t{y} + height + 1, INT32_MAX))};
    each_draw_buffer(ctx, region, [&] {
      return draw_bitmap(ctx->raster, ctx->fb, x, y, width, height, bits.data(), color, rp.win[2],
                         rp);
    });
  }
  rp.win[0] += xmove;
  rp.win[1] += ymove;
}

void GLAPIENTRY CopyPixels(GLint x, GLint y, GLsizei width, GLsizei height, GLenum type) {
  PINEDA_CTX_OUTSIDE("glCopyPixels");
  if (type != GL_COLOR && type != GL_DEPTH && type != GL_STENCIL && type != GL_DEPTH_STENCIL)
    return record_error(ctx, GL_INVALID_ENUM, "glCopyPixels", type);
  if (width < 0 || height < 0) return record_error(ctx, GL_INVALID_VALUE, "glCopyPixels");
  // ARB_framebuffer_object §4.4.4: incomplete framebuffers are neither read nor written.
  if (!draw_framebuffer_ready(ctx, "glCopyPixels") || !read_framebuffer_ready(ctx, "glCopyPixels"))
    return;
  // §4.3.3: the buffer copied must exist in the read and in the draw framebuffer.
  const Framebuffer& src = ctx->read_fb;
  const bool copy_depth = type == GL_DEPTH || type == GL_DEPTH_STENCIL;
  const bool copy_stencil = type == GL_STENCIL || type == GL_DEPTH_STENCIL;
  if ((copy_depth && (ctx->fb.depth == nullptr || src.depth == nullptr)) ||
      (copy_stencil && (ctx->fb.stencil == nullptr || src.stencil == nullptr)))
    return record_error(ctx, GL_INVALID_OPERATION, "glCopyPixels");
  if (!render_mode_is_render(ctx)) return raster_token(ctx, GL_COPY_PIXEL_TOKEN); // §5.3
  if (!ctx->current.raster_pos.valid || !ctx->fb.present() || !src.present()) return;
  if (type == GL_COLOR && src.color == nullptr) return;
  // Source pixels outside the window are undefined (§4.3.2); Pineda makes no fragments for
  // them, so only the part inside is read and drawn, at its place in the full rectangle.
  const Inside in = inside_fb(src, x, y, width, height);
  if (in.empty()) return;
  validate_pixel_draw(ctx);
  const int iw = in.x1 - in.x0, ih = in.y1 - in.y0;
  PixelPlacement p = placement_at(ctx, iw, ih);
  p.col0 = int64_t{in.x0} - x;
  p.row0 = int64_t{in.y0} - y;
  // The whole source is read before anything is drawn, so overlapping rectangles copy the
  // old contents (§4.3.3: as if ReadPixels, then DrawPixels).
  const size_t n = static_cast<size_t>(iw) * static_cast<size_t>(ih);
  const PixelStore tight = tight_store();
  const PixelTransferView xfer = pixel_transfer_view(ctx);
  if (type == GL_DEPTH_STENCIL) {
    // EXT_packed_depth_stencil: both are read before either is written.
    std::vector<float> z(n);
    std::vector<uint32_t> s(n);
    read_pixels(src, in.x0, in.y0, iw, ih, GL_DEPTH_COMPONENT, GL_FLOAT, tight, z.data());
    read_pixels(src, in.x0, in.y0, iw, ih, GL_STENCIL_INDEX, GL_UNSIGNED_INT, tight, s.data());
    transfer_depth(xfer, z.data(), n);
    transfer_stencil(xfer, s.data(), n);
    draw_depth_strip(ctx, p, z.data());
    draw_stencil_rect(ctx->raster, ctx->fb, p, s.data(), nullptr);
  } else if (type == GL_STENCIL) {
    std::vector<uint32_t> s(n);
    read_pixels(src, in.x0, in.y0, iw, ih, GL_STENCIL_INDEX, GL_UNSIGNED_INT, tight, s.data());
    transfer_stencil(xfer, s.data(), n);
    draw_stencil_rect(ctx->raster, ctx->fb, p, s.data(), nullptr);
  } else if (type == GL_DEPTH) {
    std::vector<float> z(n);
    read_pixels(src, in.x0, in.y0, iw, ih, GL_DEPTH_COMPONENT, GL_FLOAT, tight, z.data());
    transfer_depth(xfer, z.data(), n);
    draw_depth_strip(ctx, p, z.data());
  } else {
    std::vector<float> c(n * 4);
    read_pixels(src, in.x0, in.y0, iw, ih, GL_RGBA, GL_FLOAT, tight, c.data());
    if (rgba_transfer_active(xfer)) transfer_rgba(xfer, c.data(), n);
    draw_color_strip(ctx, p, c.data());
  }
}

} // namespace exec
} // namespace pineda
