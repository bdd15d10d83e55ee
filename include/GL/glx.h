/*
 * Pineda's <GL/glx.h>: the GLX 1.4 API (the GLX 1.4 specification, chapter 3) with
 * GLX_ARB_create_context(_profile), GLX_ARB_get_proc_address, GLX_EXT_swap_control and
 * GLX_MESA_swap_control. Token values are those of the Khronos registry (glx.xml); the types
 * match other GLX headers so that programs written against them compile unchanged.
 */
#ifndef GLX_H
#define GLX_H 1

#include <X11/Xlib.h>
#include <X11/Xutil.h>
#include <GL/gl.h>

#ifdef __cplusplus
extern "C" {
#endif

#define GLX_VERSION_1_0 1
#define GLX_VERSION_1_1 1
#define GLX_VERSION_1_2 1
#define GLX_VERSION_1_3 1
#define GLX_VERSION_1_4 1

#define GLX_EXTENSION_NAME "GLX"

/* Opaque handles and resource ids (GLX 1.4 §2.1, §3.3). */
typedef struct __GLXcontextRec *GLXContext;
typedef struct __GLXFBConfigRec *GLXFBConfig;
typedef XID GLXDrawable;
typedef XID GLXPixmap;
typedef XID GLXWindow;
typedef XID GLXPbuffer;
typedef XID GLXFBConfigID;
typedef XID GLXContextID;
typedef void (*__GLXextFuncPtr)(void);

/* glXGetConfig (GLX 1.4 Table 3.7) and glXChooseVisual attributes. */
#define GLX_USE_GL 1
#define GLX_BUFFER_SIZE 2
#define GLX_LEVEL 3
#define GLX_RGBA 4
#define GLX_DOUBLEBUFFER 5
#define GLX_STEREO 6
#define GLX_AUX_BUFFERS 7
#define GLX_RED_SIZE 8
#define GLX_GREEN_SIZE 9
#define GLX_BLUE_SIZE 10
#define GLX_ALPHA_SIZE 11
#define GLX_DEPTH_SIZE 12
#define GLX_STENCIL_SIZE 13
#define GLX_ACCUM_RED_SIZE 14
#define GLX_ACCUM_GREEN_SIZE 15
#define GLX_ACCUM_BLUE_SIZE 16
#define GLX_ACCUM_ALPHA_SIZE 17

/* Return values of glXGetConfig and glXGetFBConfigAttrib. */
#define GLX_BAD_SCREEN 1
#define GLX_BAD_ATTRIBUTE 2
#define GLX_NO_EXTENSION 3
#define GLX_BAD_VISUAL 4
#define GLX_BAD_CONTEXT 5
#define GLX_BAD_VALUE 6
#define GLX_BAD_ENUM 7

/* glXQueryServerString / glXGetClientString names. */
#define GLX_VENDOR 0x1
#define GLX_VERSION 0x2
#define GLX_EXTENSIONS 0x3

/* GLX 1.3: config attributes, drawable and render types, events (GLX 1.4 §3.3). */
#define GLX_WINDOW_BIT 0x00000001
#define GLX_PIXMAP_BIT 0x00000002
#define GLX_PBUFFER_BIT 0x00000004
#define GLX_RGBA_BIT 0x00000001
#define GLX_COLOR_INDEX_BIT 0x00000002
#define GLX_PBUFFER_CLOBBER_MASK 0x08000000
#define GLX_FRONT_LEFT_BUFFER_BIT 0x00000001
#define GLX_FRONT_RIGHT_BUFFER_BIT 0x00000002
#define GLX_BACK_LEFT_BUFFER_BIT 0x00000004
#define GLX_BACK_RIGHT_BUFFER_BIT 0x00000008
#define GLX_AUX_BUFFERS_BIT 0x00000010
#define GLX_DEPTH_BUFFER_BIT 0x00000020
#define GLX_STENCIL_BUFFER_BIT 0x00000040
#define GLX_ACCUM_BUFFER_BIT 0x00000080
#define GLX_CONFIG_CAVEAT 0x20
#define GLX_X_VISUAL_TYPE 0x22
#define GLX_TRANSPARENT_TYPE 0x23
#define GLX_TRANSPARENT_INDEX_VALUE 0x24
#define GLX_TRANSPARENT_RED_VALUE 0x25
#define GLX_TRANSPARENT_GREEN_VALUE 0x26
#define GLX_TRANSPARENT_BLUE_VALUE 0x27
#define GLX_TRANSPARENT_ALPHA_VALUE 0x28
#define GLX_DONT_CARE 0xFFFFFFFF
#define GLX_NONE 0x8000
#define GLX_SLOW_CONFIG 0x8001
#define GLX_TRUE_COLOR 0x8002
#define GLX_DIRECT_COLOR 0x8003
#define GLX_PSEUDO_COLOR 0x8004
#define GLX_STATIC_COLOR 0x8005
#define GLX_GRAY_SCALE 0x8006
#define GLX_STATIC_GRAY 0x8007
#define GLX_TRANSPARENT_RGB 0x8008
#define GLX_TRANSPARENT_INDEX 0x8009
#define GLX_VISUAL_ID 0x800B
#define GLX_SCREEN 0x800C
#define GLX_NON_CONFORMANT_CONFIG 0x800D
#define GLX_DRAWABLE_TYPE 0x8010
#define GLX_RENDER_TYPE 0x8011
#define GLX_X_RENDERABLE 0x8012
#define GLX_FBCONFIG_ID 0x8013
#define GLX_RGBA_TYPE 0x8014
#define GLX_COLOR_INDEX_TYPE 0x8015
#define GLX_MAX_PBUFFER_WIDTH 0x8016
#define GLX_MAX_PBUFFER_HEIGHT 0x8017
#define GLX_MAX_PBUFFER_PIXELS 0x8018
#define GLX_PRESERVED_CONTENTS 0x801B
#define GLX_LARGEST_PBUFFER 0x801C
#define GLX_WIDTH 0x801D
#define GLX_HEIGHT 0x801E
#define GLX_EVENT_MASK 0x801F
#define GLX_DAMAGED 0x8020
#define GLX_SAVED 0x8021
#define GLX_WINDOW 0x8022
#define GLX_PBUFFER 0x8023
#define GLX_PBUFFER_HEIGHT 0x8040
#define GLX_PBUFFER_WIDTH 0x8041

/* GLX 1.4: multisample attributes. */
#define GLX_SAMPLE_BUFFERS 100000
#define GLX_SAMPLES 100001

/* Event numbers, relative to the GLX event base. */
#define GLX_PbufferClobber 0
#define GLX_BufferSwapComplete 1
#define __GLX_NUMBER_EVENTS 17

/* GLX error numbers, relative to the GLX error base. */
#define GLXBadContext 0
#define GLXBadContextState 1
#define GLXBadDrawable 2
#define GLXBadPixmap 3
#define GLXBadContextTag 4
#define GLXBadCurrentWindow 5
#define GLXBadRenderRequest 6
#define GLXBadLargeRequest 7
#define GLXUnsupportedPrivateRequest 8
#define GLXBadFBConfig 9
#define GLXBadPbuffer 10
#define GLXBadCurrentDrawable 11
#define GLXBadWindow 12
#define GLXBadProfileARB 13

/* The pbuffer clobber event (GLX 1.4 §3.3.8). */
typedef struct {
  int event_type;       /* GLX_DAMAGED or GLX_SAVED */
  int draw_type;        /* GLX_WINDOW or GLX_PBUFFER */
  unsigned long serial; /* last request the server processed */
  Bool send_event;      /* true if it came from a SendEvent request */
  Display *display;
  GLXDrawable drawable;
  unsigned int buffer_mask; /* GLX_*_BUFFER_BIT */
  unsigned int aux_buffer;
  int x, y;
  int width, height;
  int count; /* when nonzero, at least this many more events follow */
} GLXPbufferClobberEvent;

typedef union __GLXEvent {
  GLXPbufferClobberEvent glxpbufferclobber;
  long pad[24];
} GLXEvent;

/* GLX 1.0 - 1.2 */
XVisualInfo *glXChooseVisual(Display *dpy, int screen, int *attribList);
GLXContext glXCreateContext(Display *dpy, XVisualInfo *vis, GLXContext shareList, Bool direct);
void glXDestroyContext(Display *dpy, GLXContext ctx);
void glXCopyContext(Display *dpy, GLXContext src, GLXContext dst, unsigned long mask);
Bool glXMakeCurrent(Display *dpy, GLXDrawable drawable, GLXContext ctx);
void glXSwapBuffers(Display *dpy, GLXDrawable drawable);
GLXPixmap glXCreateGLXPixmap(Display *dpy, XVisualInfo *visual, Pixmap pixmap);
void glXDestroyGLXPixmap(Display *dpy, GLXPixmap pixmap);
Bool glXQueryExtension(Display *dpy, int *errorBase, int *eventBase);
Bool glXQueryVersion(Display *dpy, int *major, int *minor);
Bool glXIsDirect(Display *dpy, GLXContext ctx);
int glXGetConfig(Display *dpy, XVisualInfo *visual, int attrib, int *value);
GLXContext glXGetCurrentContext(void);
GLXDrawable glXGetCurrentDrawable(void);
void glXWaitGL(void);
void glXWaitX(void);
void glXUseXFont(Font font, int first, int count, int listBase);
const char *glXQueryExtensionsString(Display *dpy, int screen);
const char *glXQueryServerString(Display *dpy, int screen, int name);
const char *glXGetClientString(Display *dpy, int name);
Display *glXGetCurrentDisplay(void);

/* GLX 1.3 */
GLXFBConfig *glXGetFBConfigs(Display *dpy, int screen, int *nelements);
GLXFBConfig *glXChooseFBConfig(Display *dpy, int screen, const int *attribList,
                               int *nitems);
int glXGetFBConfigAttrib(Display *dpy, GLXFBConfig config, int attribute, int *value);
XVisualInfo *glXGetVisualFromFBConfig(Display *dpy, GLXFBConfig config);
GLXWindow glXCreateWindow(Display *dpy, GLXFBConfig config, Window win, const int *attribList);
void glXDestroyWindow(Display *dpy, GLXWindow window);
GLXPixmap glXCreatePixmap(Display *dpy, GLXFBConfig config, Pixmap pixmap,
                          const int *attribList);
void glXDestroyPixmap(Display *dpy, GLXPixmap pixmap);
GLXPbuffer glXCreatePbuffer(Display *dpy, GLXFBConfig config, const int *attribList);
void glXDestroyPbuffer(Display *dpy, GLXPbuffer pbuf);
void glXQueryDrawable(Display *dpy, GLXDrawable draw, int attribute, unsigned int *value);
GLXContext glXCreateNewContext(Display *dpy, GLXFBConfig config, int renderType,
                               GLXContext shareList, Bool direct);
Bool glXMakeContextCurrent(Display *dpy, GLXDrawable draw, GLXDrawable read, GLXContext ctx);
GLXDrawable glXGetCurrentReadDrawable(void);
int glXQueryContext(Display *dpy, GLXContext ctx, int attribute, int *value);
void glXSelectEvent(Display *dpy, GLXDrawable drawable, unsigned long mask);
void glXGetSelectedEvent(Display *dpy, GLXDrawable drawable, unsigned long *mask);

/* GLX 1.4 */
__GLXextFuncPtr glXGetProcAddress(const GLubyte *procName);

typedef XVisualInfo *(*PFNGLXCHOOSEVISUALPROC)(Display *dpy, int screen, int *attribList);
typedef GLXFBConfig *(*PFNGLXCHOOSEFBCONFIGPROC)(Display *dpy, int screen,
                                                 const int *attribList, int *nitems);
typedef GLXContext (*PFNGLXCREATENEWCONTEXTPROC)(Display *dpy, GLXFBConfig config,
                                                 int renderType, GLXContext shareList,
                                                 Bool direct);
typedef Bool (*PFNGLXMAKECONTEXTCURRENTPROC)(Display *dpy, GLXDrawable draw, GLXDrawable read,
                                             GLXContext ctx);
typedef __GLXextFuncPtr (*PFNGLXGETPROCADDRESSPROC)(const GLubyte *procName);

/* GLX_ARB_get_proc_address */
#ifndef GLX_ARB_get_proc_address
#define GLX_ARB_get_proc_address 1
__GLXextFuncPtr glXGetProcAddressARB(const GLubyte *procName);
typedef __GLXextFuncPtr (*PFNGLXGETPROCADDRESSARBPROC)(const GLubyte *procName);
#endif

/* GLX_ARB_create_context and GLX_ARB_create_context_profile */
#ifndef GLX_ARB_create_context
#define GLX_ARB_create_context 1
#define GLX_CONTEXT_DEBUG_BIT_ARB 0x00000001
#define GLX_CONTEXT_FORWARD_COMPATIBLE_BIT_ARB 0x00000002
#define GLX_CONTEXT_MAJOR_VERSION_ARB 0x2091
#define GLX_CONTEXT_MINOR_VERSION_ARB 0x2092
#define GLX_CONTEXT_FLAGS_ARB 0x2094
GLXContext glXCreateContextAttribsARB(Display *dpy, GLXFBConfig config, GLXContext shareContext,
                                      Bool direct, const int *attribList);
typedef GLXContext (*PFNGLXCREATECONTEXTATTRIBSARBPROC)(Display *dpy, GLXFBConfig config,
                                                        GLXContext shareContext, Bool direct,
                                                        const int *attribList);
#endif
#ifndef GLX_ARB_create_context_profile
#define GLX_ARB_create_context_profile 1
#define GLX_CONTEXT_CORE_PROFILE_BIT_ARB 0x00000001
#define GLX_CONTEXT_COMPATIBILITY_PROFILE_BIT_ARB 0x00000002
#define GLX_CONTEXT_PROFILE_MASK_ARB 0x9126
#endif

/* GLX_EXT_swap_control */
#ifndef GLX_EXT_swap_control
#define GLX_EXT_swap_control 1
#define GLX_SWAP_INTERVAL_EXT 0x20F1
#define GLX_MAX_SWAP_INTERVAL_EXT 0x20F2
void glXSwapIntervalEXT(Display *dpy, GLXDrawable drawable, int interval);
typedef void (*PFNGLXSWAPINTERVALEXTPROC)(Display *dpy, GLXDrawable drawable, int interval);
#endif

/* GLX_MESA_swap_control */
#ifndef GLX_MESA_swap_control
#define GLX_MESA_swap_control 1
int glXSwapIntervalMESA(unsigned int interval);
int glXGetSwapIntervalMESA(void);
typedef int (*PFNGLXSWAPINTERVALMESAPROC)(unsigned int interval);
typedef int (*PFNGLXGETSWAPINTERVALMESAPROC)(void);
#endif

/* GLX_EXT_visual_info: the GLX 1.3 visual-type tokens, also accepted by glXChooseVisual. */
#ifndef GLX_EXT_visual_info
#define GLX_EXT_visual_info 1
#define GLX_X_VISUAL_TYPE_EXT 0x22
#define GLX_TRANSPARENT_TYPE_EXT 0x23
#define GLX_TRANSPARENT_INDEX_VALUE_EXT 0x24
#define GLX_TRANSPARENT_RED_VALUE_EXT 0x25
#define GLX_TRANSPARENT_GREEN_VALUE_EXT 0x26
#define GLX_TRANSPARENT_BLUE_VALUE_EXT 0x27
#define GLX_TRANSPARENT_ALPHA_VALUE_EXT 0x28
#define GLX_NONE_EXT 0x8000
#define GLX_TRUE_COLOR_EXT 0x8002
#define GLX_DIRECT_COLOR_EXT 0x8003
#define GLX_PSEUDO_COLOR_EXT 0x8004
#define GLX_STATIC_COLOR_EXT 0x8005
#define GLX_GRAY_SCALE_EXT 0x8006
#define GLX_STATIC_GRAY_EXT 0x8007
#define GLX_TRANSPARENT_RGB_EXT 0x8008
#define GLX_TRANSPARENT_INDEX_EXT 0x8009
#endif

#ifdef __cplusplus
}
#endif

/*
 * Like other GLX headers, the registry's <GL/glxext.h> (other GLX extensions' tokens and
 * function pointer types) follows unless GLX_GLXEXT_LEGACY is defined. Pineda does not ship
 * one; a system copy is used when present. The blocks above already define its guards for
 * what Pineda implements.
 */
#if !defined(GLX_GLXEXT_LEGACY) && defined(__has_include)
#if __has_include(<GL/glxext.h>)
#include <GL/glxext.h>
#endif
#endif

#endif /* GLX_H */
