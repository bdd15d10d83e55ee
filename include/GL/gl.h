/*
 * Pineda's <GL/gl.h>: the OpenGL 1.x API of the Pineda CPU implementation.
 *
 * Programs written for Mesa's or another vendor's gl.h compile against this header unchanged:
 * it has the same include guards, the same calling-convention macros, the same basic types and
 * (from the generated pineda_gl_api.h) the enums and prototypes of OpenGL 1.0 to 1.5. Like
 * Mesa's gl.h it then includes <GL/glext.h> unless GL_GLEXT_LEGACY is defined.
 */
#ifndef __gl_h_
#define __gl_h_ 1
/* Older code tests this spelling of the guard. */
#define __GL_H__ 1

/*
 * GLAPIENTRY is the calling convention of GL entry points. On the Linux targets Pineda
 * supports there is just one, so it expands to nothing; it stays overridable for code that
 * defines it first.
 */
#ifndef GLAPIENTRY
#define GLAPIENTRY
#endif
#ifndef GLAPIENTRYP
#define GLAPIENTRYP GLAPIENTRY *
#endif
#ifndef APIENTRY
#define APIENTRY GLAPIENTRY
#endif
#ifndef APIENTRYP
#define APIENTRYP APIENTRY *
#endif

/*
 * GLAPI starts every declaration of a GL entry point. The library is built with hidden
 * visibility by default, so the declarations the implementation sees must mark the entry points
 * as exported. C++ linkage is handled by the extern "C" blocks around the declarations.
 */
#ifndef GLAPI
#if defined(__GNUC__) || defined(__clang__)
#define GLAPI extern __attribute__((visibility("default")))
#else
#define GLAPI extern
#endif
#endif

#ifdef __cplusplus
extern "C" {
#endif

/*
 * The basic types, as the Khronos registry defines them (its khrplatform.h types spelled out
 * for Linux). <GL/glext.h> defines the rest, and the generator that writes it knows this list:
 * keep tools/gen/gen_gl.py's GL_H_TYPES in step with it.
 */
typedef unsigned int GLenum;
typedef unsigned char GLboolean;
typedef unsigned int GLbitfield;
typedef void GLvoid;
typedef signed char GLbyte;
typedef short GLshort;
typedef int GLint;
typedef unsigned char GLubyte;
typedef unsigned short GLushort;
typedef unsigned int GLuint;
typedef int GLsizei;
typedef float GLfloat;
typedef float GLclampf;
typedef double GLdouble;
typedef double GLclampd;
typedef char GLchar;
/* Pointer-sized signed integers (GL 1.5 buffer objects); khrplatform.h's "signed long int". */
typedef signed long int GLintptr;
typedef signed long int GLsizeiptr;

#ifdef __cplusplus
}
#endif

/* Enums and prototypes of GL 1.0-1.5, generated from the Khronos registry. */
#include <GL/pineda_gl_api.h>

#ifndef GL_GLEXT_LEGACY
#include <GL/glext.h>
#endif

/*
 * Names Mesa's gl.h has that the Khronos registry does not, kept so that programs written
 * against Mesa's header compile here too.
 */
#ifdef __cplusplus
extern "C" {
#endif

/* Mesa's older spelling of GL_CLIENT_ALL_ATTRIB_BITS. */
#ifndef GL_ALL_CLIENT_ATTRIB_BITS
#define GL_ALL_CLIENT_ATTRIB_BITS 0xFFFFFFFF
#endif

/* An obsolete Mesa extension, superseded by GL_EXT_packed_depth_stencil. */
#ifndef GL_MESA_packed_depth_stencil
#define GL_MESA_packed_depth_stencil 1
#define GL_DEPTH_STENCIL_MESA 0x8750
#define GL_UNSIGNED_INT_24_8_MESA 0x8751
#define GL_UNSIGNED_INT_8_24_REV_MESA 0x8752
#define GL_UNSIGNED_SHORT_15_1_MESA 0x8753
#define GL_UNSIGNED_SHORT_1_15_REV_MESA 0x8754
#endif

/* ATI's precursor of glBlendEquationSeparate. */
#ifndef GL_ATI_blend_equation_separate
#define GL_ATI_blend_equation_separate 1
#define GL_ALPHA_BLEND_EQUATION_ATI 0x883D
GLAPI void GLAPIENTRY glBlendEquationSeparateATI(GLenum modeRGB, GLenum modeA);
typedef void(APIENTRYP PFNGLBLENDEQUATIONSEPARATEATIPROC)(GLenum modeRGB, GLenum modeA);
#endif

#ifdef __cplusplus
}
#endif

#endif /* __gl_h_ */
