// Texture image units, coordinate sets and conventional units (GL 2.1 §2.7, §2.15.4, §6.1.2):
// the limits, ActiveTexture's range, the INVALID_OPERATION of commands on state an active
// texture lacks, samplers on the units above the conventional ones in both shader stages
// (vertex texture fetch), and the sampler limits of the link (§2.15.3 "Samplers").
#define GL_GLEXT_PROTOTYPES 1
#include "api_fixture.h"

#include <GL/glext.h>

#include <string>
#include <vector>

namespace {

class UnitsTest : public GLTest {
protected:
  GLuint shader(GLenum type, const std::string& src) {
    const GLuint s = glCreateShader(type);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    return s;
  }
  GLuint link(const std::string& vs, const std::string& fs, bool expect = true) {
    const GLuint p = glCreateProgram();
    if (!vs.empty()) glAttachShader(p, shader(GL_VERTEX_SHADER, vs));
    if (!fs.empty()) glAttachShader(p, shader(GL_FRAGMENT_SHADER, fs));
    glLinkProgram(p);
    GLint ok = 0;
    glGetProgramiv(p, GL_LINK_STATUS, &ok);
    EXPECT_EQ(ok, expect ? GL_TRUE : GL_FALSE) << log(p);
    return p;
  }
  std::string log(GLuint p) {
    char buf[2048] = {};
    glGetProgramInfoLog(p, sizeof buf, nullptr, buf);
    return buf;
  }
  // A 1x1 2D texture of one colour on `unit`, left active.
  GLuint solid_texture(int unit, const uint8_t rgba[4]) {
    glActiveTexture(GL_TEXTURE0 + unit);
    GLuint t = 0;
    glGenTextures(1, &t);
    glBindTexture(GL_TEXTURE_2D, t);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    return t;
  }
  void quad() {
    glBegin(GL_QUADS);
    glVertex2f(-1, -1);
    glVertex2f(1, -1);
    glVertex2f(1, 1);
    glVertex2f(-1, 1);
    glEnd();
  }
  GLenum err() { return glGetError(); }
  GLint get(GLenum pname) {
    GLint v = -1;
    glGetIntegerv(pname, &v);
    return v;
  }
};

constexpr GLenum kNoError = GL_NO_ERROR;
constexpr GLenum kInvalidEnum = GL_INVALID_ENUM;
constexpr GLenum kInvalidOperation = GL_INVALID_OPERATION;
constexpr GLenum kInvalidValue = GL_INVALID_VALUE;

TEST_F(UnitsTest, Limits) {
  // Table 6.37: 16 image units per stage, 32 in all, as many coordinate sets as conventional
  // units.
  EXPECT_EQ(get(GL_MAX_TEXTURE_IMAGE_UNITS), 16);
  EXPECT_EQ(get(GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS), 16);
  EXPECT_EQ(get(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS), 32);
  EXPECT_EQ(get(GL_MAX_TEXTURE_COORDS), 4);
  EXPECT_EQ(get(GL_MAX_TEXTURE_UNITS), 4);
  EXPECT_EQ(err(), kNoError);
}

TEST_F(UnitsTest, ActiveTextureRange) {
  // §2.7: TEXTUREi for i below the larger of MAX_TEXTURE_COORDS and the combined units.
  glActiveTexture(GL_TEXTURE31);
  EXPECT_EQ(err(), kNoError);
  EXPECT_EQ(get(GL_ACTIVE_TEXTURE), GL_TEXTURE31);
  glActiveTexture(GL_TEXTURE0 + 32);
  EXPECT_EQ(err(), kInvalidEnum);
  EXPECT_EQ(get(GL_ACTIVE_TEXTURE), GL_TEXTURE31);
  // Client active texture and MultiTexCoord name coordinate sets.
  glClientActiveTexture(GL_TEXTURE4);
  EXPECT_EQ(err(), kInvalidEnum);
  glClientActiveTexture(GL_TEXTURE3);
  EXPECT_EQ(err(), kNoError);
  glMultiTexCoord2f(GL_TEXTURE4, 1, 2);
  EXPECT_EQ(err(), kInvalidEnum);
}

TEST_F(UnitsTest, ImageUnitStateAboveTheConventionalUnits) {
  glActiveTexture(GL_TEXTURE10);
  // Image unit state: bindings, parameters, images, the LOD bias of TEXTURE_FILTER_CONTROL.
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  const uint8_t texel[4] = {1, 2, 3, 4};
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, texel);
  EXPECT_EQ(err(), kNoError);
  EXPECT_EQ(get(GL_TEXTURE_BINDING_2D), static_cast<GLint>(t));
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 1.5f);
  GLfloat bias = 0;
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, 1.5f);
  EXPECT_EQ(err(), kNoError);
  // The other units keep their own binding and bias.
  glActiveTexture(GL_TEXTURE0);
  EXPECT_EQ(get(GL_TEXTURE_BINDING_2D), 0);
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, 0.0f);
  glActiveTexture(GL_TEXTURE10);

  // Conventional-unit and coordinate-set state: INVALID_OPERATION (§2.7, §6.1.2), unchanged.
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
  EXPECT_EQ(err(), kInvalidOperation);
  GLint mode = 0;
  glGetTexEnviv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, &mode);
  EXPECT_EQ(err(), kInvalidOperation);
  glTexEnvi(GL_POINT_SPRITE, GL_COORD_REPLACE, GL_TRUE);
  EXPECT_EQ(err(), kInvalidOperation);
  glEnable(GL_TEXTURE_2D);
  EXPECT_EQ(err(), kInvalidOperation);
  EXPECT_EQ(glIsEnabled(GL_TEXTURE_2D), GL_FALSE);
  EXPECT_EQ(err(), kInvalidOperation);
  GLboolean b = GL_TRUE;
  glGetBooleanv(GL_TEXTURE_GEN_S, &b);
  EXPECT_EQ(err(), kInvalidOperation);
  EXPECT_EQ(b, GL_TRUE); // untouched
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  EXPECT_EQ(err(), kInvalidOperation);
  GLint gen = 0;
  glGetTexGeniv(GL_S, GL_TEXTURE_GEN_MODE, &gen);
  EXPECT_EQ(err(), kInvalidOperation);
  glMatrixMode(GL_TEXTURE);
  EXPECT_EQ(err(), kNoError);
  glLoadIdentity();
  EXPECT_EQ(err(), kInvalidOperation);
  glPushMatrix();
  EXPECT_EQ(err(), kInvalidOperation);
  glScalef(2, 2, 2);
  EXPECT_EQ(err(), kInvalidOperation);
  GLfloat m[16] = {};
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(err(), kInvalidOperation);
  glGetFloatv(GL_CURRENT_TEXTURE_COORDS, m);
  EXPECT_EQ(err(), kInvalidOperation);
  glGetFloatv(GL_CURRENT_RASTER_TEXTURE_COORDS, m);
  EXPECT_EQ(err(), kInvalidOperation);
  glMatrixMode(GL_MODELVIEW);
  glActiveTexture(GL_TEXTURE0);
  glMatrixMode(GL_TEXTURE);
  glGetFloatv(GL_TEXTURE_MATRIX, m);
  EXPECT_EQ(m[0], 1.0f); // the scale above reached no unit
  glMatrixMode(GL_MODELVIEW);
  EXPECT_EQ(err(), kNoError);
}

TEST_F(UnitsTest, PushPopKeepsEveryImageUnitsBinding) {
  glActiveTexture(GL_TEXTURE20);
  GLuint t[2] = {};
  glGenTextures(2, t);
  glBindTexture(GL_TEXTURE_2D, t[0]);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, -1.0f);
  glPushAttrib(GL_TEXTURE_BIT);
  glBindTexture(GL_TEXTURE_2D, t[1]);
  glTexEnvf(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, 2.0f);
  glActiveTexture(GL_TEXTURE3);
  glPopAttrib();
  EXPECT_EQ(get(GL_ACTIVE_TEXTURE), GL_TEXTURE20);
  EXPECT_EQ(get(GL_TEXTURE_BINDING_2D), static_cast<GLint>(t[0]));
  GLfloat bias = 0;
  glGetTexEnvfv(GL_TEXTURE_FILTER_CONTROL, GL_TEXTURE_LOD_BIAS, &bias);
  EXPECT_EQ(bias, -1.0f);
  EXPECT_EQ(err(), kNoError);
}

TEST_F(UnitsTest, FragmentSamplersOnHighUnits) {
  const uint8_t red[4] = {255, 0, 0, 255}, green[4] = {0, 255, 0, 255};
  solid_texture(12, red);
  solid_texture(15, green);
  const GLuint p = link(
      "", "uniform sampler2D a, b;\n"
          "void main() { gl_FragColor = texture2D(a, vec2(0.5)) + texture2D(b, vec2(0.5)); }\n");
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "a"), 12);
  glUniform1i(glGetUniformLocation(p, "b"), 15);
  quad();
  EXPECT_EQ(pixel(5, 5), 0xff00ffffu);
  // §2.15.3: a sampler takes the units below MAX_COMBINED_TEXTURE_IMAGE_UNITS.
  glUniform1i(glGetUniformLocation(p, "a"), 31);
  EXPECT_EQ(err(), kNoError);
  glUniform1i(glGetUniformLocation(p, "a"), 32);
  EXPECT_EQ(err(), kInvalidValue);
}

TEST_F(UnitsTest, VertexTextureFetch) {
  // GL 2.1 §2.15.4 "Texture Access": a vertex shader samples any image unit; lookups without
  // Lod use level 0, the *Lod ones the level given. Level 0 is blue, level 1 yellow.
  glActiveTexture(GL_TEXTURE9);
  GLuint t = 0;
  glGenTextures(1, &t);
  glBindTexture(GL_TEXTURE_2D, t);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  const std::vector<uint8_t> yellow = {255, 255, 0, 255};
  std::vector<uint8_t> level0(2 * 2 * 4);
  for (size_t i = 0; i < level0.size(); i += 4)
    level0[i + 2] = level0[i + 3] = 255;
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 2, 2, 0, GL_RGBA, GL_UNSIGNED_BYTE, level0.data());
  glTexImage2D(GL_TEXTURE_2D, 1, GL_RGBA, 1, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, yellow.data());
  glActiveTexture(GL_TEXTURE0);
  const GLuint p = link("uniform sampler2D s;\nuniform float level;\n"
                        "void main() { gl_Position = gl_Vertex;\n"
                        "  gl_FrontColor = level < 0.0 ? texture2D(s, vec2(0.5))\n"
                        "                              : texture2DLod(s, vec2(0.5), level); }\n",
                        "");
  glUseProgram(p);
  glUniform1i(glGetUniformLocation(p, "s"), 9);
  glUniform1f(glGetUniformLocation(p, "level"), -1.0f);
  quad();
  EXPECT_EQ(pixel(5, 5), 0xffff0000u);
  glUniform1f(glGetUniformLocation(p, "level"), 1.0f);
  quad();
  EXPECT_EQ(pixel(5, 5), 0xff00ffffu);
  glUniform1f(glGetUniformLocation(p, "level"), 0.0f);
  quad();
  EXPECT_EQ(pixel(5, 5), 0xffff0000u);
  EXPECT_EQ(err(), kNoError);
}

// A shader that adds the lookups of n samplers (explicit level 0 in a vertex shader) into
// `out`; the caller closes main.
std::string sampler_sum(const char* out, int n, bool vertex) {
  std::string s = "uniform sampler2D s[" + std::to_string(n) + "];\nvoid main() {\n";
  s += "  vec4 c = vec4(0.0);\n";
  for (int i = 0; i < n; ++i) {
    s += vertex ? "  c += texture2DLod(s[" : "  c += texture2D(s[";
    s += std::to_string(i);
    s += vertex ? "], vec2(0.5), 0.0);\n" : "], vec2(0.5));\n";
  }
  s += "  ";
  s += out;
  s += " = c;\n";
  return s;
}

TEST_F(UnitsTest, LinkFailsWithTooManySamplers) {
  // §2.15.3 "Samplers": the link fails when a stage uses more samplers than its units, or
  // both together more than the combined units; each stage's samplers count.
  GLuint p = link("", sampler_sum("gl_FragColor", 17, false) + "}\n", false);
  EXPECT_NE(log(p).find("too many samplers"), std::string::npos) << log(p);
  const std::string position = "  gl_Position = gl_Vertex;\n}\n";
  p = link(sampler_sum("gl_FrontColor", 17, true) + position, "", false);
  EXPECT_NE(log(p).find("too many samplers"), std::string::npos) << log(p);
  // 16 in each stage: 32 in all, within the combined limit.
  link(sampler_sum("gl_FrontColor", 16, true) + position,
       sampler_sum("gl_FragColor", 16, false) + "}\n", true);
  EXPECT_EQ(err(), kNoError);
}

} // namespace
