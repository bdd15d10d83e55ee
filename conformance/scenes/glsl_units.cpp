// GLSL programs against the texture image units and the user clip planes (GL 2.1 §2.15.4
// "Texture Access", §2.12, §2.20.3): samplers of both stages on image units above the
// conventional ones, vertex lookups with and without an explicit level, and clipping against
// gl_ClipVertex (and, where a shader does not write it, against gl_Position as Mesa does).
// Each scene deletes its objects and puts back the state it touched.
#include "glsl_util.h"

using namespace scenes;
using namespace scenes::glsl;

namespace {

// A 2D texture on `unit` whose levels 0..2 (4x4, 2x2, 1x1) are each one palette colour, a
// quarter of level 0 another one; nearest filtering within and between levels.
GLuint level_texture(GL2& gl, int unit, int colour) {
  gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
  GLuint tex = 0;
  glGenTextures(1, &tex);
  glBindTexture(GL_TEXTURE_2D, tex);
  for (int level = 0, size = 4; level < 3; ++level, size /= 2) {
    std::vector<unsigned char> texels(static_cast<size_t>(size * size * 4));
    for (int y = 0; y < size; ++y)
      for (int x = 0; x < size; ++x) {
        const bool corner = level == 0 && x < size / 2 && y < size / 2;
        const float* c = palette(colour + level + (corner ? 5 : 0));
        unsigned char* t = &texels[static_cast<size_t>((y * size + x) * 4)];
        for (int k = 0; k < 3; ++k)
          t[k] = static_cast<unsigned char>(c[k] * 255.0f);
        t[3] = 255;
      }
    glTexImage2D(GL_TEXTURE_2D, level, GL_RGBA, size, size, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 texels.data());
  }
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST_MIPMAP_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return tex;
}

} // namespace

PINEDA_SCENE(glsl_texture_image_units,
             "samplers on image units 5-15 in both stages: texture2D and texture2DLod at levels "
             "0-2 in the vertex shader, three fragment samplers",
             .gl_version = "2.1") {
  GL2 gl;
  clear_frame(0, 0, 0);
  perspective(frame);
  const int units[5] = {13, 7, 5, 11, 15};
  GLuint tex[5];
  for (int i = 0; i < 5; ++i)
    tex[i] = level_texture(gl, units[i], 2 * i);
  // Units 5, 11 and 15 also get a checker to filter in the fragment shader.
  gl.ActiveTexture(GL_TEXTURE11);
  const GLuint checker = checker_texture();
  gl.ActiveTexture(GL_TEXTURE0);
  const GLuint p = gl.program("uniform sampler2D v0, v1;\nuniform float level;\n"
                              "void main() {\n"
                              "  vec2 st = gl_MultiTexCoord0.st;\n"
                              "  vec4 a = texture2D(v0, st);\n"
                              "  vec4 b = texture2DLod(v1, st, level + st.x * 2.0);\n"
                              "  gl_Position = gl_ModelViewProjectionMatrix * (gl_Vertex + "
                              "vec4(0.0, 0.0, a.g * 0.3, 0.0));\n"
                              "  gl_FrontColor = mix(a, b, step(0.5, st.y));\n"
                              "  gl_TexCoord[0] = gl_MultiTexCoord0; }\n",
                              "uniform sampler2D f0, f1, f2;\n"
                              "void main() {\n"
                              "  vec2 st = gl_TexCoord[0].st;\n"
                              "  vec4 c = texture2D(f1, st * 3.0) * 0.5 + gl_Color * 0.5;\n"
                              "  if (st.x < 0.2) c = texture2D(f0, st);\n"
                              "  if (st.x > 0.8) c = texture2D(f2, st * 2.0);\n"
                              "  gl_FragColor = c; }\n");
  gl.Uniform1i(gl.loc(p, "v0"), 13);
  gl.Uniform1i(gl.loc(p, "v1"), 7);
  gl.Uniform1i(gl.loc(p, "f0"), 5);
  gl.Uniform1i(gl.loc(p, "f1"), 11);
  gl.Uniform1i(gl.loc(p, "f2"), 15);
  // Levels 0.1 to 2.1 across the grid, never a tie between two levels: llvmpipe's vertex
  // lookups take level 0 at exactly 0.5 and level 2 at 1.5 (ties to even), where GL 2.1
  // §3.8.8 (eq. 3.27) takes 0 and 1, and Pineda, as llvmpipe's fragment lookups, 1 and 2.
  gl.Uniform1f(gl.loc(p, "level"), 0.1f);
  glRotatef(-50.0f, 1, 0, 0);
  glScalef(1.4f, 1.4f, 1.0f);
  grid(16, 16);
  gl.done(p);
  for (int i = 0; i < 5; ++i) {
    gl.ActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(units[i]));
    glBindTexture(GL_TEXTURE_2D, 0);
  }
  gl.ActiveTexture(GL_TEXTURE0);
  glDeleteTextures(5, tex);
  glDeleteTextures(1, &checker);
}

PINEDA_SCENE(glsl_clip_vertex,
             "user clip planes with a vertex shader: gl_ClipVertex in eye space (moved away "
             "from the position), and gl_Position where the shader does not write it",
             .gl_version = "2.1") {
  GL2 gl;
  clear_frame(0.1f, 0.1f, 0.1f);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  // Planes given under a rotated model-view: stored in eye space (§2.12).
  glPushMatrix();
  glRotatef(30.0f, 0, 0, 1);
  const GLdouble p0[4] = {1.0, 0.2, 0.0, 0.1};
  const GLdouble p1[4] = {-0.3, 1.0, 0.4, 0.35};
  glClipPlane(GL_CLIP_PLANE0, p0);
  glClipPlane(GL_CLIP_PLANE3, p1);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE0);
  glEnable(GL_CLIP_PLANE3);
  // Left: the clip vertex is the eye position mirrored in x and pushed back, so the planes
  // cut the sphere where the position alone would not.
  GLuint p = gl.program("void main() {\n"
                        "  gl_Position = ftransform();\n"
                        "  vec4 eye = gl_ModelViewMatrix * gl_Vertex;\n"
                        "  gl_ClipVertex = vec4(-eye.x, eye.y, eye.z - 0.5 * eye.w, eye.w);\n"
                        "  gl_FrontColor = vec4(gl_Normal * 0.5 + 0.5, 1.0);\n"
                        "}\n",
                        nullptr);
  glPushMatrix();
  glTranslatef(-0.75f, 0.0f, 0.0f);
  sphere(0.7f, 24, 16);
  // Lines and points are clipped the same way.
  glBegin(GL_LINES);
  for (int i = 0; i <= 16; ++i) {
    const float a = static_cast<float>(i) * 0.4f;
    glNormal3f(0.0f, 1.0f, 0.0f);
    glVertex3f(-0.9f, std::sin(a) * 0.8f, 0.8f);
    glNormal3f(1.0f, 0.0f, 0.0f);
    glVertex3f(0.9f, std::cos(a) * 0.8f, 0.8f);
  }
  glEnd();
  glPopMatrix();
  gl.done(p);
  // Right: no gl_ClipVertex, and one more plane, eye z >= -2.9, which would cut the sphere
  // (its centre is at eye z = -3) on eye coordinates but keeps every gl_Position.
  glPushMatrix();
  glLoadIdentity();
  const GLdouble p2[4] = {0.0, 0.0, 1.0, 2.9};
  glClipPlane(GL_CLIP_PLANE1, p2);
  glPopMatrix();
  glEnable(GL_CLIP_PLANE1);
  p = gl.program("void main() {\n"
                 "  gl_Position = ftransform();\n"
                 "  gl_FrontColor = vec4(gl_Normal * 0.5 + 0.5, 1.0);\n"
                 "}\n",
                 nullptr);
  glPushMatrix();
  glTranslatef(0.75f, 0.0f, 0.0f);
  sphere(0.7f, 24, 16);
  glPopMatrix();
  gl.done(p);
  glDisable(GL_CLIP_PLANE0);
  glDisable(GL_CLIP_PLANE1);
  glDisable(GL_CLIP_PLANE3);
  glDisable(GL_DEPTH_TEST);
}
