// The commands of ARB_shader_objects that are not gl.xml aliases of GL 2.0 commands: the
// generic-object view of shader and program objects (ARB_shader_objects §2.14 "Generic
// Objects", §6.1.12). A handle is the GL 2.0 name of the object; one command serves both kinds
// of object, and asking a shader for program state (or a program for shader state) is
// INVALID_OPERATION. The other ARB commands (CreateShaderObjectARB, AttachObjectARB,
// DetachObjectARB, ...) are generated as thunks into their GL 2.0 aliases.
#include <GL/glext.h>

#include <type_traits>

#include "dispatch.h"
#include "state/api_util.h"
#include "state/program_internal.h"

namespace pineda {

namespace {

enum class ObjectKind { kNone, kShader, kProgram };

// ARB_shader_objects "Errors": a handle that is not an object (zero included) is INVALID_VALUE.
ObjectKind kind_of(Context* ctx, GLhandleARB obj, const char* func) {
  const GlslObjects& o = ctx->shared->glsl;
  if (o.shaders.count(obj) != 0) return ObjectKind::kShader;
  if (o.programs.count(obj) != 0) return ObjectKind::kProgram;
  record_error(ctx, GL_INVALID_VALUE, func);
  return ObjectKind::kNone;
}

// GetObjectParameter{if}vARB: the object's value of `pname`, or false with the error the
// extension names. The OBJECT_*_ARB values equal the GL 2.0 enums GetShaderiv and
// GetProgramiv take (DELETE_STATUS is OBJECT_DELETE_STATUS_ARB ...), so the GL 2.0 queries
// answer once the object's kind fits the parameter.
bool object_parameter(Context* ctx, GLhandleARB obj, GLenum pname, GLint& value, const char* func) {
  const ObjectKind kind = kind_of(ctx, obj, func);
  if (kind == ObjectKind::kNone) return false;
  bool shader_ok = false, program_ok = false;
  switch (pname) {
  case GL_OBJECT_TYPE_ARB:
    value = kind == ObjectKind::kShader ? GL_SHADER_OBJECT_ARB : GL_PROGRAM_OBJECT_ARB;
    return true;
  case GL_OBJECT_DELETE_STATUS_ARB:
  case GL_OBJECT_INFO_LOG_LENGTH_ARB:
    shader_ok = program_ok = true;
    break;
  case GL_OBJECT_SUBTYPE_ARB:
  case GL_OBJECT_COMPILE_STATUS_ARB:
  case GL_OBJECT_SHADER_SOURCE_LENGTH_ARB:
    shader_ok = true;
    break;
  case GL_OBJECT_LINK_STATUS_ARB:
  case GL_OBJECT_VALIDATE_STATUS_ARB:
  case GL_OBJECT_ATTACHED_OBJECTS_ARB:
  case GL_OBJECT_ACTIVE_UNIFORMS_ARB:
  case GL_OBJECT_ACTIVE_UNIFORM_MAX_LENGTH_ARB:
  // ARB_vertex_shader adds the attribute counts to the program's parameters.
  case GL_OBJECT_ACTIVE_ATTRIBUTES_ARB:
  case GL_OBJECT_ACTIVE_ATTRIBUTE_MAX_LENGTH_ARB:
    program_ok = true;
    break;
  default:
    record_error(ctx, GL_INVALID_ENUM, func, pname);
    return false;
  }
  if (kind == ObjectKind::kShader ? !shader_ok : !program_ok) {
    record_error(ctx, GL_INVALID_OPERATION, func);
    return false;
  }
  if (kind == ObjectKind::kShader) {
    if (pname == GL_OBJECT_SUBTYPE_ARB) pname = GL_SHADER_TYPE;
    exec::GetShaderiv(obj, pname, &value);
  } else {
    exec::GetProgramiv(obj, pname, &value);
  }
  return true;
}

} // namespace

namespace exec {

void GLAPIENTRY DeleteObjectARB(GLhandleARB obj) {
  PINEDA_CTX_OUTSIDE("glDeleteObjectARB");
  if (obj == 0) return; // ARB_shader_objects §2.14: zero is silently ignored
  // Deleted now, or flagged for deletion while attached or in use (the GL 2.0 rules).
  switch (kind_of(ctx, obj, "glDeleteObjectARB")) {
  case ObjectKind::kShader:
    return DeleteShader(obj);
  case ObjectKind::kProgram:
    return DeleteProgram(obj);
  default:
    return;
  }
}

GLhandleARB GLAPIENTRY GetHandleARB(GLenum pname) {
  Context* ctx = outside_begin_end("glGetHandleARB");
  if (ctx == nullptr) return 0;
  // PROGRAM_OBJECT_ARB is the only handle the extension defines: the program in use.
  if (pname != GL_PROGRAM_OBJECT_ARB) {
    record_error(ctx, GL_INVALID_ENUM, "glGetHandleARB", pname);
    return 0;
  }
  return ctx->program.current;
}

void GLAPIENTRY GetObjectParameterivARB(GLhandleARB obj, GLenum pname, GLint* params) {
  PINEDA_CTX_OUTSIDE("glGetObjectParameterivARB");
  GLint v = 0;
  if (object_parameter(ctx, obj, pname, v, "glGetObjectParameterivARB") && params != nullptr)
    *params = v;
}

void GLAPIENTRY GetObjectParameterfvARB(GLhandleARB obj, GLenum pname, GLfloat* params) {
  PINEDA_CTX_OUTSIDE("glGetObjectParameterfvARB");
  GLint v = 0;
  if (object_parameter(ctx, obj, pname, v, "glGetObjectParameterfvARB") && params != nullptr)
    *params = static_cast<GLfloat>(v);
}

void GLAPIENTRY GetInfoLogARB(GLhandleARB obj, GLsizei maxLength, GLsizei* length,
                              GLcharARB* infoLog) {
  PINEDA_CTX_OUTSIDE("glGetInfoLogARB");
  switch (kind_of(ctx, obj, "glGetInfoLogARB")) {
  case ObjectKind::kShader:
    return GetShaderInfoLog(obj, maxLength, length, infoLog);
  case ObjectKind::kProgram:
    return GetProgramInfoLog(obj, maxLength, length, infoLog);
  default:
    return;
  }
}

void GLAPIENTRY GetAttachedObjectsARB(GLhandleARB containerObj, GLsizei maxCount, GLsizei* count,
                                      GLhandleARB* obj) {
  // A handle is the object's GLuint name (GLhandleARB is unsigned int outside Apple).
  static_assert(std::is_same_v<GLhandleARB, GLuint>);
  GetAttachedShaders(containerObj, maxCount, count, obj);
}

} // namespace exec
} // namespace pineda
