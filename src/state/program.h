// Shader and program objects (GL 2.1 §2.15, §2.20; Tables 6.29-6.31 "Shader Object State",
// "Program Object State", "Vertex Shader State"), uniforms (§2.15.3) and the generic vertex
// attributes (§2.7 current values, §2.8 arrays). Commands in shader_object.cpp (objects,
// compile, link, queries), uniform.cpp (Uniform*, GetUniform*, GetActiveUniform) and
// vertex_attrib.cpp (VertexAttrib*, VertexAttribPointer, GetVertexAttrib*).
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "core/limits.h"
#include "shader/io.h"

// Only pointers to the front end's, the engine's and the back end's types here: context.h
// includes this header, and their names (Bool, Region, None) collide with Xlib's macros in
// the GLX files.
namespace pineda::glsl {
class Shader;
class Program;
} // namespace pineda::glsl
namespace pineda::shader {
struct Prepared;
} // namespace pineda::shader

namespace pineda {

struct Context;
struct StateArea;
class ShaderSampler;

constexpr int kMaxVertexAttribs = shader::kMaxVertexAttribs;    // MAX_VERTEX_ATTRIBS
constexpr int kMaxVaryingFloats = 4 * shader::kMaxVaryingSlots; // MAX_VARYING_FLOATS
constexpr int kMaxUniformComponents = 4096; // MAX_{VERTEX,FRAGMENT}_UNIFORM_COMPONENTS

// A shader object (§2.15.1).
struct ShaderObject {
  GLenum type = GL_VERTEX_SHADER;
  std::vector<std::string> source; // ShaderSource's strings, as given
  bool has_source = false;
  std::shared_ptr<glsl::Shader> compiled; // the last CompileShader's result
  bool delete_pending = false;            // DeleteShader while attached (§2.15.1)
  int attachments = 0;                    // programs it is attached to
};

// One word group of built-in uniform state (GLSL 1.20 §7.5) a program reads, decoded from its
// name at link time (program_draw.cpp): what to derive and where it goes.
struct BuiltinSlot {
  uint16_t kind = 0; // program_draw.cpp's BuiltinKind
  uint8_t index = 0; // light, texture unit, plane
  uint8_t field = 0; // member or matrix form
  int word = 0;
};

// What a successful link installs (§2.15.2): the executables, the reflection and the uniform
// values. Contexts draw with it; the program object keeps it until the next successful link.
struct LinkedProgram {
  std::shared_ptr<const glsl::Program> program;
  std::vector<uint32_t> uniforms; // the uniform buffer (glsl.h)
  uint64_t uniform_serial = 1;    // advanced with every change of `uniforms`
  uint32_t generic_inputs = 0;    // bit i: the vertex shader reads generic attribute i
  bool has_vertex = false;        // the program has a vertex shader
  std::vector<BuiltinSlot> builtins;
};

// Decodes the program's built-in uniforms (program_draw.cpp).
std::vector<BuiltinSlot> decode_builtins(const glsl::Program& program);

// A program object (§2.15.2).
struct ProgramObject {
  std::vector<GLuint> attached; // shader names, in attachment order
  struct Binding {
    std::string name;
    int location = 0;
  };
  std::vector<Binding> bindings; // BindAttribLocation (applied at the next link)
  bool link_status = false;
  bool validate_status = false;
  bool ever_linked = false;
  std::string info_log;
  // The last link attempt (its reflection answers the queries) and the last successful one
  // (what contexts that use the program draw with, §2.15.2: a failed relink leaves it).
  std::shared_ptr<LinkedProgram> last;
  std::shared_ptr<LinkedProgram> active;
  bool delete_pending = false;
  int users = 0; // contexts whose current program it is
};

// The shader and program objects of a share group (one name space, §2.15).
struct GlslObjects {
  std::unordered_map<GLuint, std::unique_ptr<ShaderObject>> shaders;
  std::unordered_map<GLuint, std::unique_ptr<ProgramObject>> programs;
  GLuint next_name = 1;
};

// CURRENT_BIT part of Table 6.5: the generic attributes' current values (attribute 0 is the
// vertex, §2.7, and has none).
struct VertexAttribCurrentGroup {
  float value[kMaxVertexAttribs][4] = {};
  VertexAttribCurrentGroup() {
    for (auto& v : value)
      v[3] = 1.0f;
  }
};

// One generic vertex attribute array (§2.8, Table 6.7).
struct GenericArray {
  bool enabled = false;
  GLint size = 4;
  GLenum type = GL_FLOAT;
  bool normalized = false;
  GLsizei stride = 0;
  const void* pointer = nullptr;
  GLuint buffer = 0;
};

// CLIENT_VERTEX_ARRAY_BIT part of Table 6.7: the generic arrays.
struct VertexAttribArrayGroup {
  GenericArray array[kMaxVertexAttribs];
};

// The program in use (Table 6.30 CURRENT_PROGRAM, no attribute group) and the two vertex
// shader enables (Table 6.31, "enable").
struct ProgramState {
  GLuint current = 0;
  ProgramObject* object = nullptr; // of `current`, null when 0
  bool point_size = false;         // VERTEX_PROGRAM_POINT_SIZE
  bool two_side = false;           // VERTEX_PROGRAM_TWO_SIDE
};

// The executable the current program draws with, or null: the state a draw reads.
const LinkedProgram* active_program(const Context* ctx);

struct ProgramDerived; // program_draw.h

// With a fragment shader and no vertex shader: the units whose coordinates the shader reads
// (bit u for gl_TexCoord[u]) and, in *fog, whether it reads gl_FogFragCoord; what the
// fixed-function vertex stage must compute for it. Zero otherwise.
uint32_t fixed_vertex_program_inputs(const Context& ctx, bool* fog);

// The program area's derived state (ProgramDerived) when the program changed.
void derive_program(Context& ctx, uint32_t dirty);
// Before a draw with a program: uniforms, built-in state and texture views.
void refresh_program(Context* ctx);

// Marks the program's derived state stale when the program in use was relinked (also by
// another context of the share group) since it was derived.
void check_program_link(Context* ctx);

// Per-vertex generic attribute values a draw hands down with its vertices (draw_call.h): four
// floats per attribute of `mask`, in attribute order; attributes outside `mask` take their
// current values.
struct GenericVertices {
  const float* data = nullptr;
  uint32_t mask = 0;
};

// Fills `out` with the generic attributes of `mask` of element first + k, k < n, from their
// arrays (fetch.cpp's conversions); false when a buffer-backed array would be read outside its
// storage. And of an explicit list of elements.
bool fetch_generic_range(Context* ctx, uint32_t mask, size_t first, size_t n, float* out);
bool fetch_generic_list(Context* ctx, uint32_t mask, const uint32_t* elements, size_t n,
                        float* out);
// The generic arrays (of attributes 1..15) that are enabled (bit i for attribute i).
uint32_t enabled_generic_arrays(const Context* ctx);
// Whether generic array 0 is enabled: it then supplies the vertex (§2.8).
bool generic_array0_enabled(const Context* ctx);

// Drops the context's use of its current program (context destruction).
void release_program(Context* ctx);

extern const StateArea kProgramArea; // shader_object.cpp

} // namespace pineda
