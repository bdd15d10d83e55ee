// GLSL 1.10/1.20 programs (GL 2.1 §2.15, §2.20, §3.11), part two: built-in state (matrices,
// lights, materials, fog, texture state, planes), each stage programmable with the other fixed,
// generic attributes from arrays, buffers and display lists, varyings, facing, point size and
// the per-fragment operations after a shader. Part one: glsl.cpp.
#include "glsl_util.h"

using namespace scenes;
using namespace scenes::glsl;

PINEDA_SCENE(glsl_fragment_constant,
             "fragment shader writing a constant over fixed-function geometry") {
  GL2 gl;
  clear_frame(0.1f, 0.1f, 0.1f);
  const GLuint p =
      gl.program(nullptr, "void main() { gl_FragColor = vec4(0.9, 0.4, 0.1, 1.0); }\n");
  glBegin(GL_TRIANGLES);
  glVertex2f(20, 20);
  glVertex2f(230, 40);
  glVertex2f(120, 240);
  glEnd();
  gl.done(p);
}

PINEDA_SCENE(glsl_fixed_vertex_color,
             "fixed-function vertex stage, fragment shader reading gl_Color and gl_TexCoord") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program(nullptr, "void main() {\n"
                          "  gl_FragColor = vec4(gl_Color.gb, gl_TexCoord[0].s, 1.0);\n"
                          "}\n");
  glMatrixMode(GL_PROJECTION);
  glLoadIdentity();
  glMatrixMode(GL_MODELVIEW);
  grid(6, 5);
  gl.done(p);
}

PINEDA_SCENE(glsl_varyings, "user varyings of every size interpolated with perspective") {
  GL2 gl;
  clear_frame(0, 0, 0);
  perspective(frame);
  glRotatef(-60.0f, 1, 0, 0);
  const GLuint p = gl.program(
      "varying float a;\nvarying vec2 b;\nvarying vec3 c;\nvarying vec4 d;\n"
      "void main() {\n  gl_Position = ftransform();\n"
      "  a = gl_Vertex.x; b = gl_Vertex.xy * 0.5 + 0.5; c = gl_Color.rgb; d = gl_Vertex.yxyx;\n}\n",
      "varying float a;\nvarying vec2 b;\nvarying vec3 c;\nvarying vec4 d;\n"
      "void main() {\n"
      "  gl_FragColor = vec4(fract(b * 4.0) * c.rg, abs(a) * c.b + 0.2 * d.w, 1.0);\n}\n");
  glScalef(1.5f, 1.5f, 1.0f);
  grid(4, 4);
  gl.done(p);
}

PINEDA_SCENE(glsl_builtin_matrices,
             "gl_ModelViewProjection, ModelView, Projection and Normal matrices") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  glRotatef(30.0f, 1, 0, 0);
  glRotatef(40.0f, 0, 1, 0);
  glScalef(1.0f, 1.3f, 0.8f);
  const GLuint p =
      gl.program("varying vec3 n;\nvarying vec4 eye;\n"
                 "void main() {\n"
                 "  eye = gl_ModelViewMatrix * gl_Vertex;\n"
                 "  gl_Position = gl_ProjectionMatrix * eye;\n"
                 "  n = gl_NormalMatrix * gl_Normal;\n"
                 "  gl_FrontColor = gl_ModelViewProjectionMatrix * gl_Vertex * 0.1 + 0.5;\n}\n",
                 "varying vec3 n;\nvarying vec4 eye;\n"
                 "void main() { gl_FragColor = vec4(normalize(n) * 0.5 + 0.5, 1.0) * 0.7 +\n"
                 "  gl_Color * 0.3 + vec4(0.0, 0.0, -eye.z * 0.05, 0.0); }\n");
  sphere(1.0f, 24, 16);
  gl.done(p);
}

PINEDA_SCENE(glsl_vertex_lighting,
             "per-vertex lighting from gl_LightSource, gl_FrontMaterial and gl_LightModel") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  const float pos[4] = {2.0f, 3.0f, 4.0f, 0.0f}, diffuse[4] = {0.9f, 0.8f, 0.6f, 1.0f};
  const float spec[4] = {1, 1, 1, 1}, amb[4] = {0.1f, 0.1f, 0.2f, 1.0f};
  const float mdiff[4] = {0.3f, 0.6f, 0.9f, 1.0f}, mspec[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, diffuse);
  glLightfv(GL_LIGHT0, GL_SPECULAR, spec);
  glLightfv(GL_LIGHT0, GL_AMBIENT, amb);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, mdiff);
  glMaterialfv(GL_FRONT, GL_SPECULAR, mspec);
  glMaterialf(GL_FRONT, GL_SHININESS, 24.0f);
  const GLuint p = gl.program(
      "void main() {\n"
      "  vec3 n = normalize(gl_NormalMatrix * gl_Normal);\n"
      "  vec3 l = normalize(gl_LightSource[0].position.xyz);\n"
      "  vec3 h = normalize(gl_LightSource[0].halfVector.xyz);\n"
      "  float d = max(dot(n, l), 0.0);\n"
      "  float s = d > 0.0 ? pow(max(dot(n, h), 0.0), gl_FrontMaterial.shininess) : 0.0;\n"
      "  gl_FrontColor = gl_FrontLightModelProduct.sceneColor +\n"
      "    gl_FrontLightProduct[0].ambient + d * gl_FrontLightProduct[0].diffuse +\n"
      "    s * gl_FrontLightProduct[0].specular;\n"
      "  gl_Position = ftransform();\n}\n",
      nullptr);
  sphere(1.1f, 32, 20);
  gl.done(p);
  const float def_pos[4] = {0, 0, 1, 0}, one[4] = {1, 1, 1, 1}, zero[4] = {0, 0, 0, 1};
  const float d8[4] = {0.8f, 0.8f, 0.8f, 1.0f};
  glLightfv(GL_LIGHT0, GL_POSITION, def_pos);
  glLightfv(GL_LIGHT0, GL_DIFFUSE, one);
  glLightfv(GL_LIGHT0, GL_SPECULAR, one);
  glLightfv(GL_LIGHT0, GL_AMBIENT, zero);
  glMaterialfv(GL_FRONT, GL_DIFFUSE, d8);
  glMaterialfv(GL_FRONT, GL_SPECULAR, zero);
  glMaterialf(GL_FRONT, GL_SHININESS, 0.0f);
}

PINEDA_SCENE(glsl_pixel_lighting,
             "per-fragment point light with attenuation and a spot from varyings") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  const float pos[4] = {0.5f, 0.8f, 1.5f, 1.0f}, dir[3] = {-0.3f, -0.5f, -1.0f};
  glLightfv(GL_LIGHT1, GL_POSITION, pos);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, dir);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 40.0f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.3f);
  const GLuint p = gl.program(
      "varying vec3 n;\nvarying vec3 e;\n"
      "void main() { e = (gl_ModelViewMatrix * gl_Vertex).xyz;\n"
      "  n = gl_NormalMatrix * gl_Normal; gl_Position = ftransform(); }\n",
      "varying vec3 n;\nvarying vec3 e;\n"
      "void main() {\n"
      "  vec3 l = gl_LightSource[1].position.xyz - e;\n"
      "  float dist = length(l);\n  l /= dist;\n"
      "  float att = 1.0 / (gl_LightSource[1].constantAttenuation +\n"
      "    gl_LightSource[1].linearAttenuation * dist);\n"
      "  float spot = dot(-l, normalize(gl_LightSource[1].spotDirection));\n"
      "  float inside = smoothstep(gl_LightSource[1].spotCosCutoff, "
      "gl_LightSource[1].spotCosCutoff + 0.05, spot);\n"
      "  vec3 nn = normalize(n);\n"
      "  vec3 r = reflect(-l, nn);\n"
      "  float s = pow(max(dot(r, normalize(-e)), 0.0), 16.0);\n"
      "  float d = max(dot(nn, l), 0.0);\n"
      "  gl_FragColor = vec4(vec3(0.1) + att * inside * (d * vec3(0.9, 0.7, 0.4) + s), 1.0);\n}\n");
  glRotatef(20.0f, 1, 0, 0);
  sphere(1.0f, 32, 24);
  gl.done(p);
  const float def_pos[4] = {0, 0, 1, 0}, def_dir[3] = {0, 0, -1};
  glLightfv(GL_LIGHT1, GL_POSITION, def_pos);
  glLightfv(GL_LIGHT1, GL_SPOT_DIRECTION, def_dir);
  glLightf(GL_LIGHT1, GL_SPOT_CUTOFF, 180.0f);
  glLightf(GL_LIGHT1, GL_LINEAR_ATTENUATION, 0.0f);
}

PINEDA_SCENE(glsl_fog_state, "gl_Fog and gl_FogFragCoord: fog computed in the fragment shader") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  const float color[4] = {0.6f, 0.7f, 0.8f, 1.0f};
  glFogfv(GL_FOG_COLOR, color);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 9.0f);
  glFogf(GL_FOG_DENSITY, 0.25f);
  const GLuint p =
      gl.program("void main() { gl_Position = ftransform(); gl_FrontColor = gl_Color;\n"
                 "  gl_FogFragCoord = -(gl_ModelViewMatrix * gl_Vertex).z; }\n",
                 "void main() {\n"
                 "  float lin = clamp((gl_Fog.end - gl_FogFragCoord) * gl_Fog.scale, 0.0, 1.0);\n"
                 "  float ex = exp(-gl_Fog.density * gl_FogFragCoord);\n"
                 "  float f = gl_FragCoord.x < 128.0 ? lin : ex;\n"
                 "  gl_FragColor = mix(gl_Fog.color, gl_Color, f);\n}\n");
  glRotatef(-75.0f, 1, 0, 0);
  glScalef(3.0f, 8.0f, 1.0f);
  glTranslatef(0.0f, -0.8f, 0.0f);
  grid(8, 8);
  gl.done(p);
  const float zero[4] = {0, 0, 0, 0};
  glFogfv(GL_FOG_COLOR, zero);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  glFogf(GL_FOG_DENSITY, 1.0f);
}

PINEDA_SCENE(glsl_vertex_fixed_fog_texture,
             "vertex shader with fixed-function texturing and fog after it") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  const GLuint tex = checker_texture();
  glEnable(GL_TEXTURE_2D);
  glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_MODULATE);
  glEnable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_LINEAR);
  glFogf(GL_FOG_START, 2.0f);
  glFogf(GL_FOG_END, 10.0f);
  const GLuint p =
      gl.program("void main() { gl_Position = ftransform(); gl_FrontColor = gl_Color;\n"
                 "  gl_TexCoord[0] = gl_MultiTexCoord0 * 3.0;\n"
                 "  gl_FogFragCoord = length((gl_ModelViewMatrix * gl_Vertex).xyz); }\n",
                 nullptr);
  glRotatef(-70.0f, 1, 0, 0);
  glScalef(3.0f, 8.0f, 1.0f);
  glTranslatef(0.0f, -0.8f, 0.0f);
  grid(6, 6);
  gl.done(p);
  glDisable(GL_FOG);
  glFogi(GL_FOG_MODE, GL_EXP);
  glFogf(GL_FOG_START, 0.0f);
  glFogf(GL_FOG_END, 1.0f);
  glDisable(GL_TEXTURE_2D);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_generic_attributes, "generic attribute arrays (float and normalized bytes) with "
                                      "attribute 0 as the position, and current generic values") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program("attribute vec2 pos;\nattribute vec4 col;\nattribute float size;\n"
                 "void main() { gl_Position = vec4(pos * size, 0.0, 1.0); gl_FrontColor = col; }\n",
                 nullptr, {{0, "pos"}, {2, "col"}, {5, "size"}});
  std::vector<float> pos;
  std::vector<unsigned char> col;
  Rng rng(7);
  for (int i = 0; i < 60; ++i) {
    for (int k = 0; k < 3; ++k) {
      pos.push_back(rng.range(-1.0f, 1.0f));
      pos.push_back(rng.range(-1.0f, 1.0f));
      const float* c = palette(i + k);
      for (int ch = 0; ch < 3; ++ch)
        col.push_back(static_cast<unsigned char>(c[ch] * 255.0f));
      col.push_back(255);
    }
  }
  gl.VertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, pos.data());
  gl.VertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, 0, col.data());
  gl.EnableVertexAttribArray(0);
  gl.EnableVertexAttribArray(2);
  gl.VertexAttrib4f(5, 0.9f, 0, 0, 1);
  glDrawArrays(GL_TRIANGLES, 0, 90);
  gl.DisableVertexAttribArray(2);
  gl.VertexAttrib4f(2, 1.0f, 1.0f, 1.0f, 1.0f);
  gl.VertexAttrib4f(5, 0.5f, 0, 0, 1);
  glDrawArrays(GL_TRIANGLES, 90, 90);
  gl.DisableVertexAttribArray(0);
  gl.done(p);
}

PINEDA_SCENE(glsl_front_facing,
             "gl_FrontFacing on both faces, and VERTEX_PROGRAM_TWO_SIDE with gl_BackColor") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program(nullptr, "void main() {\n"
                          "  gl_FragColor = gl_FrontFacing ? vec4(1.0, 0.5, 0.0, 1.0)\n"
                          "                                : vec4(0.0, 0.5, 1.0, 1.0);\n}\n");
  glBegin(GL_TRIANGLES);
  glVertex2f(10, 10);
  glVertex2f(120, 10);
  glVertex2f(60, 120);
  glVertex2f(130, 10);
  glVertex2f(190, 120);
  glVertex2f(250, 10);
  glEnd();
  gl.done(p);
  const GLuint q = gl.program(
      "void main() { gl_Position = ftransform(); gl_FrontColor = vec4(0.9, 0.9, 0.1, 1.0);\n"
      "  gl_BackColor = vec4(0.6, 0.1, 0.8, 1.0); }\n",
      nullptr);
  glEnable(GL_VERTEX_PROGRAM_TWO_SIDE);
  glBegin(GL_TRIANGLES);
  glVertex2f(10, 130);
  glVertex2f(120, 130);
  glVertex2f(60, 250);
  glVertex2f(130, 130);
  glVertex2f(190, 250);
  glVertex2f(250, 130);
  glEnd();
  glDisable(GL_VERTEX_PROGRAM_TWO_SIDE);
  gl.done(q);
}

PINEDA_SCENE(glsl_point_size,
             "gl_PointSize under VERTEX_PROGRAM_POINT_SIZE, and POINT_SIZE without it") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program("void main() { gl_Position = ftransform(); gl_FrontColor = gl_Color;\n"
                 "  gl_PointSize = 1.0 + gl_Vertex.x / 16.0; }\n",
                 nullptr);
  glEnable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glBegin(GL_POINTS);
  for (int i = 0; i < 12; ++i) {
    palette_color(i);
    glVertex2f(12.0f + 20.0f * i, 60.0f);
  }
  glEnd();
  glDisable(GL_VERTEX_PROGRAM_POINT_SIZE);
  glPointSize(5.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 12; ++i) {
    palette_color(i + 4);
    glVertex2f(12.0f + 20.0f * i, 180.0f);
  }
  glEnd();
  glPointSize(1.0f);
  gl.done(p);
}

PINEDA_SCENE(glsl_per_fragment_ops,
             "shader output through alpha test, blending and the depth test") {
  GL2 gl;
  clear_frame(0.2f, 0.2f, 0.2f);
  glEnable(GL_DEPTH_TEST);
  const GLuint p = gl.program(
      "varying vec2 q;\nvoid main() { gl_Position = ftransform(); gl_FrontColor = gl_Color;\n"
      "  q = gl_Vertex.xy / 256.0; }\n",
      "varying vec2 q;\nvoid main() { gl_FragColor = vec4(gl_Color.rgb, fract(q.x * 3.0 + q.y)); "
      "}\n");
  glEnable(GL_ALPHA_TEST);
  glAlphaFunc(GL_GREATER, 0.25f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
  for (int i = 0; i < 5; ++i) {
    palette_color(i * 3);
    const float x = 20.0f + 35.0f * i, z = 0.5f - 0.2f * i;
    glBegin(GL_QUADS);
    glVertex3f(x, 20, z);
    glVertex3f(x + 100, 20, z);
    glVertex3f(x + 100, 200, z);
    glVertex3f(x, 200, z);
    glEnd();
  }
  glDisable(GL_ALPHA_TEST);
  glAlphaFunc(GL_ALWAYS, 0.0f);
  glDisable(GL_BLEND);
  gl.done(p);
}

PINEDA_SCENE(glsl_uniform_structs_arrays,
             "uniform arrays of structs, vec4 arrays set with Uniform4fv, int loops over them") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p = gl.program(
      kTransformVs,
      "struct Blob { vec2 center; float radius; vec4 color; };\n"
      "uniform Blob blobs[4];\nuniform vec4 weights[2];\n"
      "void main() {\n"
      "  vec2 q = gl_TexCoord[0].st;\n"
      "  vec4 c = vec4(0.0);\n"
      "  for (int i = 0; i < 4; ++i) {\n"
      "    float d = distance(q, blobs[i].center) / blobs[i].radius;\n"
      "    c += blobs[i].color * max(1.0 - d * d, 0.0) * weights[i / 2][i - 2 * (i / 2)];\n"
      "  }\n"
      "  gl_FragColor = vec4(c.rgb, 1.0);\n}\n");
  for (int i = 0; i < 4; ++i) {
    char name[64];
    std::snprintf(name, sizeof name, "blobs[%d].center", i);
    gl.Uniform2f(gl.loc(p, name), 0.25f + 0.5f * (i % 2), 0.3f + 0.4f * static_cast<float>(i / 2));
    std::snprintf(name, sizeof name, "blobs[%d].radius", i);
    gl.Uniform1f(gl.loc(p, name), 0.3f + 0.05f * i);
    std::snprintf(name, sizeof name, "blobs[%d].color", i);
    const float* c = palette(i * 3 + 1);
    gl.Uniform4f(gl.loc(p, name), c[0], c[1], c[2], 1.0f);
  }
  const float weights[8] = {1.0f, 0.8f, 0.6f, 1.2f, 0, 0, 0, 0};
  gl.Uniform4fv(gl.loc(p, "weights"), 2, weights);
  clip_quad();
  gl.done(p);
}

PINEDA_SCENE(glsl_fixed_vertex_texgen, "fixed-function vertex stage with texture generation and a "
                                       "texture matrix, fragment shader reading gl_TexCoord") {
  GL2 gl;
  clear_frame(0, 0, 0);
  perspective(frame);
  const GLuint tex = checker_texture();
  const float splane[4] = {1.5f, 0.0f, 0.0f, 0.5f}, tplane[4] = {0.0f, 1.5f, 0.5f, 0.5f};
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
  glTexGenfv(GL_S, GL_OBJECT_PLANE, splane);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, tplane);
  glEnable(GL_TEXTURE_GEN_S);
  glEnable(GL_TEXTURE_GEN_T);
  const GLuint p =
      gl.program(nullptr, "uniform sampler2D t;\n"
                          "void main() { gl_FragColor = texture2D(t, gl_TexCoord[0].st) *\n"
                          "  vec4(gl_Color.rgb, 1.0); }\n");
  gl.Uniform1i(gl.loc(p, "t"), 0);
  glRotatef(25.0f, 1, 1, 0);
  sphere(1.1f, 24, 16);
  gl.done(p);
  glDisable(GL_TEXTURE_GEN_S);
  glDisable(GL_TEXTURE_GEN_T);
  const float s0[4] = {1, 0, 0, 0}, t0[4] = {0, 1, 0, 0};
  glTexGenfv(GL_S, GL_OBJECT_PLANE, s0);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t0);
  glTexGeni(GL_S, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glTexGeni(GL_T, GL_TEXTURE_GEN_MODE, GL_EYE_LINEAR);
  glDeleteTextures(1, &tex);
}

PINEDA_SCENE(glsl_lines_points_flat,
             "a program on lines and points, and flat shading of shader colours") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p = gl.program(
      "varying float t;\nvoid main() { gl_Position = ftransform(); gl_FrontColor = gl_Color;\n"
      "  t = gl_Vertex.x / 256.0; }\n",
      "varying float t;\nvoid main() { gl_FragColor = gl_Color * (0.5 + 0.5 * t); }\n");
  glBegin(GL_LINES);
  for (int i = 0; i < 16; ++i) {
    palette_color(i);
    glVertex2f(8.0f + 15.0f * i, 10.0f);
    palette_color(i + 5);
    glVertex2f(40.0f + 12.0f * i, 100.0f);
  }
  glEnd();
  glPointSize(3.0f);
  glBegin(GL_POINTS);
  for (int i = 0; i < 30; ++i) {
    palette_color(i);
    glVertex2f(8.5f + 8.0f * i, 120.5f);
  }
  glEnd();
  glPointSize(1.0f);
  glShadeModel(GL_FLAT);
  glBegin(GL_TRIANGLE_STRIP);
  for (int i = 0; i < 10; ++i) {
    palette_color(i);
    glVertex2f(10.0f + 24.0f * i, 140.0f + 100.0f * static_cast<float>(i % 2));
  }
  glEnd();
  gl.done(p);
}

PINEDA_SCENE(glsl_display_list, "uniforms and generic attributes compiled into display lists") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const GLuint p =
      gl.program("attribute float k;\nuniform vec2 shift;\nvarying float v;\n"
                 "void main() { gl_Position = ftransform() + vec4(shift, 0.0, 0.0); v = k; }\n",
                 "uniform vec4 tint;\nvarying float v;\nvoid main() { gl_FragColor = tint * v; }\n",
                 {{6, "k"}});
  const GLuint list = glGenLists(1);
  glNewList(list, GL_COMPILE);
  glBegin(GL_TRIANGLES);
  gl.VertexAttrib4f(6, 1.0f, 0, 0, 1);
  glVertex2f(20, 20);
  gl.VertexAttrib4f(6, 0.5f, 0, 0, 1);
  glVertex2f(120, 20);
  gl.VertexAttrib4f(6, 0.1f, 0, 0, 1);
  glVertex2f(70, 110);
  glEnd();
  glEndList();
  const float tints[3][4] = {{1, 0.3f, 0.2f, 1}, {0.2f, 1, 0.3f, 1}, {0.3f, 0.4f, 1, 1}};
  for (int i = 0; i < 3; ++i) {
    const GLuint set = glGenLists(1);
    glNewList(set, GL_COMPILE);
    gl.Uniform4f(gl.loc(p, "tint"), tints[i][0], tints[i][1], tints[i][2], tints[i][3]);
    gl.Uniform2f(gl.loc(p, "shift"), 0.4f * i, 0.5f * static_cast<float>(i % 2));
    glEndList();
    glCallList(set);
    glCallList(list);
    glDeleteLists(set, 1);
  }
  glDeleteLists(list, 1);
  gl.done(p);
}

PINEDA_SCENE(glsl_vbo_elements,
             "interleaved generic attributes from a buffer object, drawn with DrawElements") {
  GL2 gl;
  clear_frame(0, 0, 0);
  const auto gen_buffers = proc<PFNGLGENBUFFERSPROC>("glGenBuffers");
  const auto bind_buffer = proc<PFNGLBINDBUFFERPROC>("glBindBuffer");
  const auto buffer_data = proc<PFNGLBUFFERDATAPROC>("glBufferData");
  const auto delete_buffers = proc<PFNGLDELETEBUFFERSPROC>("glDeleteBuffers");
  const GLuint p =
      gl.program("attribute vec3 pos;\nattribute vec3 nrm;\nattribute vec2 uv;\nvarying vec3 c;\n"
                 "void main() { gl_Position = gl_ModelViewProjectionMatrix * vec4(pos, 1.0);\n"
                 "  c = abs(nrm) * 0.7 + vec3(uv, 0.0) * 0.3; }\n",
                 "varying vec3 c;\nvoid main() { gl_FragColor = vec4(c, 1.0); }\n",
                 {{1, "pos"}, {4, "nrm"}, {9, "uv"}});
  // A 16 x 16 grid of a bumpy surface: position, normal, uv interleaved.
  std::vector<float> verts;
  for (int j = 0; j <= 16; ++j)
    for (int i = 0; i <= 16; ++i) {
      const float u = static_cast<float>(i) / 16.0f, v = static_cast<float>(j) / 16.0f;
      const float h = 0.2f * std::sin(u * 9.0f) * std::cos(v * 7.0f);
      const float n[3] = {-std::cos(u * 9.0f) * 0.3f, std::sin(v * 7.0f) * 0.3f, 1.0f};
      for (float x : {2.0f * u - 1.0f, 2.0f * v - 1.0f, h, n[0], n[1], n[2], u, v})
        verts.push_back(x);
    }
  std::vector<unsigned short> idx;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const auto a = static_cast<unsigned short>(j * 17 + i);
      for (int k : {0, 1, 18, 0, 18, 17})
        idx.push_back(static_cast<unsigned short>(a + k));
    }
  GLuint buf[2];
  gen_buffers(2, buf);
  bind_buffer(GL_ARRAY_BUFFER, buf[0]);
  buffer_data(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(verts.size() * sizeof(float)), verts.data(),
              GL_STATIC_DRAW);
  bind_buffer(GL_ELEMENT_ARRAY_BUFFER, buf[1]);
  buffer_data(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * 2), idx.data(),
              GL_STATIC_DRAW);
  const GLsizei stride = 8 * sizeof(float);
  gl.VertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
  gl.VertexAttribPointer(4, 3, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<const void*>(3 * sizeof(float)));
  gl.VertexAttribPointer(9, 2, GL_FLOAT, GL_FALSE, stride,
                         reinterpret_cast<const void*>(6 * sizeof(float)));
  for (GLuint a : {1u, 4u, 9u})
    gl.EnableVertexAttribArray(a);
  perspective(frame);
  glRotatef(-50.0f, 1, 0, 0);
  glRotatef(25.0f, 0, 0, 1);
  glEnable(GL_DEPTH_TEST);
  // Generic array 0 is not enabled: the vertex array must be (§2.8), even though the shader
  // does not read gl_Vertex.
  glVertexPointer(3, GL_FLOAT, stride, nullptr);
  glEnableClientState(GL_VERTEX_ARRAY);
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(idx.size()), GL_UNSIGNED_SHORT, nullptr);
  glDisableClientState(GL_VERTEX_ARRAY);
  for (GLuint a : {1u, 4u, 9u})
    gl.DisableVertexAttribArray(a);
  bind_buffer(GL_ARRAY_BUFFER, 0);
  bind_buffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  delete_buffers(2, buf);
  gl.done(p);
}

PINEDA_SCENE(glsl_builtin_state_misc,
             "gl_DepthRange, gl_Point, gl_ClipPlane, env colours and texgen planes") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glDepthRange(0.2, 0.7);
  glPointSize(6.0f);
  const double plane[4] = {0.5, -0.25, 0.1, 0.3};
  glClipPlane(GL_CLIP_PLANE2, plane);
  const float env[4] = {0.2f, 0.9f, 0.4f, 1.0f};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, env);
  const float eye_s[4] = {0.3f, 0.6f, 0.9f, 0.1f}, obj_t[4] = {0.7f, 0.2f, 0.5f, 0.4f};
  glTexGenfv(GL_S, GL_EYE_PLANE, eye_s);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, obj_t);
  const GLuint p = gl.program(
      kTransformVs,
      "void main() {\n"
      "  float x = gl_TexCoord[0].s;\n"
      "  vec4 c;\n"
      "  if (x < 0.16) c = vec4(gl_DepthRange.near, gl_DepthRange.far, gl_DepthRange.diff, 1.0);\n"
      "  else if (x < 0.33) c = vec4(gl_Point.size / 10.0, gl_Point.sizeMin, gl_Point.sizeMax / "
      "512.0, 1.0);\n"
      "  else if (x < 0.5) c = gl_ClipPlane[2] + 0.5;\n"
      "  else if (x < 0.66) c = gl_TextureEnvColor[0];\n"
      "  else if (x < 0.83) c = gl_EyePlaneS[0];\n"
      "  else c = gl_ObjectPlaneT[0];\n"
      "  gl_FragColor = vec4(c.rgb, 1.0);\n}\n");
  clip_quad();
  gl.done(p);
  glDepthRange(0.0, 1.0);
  glPointSize(1.0f);
  const double zero[4] = {0, 0, 0, 0};
  glClipPlane(GL_CLIP_PLANE2, zero);
  const float black[4] = {0, 0, 0, 0}, s0[4] = {1, 0, 0, 0}, t0[4] = {0, 1, 0, 0};
  glTexEnvfv(GL_TEXTURE_ENV, GL_TEXTURE_ENV_COLOR, black);
  glTexGenfv(GL_S, GL_EYE_PLANE, s0);
  glTexGenfv(GL_T, GL_OBJECT_PLANE, t0);
}

PINEDA_SCENE(glsl_fragcoord, "gl_FragCoord x, y, z and w in perspective with the depth test") {
  GL2 gl;
  clear_frame(0, 0, 0);
  glEnable(GL_DEPTH_TEST);
  perspective(frame);
  const GLuint p = gl.program(
      nullptr,
      "void main() {\n"
      "  vec2 ring = fract(gl_FragCoord.xy / 32.0);\n"
      "  gl_FragColor = vec4(ring.x * 0.5 + gl_FragCoord.z * 0.5,\n"
      "                      ring.y * 0.3 + gl_FragCoord.w * 2.0, gl_FragCoord.z, 1.0);\n}\n");
  glRotatef(-60.0f, 1, 0, 0);
  glRotatef(30.0f, 0, 0, 1);
  glScalef(1.5f, 3.0f, 1.0f);
  grid(3, 3);
  glRotatef(90.0f, 1, 0, 0);
  grid(2, 2);
  gl.done(p);
}
