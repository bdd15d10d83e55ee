// The GL state machine of one context: the attribute groups of the GL 2.1 §6.2 state tables,
// each declared in its area's header, the state no attribute group saves, and the state
// derived from them for the draw. Front-end files (src/state/*.cpp) change it through the
// entry-point skeleton in api_util.h; the areas' table (area.h) tells enable.cpp, get.cpp,
// attrib.cpp and validate.cpp what each area has.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include <glm/mat4x4.hpp>

#include "core/limits.h"
#include "core/raster_state.h"
#include "framebuffer/framebuffer.h"
#include "draw/draw.h"
#include "raster/workers.h"
#include "state/attrib.h"
#include "state/current.h"
#include "state/dlist_state.h"
#include "state/eval.h"
#include "state/fog.h"
#include "state/fragment_state.h"
#include "state/framebuffer_object.h"
#include "state/hints.h"
#include "state/lighting.h"
#include "state/multisample.h"
#include "state/pixel.h"
#include "state/program.h"
#include "state/rasterization.h"
#include "state/select.h"
#include "state/texenv.h"
#include "state/transform.h"
#include "state/varray.h"
#include "state/viewport.h"
#include "state/texture_object.h"

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
  kDirtyProgram = 1u << 11,    // the current program, its link, the vertex shader enables
  kDirtyLighting = 1u << 16,   // lighting state, or normalize / rescale-normal enables
  kDirtyAll = 0xffffffffu,
};

// The objects a share group of contexts has in common (GLX 1.4 §3.3.7 share lists): buffer
// objects and display lists. Contexts of one group on different threads must not create or delete
// objects concurrently (the container itself is not locked).
struct SharedObjects {
  std::unordered_map<GLuint, std::unique_ptr<BufferObject>> buffers;
  // Texture objects (GL 2.1 §3.8.12) by name; name 0 is each context's default object.
  // Shared pointers: a framebuffer attachment keeps its texture alive after the name is
  // deleted (ARB_framebuffer_object §4.4.2.3).
  std::unordered_map<GLuint, std::shared_ptr<TextureObject>> textures;
  // Renderbuffers (ARB_framebuffer_object §4.4.2.1) by name.
  std::unordered_map<GLuint, std::shared_ptr<Renderbuffer>> renderbuffers;
  // Bumped on every change of any texture image or parameter (also of default objects) or
  // renderbuffer storage, so views made by make_sampler_view (state/texture_object.h) and the
  // framebuffers derived from attached images (framebuffer_object.h) know when to be remade.
  uint64_t texture_generation = 0;
  DisplayLists lists; // src/state/dlist.cpp
  GlslObjects glsl;   // shader and program objects (src/state/shader_object.cpp)
};

// The colour buffers of GL 2.1 table 4.4 (no auxiliary buffers exist: GL_AUX_BUFFERS is 0).
enum ColorBufferBit : uint32_t {
  kColorBufferFrontLeft = 1u << 0,
  kColorBufferFrontRight = 1u << 1,
  kColorBufferBackLeft = 1u << 2,
  kColorBufferBackRight = 1u << 3,
};

struct Context {
  Context();
  // A context in the share group that owns `objects`.
  explicit Context(std::shared_ptr<SharedObjects> objects);
  ~Context();
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  // ---- window system (set by osmesa.cpp / glx through winsys/common/surface_binding.h) ----
  Framebuffer window; // the drawable's buffers
  // ---- the framebuffers the commands use (framebuffer_object.h: sync_framebuffers) ----
  Framebuffer fb;       // drawing: the window's draw buffers or a framebuffer object's images
  Framebuffer read_fb;  // reading: its colour is the read buffer
  FramebufferState fbo; // framebuffer and renderbuffer objects, bindings
  bool ever_current = false;
  // The colour buffers the window has (GL 2.1 table 4.4), kColorBuffer* bits: window.color is
  // the front left buffer unless a window-system layer says otherwise.
  uint32_t color_buffers = kColorBufferFrontLeft;
  // Called by glFlush and glFinish when set (GLX: a single-buffered window or a pixmap shows
  // what was rendered once the commands are flushed, GL 2.1 §5.5).
  void (*present_front)(Context*) = nullptr;
  // Called when DrawBuffer/ReadBuffer select window.front_color of a double-buffered drawable,
  // before it is used (GLX: the front buffer's contents may still have to be fetched).
  void (*front_selected)(Context*) = nullptr;

  // ---- errors (GL 2.1 §2.5): the first error is kept until glGetError ----
  GLenum error = GL_NO_ERROR;

  // ---- the attribute groups of the GL 2.1 §6.2 state tables ----
  CurrentGroup current;     // Table 6.5, current.h
  TransformGroup transform; // Table 6.7, transform.h
  ViewportGroup viewport;   // Table 6.8, viewport.h
  LightingGroup lighting;   // Tables 6.9-6.11, lighting.h
  FogGroup fog;             // Table 6.11, fog.h
  PointGroup point;         // Table 6.12, rasterization.h
  LineGroup line;           // Table 6.13
  PolygonGroup polygon;     // Table 6.14
  PolygonStippleGroup polygon_stipple;
  MultisampleGroup multisample;  // Table 6.15, multisample.h
  TextureGroup texture;          // Tables 6.15-6.19, texenv.h
  ScissorGroup scissor;          // Table 6.20, fragment_state.h
  ColorBufferGroup color_buffer; // Tables 6.20-6.22
  DepthGroup depth;              // Tables 6.20-6.22
  StencilGroup stencil;          // Tables 6.20-6.22
  AccumGroup accum;              // Table 6.22
  PixelGroup pixel;              // Tables 6.24, 6.27, pixel.h
  EvalGroup eval;                // Table 6.28, eval.h
  HintGroup hint;                // Table 6.32, hints.h
  ListGroup list;                // Table 6.31, dlist_state.h
  // Client groups (glPushClientAttrib).
  PixelStoreGroup pixel_store; // Table 6.23, pixel.h
  VertexArrayGroup arrays;     // Tables 6.6-6.9, varray.h
  // Generic vertex attributes (program.h): current values (CURRENT_BIT) and arrays (client).
  VertexAttribCurrentGroup vertex_attrib;
  VertexAttribArrayGroup attrib_arrays;

  // ---- state no attribute group saves ----
  BeginEndState imm; // the primitive between Begin and End (§2.6), current.h
  MatrixStack modelview{kModelviewStackDepth}; // §2.11.2, transform.h
  MatrixStack projection{kProjectionStackDepth};
  MatrixStack texture_matrix[kMaxTexUnits] = {
      MatrixStack(kTextureStackDepth), MatrixStack(kTextureStackDepth),
      MatrixStack(kTextureStackDepth), MatrixStack(kTextureStackDepth)};
  PixelMaps pixel_maps;        // Table 6.25, pixel/transfer.h
  TextureState texobj;         // default and proxy objects, bindings (texture_object.h)
  RenderModeState render_mode; // Table 6.31 selection and feedback, select.h
  QueryState queries;          // occlusion queries (§4.1.7), select.h
  DisplayListState dlist;      // lists being compiled or executed (§5.4), dlist_state.h
  ProgramState program;        // the current program (§2.15.2), program.h
  std::shared_ptr<SharedObjects> shared;
  std::unordered_map<GLuint, std::unique_ptr<BufferObject>>& buffers; // shared->buffers
  std::vector<AttribFrame> attrib_stack;                              // glPushAttrib (attrib.cpp)
  std::vector<AttribFrame> client_attrib_stack; // glPushClientAttrib (attrib.cpp)

  // ---- derived state (validate.cpp, the areas' derive functions) ----
  uint32_t dirty = kDirtyAll;
  // SharedObjects::texture_generation at the last validation (validate.cpp).
  uint64_t validated_generation = ~uint64_t{0};
  RasterState raster;
  uint64_t raster_serial = 0;       // advanced by every change of `raster`
  glm::mat4 mvp{1.0f};              // projection * modelview
  glm::mat4 modelview_matrix{1.0f}; // the model-view stack's top, where the draws read it
  LightSetup light_setup;           // the lighting area's (lighting.cpp)
  TexPipeDerived texpipe;           // the texture area's (validate_texpipe.cpp)
  std::unique_ptr<ProgramDerived> program_draw; // the program area's (program_draw.h)

  // What the draw home keeps across draws (draw/draw.h): the draw cache, processed vertices.
  DrawContext draw;

  // Scratch space reused across draws so the hot path does not allocate.
  std::vector<InputVertex> fetch_scratch;
  std::vector<uint32_t> index_scratch;
  std::vector<float> generic_scratch; // generic attributes of an array draw (vertex_attrib.cpp)

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
