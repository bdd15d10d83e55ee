// The GL version and extensions Pineda reports (GL 2.1 §6.1.11), in one place: glGetString,
// OSMesaCreateContextAttribs and glXCreateContextAttribsARB (the highest version a context can
// be asked for) all read them from here.
#pragma once

namespace pineda {

// GL 1.5: every GL 1.0-1.5 command is implemented (src/api/entry_points.txt; the check is
// tests/unit/api/version_test.cpp).
constexpr int kGLVersionMajor = 1;
constexpr int kGLVersionMinor = 5;
constexpr const char* kGLVersionString = "1.5 Pineda 0.2";

// Extensions whose whole behaviour is core GL 1.5 behaviour Pineda has and which add no entry
// points (their enums are the core ones), so advertising them adds no new code path. Extensions
// with entry points of their own (ARB/EXT-suffixed names) are not listed until those names are
// exported.
constexpr const char* kGLExtensions =
    "GL_ARB_depth_texture GL_ARB_shadow GL_ARB_texture_border_clamp GL_ARB_texture_cube_map "
    "GL_ARB_texture_env_add GL_ARB_texture_env_combine GL_ARB_texture_env_crossbar "
    "GL_ARB_texture_env_dot3 GL_ARB_texture_mirrored_repeat GL_ARB_texture_non_power_of_two "
    "GL_EXT_bgra GL_EXT_packed_pixels GL_EXT_rescale_normal GL_EXT_separate_specular_color "
    "GL_EXT_stencil_wrap GL_EXT_texture_edge_clamp GL_EXT_texture_env_add "
    "GL_EXT_texture_env_combine GL_EXT_texture_lod_bias GL_SGIS_generate_mipmap "
    "GL_SGIS_texture_edge_clamp";

} // namespace pineda
