// The GL state machine of one context (GL 2.1 chapter 6 state tables, restricted to what Pineda
// implements). Front-end files (src/state/*.cpp) change it through the entry-point skeleton in
// api_util.h; validate.cpp derives the back end's RasterState from it at draw time.
#pragma once

#include <GL/gl.h>

#include <array>
#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>

#include "framebuffer/framebuffer.h"
#include "framebuffer/pixel_store.h"
#include "pixel/raster_pos.h"
#include "pixel/transfer.h"
#include "raster/raster.h"
#include "state/dlist_state.h"
#include "state/lighting_state.h"
#include "state/misc_state.h"
#include "state/texpipe_state.h"
#include "texture/texture_object.h"
#include "state/raster_mode_state.h"
#include "state/select.h"
#include "state/eval_state.h"
#include "core/limits.h"

namespace pineda {

// Which groups of derived state must be recomputed before the next draw.
enum DirtyBit : uint32_t {
  kDirtyTransform = 1u << 0,   // modelview or projection changed: composite matrix
  kDirtyViewport = 1u << 1,    // viewport, depth range
  kDirtyClipPlanes = 1u << 2,  // user clip planes or their enables
  kDirtyPolygon = 1u << 3,     // culling, front face, polygon mode, shade model
  kDirtyFragment = 1u << 4,    // depth, blend, colour mask
  kDirtyFramebuffer = 1u << 5, // the drawable changed
  kDirtyTexture = 1u << 6, // texture enables, bindings, objects, environment, coordinate generation
  kDirtyFog = 1u << 7,     // fog state, fog coordinate source
  kDirtyRasterMode =
      1u << 8,           // line width/stipple/smooth, point size/parameters, polygon offset/stipple
  kDirtyPixel = 1u << 9, // pixel transfer, pixel maps, pixel zoom
  kDirtyRenderMode = 1u << 10, // glRenderMode, feedback/selection buffers, active queries
  kDirtyLighting = 1u << 16,   // lighting state, or normalize / rescale-normal enables
  kDirtyAll = 0xffffffffu,
};

// A matrix stack (GL 2.1 §2.11.2). Element 0 is the bottom; back() is the current matrix.
struct MatrixStack {
  std::vector<glm::mat4> stack;
  size_t max_depth = 0;
  explicit MatrixStack(size_t depth) : stack(1, glm::mat4(1.0f)), max_depth(depth) {}
  glm::mat4& top() { return stack.back(); }
  const glm::mat4& top() const { return stack.back(); }
};

// One client vertex array (GL 2.1 §2.8) and the buffer object bound when it was specified.
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0; // as given; 0 means tightly packed
  const void* pointer = nullptr;
  GLuint buffer = 0;     // GL_ARRAY_BUFFER_BINDING captured at glXxxPointer time
  GLsizei count_ext = 0; // EXT_vertex_array's count (src/state/ext_commands.cpp)
};

struct VertexArrays {
  ClientArray vertex{false, 4, GL_FLOAT, 0, nullptr, 0};
  ClientArray color{false, 4, GL_FLOAT, 0, nullptr, 0};
  ClientArray normal{false, 3, GL_FLOAT, 0, nullptr, 0};
  ClientArray texcoord[kMaxTexUnits];
  ClientArray edgeflag{false, 1, GL_BOOL, 0, nullptr, 0};
  ClientArray secondary{false, 3, GL_FLOAT, 0, nullptr, 0}; // SECONDARY_COLOR_ARRAY
  ClientArray fog{false, 1, GL_FLOAT, 0, nullptr, 0};       // FOG_COORD_ARRAY (GL 1.4)
  ClientArray index{false, 1, GL_FLOAT, 0, nullptr, 0};     // INDEX_ARRAY (never read)
};

// A buffer object (GL 2.1 §2.9).
struct BufferObject {
  std::vector<uint8_t> data;
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;
  bool mapped = false;
  bool ever_bound = false;
};

// The objects a share group of contexts has in common (GLX 1.4 §3.3.7 share lists): buffer
// objects and display lists. Contexts of one group on different threads must not create or delete
// objects concurrently (the container itself is not locked).
struct SharedObjects {
  std::unordered_map<GLuint, std::unique_ptr<BufferObject>> buffers;
  // Texture objects (GL 2.1 §3.8.12) by name; name 0 is each context's default object.
  std::unordered_map<GLuint, std::unique_ptr<TextureObject>> textures;
  // Bumped on every change of any texture image or parameter (also of default objects), so
  // views made by make_sampler_view (texture/sampler.h) know when to be remade.
  uint64_t texture_generation = 0;
  DisplayLists lists; // src/state/dlist.cpp
};

// glPushClientAttrib saves these (GL 2.1 §6.1.14, CLIENT_PIXEL_STORE_BIT and
// CLIENT_VERTEX_ARRAY_BIT).
struct ClientAttribFrame {
  GLbitfield mask = 0;
  PixelStore pack, unpack;
  VertexArrays arrays;
  GLuint array_buffer = 0;
  GLuint element_array_buffer = 0;
  GLuint client_active_texture = 0;
};

// The vertex the immediate-mode and array paths collect: object position plus a snapshot of
// the current attributes (GL 2.1 §2.7). The attributes every draw reads fill the first 64
// bytes (one cache line); the texture coordinates, read only by units that are on, follow.
struct InputVertex {
  // Deliberately leaves the members uninitialized, also where a container value-initializes
  // (imm.emplace_back()): every path that makes a vertex fills what its draw reads, and
  // zeroing 128 bytes per glVertex call is measurable.
  InputVertex() {} // NOLINT(modernize-use-equals-default): = default would zero them
  float pos[4];
  float color[4];
  float normal[3];
  float color2[3]; // secondary colour (GL 1.4, §2.7)
  float fog;       // fog coordinate (GL 1.4, §2.7)
  uint32_t edge;
  float tex[kMaxTexUnits][4]; // per texture unit
};

// Which texture units' coordinates a draw's geometry stage reads from its InputVertex array
// (bit u for unit u); the paths that build InputVertex arrays for one draw copy only those.
// Display lists and glArrayElement keep every unit (kAllTexUnits).
constexpr uint32_t kAllTexUnits = (1u << kMaxTexUnits) - 1;

// The colour buffers of GL 2.1 table 4.4 (no auxiliary buffers exist: GL_AUX_BUFFERS is 0).
enum ColorBufferBit : uint32_t {
  kColorBufferFrontLeft = 1u << 0,
  kColorBufferFrontRight = 1u << 1,
  kColorBufferBackLeft = 1u << 2,
  kColorBufferBackRight = 1u << 3,
};

constexpr GLenum kOutsideBeginEnd = 0xffffffffu;

// What glPushAttrib saves (GL 2.1 §6.1.14): one member per attribute group of the state tables'
// "attribute" column, filled only for the groups in `mask`. Groups whose state Pineda does not
// have yet are listed in attrib.cpp with the state they must grow to cover.
struct AttribFrame {
  GLbitfield mask = 0;
  struct Current { // current (Table 6.5)
    float color[4], color2[4], normal[3], tex[kMaxTexUnits][4];
    bool edge;
    RasterPos raster; // the current raster position and its data (§2.13)
  } current{};
  struct Enables { // enable: every flag of enable_flags() in attrib.cpp, in that order
    bool flag[kMaxClipPlanes + kMaxLights + 16];
  } enables{};
  struct Polygon { // polygon (Table 6.14)
    bool cull_enabled;
    GLenum cull_face, front_face, polygon_mode[2];
  } polygon{};
  struct Lighting { // lighting (Tables 6.11-6.13)
    bool enabled, local_viewer, two_side, color_material;
    Light light[kMaxLights];
    Material material[2];
    float model_ambient[4];
    GLenum color_control, color_material_face, color_material_mode, shade_model;
  } lighting{};
  struct Depth { // depth-buffer (Tables 6.21, 6.22)
    bool test, mask;
    GLenum func;
    double clear;
  } depth{};
  struct ColorBuffer { // color-buffer (Tables 6.20-6.22)
    bool alpha_test, blend, dither, color_logic_op, index_logic_op, color_mask[4];
    GLenum alpha_func, blend_src_rgb, blend_dst_rgb, blend_src_a, blend_dst_a, blend_eq_rgb,
        blend_eq_a, logic_op, draw_buffer;
    float alpha_ref, blend_color[4], clear_color[4];
  } color{};
  struct Stencil { // stencil-buffer (Tables 6.21, 6.22)
    bool test;
    GLenum func, fail, depth_fail, depth_pass;
    GLint ref, clear;
    GLuint value_mask, writemask;
  } stencil{};
  struct Scissor { // scissor (Table 6.20)
    bool test;
    GLint box[4];
  } scissor{};
  struct Viewport { // viewport (Table 6.10)
    GLint x, y;
    GLsizei w, h;
    double near, far;
  } viewport{};
  struct Transform { // transform (Table 6.10)
    GLenum matrix_mode;
    double clip_plane[kMaxClipPlanes][4];
    bool clip_enabled[kMaxClipPlanes];
    bool normalize, rescale_normal;
  } transform{};
  struct Hints { // hint (Table 6.32)
    GLenum perspective, point_smooth, line_smooth, polygon_smooth, fog, generate_mipmap,
        texture_compression;
  } hints{};
  bool color_sum = false;        // fog: the COLOR_SUM enable (Table 6.11)
  GLenum read_buffer = GL_FRONT; // pixel (Table 6.27)
  TexPipeAttrib texpipe; // texture environment/generation/enables, fog (src/state/texenv.cpp)
  RasterModeAttrib raster_modes{}; // line, point, polygon stipple/offset/smooth (raster_modes.cpp)
  float accum_clear[4] = {};       // accum-buffer (Table 6.22)
  GLuint list_base = 0;            // list (Table 6.31)
  struct PixelMode { // pixel (Tables 6.24-6.27): the transfer modes and zoom, not the maps
    bool map_color, map_stencil;
    int index_shift, index_offset;
    float scale[4], bias[4], depth_scale, depth_bias, zoom_x, zoom_y;
  } pixel{};
  TextureAttrib texture_objects{}; // texture: bindings, object parameters (texture_object.cpp)
  MiscState misc{};                // colour index, multisample (color_index.cpp, multisample.cpp)
  EvalAttrib eval;                 // eval and the evaluator enables (src/state/eval.cpp)
};

struct DrawCache;

struct Context {
  Context();
  // A context in the share group that owns `objects`.
  explicit Context(std::shared_ptr<SharedObjects> objects);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // ---- window system (set by osmesa.cpp / glx) ----
  Framebuffer fb;
  bool ever_current = false;
  // The colour buffers the context has (GL 2.1 table 4.4), kColorBuffer* bits. Pineda draws
  // into fb.color, which is the front left buffer unless a window-system layer says otherwise.
  uint32_t color_buffers = kColorBufferFrontLeft;
  // Called by glFlush and glFinish when set (GLX: a single-buffered window or a pixmap shows
  // what was rendered once the commands are flushed, GL 2.1 §5.5).
  void (*present_front)(Context*) = nullptr;
  // Called when DrawBuffer/ReadBuffer select fb.front_color of a double-buffered drawable,
  // before it is used (GLX: the front buffer's contents may still have to be fetched).
  void (*front_selected)(Context*) = nullptr;

  // ---- errors (GL 2.1 §2.5): the first error is kept until glGetError ----
  GLenum error = GL_NO_ERROR;

  // ---- Begin/End (GL 2.1 §2.6) ----
  GLenum begin_mode = kOutsideBeginEnd;
  std::vector<InputVertex> imm;
  // Texture units whose current coordinates the vertices of this Begin/End copy (set by
  // glBegin from the validated state, which cannot change before glEnd).
  uint32_t imm_tex_units = kAllTexUnits;

  // ---- current values (GL 2.1 §2.7, Table 6.5) ----
  float cur_color[4] = {1, 1, 1, 1};
  float cur_color2[4] = {0, 0, 0, 1}; // CURRENT_SECONDARY_COLOR
  float cur_normal[3] = {0, 0, 1};
  float cur_tex[kMaxTexUnits][4] = {{0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}, {0, 0, 0, 1}};
  bool cur_edge = true;

  // ---- transformation (GL 2.1 §2.11, Table 6.6) ----
  GLenum matrix_mode = GL_MODELVIEW;
  MatrixStack modelview{kModelviewStackDepth};
  MatrixStack projection{kProjectionStackDepth};
  MatrixStack texture[kMaxTexUnits] = {
      MatrixStack(kTextureStackDepth), MatrixStack(kTextureStackDepth),
      MatrixStack(kTextureStackDepth), MatrixStack(kTextureStackDepth)};
  GLuint active_texture = 0; // GL_TEXTUREi - GL_TEXTURE0
  GLint vp_x = 0, vp_y = 0;
  GLsizei vp_w = 0, vp_h = 0;
  double depth_near = 0.0, depth_far = 1.0;
  double clip_plane[kMaxClipPlanes][4] = {}; // eye coordinates (GL 2.1 §2.12)
  bool clip_enabled[kMaxClipPlanes] = {};
  bool normalize = false;
  bool rescale_normal = false;

  // ---- texture objects and bindings (GL 2.1 §3.8.12), src/texture/texture_object.cpp ----
  TextureState texobj;

  // ---- lighting (GL 2.1 §2.14.1-§2.14.4), src/state/lighting.cpp ----
  LightingState lighting;

  // ---- texture units and fog (GL 2.1 §2.11.4, §3.8.13, §3.10), src/state/texenv.cpp ----
  TexPipeState texpipe;

  // ---- colour index and multisample (no effect in RGBA, SAMPLE_BUFFERS 0), misc_state.h ----
  MiscState misc;

  // ---- rasterization (Table 6.11, 6.12) ----
  bool cull_enabled = false;
  GLenum cull_face = GL_BACK;
  GLenum front_face = GL_CCW;
  GLenum polygon_mode[2] = {GL_FILL, GL_FILL}; // front, back
  GLenum shade_model = GL_SMOOTH;
  float point_size = 1.0f;
  float line_width = 1.0f;
  RasterModeState raster_modes; // stipples, smoothing, point parameters, offset (raster_modes.cpp)
  EvalState eval; // evaluator maps, enables and grids (GL 2.1 §5.1, src/state/eval.cpp)

  // ---- per-fragment operations and framebuffer control (Tables 6.20-6.22) ----
  bool depth_test = false;
  GLenum depth_func = GL_LESS;
  bool depth_mask = true;
  bool blend = false;
  GLenum blend_src_rgb = GL_ONE, blend_dst_rgb = GL_ZERO;
  GLenum blend_src_a = GL_ONE, blend_dst_a = GL_ZERO;
  GLenum blend_eq_rgb = GL_FUNC_ADD, blend_eq_a = GL_FUNC_ADD;
  float blend_color[4] = {0, 0, 0, 0};
  bool dither = true;
  bool color_mask[4] = {true, true, true, true};
  float clear_color[4] = {0, 0, 0, 0};
  double clear_depth = 1.0;
  GLint clear_stencil = 0;
  GLuint stencil_writemask = 0xffffffffu;
  bool scissor_test = false;
  GLint scissor_box[4] = {0, 0, 0, 0}; // x, y, width, height; the window size once current
  bool alpha_test = false;
  GLenum alpha_func = GL_ALWAYS;
  float alpha_ref = 0.0f;
  bool stencil_test = false;
  GLenum stencil_func = GL_ALWAYS;
  GLint stencil_ref = 0;
  GLuint stencil_value_mask = 0xffffffffu;
  GLenum stencil_fail = GL_KEEP, stencil_depth_fail = GL_KEEP, stencil_depth_pass = GL_KEEP;
  bool color_logic_op = false;
  bool index_logic_op = false; // state only: Pineda has no colour index mode (GL 2.1 §4.1.10)
  GLenum logic_op = GL_COPY;
  // GL 2.1 §4.2.1, §4.3.2: FRONT when the context has no back buffer, BACK otherwise; a
  // window-system layer that gives the context a back buffer sets both to GL_BACK.
  GLenum draw_buffer = GL_FRONT;
  GLenum read_buffer = GL_FRONT;

  // ---- pixel transfer, pixel maps and zoom (GL 2.1 §3.6.3, §3.6.4), src/state/pixel.cpp ----
  PixelTransfer pixel_transfer;
  // The current raster position (GL 2.1 §2.13), src/state/raster_pos.cpp.
  RasterPos raster_pos;

  // ---- hints (Table 6.38) ----
  GLenum hint_perspective = GL_DONT_CARE;
  GLenum hint_point_smooth = GL_DONT_CARE;
  GLenum hint_line_smooth = GL_DONT_CARE;
  GLenum hint_polygon_smooth = GL_DONT_CARE;
  GLenum hint_fog = GL_DONT_CARE;
  GLenum hint_generate_mipmap = GL_DONT_CARE;
  GLenum hint_texture_compression = GL_DONT_CARE;

  // ---- client state: pixel store, vertex arrays, buffer objects ----
  PixelStore pack, unpack;
  VertexArrays arrays;
  GLuint client_active_texture = 0;
  GLuint array_buffer = 0;
  GLuint element_array_buffer = 0;
  std::shared_ptr<SharedObjects> shared;
  std::unordered_map<GLuint, std::unique_ptr<BufferObject>>& buffers; // shared->buffers
  std::vector<ClientAttribFrame> client_attrib_stack;
  std::vector<AttribFrame> attrib_stack; // glPushAttrib (src/state/attrib.cpp)

  // ---- selection, feedback, occlusion queries, accumulation (src/state/select.h) ----
  RenderModeState render_mode;
  QueryState queries;
  AccumState accum;
  // ---- display lists (GL 2.1 §5.4), src/state/dlist.cpp ----
  DisplayListState dlist;

  // ---- derived state (validate.cpp) ----
  uint32_t dirty = kDirtyAll;
  RasterState raster;
  uint64_t raster_serial = 0; // advanced by every change of `raster`
  // The per-draw setup kept across draws (geometry/draw_cache.h, transform.cpp); made at the
  // first draw.
  std::unique_ptr<DrawCache> draw_cache;
  glm::mat4 mvp{1.0f}; // projection * modelview
  bool modelview_identity = true;
  bool need_eye = false; // eye coordinates needed (user clip planes)

  // Scratch space reused across draws so the hot path does not allocate.
  std::vector<InputVertex> fetch_scratch;
  std::vector<PVertex> pvert_scratch;
  std::vector<uint32_t> index_scratch;

  // Worker threads sharing large draws and clears (src/raster/workers.h), started on first use.
  RasterWorkers workers;
};

// The context current on this thread, or nullptr (GL 2.1 §2.1: commands without a current
// context have no effect).
Context* current_context();
void set_current_context(Context* ctx);

// Mark derived state stale.
inline void mark_dirty(Context* ctx, uint32_t bits) {
  ctx->dirty |= bits;
}

} // namespace pineda
