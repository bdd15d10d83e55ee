// Framebuffer and renderbuffer objects (ARB_framebuffer_object and EXT_framebuffer_object: the
// GL 3.0 §4.4 semantics on GL 2.1): the objects, the bindings, attachment and framebuffer
// completeness (§4.4.4), and the derivation of the two plain Framebuffer descriptions the
// rest of Pineda reads, Context::fb (drawing) and Context::read_fb (reading), from either the
// window's buffers or a framebuffer object's attached images. Commands in
// framebuffer_object.cpp (objects, attachments, queries) and draw_read_buffer.cpp (draw and
// read buffers).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <unordered_map>
#include <vector>

#include "core/limits.h"
#include "framebuffer/framebuffer.h"
#include "texture/sampler.h"

namespace pineda {

struct Context;
struct TextureObject;

// A renderbuffer (§4.4.2.1): one image of a colour, depth, stencil or depth-stencil format.
// Colour is stored as texture images are (4 bytes a pixel, expanded by base format), depth
// and stencil as the window's depth and stencil buffers, so the back end draws into either
// with the same loops.
struct Renderbuffer {
  GLuint name = 0;
  bool bound_once = false; // IsRenderbuffer is true from the first BindRenderbuffer on
  GLenum internal_format = GL_RGBA;
  int width = 0, height = 0;
  TexBase base = TexBase::RGBA; // colour formats
  bool color = false;
  uint8_t red_size = 0, green_size = 0, blue_size = 0, alpha_size = 0;
  uint8_t depth_size = 0, stencil_size = 0;
  std::vector<uint8_t> rgba;
  std::vector<uint32_t> depth; // depth_size bits a value
  std::vector<uint8_t> stencil;
};

// One attachment point of a framebuffer object (Table 6.X "Framebuffer (state per attachment
// point)").
struct Attachment {
  GLenum type = GL_NONE; // FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE: NONE, TEXTURE or RENDERBUFFER
  GLuint name = 0;
  // The objects stay alive while attached, even when their names are deleted (§4.4.2.3).
  std::shared_ptr<TextureObject> texture;
  std::shared_ptr<Renderbuffer> renderbuffer;
  int level = 0;
  int face = 0;  // cube map face index, 0 for other targets
  int layer = 0; // 3D texture slice (FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER)
  GLenum textarget = GL_NONE;
};

// Attachment points: COLOR_ATTACHMENT0..7, DEPTH_ATTACHMENT, STENCIL_ATTACHMENT.
constexpr int kAttachDepth = kMaxColorAttachments;
constexpr int kAttachStencil = kMaxColorAttachments + 1;
constexpr int kAttachCount = kMaxColorAttachments + 2;

struct FramebufferObject {
  GLuint name = 0;
  bool bound_once = false;
  Attachment att[kAttachCount];
  // Per framebuffer object (§4.2.1, §4.3.2): while it is the draw (read) framebuffer these
  // live in ColorBufferGroup::draw_buffers (PixelGroup::read_buffer), so that glPushAttrib
  // saves the bound framebuffer's values; they are kept here while it is not bound.
  GLenum draw_buffers[kMaxDrawBuffers] = {GL_COLOR_ATTACHMENT0};
  GLenum read_buffer = GL_COLOR_ATTACHMENT0;
};

// An attached image as the back end addresses it (sizes without border).
struct AttachedImage {
  int width = 0, height = 0;
  GLenum internal_format = 0;
  bool color = false;
  TexBase base = TexBase::RGBA;
  uint8_t* rgba = nullptr; // colour: 4 bytes a pixel
  ptrdiff_t rgba_stride = 0;
  uint32_t* depth = nullptr;
  int depth_bits = 0, depth_stride = 0;
  uint8_t* stencil = nullptr;
  int stencil_stride = 0;
  uint8_t red_size = 0, green_size = 0, blue_size = 0, alpha_size = 0;
  uint8_t depth_size = 0, stencil_size = 0;
};

// The renderbuffer named `name`, or null.
std::shared_ptr<Renderbuffer> find_renderbuffer(Context* ctx, GLuint name);

// Component sizes as the queries report them: Pineda stores 8 bits a colour component at most.
inline uint8_t reported_bits(int bits) {
  return uint8_t(bits < 8 ? bits : 8);
}

// The image an attachment names, or false when it names none (no object, or a texture level
// or slice that has no image).
bool attached_image(const Attachment& a, AttachedImage& out);

// Per-context framebuffer state (Table 6.X "Framebuffer"): the bindings, the objects and what
// is derived from them. Bindings are not saved by glPushAttrib (ARB_framebuffer_object).
struct FramebufferState {
  GLuint draw_binding = 0, read_binding = 0; // DRAW_FRAMEBUFFER_BINDING, READ_...
  GLuint renderbuffer_binding = 0;           // RENDERBUFFER_BINDING
  // Framebuffer objects are per context (ARB_framebuffer_object Issue: not shared).
  std::unordered_map<GLuint, std::unique_ptr<FramebufferObject>> objects;
  // The window's draw and read buffers while a framebuffer object is bound in their place.
  GLenum window_draw_buffers[kMaxDrawBuffers] = {GL_FRONT};
  GLenum window_read_buffer = GL_FRONT;

  // ---- derived (sync_framebuffers) ----
  bool stale = true;
  uint64_t generation = ~uint64_t{0}; // SharedObjects::texture_generation when derived
  GLenum draw_status = GL_FRAMEBUFFER_COMPLETE, read_status = GL_FRAMEBUFFER_COMPLETE;
  // Colour images of the draw framebuffer whose base format is not RGBA: drawing writes all
  // four bytes, so after drawing they are brought back to their base format's expansion
  // (Table 3.23) before anything reads them (normalize_drawn_images).
  std::vector<Attachment> expand_after_drawing;
  bool drawn = false; // drawing touched the draw framebuffer since the last expansion
};

// Re-derives Context::fb and Context::read_fb when a binding, an attachment, a draw or read
// buffer, the window's buffers or an object of the share group changed.
void sync_framebuffers(Context* ctx);
// Marks the derived framebuffers stale (and kDirtyFramebuffer).
void framebuffers_changed(Context* ctx);

// The draw (read) framebuffer for a command that writes (reads) it: false with
// INVALID_FRAMEBUFFER_OPERATION when it is not complete (§4.4.4), and then the command does
// nothing. A drawing command also records that the draw framebuffer was written.
bool draw_framebuffer_ready(Context* ctx, const char* func);
bool read_framebuffer_ready(Context* ctx, const char* func);

// Brings colour images that drawing wrote in all four bytes back to their base format
// (FramebufferState::expand_after_drawing); before anything reads them or they stop being
// drawn into.
void normalize_drawn_images(Context* ctx);

// DeleteTextures: a deleted texture attached to the bound draw or read framebuffer is detached
// from it (§4.4.2.3); other framebuffers keep it.
void detach_deleted_texture(Context* ctx, const TextureObject* tex);

// The framebuffer object bound as draw (read) framebuffer, or nullptr for the window.
FramebufferObject* draw_framebuffer_object(Context* ctx);
FramebufferObject* read_framebuffer_object(Context* ctx);

struct StateArea;
extern const StateArea kFramebufferObjectArea; // framebuffer_object.cpp

} // namespace pineda
