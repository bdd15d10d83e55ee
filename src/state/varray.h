// Vertex arrays and buffer objects (GL 2.1 §2.8, §2.9; Tables 6.6-6.9 "Vertex Array Data" and
// "Buffer Object State", the client "vertex-array" attribute group). Commands in varray.cpp,
// bufferobj.cpp, texenv.cpp (ClientActiveTexture), color_index.cpp (IndexPointer) and
// ext_commands.cpp (EXT_vertex_array).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <vector>

#include "core/limits.h"

namespace pineda {

struct StateArea;

// One client vertex array (GL 2.1 §2.8) and the buffer object bound when it was specified.
struct ClientArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  GLsizei stride = 0; // as given; 0 means tightly packed
  const void* pointer = nullptr;
  GLuint buffer = 0;     // ARRAY_BUFFER_BINDING captured at glXxxPointer time
  GLsizei count_ext = 0; // EXT_vertex_array's count (ext_commands.cpp)
};

// CLIENT_VERTEX_ARRAY_BIT: Tables 6.6-6.8 and the buffer bindings of Table 6.9.
struct VertexArrayGroup {
  ClientArray vertex{false, 4, GL_FLOAT, 0, nullptr, 0};
  ClientArray color{false, 4, GL_FLOAT, 0, nullptr, 0};
  ClientArray normal{false, 3, GL_FLOAT, 0, nullptr, 0};
  ClientArray texcoord[kMaxTexUnits];
  ClientArray edgeflag{false, 1, GL_BOOL, 0, nullptr, 0};
  ClientArray secondary{false, 3, GL_FLOAT, 0, nullptr, 0}; // SECONDARY_COLOR_ARRAY
  ClientArray fog{false, 1, GL_FLOAT, 0, nullptr, 0};       // FOG_COORD_ARRAY (GL 1.4)
  ClientArray index{false, 1, GL_FLOAT, 0, nullptr, 0};     // INDEX_ARRAY (never read)
  GLuint client_active_texture = 0;                         // CLIENT_ACTIVE_TEXTURE - TEXTURE0
  GLuint array_buffer = 0;                                  // ARRAY_BUFFER_BINDING
  GLuint element_array_buffer = 0;                          // ELEMENT_ARRAY_BUFFER_BINDING
};

// A buffer object (GL 2.1 §2.9).
struct BufferObject {
  std::vector<uint8_t> data;
  GLenum usage = GL_STATIC_DRAW;
  GLenum access = GL_READ_WRITE;
  bool mapped = false;
  bool ever_bound = false;
};

extern const StateArea kVertexArrayArea; // varray.cpp

} // namespace pineda
