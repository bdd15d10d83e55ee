// Copies of rectangles between framebuffers (EXT_framebuffer_blit, ARB_framebuffer_object
// §4.3.3 BlitFramebuffer): colour scaled with NEAREST or LINEAR filtering, depth and stencil
// with NEAREST, mirrored when a rectangle's ends are swapped; only the scissor test applies.
#pragma once

#include <GL/gl.h>

#include "framebuffer/framebuffer.h"

namespace pineda {

// One blit as the state layer validated it (state/framebuffer_object.cpp).
struct BlitRequest {
  int src[4] = {}; // srcX0, srcY0, srcX1, srcY1
  int dst[4] = {}; // dstX0, dstY0, dstX1, dstY1
  bool color = false, depth = false, stencil = false;
  bool linear = false; // LINEAR (colour only); NEAREST otherwise
  bool scissor_test = false;
  int scissor[4] = {};
};

// Blits from `src` (its colour is the read buffer) into every colour buffer of `dst` (the
// primary one and `more`) and into its depth and stencil buffers as the request says. The
// source is read completely before anything is written, so overlapping rectangles of one
// framebuffer copy the old contents. Destination pixels whose source pixel lies outside the
// read framebuffer are not written.
void blit_framebuffer(const Framebuffer& src, const Framebuffer& dst, const BlitRequest& r);

} // namespace pineda
