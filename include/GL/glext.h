/*
 * Pineda's <GL/glext.h>: OpenGL 2.0 and later and the extensions of desktop GL, as enums,
 * PFNGL...PROC function pointer types and, when GL_GLEXT_PROTOTYPES is defined before the
 * first GL header, prototypes; all generated from the Khronos registry (pineda_glext_api.h).
 * The PFNGL...PROC types of the GL 1.0-1.5 commands come with their prototypes in <GL/gl.h>,
 * which this header includes.
 *
 * A prototype here does not mean Pineda implements the command: query
 * OSMesaGetProcAddress() or glXGetProcAddress() and check the result against nullptr.
 */
#ifndef __gl_glext_h_
#define __gl_glext_h_ 1

/*
 * The declarations need the basic types and macros of <GL/gl.h>. Including it here lets a
 * program include <GL/glext.h> first; the include guards stop the two headers from looping.
 */
#include <GL/gl.h>

#include <GL/pineda_glext_api.h>

#endif /* __gl_glext_h_ */
