// The GLSL 1.10/1.20 front end: compiles shader objects with glslang and links programs into
// engine executables (shader/engine.h), with the reflection GL 2.1 §2.15 asks for. This is
// what glCompileShader, glLinkProgram, glGetActiveUniform/Attrib, glGetUniformLocation and the
// draw path call; it knows nothing of the GL context.
//
// Compile: glslang parses the source as desktop GLSL with no client or target (versions 110
// and 120; others are refused), then Pineda's own checks close the gaps where glslang accepts
// what GLSL 1.10/1.20 forbids (checks.cpp). Link: glslang links the stages; Pineda checks what
// it does not (interface, initializers, limits), lowers each stage to its IR (lower.h),
// optimizes it, keeps only what the other stage or the fixed-function stages read, and builds
// the executables. Failures never throw: they set the status and write the log.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "shader/engine.h"

namespace pineda::glsl {

enum class ShaderStage : uint8_t { Vertex, Fragment };

// The implementation limits a program is checked against (GL 2.1 Table 6.37 and the built-in
// constants of GLSL 1.20 §7.4).
struct Limits {
  int max_lights = 8;
  int max_clip_planes = 6;
  int max_texture_units = 4;  // fixed-function texture units: gl_TextureEnvColor[]
  int max_texture_coords = 8; // gl_TexCoord[], gl_TextureMatrix[]
  int max_vertex_attribs = 16;
  int max_vertex_uniform_components = 4096;
  int max_fragment_uniform_components = 4096;
  int max_varying_floats = 64;
  int max_vertex_texture_image_units = 16;
  int max_texture_image_units = 16;
  int max_combined_texture_image_units = 32;
  int max_draw_buffers = 8;
  // Not a limit: keep the optimized IR and code as text (Program::ir_text), as PINEDA_DEBUG=ir
  // does (which also prints it).
  bool keep_ir = false;
};

class Shader {
public:
  // Compiles the concatenation of `strings` (glShaderSource's strings, GLSL 1.10 §3.2: the log
  // names them by index). Always returns a shader; compiled() says whether it compiled.
  static std::shared_ptr<Shader> compile(ShaderStage stage, const std::vector<std::string>& strings,
                                         const Limits& limits = {});
  ~Shader();

  ShaderStage stage() const { return stage_; }
  bool compiled() const { return compiled_; }
  const std::string& info_log() const { return log_; }

  struct Impl;
  Impl* impl() const { return impl_.get(); }

private:
  Shader() = default;
  ShaderStage stage_ = ShaderStage::Vertex;
  bool compiled_ = false;
  std::string log_;
  std::unique_ptr<Impl> impl_;
};

// One string of glGetActiveUniform: a basic type or an array of one (GL 2.1 §2.15.3: structs
// broken into members, arrays named with "[0]").
struct ActiveUniform {
  std::string name; // "light.color", "weights[0]", "gl_ModelViewMatrix"
  GLenum type = GL_FLOAT;
  int size = 1;      // highest element the program reads, plus one
  int location = -1; // first element's location; -1 for built-in uniforms (names "gl_...")
  int word = 0;      // first word in the uniform buffer
  int stride = 0;    // words from one element to the next
  bool array = false;
};

// One location: what glUniform* with it writes.
struct UniformLocation {
  int uniform = 0; // index into Program::uniforms()
  int element = 0;
  int word = 0;
};

struct ActiveAttrib {
  std::string name;
  GLenum type = GL_FLOAT_VEC4;
  int size = 1;
  int location = -1; // generic attribute index; -1 for gl_Vertex and the other built-ins
};

// Built-in uniform state (GLSL 1.20 §7.5) the program reads, one entry per basic-type leaf
// ("gl_ModelViewProjectionMatrix", "gl_LightSource[1].diffuse", "gl_TextureMatrix[0]"): the
// draw path derives and writes these words before drawing, and nothing else.
struct BuiltinUniform {
  std::string name;
  GLenum type = GL_FLOAT;
  int word = 0;
};

struct AttribBinding {
  std::string name;
  int location = 0;
};

struct ProgramImpl;

class Program {
public:
  // Links the shaders (any mix of compiled vertex and fragment shaders; none links to a
  // program without executables, which leaves both stages to fixed function). `bindings` are
  // glBindAttribLocation's. Always returns a program; linked() says whether it linked.
  static std::unique_ptr<Program> link(const std::vector<std::shared_ptr<const Shader>>& shaders,
                                       const std::vector<AttribBinding>& bindings,
                                       const Limits& limits = {});
  ~Program();

  bool linked() const { return linked_; }
  const std::string& info_log() const { return log_; }

  // ---- reflection (GL 2.1 §2.15.3) ----
  const std::vector<ActiveUniform>& uniforms() const;
  const std::vector<UniformLocation>& locations() const; // indexed by location
  const std::vector<ActiveAttrib>& attribs() const;
  // glGetUniformLocation / glGetAttribLocation (-1: no such active variable).
  int uniform_location(std::string_view name) const;
  int attrib_location(std::string_view name) const;
  size_t max_uniform_name_length() const; // with the terminator, ACTIVE_UNIFORM_MAX_LENGTH
  size_t max_attrib_name_length() const;

  // ---- what the draw path needs ----
  // The uniform buffer: its size, and its contents right after the link (zero, or the
  // initializers of GLSL 1.20 §4.3.5). Samplers hold their texture unit as an int; bools 0/1.
  int uniform_words() const;
  const std::vector<uint32_t>& initial_uniforms() const;
  const std::vector<BuiltinUniform>& builtin_uniforms() const;
  // Null for a stage the program does not have.
  const shader::Executable* vertex() const;
  const shader::Executable* fragment() const;
  // The fragment shader writes gl_FragColor (to every draw buffer) rather than gl_FragData[].
  bool writes_frag_color() const;
  bool writes_frag_depth() const;
  // Where flat component `comp` of user varying `name` went when the link packed the varyings
  // the fragment shader reads: index k, so fragment input kFragVarying0 * 4 + k and vertex
  // output kOutVarying0 * 4 + k (shader/io.h); -1 when the fragment shader does not read it.
  int varying_component(const std::string& name, int comp) const;
  // The optimized IR of each stage, for PINEDA_DEBUG=ir.
  const std::string& ir_text() const;

private:
  Program() = default;
  bool linked_ = false;
  std::string log_;
  std::unique_ptr<ProgramImpl> impl_;
};

} // namespace pineda::glsl
