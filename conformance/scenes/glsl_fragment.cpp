// GLSL fragment shader outputs and built-ins (GL 2.1 §3.11.2): gl_FragDepth in the depth test
// and write, gl_PointCoord on point sprites, gl_FragData[n] into the draw buffers of a
// framebuffer object, and pixel rectangles (DrawPixels, Bitmap, CopyPixels) through a fragment
// shader. Each scene deletes its objects and puts back the state it touched.
#include "glsl_util.h"

using namespace scenes;
using namespace scenes::glsl;

namespace {

// A vertex shader passing the colour, unit 0's coordinates and the object position (varying p).
const char* kPassVs = "varying vec3 p;\n"
                      "void main() {\n"
                      "  gl_Position = ftransform();\n"
                      "  gl_FrontColor = gl_Color;\n"
                      "  gl_TexCoord[0] = gl_MultiTexCoord0;\n"
                      "  p = gl_Vertex.xyz;\n"
                      "}\n";

// An axis-aligned quad in window pixels at window depth z (ortho -1..1: object z = -(2z - 1)).
void rect_at(float x0, float y0, float x1, float y1, float z) {
  const float oz = 1.0f - 2.0f * z;
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex3f(x0, y0, oz);
  glTexCoord2f(1, 0);
  glVertex3f(x1, y0, oz);
  glTexCoord2f(1, 1);
  glVertex3f(x1, y1, oz);
  glTexCoord2f(0, 1);
  glVertex3f(x0, y1, oz);
  glEnd();
}

} // namespace

PINEDA_SCENE(glsl_frag_depth,
             "gl_FragDepth: waves of shader depth crossing flat and offset quads under LESS, "
             "values beyond [0,1] clamped, then GREATER with the depth buffer shown as grey",
             .gl_version = "2.1") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glClearDepth(1.0);
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  // Flat quads at interpolated depth, one with a polygon offset.
  glColor3f(0.2f, 0.3f, 0.8f);
  rect_at(8, 8, 248, 120, 0.45f);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, -20000.0f);
  glColor3f(0.8f, 0.3f, 0.2f);
  rect_at(8, 136, 248, 248, 0.55f);
  // The wave shader sets depth from the texture coordinate, ignoring the offset (§3.11.2).
  const GLuint p = gl.program(kPassVs, "varying vec3 p;\n"
                                       "void main() {\n"
                                       "  float d = 0.5 + 0.3 * sin(gl_TexCoord[0].s * 12.0)\n"
                                       "              + 0.3 * (gl_TexCoord[0].t - 0.5);\n"
                                       "  gl_FragDepth = d < 0.3 ? d - 1.0 : d;\n"
                                       "  gl_FragColor = vec4(d, 1.0 - d, 0.5, 1.0);\n"
                                       "}\n");
  rect_at(16, 16, 240, 240, 0.0f);
  gl.done(p);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(0.0f, 0.0f);
  // A strip whose shader depth exceeds 1 (clamped to 1): GREATER with depth writes off shows
  // which stored depths are below it.
  glDepthFunc(GL_GREATER);
  glDepthMask(GL_FALSE);
  const GLuint q = gl.program(kPassVs, "void main() {\n"
                                       "  gl_FragDepth = 2.0 * gl_TexCoord[0].s;\n"
                                       "  gl_FragColor = vec4(vec3(gl_TexCoord[0].s), 1.0);\n"
                                       "}\n");
  rect_at(100, 60, 156, 200, 0.0f);
  gl.done(q);
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
}

PINEDA_SCENE(glsl_frag_depth_prepass,
             "gl_FragDepth and discard in a depth-only pass (colour mask off), then EQUAL colour "
             "passes of the same shader, with the stencil test counting layers",
             .stencil_bits = 8, .gl_version = "2.1") {
  GL2 gl;
  clear_frame(0.1f, 0.1f, 0.1f);
  glClear(GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  const char* fs = "uniform float phase;\n"
                   "varying vec3 p;\n"
                   "void main() {\n"
                   "  vec2 c = gl_TexCoord[0].st - 0.5;\n"
                   "  float r = length(c);\n"
                   "  if (r > 0.5) discard;\n"
                   "  gl_FragDepth = 0.2 + r + 0.1 * sin(phase + 9.0 * c.x);\n"
                   "  gl_FragColor = vec4(0.5 + 0.5 * sin(phase), r * 2.0, 0.5 - c.y, 1.0);\n"
                   "}\n";
  const GLuint p = gl.program(kPassVs, fs);
  const GLint phase = gl.loc(p, "phase");
  const float boxes[3][4] = {{20, 20, 160, 160}, {90, 70, 230, 210}, {40, 110, 180, 250}};
  glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  for (int i = 0; i < 3; ++i) {
    gl.Uniform1f(phase, 1.3f * static_cast<float>(i));
    rect_at(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3], 0.0f);
  }
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDepthFunc(GL_EQUAL);
  glDepthMask(GL_FALSE);
  glEnable(GL_STENCIL_TEST);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glStencilOp(GL_KEEP, GL_INCR, GL_INCR);
  for (int i = 0; i < 3; ++i) {
    gl.Uniform1f(phase, 1.3f * static_cast<float>(i));
    rect_at(boxes[i][0], boxes[i][1], boxes[i][2], boxes[i][3], 0.0f);
  }
  gl.done(p);
  // The stencil counts (1, 2 and 3 layers) as tints over the right half.
  glDisable(GL_DEPTH_TEST);
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int n = 1; n <= 3; ++n) {
    glStencilFunc(GL_EQUAL, n, 0xff);
    glColor4f(0.3f * static_cast<float>(n), 0.3f * static_cast<float>(n), 1.0f, 0.5f);
    glRectf(128, 0, 256, 256);
  }
  glDisable(GL_BLEND);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
  glDisable(GL_STENCIL_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColor3f(1, 1, 1);
}

namespace {

// Point sprites of several sizes at fractional positions, coloured by gl_PointCoord and by
// gl_TexCoord[0] under COORD_REPLACE.
void point_coord_scene(GLenum origin) {
  GL2 gl;
  const auto point_parameteri = proc<PFNGLPOINTPARAMETERIPROC>("glPointParameteri");
  clear_frame(0, 0, 0);
  glEnable(GL_POINT_SPRITE);
  point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, static_cast<GLint>(origin));
  const GLuint p = gl.program(kPassVs, "#version 120\nvoid main() {\n"
                                       "  gl_FragColor = vec4(gl_PointCoord, gl_Color.b, 1.0);\n"
                                       "}\n");
  const float sizes[6] = {3.0f, 6.5f, 11.0f, 16.0f, 24.25f, 37.0f};
  for (int i = 0; i < 6; ++i) {
    glPointSize(sizes[i]);
    glBegin(GL_POINTS);
    glColor3f(0.0f, 0.0f, 0.2f * static_cast<float>(i));
    glVertex2f(20.0f + 40.0f * static_cast<float>(i) + 0.3f, 40.0f + 0.6f * static_cast<float>(i));
    glEnd();
  }
  gl.done(p);
  // gl_TexCoord[0] replaced by the sprite coordinates; unit 1's pass through.
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  const GLuint q = gl.program(
      "void main() { gl_Position = ftransform(); gl_TexCoord[0] = gl_MultiTexCoord0;\n"
      "  gl_TexCoord[1] = gl_MultiTexCoord1; }\n",
      "void main() {\n"
      "  vec4 t = gl_TexCoord[0];\n"
      "  float ring = step(0.25, distance(t.st, vec2(0.5)));\n"
      "  gl_FragColor = vec4(t.s * ring, t.t, t.q * 0.5 + t.p + gl_TexCoord[1].x, 1.0);\n"
      "}\n");
  const auto multi_tex_coord = proc<PFNGLMULTITEXCOORD2FARBPROC>("glMultiTexCoord2f");
  for (int i = 0; i < 6; ++i) {
    glPointSize(sizes[i]);
    glBegin(GL_POINTS);
    glTexCoord2f(0.9f, 0.9f);
    multi_tex_coord(GL_TEXTURE1, 0.1f * static_cast<float>(i), 0.0f);
    glVertex2f(20.0f + 40.0f * static_cast<float>(i) + 0.5f, 140.0f + 0.3f * static_cast<float>(i));
    glEnd();
  }
  gl.done(q);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_FALSE);
  // Aliased points that are not sprites: llvmpipe gives gl_PointCoord across their square too
  // (GL 2.1 leaves it undefined).
  glDisable(GL_POINT_SPRITE);
  const GLuint r = gl.program(kPassVs, "#version 120\nvoid main() {\n"
                                       "  gl_FragColor = vec4(gl_PointCoord, 0.5, 1.0);\n"
                                       "}\n");
  const float aliased[5] = {2.0f, 3.0f, 5.0f, 8.0f, 13.0f};
  for (int i = 0; i < 5; ++i) {
    glPointSize(aliased[i]);
    glBegin(GL_POINTS);
    glVertex2f(30.0f + 45.0f * static_cast<float>(i) + 0.25f, 220.0f + 0.5f);
    glEnd();
  }
  gl.done(r);
  point_parameteri(GL_POINT_SPRITE_COORD_ORIGIN, GL_UPPER_LEFT);
  glPointSize(1.0f);
  glColor3f(1, 1, 1);
}

} // namespace

PINEDA_SCENE(glsl_point_coord_upper_left,
             "gl_PointCoord and COORD_REPLACE gl_TexCoord[0] on point sprites of whole and "
             "fractional sizes, POINT_SPRITE_COORD_ORIGIN UPPER_LEFT; gl_PointCoord on aliased "
             "points that are not sprites",
             .gl_version = "2.1") {
  point_coord_scene(GL_UPPER_LEFT);
}

PINEDA_SCENE(glsl_point_coord_lower_left,
             "gl_PointCoord and COORD_REPLACE gl_TexCoord[0] on point sprites, "
             "POINT_SPRITE_COORD_ORIGIN LOWER_LEFT",
             .gl_version = "2.1") {
  point_coord_scene(GL_LOWER_LEFT);
}

namespace {

struct FboCommands {
  PFNGLGENFRAMEBUFFERSPROC gen = proc<PFNGLGENFRAMEBUFFERSPROC>("glGenFramebuffers");
  PFNGLDELETEFRAMEBUFFERSPROC del = proc<PFNGLDELETEFRAMEBUFFERSPROC>("glDeleteFramebuffers");
  PFNGLBINDFRAMEBUFFERPROC bind = proc<PFNGLBINDFRAMEBUFFERPROC>("glBindFramebuffer");
  PFNGLFRAMEBUFFERTEXTURE2DPROC tex2d =
      proc<PFNGLFRAMEBUFFERTEXTURE2DPROC>("glFramebufferTexture2D");
  PFNGLFRAMEBUFFERRENDERBUFFERPROC rb =
      proc<PFNGLFRAMEBUFFERRENDERBUFFERPROC>("glFramebufferRenderbuffer");
  PFNGLGENRENDERBUFFERSPROC gen_rb = proc<PFNGLGENRENDERBUFFERSPROC>("glGenRenderbuffers");
  PFNGLDELETERENDERBUFFERSPROC del_rb = proc<PFNGLDELETERENDERBUFFERSPROC>("glDeleteRenderbuffers");
  PFNGLBINDRENDERBUFFERPROC bind_rb = proc<PFNGLBINDRENDERBUFFERPROC>("glBindRenderbuffer");
  PFNGLRENDERBUFFERSTORAGEPROC storage =
      proc<PFNGLRENDERBUFFERSTORAGEPROC>("glRenderbufferStorage");
  PFNGLCHECKFRAMEBUFFERSTATUSPROC status =
      proc<PFNGLCHECKFRAMEBUFFERSTATUSPROC>("glCheckFramebufferStatus");
  PFNGLDRAWBUFFERSPROC draw_buffers = proc<PFNGLDRAWBUFFERSPROC>("glDrawBuffers");
};

GLuint target_texture(GLenum format) {
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTexImage2D(GL_TEXTURE_2D, 0, static_cast<GLint>(format), 64, 64, 0, GL_RGBA, GL_UNSIGNED_BYTE,
               nullptr);
  return t;
}

// Shows the 64x64 texture at (x, y) in the window, 1:1.
void show_texture(GLuint t, float x, float y) {
  glEnable(GL_TEXTURE_2D);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  glBegin(GL_QUADS);
  glTexCoord2f(0, 0);
  glVertex2f(x, y);
  glTexCoord2f(1, 0);
  glVertex2f(x + 64, y);
  glTexCoord2f(1, 1);
  glVertex2f(x + 64, y + 64);
  glTexCoord2f(0, 1);
  glVertex2f(x, y + 64);
  glEnd();
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glDisable(GL_TEXTURE_2D);
}

} // namespace

PINEDA_SCENE(glsl_frag_data,
             "gl_FragData[0..3] into four draw buffers (RGBA8, RGB8, RGBA8 with NONE between, "
             "blended, depth-tested), then gl_FragColor into every buffer, each shown",
             .gl_version = "2.1") {
  GL2 gl;
  const FboCommands fbo;
  clear_frame(0, 0, 0);
  const GLenum formats[4] = {GL_RGBA8, GL_RGB8, GL_RGBA8, GL_RGBA8};
  GLuint tex[4];
  for (int i = 0; i < 4; ++i)
    tex[i] = target_texture(formats[i]);
  GLuint f = 0, depth = 0;
  fbo.gen(1, &f);
  fbo.bind(GL_FRAMEBUFFER, f);
  for (int i = 0; i < 4; ++i)
    fbo.tex2d(GL_FRAMEBUFFER, static_cast<GLenum>(GL_COLOR_ATTACHMENT0 + i), GL_TEXTURE_2D, tex[i],
              0);
  fbo.gen_rb(1, &depth);
  fbo.bind_rb(GL_RENDERBUFFER, depth);
  fbo.storage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, 64, 64);
  fbo.rb(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  // Draw buffer 2 is NONE: gl_FragData[2] goes nowhere, gl_FragData[3] to attachment 3.
  const GLenum bufs[4] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_NONE,
                          GL_COLOR_ATTACHMENT3};
  fbo.draw_buffers(4, bufs);
  if (fbo.status(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error("framebuffer incomplete");
  glViewport(0, 0, 64, 64);
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glOrtho(0, 64, 0, 64, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  glLoadIdentity();
  glClearColor(0.2f, 0.4f, 0.6f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  const GLuint p = gl.program(kPassVs, "varying vec3 p;\n"
                                       "void main() {\n"
                                       "  vec2 t = gl_TexCoord[0].st;\n"
                                       "  gl_FragData[0] = vec4(t, gl_Color.b, 0.7);\n"
                                       "  gl_FragData[1] = vec4(gl_Color.rgb, 0.4);\n"
                                       "  gl_FragData[2] = vec4(1.0);\n"
                                       "  gl_FragData[3] = vec4(fract(p.xy / 8.0), 1.0 - t.x, "
                                       "t.y);\n"
                                       "}\n");
  for (int i = 0; i < 6; ++i) {
    palette_color(i);
    const float x = 4.0f + 8.0f * static_cast<float>(i), y = 2.0f + 6.0f * static_cast<float>(i);
    rect_at(x, y, x + 28.0f, y + 24.0f, 0.8f - 0.1f * static_cast<float>(i % 3));
  }
  gl.done(p);
  // gl_FragColor to every draw buffer.
  const GLuint q = gl.program(kPassVs, "void main() {\n"
                                       "  gl_FragColor = vec4(1.0, gl_TexCoord[0].s, 0.2, 0.8);\n"
                                       "}\n");
  rect_at(40, 40, 62, 62, 0.1f);
  gl.done(q);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  fbo.bind(GL_FRAMEBUFFER, 0);
  window_projection(frame);
  glColor4f(1, 1, 1, 1);
  for (int i = 0; i < 4; ++i)
    show_texture(tex[i], 8.0f + 62.0f * static_cast<float>(i), 96.0f);
  fbo.del(1, &f);
  fbo.del_rb(1, &depth);
  glDeleteTextures(4, tex);
}

PINEDA_SCENE(glsl_pixel_rectangles,
             "DrawPixels, Bitmap and CopyPixels fragments through a fragment shader: the pixel's "
             "colour as gl_Color, the raster position's texture coordinates, gl_FragCoord",
             .gl_version = "2.1") {
  GL2 gl;
  clear_frame(0, 0, 0);
  // A 48x40 image with a gradient and a checker.
  std::vector<unsigned char> img(48 * 40 * 4);
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 48; ++x) {
      unsigned char* t = &img[static_cast<size_t>((y * 48 + x) * 4)];
      t[0] = static_cast<unsigned char>(x * 5);
      t[1] = static_cast<unsigned char>(y * 6);
      t[2] = static_cast<unsigned char>(((x / 6 + y / 5) % 2) * 200);
      t[3] = 255;
    }
  const GLuint p =
      gl.program(nullptr, "void main() {\n"
                          "  vec2 w = fract(gl_FragCoord.xy / 16.0);\n"
                          "  gl_FragColor = vec4(gl_Color.r, gl_Color.g * w.x,\n"
                          "                      gl_Color.b * 0.5 + gl_TexCoord[0].s,\n"
                          "                      1.0);\n"
                          "}\n");
  glTexCoord2f(0.4f, 0.0f);
  glRasterPos2i(10, 10);
  glDrawPixels(48, 40, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  // Zooms whose group edges never fall on pixel centres (conformance/README.md).
  glPixelZoom(2.0f, 1.4f);
  glTexCoord2f(0.2f, 0.0f);
  glRasterPos2i(80, 10);
  glDrawPixels(48, 40, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelZoom(1.0f, 1.0f);
  gl.done(p);
  // A bitmap in the raster colour. (llvmpipe hands its fragments its own bitmap texture's
  // coordinates as gl_TexCoord[0] instead of the raster position's, §3.7: this shader does not
  // read them.)
  const GLuint pb = gl.program(nullptr, "void main() {\n"
                                        "  vec2 w = fract(gl_FragCoord.xy / 8.0);\n"
                                        "  gl_FragColor = vec4(gl_Color.rg * w, gl_Color.b, 1.0);\n"
                                        "}\n");
  std::vector<GLubyte> bits(32 * 32 / 8);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x)
      if ((x - 16) * (x - 16) + (y - 16) * (y - 16) < 200 && ((x + y) % 3) != 0)
        bits[static_cast<size_t>(y * 4 + x / 8)] |= static_cast<GLubyte>(0x80u >> (x % 8));
  glColor3f(0.9f, 0.7f, 0.4f);
  glTexCoord2f(0.1f, 0.0f);
  glRasterPos2i(190, 20);
  glBitmap(32, 32, 0, 0, 0, 0, bits.data());
  gl.done(pb);
  // CopyPixels of the first image, shaded again.
  const GLuint pc =
      gl.program(nullptr, "void main() {\n"
                          "  vec2 w = fract(gl_FragCoord.xy / 16.0);\n"
                          "  gl_FragColor = vec4(gl_Color.r, gl_Color.g * w.x,\n"
                          "                      gl_Color.b * 0.5 + gl_TexCoord[0].s,\n"
                          "                      1.0);\n"
                          "}\n");
  glTexCoord2f(0.5f, 0.0f);
  glRasterPos2i(20, 120);
  glCopyPixels(10, 10, 48, 40, GL_COLOR);
  gl.done(pc);
  // A shader writing gl_FragDepth under the depth test for a DrawPixels image over a quad.
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glColor3f(0.3f, 0.3f, 0.9f);
  rect_at(120, 120, 240, 240, 0.5f);
  const GLuint q = gl.program(nullptr, "void main() {\n"
                                       "  gl_FragDepth = fract(gl_FragCoord.x / 24.0);\n"
                                       "  gl_FragColor = gl_Color;\n"
                                       "}\n");
  glRasterPos2i(130, 140);
  glPixelZoom(2.0f, 2.0f);
  glDrawPixels(48, 40, GL_RGBA, GL_UNSIGNED_BYTE, img.data());
  glPixelZoom(1.0f, 1.0f);
  gl.done(q);
  glDisable(GL_DEPTH_TEST);
  glColor3f(1, 1, 1);
  glTexCoord2f(0, 0);
}
