// The extensions GL_EXTENSIONS advertises (src/api/extensions.txt): every command their gl.xml
// <require> blocks name is exported, the aliases behave as the core commands they stand for,
// and the commands of their own (src/state/ext_commands.cpp) do what the extensions say.
#include "api_fixture.h"

#include <GL/glext.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

std::string read_registry() {
  std::ifstream in(PINEDA_GL_XML);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The value of attribute `name` in the tag that starts at `at`, or "" if the tag has none.
std::string tag_attribute(const std::string& xml, size_t at, const std::string& name) {
  const size_t close = xml.find('>', at);
  const size_t a = xml.find(" " + name + "=\"", at);
  if (a == std::string::npos || a > close) return "";
  const size_t b = a + name.size() + 3;
  return xml.substr(b, xml.find('"', b) - b);
}

// The desktop-GL commands an extension requires: the <command> entries of its <require>
// blocks that are for every API or for "gl". Sets *found when the extension exists.
std::vector<std::string> extension_commands(const std::string& xml, const std::string& ext,
                                            bool* found) {
  std::vector<std::string> out;
  const size_t at = xml.find("<extension name=\"" + ext + "\"");
  *found = at != std::string::npos;
  if (!*found) return out;
  // <extension name="..." supported="gl"/> requires nothing.
  const size_t open_end = xml.find('>', at);
  if (xml[open_end - 1] == '/') return out;
  const size_t end = xml.find("</extension>", at);
  for (size_t r = xml.find("<require", at); r != std::string::npos && r < end;
       r = xml.find("<require", r + 1)) {
    const std::string api = tag_attribute(xml, r, "api");
    const size_t rend = xml.find("</require>", r);
    if (!api.empty() && api != "gl") continue;
    for (size_t c = xml.find("<command name=\"", r); c != std::string::npos && c < rend;
         c = xml.find("<command name=\"", c + 1)) {
      const size_t b = c + 15;
      out.push_back(xml.substr(b, xml.find('"', b) - b));
    }
  }
  return out;
}

std::vector<std::string> advertised() {
  std::istringstream words(reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS)));
  std::vector<std::string> out;
  for (std::string w; words >> w;)
    out.push_back(w);
  return out;
}

template <typename F> F proc(const char* name) {
  return reinterpret_cast<F>(OSMesaGetProcAddress(name));
}

using Extensions = GLTest;

TEST_F(Extensions, EveryCommandOfEveryAdvertisedExtensionIsExported) {
  const std::string xml = read_registry();
  ASSERT_FALSE(xml.empty()) << "could not read " << PINEDA_GL_XML;
  // Names drivers advertise that never entered the registry (extensions.txt "unregistered").
  const std::set<std::string> unregistered = {"GL_EXT_texture_edge_clamp"};
  const std::vector<std::string> exts = advertised();
  EXPECT_GE(exts.size(), 40u);
  std::set<std::string> unique(exts.begin(), exts.end());
  EXPECT_EQ(unique.size(), exts.size()) << "an extension is listed twice";
  size_t commands = 0;
  for (const std::string& ext : exts) {
    bool found = false;
    for (const std::string& name : extension_commands(xml, ext, &found)) {
      ++commands;
      EXPECT_NE(OSMesaGetProcAddress(name.c_str()), nullptr) << ext << ": " << name;
    }
    EXPECT_TRUE(found || unregistered.count(ext) != 0) << ext << " is not in gl.xml";
  }
  EXPECT_GE(commands, 130u);
  // Not advertised, so not exported: the entry points of GL_EXT_polygon_offset.
  EXPECT_EQ(OSMesaGetProcAddress("glPolygonOffsetEXT"), nullptr);
}

TEST_F(Extensions, BufferObjectAliasesAreTheCoreCommands) {
  auto gen = proc<PFNGLGENBUFFERSARBPROC>("glGenBuffersARB");
  auto bind = proc<PFNGLBINDBUFFERARBPROC>("glBindBufferARB");
  auto data = proc<PFNGLBUFFERDATAARBPROC>("glBufferDataARB");
  auto is = proc<PFNGLISBUFFERARBPROC>("glIsBufferARB");
  auto map = proc<PFNGLMAPBUFFERARBPROC>("glMapBufferARB");
  auto unmap = proc<PFNGLUNMAPBUFFERARBPROC>("glUnmapBufferARB");
  auto core_param = proc<PFNGLGETBUFFERPARAMETERIVPROC>("glGetBufferParameteriv");
  ASSERT_TRUE(gen && bind && data && is && map && unmap && core_param);
  GLuint b = 0;
  gen(1, &b);
  bind(GL_ARRAY_BUFFER_ARB, b);
  const unsigned char bytes[4] = {1, 2, 3, 4};
  data(GL_ARRAY_BUFFER_ARB, 4, bytes, GL_STATIC_DRAW_ARB);
  EXPECT_TRUE(is(b));
  GLint size = 0;
  core_param(GL_ARRAY_BUFFER, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, 4);
  GLint bound = 0;
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &bound);
  EXPECT_EQ(bound, static_cast<GLint>(b));
  auto* p = static_cast<unsigned char*>(map(GL_ARRAY_BUFFER_ARB, GL_READ_ONLY_ARB));
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(p[2], 3);
  EXPECT_TRUE(unmap(GL_ARRAY_BUFFER_ARB));
  // Errors are the core command's: a second unmap is INVALID_OPERATION.
  EXPECT_FALSE(unmap(GL_ARRAY_BUFFER_ARB));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST_F(Extensions, StateAliasesSetTheCoreState) {
  proc<PFNGLACTIVETEXTUREARBPROC>("glActiveTextureARB")(GL_TEXTURE2_ARB);
  GLint unit = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
  EXPECT_EQ(unit, GL_TEXTURE2);
  proc<PFNGLACTIVETEXTUREARBPROC>("glActiveTextureARB")(GL_TEXTURE0_ARB);

  proc<PFNGLBLENDEQUATIONEXTPROC>("glBlendEquationEXT")(GL_MAX_EXT);
  GLint eq = 0;
  glGetIntegerv(GL_BLEND_EQUATION, &eq);
  EXPECT_EQ(eq, GL_MAX);
  proc<PFNGLBLENDEQUATIONEXTPROC>("glBlendEquationEXT")(GL_LINE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));

  proc<PFNGLPOINTPARAMETERFARBPROC>("glPointParameterfARB")(GL_POINT_SIZE_MIN_ARB, 2.5f);
  GLfloat f = 0;
  glGetFloatv(GL_POINT_SIZE_MIN, &f);
  EXPECT_EQ(f, 2.5f);
  proc<PFNGLPOINTPARAMETERFEXTPROC>("glPointParameterfEXT")(GL_POINT_SIZE_MIN_EXT, 1.5f);
  glGetFloatv(GL_POINT_SIZE_MIN, &f);
  EXPECT_EQ(f, 1.5f);

  proc<PFNGLWINDOWPOS2IARBPROC>("glWindowPos2iARB")(5, 7);
  GLfloat rp[4] = {};
  glGetFloatv(GL_CURRENT_RASTER_POSITION, rp);
  EXPECT_EQ(rp[0], 5.0f);
  EXPECT_EQ(rp[1], 7.0f);

  proc<PFNGLFOGCOORDFEXTPROC>("glFogCoordfEXT")(0.25f);
  glGetFloatv(GL_CURRENT_FOG_COORD, &f);
  EXPECT_EQ(f, 0.25f);

  const GLfloat m[16] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16};
  proc<PFNGLLOADTRANSPOSEMATRIXFARBPROC>("glLoadTransposeMatrixfARB")(m);
  GLfloat t[16] = {};
  glGetFloatv(GL_TRANSPOSE_MODELVIEW_MATRIX, t);
  for (int i = 0; i < 16; ++i)
    EXPECT_EQ(t[i], m[i]);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

// EXT_blend_equation_separate (GL 2.1 §4.1.8): RGB and alpha have their own equations.
TEST_F(Extensions, BlendEquationSeparate) {
  auto separate = proc<PFNGLBLENDEQUATIONSEPARATEEXTPROC>("glBlendEquationSeparateEXT");
  ASSERT_NE(separate, nullptr);
  separate(GL_FUNC_ADD, GL_FUNC_REVERSE_SUBTRACT);
  GLint rgb = 0, alpha = 0;
  glGetIntegerv(GL_BLEND_EQUATION_RGB_EXT, &rgb);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA_EXT, &alpha);
  EXPECT_EQ(rgb, GL_FUNC_ADD);
  EXPECT_EQ(alpha, GL_FUNC_REVERSE_SUBTRACT);
  // Either mode invalid: INVALID_ENUM and no change.
  separate(GL_MIN, GL_ONE);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  separate(GL_ZERO, GL_MAX);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glBegin(GL_POINTS);
  separate(GL_MIN, GL_MAX);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
  glGetIntegerv(GL_BLEND_EQUATION_RGB_EXT, &rgb);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA_EXT, &alpha);
  EXPECT_EQ(rgb, GL_FUNC_ADD);
  EXPECT_EQ(alpha, GL_FUNC_REVERSE_SUBTRACT);

  // dst (0.5, 0.5, 0.5, 0.5), src (0.25, 0, 0, 0.25), factors ONE/ONE: RGB adds (0.75, 0.5,
  // 0.5), alpha subtracts the source from the destination (0.25).
  glClearColor(0.5f, 0.5f, 0.5f, 0.5f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  glColor4f(0.25f, 0, 0, 0.25f);
  glRecti(-1, -1, 1, 1);
  glFinish();
  const uint32_t p = pixel(3, 3);
  EXPECT_NEAR(static_cast<int>(p & 0xff), 191, 1);
  EXPECT_NEAR(static_cast<int>((p >> 8) & 0xff), 128, 1);
  EXPECT_NEAR(static_cast<int>(p >> 24), 64, 1);

  // glBlendEquation sets both again.
  glBlendEquation(GL_MAX);
  glGetIntegerv(GL_BLEND_EQUATION_ALPHA_EXT, &alpha);
  EXPECT_EQ(alpha, GL_MAX);
}

TEST_F(Extensions, AliasesAreCompiledIntoDisplayLists) {
  auto color2 = proc<PFNGLSECONDARYCOLOR3FEXTPROC>("glSecondaryColor3fEXT");
  ASSERT_NE(color2, nullptr);
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  color2(0.5f, 0.25f, 1.0f);
  glEndList();
  GLfloat c[4] = {};
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 0.0f); // compiled, not executed
  glCallList(list);
  glGetFloatv(GL_CURRENT_SECONDARY_COLOR, c);
  EXPECT_EQ(c[0], 0.5f);
  EXPECT_EQ(c[1], 0.25f);
  EXPECT_EQ(c[2], 1.0f);
}

TEST_F(Extensions, OcclusionQueryAliases) {
  auto gen = proc<PFNGLGENQUERIESARBPROC>("glGenQueriesARB");
  auto begin = proc<PFNGLBEGINQUERYARBPROC>("glBeginQueryARB");
  auto end = proc<PFNGLENDQUERYARBPROC>("glEndQueryARB");
  auto result = proc<PFNGLGETQUERYOBJECTUIVARBPROC>("glGetQueryObjectuivARB");
  ASSERT_TRUE(gen && begin && end && result);
  GLuint q = 0;
  gen(1, &q);
  begin(GL_SAMPLES_PASSED_ARB, q);
  glRecti(-1, -1, 1, 1);
  end(GL_SAMPLES_PASSED_ARB);
  GLuint samples = 0;
  result(q, GL_QUERY_RESULT_ARB, &samples);
  EXPECT_EQ(samples, static_cast<GLuint>(kW * kH));
}

TEST_F(Extensions, TextureObjectCommands) {
  auto gen = proc<PFNGLGENTEXTURESEXTPROC>("glGenTexturesEXT");
  auto is = proc<PFNGLISTEXTUREEXTPROC>("glIsTextureEXT");
  auto del = proc<PFNGLDELETETEXTURESEXTPROC>("glDeleteTexturesEXT");
  auto bind = proc<PFNGLBINDTEXTUREEXTPROC>("glBindTextureEXT");
  auto resident = proc<PFNGLARETEXTURESRESIDENTEXTPROC>("glAreTexturesResidentEXT");
  ASSERT_TRUE(gen && is && del && bind && resident);
  GLuint t[2] = {};
  gen(2, t);
  EXPECT_NE(t[0], 0u);
  EXPECT_NE(t[0], t[1]);
  EXPECT_FALSE(is(t[0])); // a name becomes a texture when first bound
  bind(GL_TEXTURE_2D, t[0]);
  EXPECT_TRUE(glIsTexture(t[0]));
  EXPECT_TRUE(is(t[0]));
  GLboolean res[1] = {GL_FALSE};
  EXPECT_TRUE(resident(1, t, res));
  del(2, t);
  EXPECT_FALSE(is(t[0]));
  gen(-1, t);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
}

TEST_F(Extensions, VertexArrayPointersKeepTheirCount) {
  auto vertex = proc<PFNGLVERTEXPOINTEREXTPROC>("glVertexPointerEXT");
  auto texcoord = proc<PFNGLTEXCOORDPOINTEREXTPROC>("glTexCoordPointerEXT");
  auto edge = proc<PFNGLEDGEFLAGPOINTEREXTPROC>("glEdgeFlagPointerEXT");
  auto get_pointer = proc<PFNGLGETPOINTERVEXTPROC>("glGetPointervEXT");
  ASSERT_TRUE(vertex && texcoord && edge && get_pointer);
  const GLfloat v[8] = {};
  vertex(2, GL_FLOAT, 8, 4, v);
  GLint i = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 4);
  glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &i);
  EXPECT_EQ(i, 2);
  glGetIntegerv(GL_VERTEX_ARRAY_STRIDE, &i);
  EXPECT_EQ(i, 8);
  void* p = nullptr;
  get_pointer(GL_VERTEX_ARRAY_POINTER_EXT, &p);
  EXPECT_EQ(p, v);

  // A negative count, and the core command's own errors, change nothing.
  vertex(3, GL_FLOAT, 0, -1, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  vertex(5, GL_FLOAT, 0, 9, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_VALUE));
  vertex(3, GL_UNSIGNED_BYTE, 0, 9, nullptr);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  glGetIntegerv(GL_VERTEX_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 4);
  glGetIntegerv(GL_VERTEX_ARRAY_SIZE, &i);
  EXPECT_EQ(i, 2);

  // A pending error stays the one glGetError reports (GL 2.1 §2.5).
  glEnable(GL_TRUE + 0x7000);
  vertex(3, GL_FLOAT, 0, 6, v);
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_ENUM));
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glGetIntegerv(GL_VERTEX_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 6);

  // Texture coordinates of the client active unit; edge flags.
  glClientActiveTexture(GL_TEXTURE1);
  texcoord(2, GL_FLOAT, 0, 3, v);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 3);
  glClientActiveTexture(GL_TEXTURE0);
  glGetIntegerv(GL_TEXTURE_COORD_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 0);
  const GLboolean flags[2] = {GL_TRUE, GL_FALSE};
  edge(0, 2, flags);
  glGetIntegerv(GL_EDGE_FLAG_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 2);

  // Client state: saved by glPushClientAttrib, executed at once in display lists.
  glPushClientAttrib(GL_CLIENT_VERTEX_ARRAY_BIT);
  glNewList(glGenLists(1), GL_COMPILE);
  vertex(4, GL_FLOAT, 0, 1, v);
  glEndList();
  glGetIntegerv(GL_VERTEX_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 1);
  glPopClientAttrib();
  glGetIntegerv(GL_VERTEX_ARRAY_COUNT_EXT, &i);
  EXPECT_EQ(i, 6);

  glBegin(GL_POINTS);
  vertex(3, GL_FLOAT, 0, 1, v);
  glEnd();
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_INVALID_OPERATION));
}

TEST_F(Extensions, VertexArrayDrawsWithTheExtensionCommands) {
  auto vertex = proc<PFNGLVERTEXPOINTEREXTPROC>("glVertexPointerEXT");
  auto color = proc<PFNGLCOLORPOINTEREXTPROC>("glColorPointerEXT");
  auto draw = proc<PFNGLDRAWARRAYSEXTPROC>("glDrawArraysEXT");
  ASSERT_TRUE(vertex && color && draw);
  const GLfloat v[8] = {-1, -1, 1, -1, 1, 1, -1, 1};
  const GLubyte c[16] = {0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255, 0, 255};
  vertex(2, GL_FLOAT, 0, 4, v);
  color(4, GL_UNSIGNED_BYTE, 0, 4, c);
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  draw(GL_QUADS, 0, 4);
  glFinish();
  EXPECT_EQ(pixel(kW / 2, kH / 2), 0xFF00FF00u);
}

} // namespace

namespace {

// GL 2.1 §5.3 (piglit's gl-1.0-rendermode-feedback, which needs EXT_vertex_array): a triangle
// of collinear vertices survives clipping and, with culling off, is reported; culled (it is
// back-facing, §3.5.1) when back faces are culled. Selection counts it alike (§5.2).
TEST_F(Extensions, FeedbackAndSelectionReportZeroAreaTriangles) {
  glMatrixMode(GL_PROJECTION);
  glOrtho(0, kW, 0, kH, -1, 1);
  glMatrixMode(GL_MODELVIEW);
  const GLfloat v[12] = {1, 2, 0.4f, 1, 3, 4, 0.6f, 1, 5, 6, 0.8f, 1};
  proc<PFNGLVERTEXPOINTEREXTPROC>("glVertexPointerEXT")(4, GL_FLOAT, 0, 3, v);
  glEnableClientState(GL_VERTEX_ARRAY);
  GLfloat fb[16] = {};
  glFeedbackBuffer(16, GL_3D, fb);
  glRenderMode(GL_FEEDBACK);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  ASSERT_EQ(glRenderMode(GL_RENDER), 11);
  const GLfloat want[11] = {GL_POLYGON_TOKEN, 3, 1, 2, 0.3f, 3, 4, 0.2f, 5, 6, 0.1f};
  for (int i = 0; i < 11; ++i)
    EXPECT_NEAR(fb[i], want[i], 1e-5) << i;

  glEnable(GL_CULL_FACE);
  glRenderMode(GL_FEEDBACK);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glRenderMode(GL_RENDER), 0);
  glDisable(GL_CULL_FACE);

  GLuint hits[8] = {};
  glSelectBuffer(8, hits);
  glRenderMode(GL_SELECT);
  glInitNames();
  glPushName(7);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  EXPECT_EQ(glRenderMode(GL_RENDER), 1);
  EXPECT_EQ(hits[3], 7u);
  // Rendering it draws nothing.
  glClear(GL_COLOR_BUFFER_BIT);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glFinish();
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      ASSERT_EQ(pixel(x, y), 0u) << x << "," << y;
}

} // namespace

namespace {

// GL 2.1 §4.1.7 (piglit's occlusion_query_meta_fragments, which needs ARB_occlusion_query):
// fragments of DrawPixels, CopyPixels and Bitmap are counted like those of primitives.
TEST_F(Extensions, OcclusionQueriesCountPixelFragments) {
  GLuint q = 0;
  glGenQueries(1, &q);
  const auto count = [&](auto draw) {
    glBeginQuery(GL_SAMPLES_PASSED, q);
    draw();
    glEndQuery(GL_SAMPLES_PASSED);
    GLuint n = 0;
    glGetQueryObjectuiv(q, GL_QUERY_RESULT, &n);
    return n;
  };
  glWindowPos2i(4, 4);
  const GLubyte rgba[4 * 4] = {};
  EXPECT_EQ(count([&] { glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba); }), 4u);
  EXPECT_EQ(count([&] { glCopyPixels(0, 0, 2, 2, GL_COLOR); }), 4u);
  const GLubyte bits[2] = {0xF0, 0xF0}; // two rows of four set bits
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  EXPECT_EQ(count([&] { glBitmap(8, 2, 0, 0, 0, 0, bits); }), 8u);
  // Fragments that fail the depth test are not counted.
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_NEVER);
  EXPECT_EQ(count([&] { glDrawPixels(2, 2, GL_RGBA, GL_UNSIGNED_BYTE, rgba); }), 0u);
  EXPECT_EQ(count([&] { glBitmap(8, 2, 0, 0, 0, 0, bits); }), 0u);
  glDeleteQueries(1, &q);
}

} // namespace
