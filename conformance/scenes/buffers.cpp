// Buffer objects (GL 2.1 §2.9): vertex data and indices sourced from buffers with offsets as
// pointers (§2.9.1, §2.9.2), updated with glBufferSubData and glMapBuffer, mixed with client
// arrays. All entry points are GL 1.5, so they are looked up with proc().
#include "scene_util.h"

#include <cmath>
#include <cstddef>
#include <cstring>
#include <vector>

using namespace scenes;

namespace {

struct BufferApi {
  PFNGLGENBUFFERSPROC gen = proc<PFNGLGENBUFFERSPROC>("glGenBuffers");
  PFNGLDELETEBUFFERSPROC del = proc<PFNGLDELETEBUFFERSPROC>("glDeleteBuffers");
  PFNGLBINDBUFFERPROC bind = proc<PFNGLBINDBUFFERPROC>("glBindBuffer");
  PFNGLBUFFERDATAPROC data = proc<PFNGLBUFFERDATAPROC>("glBufferData");
  PFNGLBUFFERSUBDATAPROC sub = proc<PFNGLBUFFERSUBDATAPROC>("glBufferSubData");
  PFNGLMAPBUFFERPROC map = proc<PFNGLMAPBUFFERPROC>("glMapBuffer");
  PFNGLUNMAPBUFFERPROC unmap = proc<PFNGLUNMAPBUFFERPROC>("glUnmapBuffer");
};

// Offsets into a bound buffer are passed where client pointers would be (GL 2.1 §2.9.1).
const GLvoid* offset(std::size_t bytes) { return reinterpret_cast<const GLvoid*>(bytes); }

struct Vertex {
  GLfloat x, y;
  GLubyte c[4];
};

// A ring of quads (as indexed triangles) around the centre of a w x h region.
void ring(float cx, float cy, float r0, float r1, int segments, int colour_base,
          std::vector<Vertex>& v, std::vector<GLushort>& idx) {
  const GLushort base = static_cast<GLushort>(v.size());
  for (int i = 0; i <= segments; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    for (int k = 0; k < 2; ++k) {
      const float r = k ? r1 : r0;
      const float* p = palette(colour_base + i + 3 * k);
      v.push_back(Vertex{cx + r * std::cos(a), cy + r * std::sin(a),
                         {GLubyte(p[0] * 255), GLubyte(p[1] * 255), GLubyte(p[2] * 255), 255}});
    }
  }
  for (int i = 0; i < segments; ++i) {
    const GLushort a = static_cast<GLushort>(base + 2 * i), b = a + 1, c = a + 2, d = a + 3;
    const GLushort tri[6] = {a, c, b, b, c, d};
    idx.insert(idx.end(), tri, tri + 6);
  }
}

} // namespace

PINEDA_SCENE(buffer_objects, "VBO + IBO with offsets, glBufferSubData and glMapBuffer updates") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const BufferApi gl;
  const auto draw_range = proc<PFNGLDRAWRANGEELEMENTSPROC>("glDrawRangeElements");
  std::vector<Vertex> v;
  std::vector<GLushort> idx;
  ring(128.3f, 128.2f, 20.0f, 60.0f, 24, 0, v, idx);
  ring(128.3f, 128.2f, 70.0f, 120.0f, 40, 5, v, idx);
  const std::size_t first_ring_vertices = 50, first_ring_indices = 24 * 6;

  GLuint buffers[2];
  gl.gen(2, buffers);
  gl.bind(GL_ARRAY_BUFFER, buffers[0]);
  // 64 bytes of leading garbage so that every pointer is a non-zero offset.
  const std::size_t lead = 64;
  gl.data(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(lead + v.size() * sizeof(Vertex)), nullptr,
          GL_STATIC_DRAW);
  gl.sub(GL_ARRAY_BUFFER, static_cast<GLintptr>(lead),
         static_cast<GLsizeiptr>(v.size() * sizeof(Vertex)), v.data());
  // Recolour the outer ring through a mapping: every other vertex becomes white.
  if (auto* mapped = static_cast<unsigned char*>(gl.map(GL_ARRAY_BUFFER, GL_WRITE_ONLY))) {
    for (std::size_t i = first_ring_vertices; i < v.size(); i += 2) {
      Vertex white = v[i];
      std::memset(white.c, 255, 4);
      std::memcpy(mapped + lead + i * sizeof(Vertex), &white, sizeof white);
    }
    // The remaining vertices are written through the mapping as well, so the result does not
    // depend on what a write-only mapping shows of the old contents.
    for (std::size_t i = 0; i < v.size(); ++i)
      if (i < first_ring_vertices || (i - first_ring_vertices) % 2)
        std::memcpy(mapped + lead + i * sizeof(Vertex), &v[i], sizeof(Vertex));
    gl.unmap(GL_ARRAY_BUFFER);
  }
  gl.bind(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  gl.data(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(idx.size() * sizeof(GLushort)),
          idx.data(), GL_STATIC_DRAW);

  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_COLOR_ARRAY);
  glVertexPointer(2, GL_FLOAT, sizeof(Vertex), offset(lead));
  glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(Vertex), offset(lead + offsetof(Vertex, c)));
  // Inner ring with glDrawElements, outer ring with glDrawRangeElements at an index offset.
  glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(first_ring_indices), GL_UNSIGNED_SHORT, offset(0));
  draw_range(GL_TRIANGLES, static_cast<GLuint>(first_ring_vertices), static_cast<GLuint>(v.size() - 1),
             static_cast<GLsizei>(idx.size() - first_ring_indices), GL_UNSIGNED_SHORT,
             offset(first_ring_indices * sizeof(GLushort)));
  glDisableClientState(GL_VERTEX_ARRAY);
  glDisableClientState(GL_COLOR_ARRAY);
  gl.bind(GL_ARRAY_BUFFER, 0);
  gl.bind(GL_ELEMENT_ARRAY_BUFFER, 0);
  gl.del(2, buffers);
}

PINEDA_SCENE(buffer_mixed, "Positions from a buffer, colours from client memory; client indices; glDrawArrays") {
  clear_frame(0.0f, 0.0f, 0.0f);
  const BufferApi gl;
  const auto multi_elements = proc<PFNGLMULTIDRAWELEMENTSPROC>("glMultiDrawElements");
  Rng rng(900);
  // A strip field: positions in a buffer object, colours in a client array.
  const int cols = 16, rows = 12;
  std::vector<GLfloat> pos;
  std::vector<GLubyte> col;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= cols; ++i) {
      pos.push_back(6.0f + 244.0f * i / cols + rng.range(-3.0f, 3.0f));
      pos.push_back(6.0f + 244.0f * j / rows + rng.range(-3.0f, 3.0f));
      const float* p = palette(rng.below(16));
      for (int k = 0; k < 3; ++k) col.push_back(GLubyte(p[k] * 255));
    }
  }
  GLuint buffers[2];
  gl.gen(2, buffers);
  gl.bind(GL_ARRAY_BUFFER, buffers[0]);
  gl.data(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(pos.size() * sizeof(GLfloat)), pos.data(),
          GL_STREAM_DRAW);
  glEnableClientState(GL_VERTEX_ARRAY);
  glVertexPointer(2, GL_FLOAT, 0, offset(0));
  gl.bind(GL_ARRAY_BUFFER, 0); // the vertex pointer keeps its buffer binding (GL 2.1 §2.9.1)
  glEnableClientState(GL_COLOR_ARRAY);
  glColorPointer(3, GL_UNSIGNED_BYTE, 0, col.data());
  // Lower half: client-memory indices, one strip per row.
  for (int j = 0; j < rows / 2; ++j) {
    std::vector<GLuint> strip;
    for (int i = 0; i <= cols; ++i) {
      strip.push_back(static_cast<GLuint>(j * (cols + 1) + i));
      strip.push_back(static_cast<GLuint>((j + 1) * (cols + 1) + i));
    }
    glDrawElements(GL_TRIANGLE_STRIP, static_cast<GLsizei>(strip.size()), GL_UNSIGNED_INT, strip.data());
  }
  // Upper half: indices in an element buffer, drawn by glMultiDrawElements with offsets.
  std::vector<GLuint> all;
  std::vector<const GLvoid*> offsets;
  std::vector<GLsizei> counts;
  for (int j = rows / 2; j < rows; ++j) {
    offsets.push_back(offset(all.size() * sizeof(GLuint)));
    for (int i = 0; i <= cols; ++i) {
      all.push_back(static_cast<GLuint>(j * (cols + 1) + i));
      all.push_back(static_cast<GLuint>((j + 1) * (cols + 1) + i));
    }
    counts.push_back(static_cast<GLsizei>(2 * (cols + 1)) - (j % 3 == 0 ? 10 : 0));
  }
  gl.bind(GL_ELEMENT_ARRAY_BUFFER, buffers[1]);
  gl.data(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(all.size() * sizeof(GLuint)), all.data(),
          GL_STATIC_DRAW);
  multi_elements(GL_TRIANGLE_STRIP, counts.data(), GL_UNSIGNED_INT, offsets.data(),
                 static_cast<GLsizei>(counts.size()));
  gl.bind(GL_ELEMENT_ARRAY_BUFFER, 0);
  // Points on top through glDrawArrays, still reading positions from the buffer.
  glDisableClientState(GL_COLOR_ARRAY);
  glColor3f(1.0f, 1.0f, 1.0f);
  glDrawArrays(GL_POINTS, 0, static_cast<GLsizei>(pos.size() / 2));
  glDisableClientState(GL_VERTEX_ARRAY);
  gl.del(2, buffers);
}
