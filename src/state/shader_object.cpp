// Shader and program objects (GL 2.1 §2.15.1, §2.15.2, §6.1.15): names, sources, compiling
// and linking through the GLSL front end (glsl/glsl.h), UseProgram, deferred deletion,
// validation and the object queries; the program area (program.h) with the two vertex shader
// enables and the generic attribute groups.
#include <algorithm>
#include <cstring>

#include "dispatch.h"
#include "state/api_util.h"
#include "state/area.h"
#include "state/program_internal.h"

namespace pineda {

namespace {

constexpr Capability kProgramCaps[] = {
    {GL_VERTEX_PROGRAM_POINT_SIZE, 1, CapabilityKind::kServer, kDirtyProgram,
     [](Context& c, unsigned, unsigned) { return &c.program.point_size; }},
    {GL_VERTEX_PROGRAM_TWO_SIDE, 1, CapabilityKind::kServer, kDirtyProgram,
     [](Context& c, unsigned, unsigned) { return &c.program.two_side; }},
};

// The groups of Table 6.5 (current generic attributes) and Table 6.7 (generic arrays).
constexpr AttribGroup kProgramGroups[] = {
    member_group<&Context::vertex_attrib>(GL_CURRENT_BIT, 0),
    member_group<&Context::attrib_arrays>(GL_CLIENT_VERTEX_ARRAY_BIT, 0, true),
};

bool get_program_state(Context& ctx, GLenum pname, QueryValues& out) {
  switch (pname) {
  case GL_CURRENT_PROGRAM:
    out.ints({double(ctx.program.current)});
    return true;
  case GL_MAX_VERTEX_ATTRIBS:
    out.ints({kMaxVertexAttribs});
    return true;
  case GL_MAX_VERTEX_UNIFORM_COMPONENTS:
  case GL_MAX_FRAGMENT_UNIFORM_COMPONENTS:
    out.ints({kMaxUniformComponents});
    return true;
  case GL_MAX_VARYING_FLOATS:
    out.ints({kMaxVaryingFloats});
    return true;
  case GL_MAX_TEXTURE_IMAGE_UNITS:
    out.ints({kMaxTextureImageUnits});
    return true;
  case GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS:
    out.ints({kMaxCombinedTextureImageUnits});
    return true;
  case GL_MAX_VERTEX_TEXTURE_IMAGE_UNITS:
    out.ints({kMaxVertexTextureImageUnits});
    return true;
  case GL_MAX_TEXTURE_COORDS:
    out.ints({kMaxTexCoordSets});
    return true;
  default:
    return false;
  }
}

} // namespace

// The program's side of the draws (program_draw.cpp) follows the program, the vertex shader
// enables, and the fixed-function state the stage without a shader reads.
const StateArea kProgramArea = {
    .name = "shaders and programs (GL 2.1 §2.15, Tables 6.29-6.31)",
    .capabilities = kProgramCaps,
    .get = get_program_state,
    .groups = kProgramGroups,
    .derive_on = kDirtyProgram | kDirtyTexture | kDirtyFog | kDirtyLighting | kDirtyRasterMode,
    .derive = derive_program,
};

// ---- helpers shared with uniform.cpp and vertex_attrib.cpp (program_internal.h) ----

glsl::Limits glsl_limits() {
  glsl::Limits l;
  l.max_lights = kMaxLights;
  l.max_clip_planes = kMaxClipPlanes;
  l.max_texture_units = kMaxTexUnits;
  l.max_texture_coords = kMaxTexCoordSets;
  l.max_vertex_attribs = kMaxVertexAttribs;
  l.max_vertex_uniform_components = kMaxUniformComponents;
  l.max_fragment_uniform_components = kMaxUniformComponents;
  l.max_varying_floats = kMaxVaryingFloats;
  l.max_vertex_texture_image_units = kMaxVertexTextureImageUnits;
  l.max_texture_image_units = kMaxTextureImageUnits;
  l.max_combined_texture_image_units = kMaxCombinedTextureImageUnits;
  l.max_draw_buffers = kMaxDrawBuffers;
  return l;
}

ShaderObject* find_shader(Context* ctx, GLuint name, const char* func) {
  GlslObjects& o = ctx->shared->glsl;
  if (auto it = o.shaders.find(name); it != o.shaders.end()) return it->second.get();
  // §2.15: a program name where a shader is expected is INVALID_OPERATION, any other
  // INVALID_VALUE.
  record_error(ctx, o.programs.count(name) != 0 ? GL_INVALID_OPERATION : GL_INVALID_VALUE, func);
  return nullptr;
}

ProgramObject* find_program(Context* ctx, GLuint name, const char* func) {
  GlslObjects& o = ctx->shared->glsl;
  if (auto it = o.programs.find(name); it != o.programs.end()) return it->second.get();
  record_error(ctx, o.shaders.count(name) != 0 ? GL_INVALID_OPERATION : GL_INVALID_VALUE, func);
  return nullptr;
}

const LinkedProgram* active_program(const Context* ctx) {
  const ProgramObject* p = ctx->program.object;
  return p != nullptr ? p->active.get() : nullptr;
}

// Copies `text` into a client buffer of bufSize bytes as GL 2.1 §6.1.15 says: at most
// bufSize - 1 characters and a terminator; *length (if given) the characters written.
void copy_string(const std::string& text, GLsizei buf_size, GLsizei* length, GLchar* out) {
  GLsizei n = 0;
  if (buf_size > 0 && out != nullptr) {
    n = static_cast<GLsizei>(std::min<size_t>(text.size(), static_cast<size_t>(buf_size - 1)));
    std::memcpy(out, text.data(), static_cast<size_t>(n));
    out[n] = '\0';
  }
  if (length != nullptr) *length = n;
}

namespace {

GLuint new_name(GlslObjects& o) {
  while (o.shaders.count(o.next_name) != 0 || o.programs.count(o.next_name) != 0 ||
         o.next_name == 0)
    ++o.next_name;
  return o.next_name++;
}

void delete_shader_now(GlslObjects& o, GLuint name) {
  o.shaders.erase(name);
}

// A shader detached from a program: deleted now if DeleteShader asked for it (§2.15.1).
void detached(GlslObjects& o, GLuint shader) {
  auto it = o.shaders.find(shader);
  if (it == o.shaders.end()) return;
  ShaderObject& s = *it->second;
  --s.attachments;
  if (s.delete_pending && s.attachments <= 0) delete_shader_now(o, shader);
}

void delete_program_now(GlslObjects& o, GLuint name) {
  auto it = o.programs.find(name);
  if (it == o.programs.end()) return;
  const std::vector<GLuint> attached = it->second->attached;
  o.programs.erase(it);
  for (GLuint s : attached)
    detached(o, s);
}

// The context stops using its current program; a program whose deletion waited for that goes
// (§2.15.2).
void drop_current(Context* ctx) {
  ProgramState& ps = ctx->program;
  if (ps.object != nullptr) {
    --ps.object->users;
    if (ps.object->delete_pending && ps.object->users <= 0)
      delete_program_now(ctx->shared->glsl, ps.current);
  }
  ps.current = 0;
  ps.object = nullptr;
}

std::string shader_source(const ShaderObject& s) {
  std::string all;
  for (const std::string& part : s.source)
    all += part;
  return all;
}

// GL 2.1 §2.15.4 validation: what would make a draw with the program fail. Samplers of
// different types may not name the same texture image unit.
bool validate(const ProgramObject& p, std::string& log) {
  if (!p.link_status || !p.active) {
    log = "the program is not linked\n";
    return false;
  }
  const LinkedProgram& lp = *p.active;
  GLenum unit_type[kMaxCombinedTextureImageUnits] = {};
  for (const glsl::ActiveUniform& u : lp.program->uniforms()) {
    if (!is_sampler_type(u.type)) continue;
    for (int e = 0; e < u.size; ++e) {
      const auto unit =
          static_cast<int32_t>(lp.uniforms[static_cast<size_t>(u.word + e * u.stride)]);
      if (unit < 0 || unit >= kMaxCombinedTextureImageUnits) continue;
      if (unit_type[unit] != 0 && unit_type[unit] != u.type) {
        log = "samplers of different types use texture image unit " + std::to_string(unit) + "\n";
        return false;
      }
      unit_type[unit] = u.type;
    }
  }
  log.clear();
  return true;
}

} // namespace

void release_program(Context* ctx) {
  if (ctx->shared) drop_current(ctx);
}

namespace exec {

GLuint GLAPIENTRY CreateShader(GLenum type) {
  Context* ctx = outside_begin_end("glCreateShader");
  if (ctx == nullptr) return 0;
  if (type != GL_VERTEX_SHADER && type != GL_FRAGMENT_SHADER) {
    record_error(ctx, GL_INVALID_ENUM, "glCreateShader", type);
    return 0;
  }
  GlslObjects& o = ctx->shared->glsl;
  const GLuint name = new_name(o);
  auto s = std::make_unique<ShaderObject>();
  s->type = type;
  o.shaders[name] = std::move(s);
  return name;
}

void GLAPIENTRY ShaderSource(GLuint shader, GLsizei count, const GLchar* const* string,
                             const GLint* length) {
  PINEDA_CTX_OUTSIDE("glShaderSource");
  ShaderObject* s = find_shader(ctx, shader, "glShaderSource");
  if (s == nullptr) return;
  if (count < 0) return record_error(ctx, GL_INVALID_VALUE, "glShaderSource");
  std::vector<std::string> parts;
  parts.reserve(static_cast<size_t>(count));
  for (GLsizei i = 0; i < count; ++i) {
    const GLchar* str = string != nullptr ? string[i] : nullptr;
    if (str == nullptr) {
      parts.emplace_back();
      continue;
    }
    // §2.15.1: a negative (or absent) length means a null-terminated string.
    if (length != nullptr && length[i] >= 0)
      parts.emplace_back(str, static_cast<size_t>(length[i]));
    else
      parts.emplace_back(str);
  }
  s->source = std::move(parts);
  s->has_source = true;
}

void GLAPIENTRY CompileShader(GLuint shader) {
  PINEDA_CTX_OUTSIDE("glCompileShader");
  ShaderObject* s = find_shader(ctx, shader, "glCompileShader");
  if (s == nullptr) return;
  const glsl::ShaderStage stage =
      s->type == GL_VERTEX_SHADER ? glsl::ShaderStage::Vertex : glsl::ShaderStage::Fragment;
  s->compiled = glsl::Shader::compile(stage, s->source, glsl_limits());
}

void GLAPIENTRY DeleteShader(GLuint shader) {
  PINEDA_CTX_OUTSIDE("glDeleteShader");
  if (shader == 0) return; // §2.15.1: zero is silently ignored
  ShaderObject* s = find_shader(ctx, shader, "glDeleteShader");
  if (s == nullptr) return;
  if (s->attachments > 0)
    s->delete_pending = true;
  else
    delete_shader_now(ctx->shared->glsl, shader);
}

GLuint GLAPIENTRY CreateProgram() {
  Context* ctx = outside_begin_end("glCreateProgram");
  if (ctx == nullptr) return 0;
  GlslObjects& o = ctx->shared->glsl;
  const GLuint name = new_name(o);
  o.programs[name] = std::make_unique<ProgramObject>();
  return name;
}

void GLAPIENTRY AttachShader(GLuint program, GLuint shader) {
  PINEDA_CTX_OUTSIDE("glAttachShader");
  ProgramObject* p = find_program(ctx, program, "glAttachShader");
  if (p == nullptr) return;
  ShaderObject* s = find_shader(ctx, shader, "glAttachShader");
  if (s == nullptr) return;
  if (std::find(p->attached.begin(), p->attached.end(), shader) != p->attached.end())
    return record_error(ctx, GL_INVALID_OPERATION, "glAttachShader");
  p->attached.push_back(shader);
  ++s->attachments;
}

void GLAPIENTRY DetachShader(GLuint program, GLuint shader) {
  PINEDA_CTX_OUTSIDE("glDetachShader");
  ProgramObject* p = find_program(ctx, program, "glDetachShader");
  if (p == nullptr) return;
  if (find_shader(ctx, shader, "glDetachShader") == nullptr) return;
  auto it = std::find(p->attached.begin(), p->attached.end(), shader);
  if (it == p->attached.end()) return record_error(ctx, GL_INVALID_OPERATION, "glDetachShader");
  p->attached.erase(it);
  detached(ctx->shared->glsl, shader);
}

void GLAPIENTRY LinkProgram(GLuint program) {
  PINEDA_CTX_OUTSIDE("glLinkProgram");
  ProgramObject* p = find_program(ctx, program, "glLinkProgram");
  if (p == nullptr) return;
  GlslObjects& o = ctx->shared->glsl;
  std::vector<std::shared_ptr<const glsl::Shader>> shaders;
  std::string log;
  for (GLuint name : p->attached) {
    const ShaderObject& s = *o.shaders.at(name);
    if (!s.compiled || !s.compiled->compiled())
      log += "error: shader " + std::to_string(name) + " is not compiled\n";
    else
      shaders.push_back(s.compiled);
  }
  auto lp = std::make_shared<LinkedProgram>();
  if (log.empty()) {
    std::vector<glsl::AttribBinding> bindings;
    for (const ProgramObject::Binding& b : p->bindings)
      bindings.push_back({b.name, b.location});
    lp->program = glsl::Program::link(shaders, bindings, glsl_limits());
    log = lp->program->info_log();
  }
  p->ever_linked = true;
  p->info_log = log;
  p->validate_status = false;
  p->link_status = lp->program != nullptr && lp->program->linked();
  if (!p->link_status) {
    // §2.15.2: a failed link leaves the executables of the last successful link installed
    // where the program is in use; its reflection is gone.
    lp->program.reset();
    p->last = std::move(lp);
    return;
  }
  lp->uniforms = lp->program->initial_uniforms();
  lp->builtins = decode_builtins(*lp->program);
  lp->has_vertex = lp->program->vertex() != nullptr;
  // §2.15.3: a matrix attribute takes one location per column.
  for (const glsl::ActiveAttrib& a : lp->program->attribs()) {
    if (a.location < 0) continue;
    const int columns = a.type == GL_FLOAT_MAT4   ? 4
                        : a.type == GL_FLOAT_MAT3 ? 3
                        : a.type == GL_FLOAT_MAT2 ? 2
                                                  : 1;
    for (int k = 0; k < std::max(1, a.size) * columns && a.location + k < kMaxVertexAttribs; ++k)
      lp->generic_inputs |= 1u << (a.location + k);
  }
  p->last = lp;
  p->active = std::move(lp);
  // A successful relink of a program in use installs the new executables (§2.15.2).
  mark_dirty(ctx, kDirtyProgram);
}

void GLAPIENTRY UseProgram(GLuint program) {
  PINEDA_CTX_OUTSIDE("glUseProgram");
  ProgramObject* p = nullptr;
  if (program != 0) {
    p = find_program(ctx, program, "glUseProgram");
    if (p == nullptr) return;
    if (!p->link_status) return record_error(ctx, GL_INVALID_OPERATION, "glUseProgram");
  }
  if (program == ctx->program.current) return;
  drop_current(ctx);
  ctx->program.current = program;
  ctx->program.object = p;
  if (p != nullptr) ++p->users;
  mark_dirty(ctx, kDirtyProgram);
}

void GLAPIENTRY DeleteProgram(GLuint program) {
  PINEDA_CTX_OUTSIDE("glDeleteProgram");
  if (program == 0) return;
  ProgramObject* p = find_program(ctx, program, "glDeleteProgram");
  if (p == nullptr) return;
  // §2.15.2: a program in use by any context is deleted when no context uses it any more.
  if (p->users > 0)
    p->delete_pending = true;
  else
    delete_program_now(ctx->shared->glsl, program);
}

void GLAPIENTRY ValidateProgram(GLuint program) {
  PINEDA_CTX_OUTSIDE("glValidateProgram");
  ProgramObject* p = find_program(ctx, program, "glValidateProgram");
  if (p == nullptr) return;
  std::string log;
  p->validate_status = validate(*p, log);
  if (!log.empty()) p->info_log = log;
}

GLboolean GLAPIENTRY IsShader(GLuint shader) {
  Context* ctx = outside_begin_end("glIsShader");
  if (ctx == nullptr) return GL_FALSE;
  return ctx->shared->glsl.shaders.count(shader) != 0 ? GL_TRUE : GL_FALSE;
}

GLboolean GLAPIENTRY IsProgram(GLuint program) {
  Context* ctx = outside_begin_end("glIsProgram");
  if (ctx == nullptr) return GL_FALSE;
  return ctx->shared->glsl.programs.count(program) != 0 ? GL_TRUE : GL_FALSE;
}

void GLAPIENTRY GetShaderiv(GLuint shader, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetShaderiv");
  ShaderObject* s = find_shader(ctx, shader, "glGetShaderiv");
  if (s == nullptr) return;
  GLint v = 0;
  switch (pname) {
  case GL_SHADER_TYPE:
    v = static_cast<GLint>(s->type);
    break;
  case GL_DELETE_STATUS:
    v = s->delete_pending ? GL_TRUE : GL_FALSE;
    break;
  case GL_COMPILE_STATUS:
    v = s->compiled && s->compiled->compiled() ? GL_TRUE : GL_FALSE;
    break;
  case GL_INFO_LOG_LENGTH: {
    // §6.1.15: with the terminator; zero for an empty log.
    const size_t n = s->compiled ? s->compiled->info_log().size() : 0;
    v = n == 0 ? 0 : static_cast<GLint>(n + 1);
    break;
  }
  case GL_SHADER_SOURCE_LENGTH: {
    const size_t n = shader_source(*s).size();
    v = s->has_source ? static_cast<GLint>(n + 1) : 0;
    break;
  }
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glGetShaderiv", pname);
  }
  if (params != nullptr) *params = v;
}

void GLAPIENTRY GetProgramiv(GLuint program, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetProgramiv");
  ProgramObject* p = find_program(ctx, program, "glGetProgramiv");
  if (p == nullptr) return;
  const glsl::Program* linked = p->link_status && p->last ? p->last->program.get() : nullptr;
  GLint v = 0;
  switch (pname) {
  case GL_DELETE_STATUS:
    v = p->delete_pending ? GL_TRUE : GL_FALSE;
    break;
  case GL_LINK_STATUS:
    v = p->link_status ? GL_TRUE : GL_FALSE;
    break;
  case GL_VALIDATE_STATUS:
    v = p->validate_status ? GL_TRUE : GL_FALSE;
    break;
  case GL_INFO_LOG_LENGTH:
    v = p->info_log.empty() ? 0 : static_cast<GLint>(p->info_log.size() + 1);
    break;
  case GL_ATTACHED_SHADERS:
    v = static_cast<GLint>(p->attached.size());
    break;
  case GL_ACTIVE_ATTRIBUTES:
    v = linked ? static_cast<GLint>(linked->attribs().size()) : 0;
    break;
  case GL_ACTIVE_ATTRIBUTE_MAX_LENGTH:
    v = linked && !linked->attribs().empty() ? static_cast<GLint>(linked->max_attrib_name_length())
                                             : 0;
    break;
  case GL_ACTIVE_UNIFORMS:
    v = linked ? static_cast<GLint>(linked->uniforms().size()) : 0;
    break;
  case GL_ACTIVE_UNIFORM_MAX_LENGTH:
    v = linked && !linked->uniforms().empty()
            ? static_cast<GLint>(linked->max_uniform_name_length())
            : 0;
    break;
  default:
    return record_error(ctx, GL_INVALID_ENUM, "glGetProgramiv", pname);
  }
  if (params != nullptr) *params = v;
}

void GLAPIENTRY GetShaderInfoLog(GLuint shader, GLsizei bufSize, GLsizei* length, GLchar* infoLog) {
  PINEDA_CTX_OUTSIDE("glGetShaderInfoLog");
  ShaderObject* s = find_shader(ctx, shader, "glGetShaderInfoLog");
  if (s == nullptr) return;
  if (bufSize < 0) return record_error(ctx, GL_INVALID_VALUE, "glGetShaderInfoLog");
  copy_string(s->compiled ? s->compiled->info_log() : std::string(), bufSize, length, infoLog);
}

void GLAPIENTRY GetProgramInfoLog(GLuint program, GLsizei bufSize, GLsizei* length,
                                  GLchar* infoLog) {
  PINEDA_CTX_OUTSIDE("glGetProgramInfoLog");
  ProgramObject* p = find_program(ctx, program, "glGetProgramInfoLog");
  if (p == nullptr) return;
  if (bufSize < 0) return record_error(ctx, GL_INVALID_VALUE, "glGetProgramInfoLog");
  copy_string(p->info_log, bufSize, length, infoLog);
}

void GLAPIENTRY GetShaderSource(GLuint shader, GLsizei bufSize, GLsizei* length, GLchar* source) {
  PINEDA_CTX_OUTSIDE("glGetShaderSource");
  ShaderObject* s = find_shader(ctx, shader, "glGetShaderSource");
  if (s == nullptr) return;
  if (bufSize < 0) return record_error(ctx, GL_INVALID_VALUE, "glGetShaderSource");
  copy_string(shader_source(*s), bufSize, length, source);
}

void GLAPIENTRY GetAttachedShaders(GLuint program, GLsizei maxCount, GLsizei* count,
                                   GLuint* shaders) {
  PINEDA_CTX_OUTSIDE("glGetAttachedShaders");
  ProgramObject* p = find_program(ctx, program, "glGetAttachedShaders");
  if (p == nullptr) return;
  if (maxCount < 0) return record_error(ctx, GL_INVALID_VALUE, "glGetAttachedShaders");
  GLsizei n = 0;
  for (GLuint s : p->attached) {
    if (n >= maxCount || shaders == nullptr) break;
    shaders[n++] = s;
  }
  if (count != nullptr) *count = n;
}

void GLAPIENTRY BindAttribLocation(GLuint program, GLuint index, const GLchar* name) {
  PINEDA_CTX_OUTSIDE("glBindAttribLocation");
  ProgramObject* p = find_program(ctx, program, "glBindAttribLocation");
  if (p == nullptr) return;
  if (index >= static_cast<GLuint>(kMaxVertexAttribs))
    return record_error(ctx, GL_INVALID_VALUE, "glBindAttribLocation");
  if (name == nullptr) return;
  // §2.15.3: built-in attributes cannot be bound.
  if (std::strncmp(name, "gl_", 3) == 0)
    return record_error(ctx, GL_INVALID_OPERATION, "glBindAttribLocation");
  // Takes effect at the next link; a later binding of the same name replaces an earlier one.
  for (ProgramObject::Binding& b : p->bindings)
    if (b.name == name) {
      b.location = static_cast<int>(index);
      return;
    }
  p->bindings.push_back({name, static_cast<int>(index)});
}

void GLAPIENTRY GetActiveAttrib(GLuint program, GLuint index, GLsizei bufSize, GLsizei* length,
                                GLint* size, GLenum* type, GLchar* name) {
  PINEDA_CTX_OUTSIDE("glGetActiveAttrib");
  ProgramObject* p = find_program(ctx, program, "glGetActiveAttrib");
  if (p == nullptr) return;
  const glsl::Program* linked = p->link_status && p->last ? p->last->program.get() : nullptr;
  if (linked == nullptr || index >= linked->attribs().size() || bufSize < 0)
    return record_error(ctx, GL_INVALID_VALUE, "glGetActiveAttrib");
  const glsl::ActiveAttrib& a = linked->attribs()[index];
  copy_string(a.name, bufSize, length, name);
  if (size != nullptr) *size = a.size;
  if (type != nullptr) *type = a.type;
}

GLint GLAPIENTRY GetAttribLocation(GLuint program, const GLchar* name) {
  Context* ctx = outside_begin_end("glGetAttribLocation");
  if (ctx == nullptr) return -1;
  ProgramObject* p = find_program(ctx, program, "glGetAttribLocation");
  if (p == nullptr) return -1;
  if (!p->link_status || !p->last) {
    record_error(ctx, GL_INVALID_OPERATION, "glGetAttribLocation");
    return -1;
  }
  return name != nullptr ? p->last->program->attrib_location(name) : -1;
}

} // namespace exec
} // namespace pineda
