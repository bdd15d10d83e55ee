/*
 * Pineda's <GL/osmesa.h>: off-screen rendering into a buffer the application owns.
 *
 * The interface, its semantics and every constant value are those of Mesa's OSMesa, so a
 * program written for Mesa's header compiles against this one and runs on libOSMesa.so.8 from
 * either implementation.
 *
 * Usage: create a context for a pixel format, make it current on a buffer of
 * width * height pixels, draw with GL, then read the pixels out of that same buffer.
 */
#ifndef OSMESA_H
#define OSMESA_H

#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

/* The OSMesa interface revision this header describes (Mesa's numbering). */
#define OSMESA_MAJOR_VERSION 11
#define OSMESA_MINOR_VERSION 2
#define OSMESA_PATCH_VERSION 0

/* Pixel formats for OSMesaCreateContext*(): the byte order of one pixel in the buffer. */
#define OSMESA_COLOR_INDEX GL_COLOR_INDEX /* accepted for compatibility, not supported */
#define OSMESA_RGBA GL_RGBA
#define OSMESA_BGRA 0x1
#define OSMESA_ARGB 0x2
#define OSMESA_RGB GL_RGB
#define OSMESA_BGR 0x4
#define OSMESA_RGB_565 0x5

/* OSMesaPixelStore() parameters. */
#define OSMESA_ROW_LENGTH 0x10 /* pixels per buffer row; 0 means the width */
#define OSMESA_Y_UP 0x11 /* nonzero: row 0 is the bottom row (the default) */

/* OSMesaGetIntegerv() parameters. */
#define OSMESA_WIDTH 0x20
#define OSMESA_HEIGHT 0x21
#define OSMESA_FORMAT 0x22
#define OSMESA_TYPE 0x23
#define OSMESA_MAX_WIDTH 0x24
#define OSMESA_MAX_HEIGHT 0x25

/* Attribute names and values for OSMesaCreateContextAttribs(). */
#define OSMESA_DEPTH_BITS 0x30
#define OSMESA_STENCIL_BITS 0x31
#define OSMESA_ACCUM_BITS 0x32
#define OSMESA_PROFILE 0x33
#define OSMESA_CORE_PROFILE 0x34
#define OSMESA_COMPAT_PROFILE 0x35
#define OSMESA_CONTEXT_MAJOR_VERSION 0x36
#define OSMESA_CONTEXT_MINOR_VERSION 0x37

/* A rendering context. Applications only hold and pass the pointer. */
typedef struct osmesa_context *OSMesaContext;

/* What OSMesaGetProcAddress() returns: cast it to the command's PFNGL...PROC type. */
typedef void (*OSMESAproc)(void);

/*
 * Creates a context whose color buffer has the given OSMESA_* format, with the library's
 * default depth and stencil buffers. sharelist, if not NULL, is a context whose display lists
 * and textures the new one shares. Returns NULL on failure.
 */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContext(GLenum format, OSMesaContext sharelist);

/* As OSMesaCreateContext(), with the sizes in bits of the depth, stencil and accumulation
 * buffers chosen by the caller (0 for none). */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextExt(GLenum format, GLint depthBits,
                                                      GLint stencilBits, GLint accumBits,
                                                      OSMesaContext sharelist);

/*
 * As OSMesaCreateContext(), configured by a list of (name, value) pairs ended by a 0 name.
 * Names and their defaults: OSMESA_FORMAT (OSMESA_RGBA), OSMESA_DEPTH_BITS (0),
 * OSMESA_STENCIL_BITS (0), OSMESA_ACCUM_BITS (0), OSMESA_PROFILE (OSMESA_COMPAT_PROFILE, or
 * OSMESA_CORE_PROFILE), OSMESA_CONTEXT_MAJOR_VERSION (1) and OSMESA_CONTEXT_MINOR_VERSION (0).
 * The context may have a higher version than requested; NULL if the request cannot be met.
 */
GLAPI OSMesaContext GLAPIENTRY OSMesaCreateContextAttribs(const int *attribList,
                                                          OSMesaContext sharelist);

/* Frees a context and its ancillary buffers; the application's color buffer is not touched. */
GLAPI void GLAPIENTRY OSMesaDestroyContext(OSMesaContext ctx);

/*
 * Binds ctx to the calling thread and makes it render into buffer, width x height pixels of
 * the context's format with components of the given type (GL_UNSIGNED_BYTE, and for some
 * formats GL_UNSIGNED_SHORT_5_6_5, GL_UNSIGNED_SHORT or GL_FLOAT). The first time a context is
 * made current its viewport becomes (0, 0, width, height). Returns GL_FALSE on a bad argument
 * (NULL context or buffer, unsupported type, a size below 1 or above OSMESA_MAX_WIDTH /
 * OSMESA_MAX_HEIGHT).
 */
GLAPI GLboolean GLAPIENTRY OSMesaMakeCurrent(OSMesaContext ctx, void *buffer, GLenum type,
                                             GLsizei width, GLsizei height);

/* The context current on the calling thread, or NULL. */
GLAPI OSMesaContext GLAPIENTRY OSMesaGetCurrentContext(void);

/* Sets OSMESA_ROW_LENGTH or OSMESA_Y_UP for the current context. */
GLAPI void GLAPIENTRY OSMesaPixelStore(GLint pname, GLint value);

/* Reads one OSMESA_* value (size, format, type or limit) of the current context. */
GLAPI void GLAPIENTRY OSMesaGetIntegerv(GLint pname, GLint *value);

/*
 * Exposes the depth buffer of context c: its size in pixels, the bytes per depth value and its
 * address. Returns GL_FALSE, with zeroes and NULL stored, if the context has no depth buffer.
 */
GLAPI GLboolean GLAPIENTRY OSMesaGetDepthBuffer(OSMesaContext c, GLint *width, GLint *height,
                                                GLint *bytesPerValue, void **buffer);

/* Exposes the color buffer context c renders into: its size, its OSMESA_* format and its
 * address. Returns GL_FALSE if the context has no color buffer bound. */
GLAPI GLboolean GLAPIENTRY OSMesaGetColorBuffer(OSMesaContext c, GLint *width, GLint *height,
                                                GLint *format, void **buffer);

/* The address of a GL or OSMesa function by name, or NULL if the library has none. */
GLAPI OSMESAproc GLAPIENTRY OSMesaGetProcAddress(const char *funcName);

/* Turns clamping of color values to [0, 1] on or off (off by default). */
GLAPI void GLAPIENTRY OSMesaColorClamp(GLboolean enable);

/* Mesa's Gallium post-processing filters; accepted for source compatibility. */
GLAPI void GLAPIENTRY OSMesaPostprocess(OSMesaContext osmesa, const char *filter,
                                        unsigned enable_value);

#ifdef __cplusplus
}
#endif

#endif /* OSMESA_H */
