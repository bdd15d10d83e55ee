// Shader compilation (glsl.h Shader): glslang's parse, with the source prepared for it and
// Pineda's own checks after it.
#include <glslang/MachineIndependent/localintermediate.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>

#include <algorithm>
#include <cstring>
#include <mutex>

#include "glsl/checks.h"
#include "glsl/const_eval.h"
#include "glsl/glsl.h"
#include "glsl/glslang_util.h"

namespace pineda::glsl {

namespace {

// Extension macros glslang 12 predefines for desktop GLSL, whatever the version (it knows
// them; Pineda supports none of them). A shader testing one with #ifdef would take a path
// Pineda cannot run, so the names are renamed away before glslang sees the source: they read
// as undefined, and "#extension NAME : require" fails as GLSL 1.10 §3.3 says it must.
constexpr const char* kForeignExtensionMacros[] = {
    "GL_AMD_gcn_shader",
    "GL_AMD_gpu_shader_half_float",
    "GL_AMD_gpu_shader_half_float_fetch",
    "GL_AMD_gpu_shader_int16",
    "GL_AMD_shader_ballot",
    "GL_AMD_shader_explicit_vertex_parameter",
    "GL_AMD_shader_fragment_mask",
    "GL_AMD_shader_image_load_store_lod",
    "GL_AMD_shader_trinary_minmax",
    "GL_AMD_texture_gather_bias_lod",
    "GL_ARB_bindless_texture",
    "GL_ARB_compute_shader",
    "GL_ARB_derivative_control",
    "GL_ARB_draw_instanced",
    "GL_ARB_enhanced_layouts",
    "GL_ARB_explicit_attrib_location",
    "GL_ARB_explicit_uniform_location",
    "GL_ARB_fragment_coord_conventions",
    "GL_ARB_fragment_shader_interlock",
    "GL_ARB_gpu_shader5",
    "GL_ARB_gpu_shader_fp64",
    "GL_ARB_gpu_shader_int64",
    "GL_ARB_post_depth_coverage",
    "GL_ARB_sample_shading",
    "GL_ARB_separate_shader_objects",
    "GL_ARB_shader_atomic_counters",
    "GL_ARB_shader_ballot",
    "GL_ARB_shader_bit_encoding",
    "GL_ARB_shader_draw_parameters",
    "GL_ARB_shader_group_vote",
    "GL_ARB_shader_image_load_store",
    "GL_ARB_shader_image_size",
    "GL_ARB_shader_stencil_export",
    "GL_ARB_shader_storage_buffer_object",
    "GL_ARB_shader_texture_image_samples",
    "GL_ARB_shader_texture_lod",
    "GL_ARB_shading_language_420pack",
    "GL_ARB_shading_language_packing",
    "GL_ARB_sparse_texture2",
    "GL_ARB_sparse_texture_clamp",
    "GL_ARB_tessellation_shader",
    "GL_ARB_texture_cube_map_array",
    "GL_ARB_texture_gather",
    "GL_ARB_texture_multisample",
    "GL_ARB_texture_query_lod",
    "GL_ARB_texture_rectangle",
    "GL_ARB_uniform_buffer_object",
    "GL_ARB_vertex_attrib_64bit",
    "GL_ARB_viewport_array",
    "GL_EXT_buffer_reference",
    "GL_EXT_buffer_reference2",
    "GL_EXT_buffer_reference_uvec2",
    "GL_EXT_control_flow_attributes",
    "GL_EXT_debug_printf",
    "GL_EXT_demote_to_helper_invocation",
    "GL_EXT_fragment_invocation_density",
    "GL_EXT_fragment_shader_barycentric",
    "GL_EXT_fragment_shading_rate",
    "GL_EXT_mesh_shader",
    "GL_EXT_nonuniform_qualifier",
    "GL_EXT_post_depth_coverage",
    "GL_EXT_ray_cull_mask",
    "GL_EXT_ray_flags_primitive_culling",
    "GL_EXT_ray_query",
    "GL_EXT_ray_tracing",
    "GL_EXT_samplerless_texture_functions",
    "GL_EXT_scalar_block_layout",
    "GL_EXT_shader_16bit_storage",
    "GL_EXT_shader_8bit_storage",
    "GL_EXT_shader_atomic_float",
    "GL_EXT_shader_atomic_float2",
    "GL_EXT_shader_atomic_int64",
    "GL_EXT_shader_explicit_arithmetic_types",
    "GL_EXT_shader_explicit_arithmetic_types_float16",
    "GL_EXT_shader_explicit_arithmetic_types_float32",
    "GL_EXT_shader_explicit_arithmetic_types_float64",
    "GL_EXT_shader_explicit_arithmetic_types_int16",
    "GL_EXT_shader_explicit_arithmetic_types_int32",
    "GL_EXT_shader_explicit_arithmetic_types_int64",
    "GL_EXT_shader_explicit_arithmetic_types_int8",
    "GL_EXT_shader_image_int64",
    "GL_EXT_shader_image_load_formatted",
    "GL_EXT_shader_integer_mix",
    "GL_EXT_shader_non_constant_global_initializers",
    "GL_EXT_shader_realtime_clock",
    "GL_EXT_shader_subgroup_extended_types_float16",
    "GL_EXT_shader_subgroup_extended_types_int16",
    "GL_EXT_shader_subgroup_extended_types_int64",
    "GL_EXT_shader_subgroup_extended_types_int8",
    "GL_EXT_shared_memory_block",
    "GL_EXT_spirv_intrinsics",
    "GL_EXT_terminate_invocation",
    "GL_FRAGMENT_SHADER",
    "GL_GOOGLE_cpp_style_line_directive",
    "GL_GOOGLE_include_directive",
    "GL_INTEL_shader_integer_functions2",
    "GL_KHR_blend_equation_advanced",
    "GL_KHR_shader_subgroup_arithmetic",
    "GL_KHR_shader_subgroup_ballot",
    "GL_KHR_shader_subgroup_basic",
    "GL_KHR_shader_subgroup_clustered",
    "GL_KHR_shader_subgroup_quad",
    "GL_KHR_shader_subgroup_shuffle",
    "GL_KHR_shader_subgroup_shuffle_relative",
    "GL_KHR_shader_subgroup_vote",
    "GL_NV_compute_shader_derivatives",
    "GL_NV_conservative_raster_underestimation",
    "GL_NV_cooperative_matrix",
    "GL_NV_fragment_shader_barycentric",
    "GL_NV_geometry_shader_passthrough",
    "GL_NV_integer_cooperative_matrix",
    "GL_NV_mesh_shader",
    "GL_NV_ray_tracing",
    "GL_NV_ray_tracing_motion_blur",
    "GL_NV_sample_mask_override_coverage",
    "GL_NV_shader_atomic_int64",
    "GL_NV_shader_execution_reorder",
    "GL_NV_shader_subgroup_partitioned",
    "GL_NV_shader_texture_footprint",
    "GL_NV_shading_rate_image",
    "GL_NV_viewport_array2",
    "GL_VERTEX_SHADER",
};
constexpr const char kRenamePrefix[] = "PINEDA_UNKNOWN_";

bool ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

// Backslash-newline joins lines (glslang 12 refuses it below GLSL 1.30 unless its errors are
// relaxed altogether, but Mesa and the drivers accept it, and piglit's GLSL 1.10 tests use
// it). The joined lines' newlines are put back after the logical line, so later lines keep
// their numbers in the log.
std::string splice_lines(const std::string& s) {
  if (s.find('\\') == std::string::npos) return s;
  std::string out;
  out.reserve(s.size());
  int pending = 0;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\') {
      size_t j = i + 1;
      if (j < s.size() && s[j] == '\r') ++j;
      if (j < s.size() && s[j] == '\n') {
        ++pending;
        i = j;
        continue;
      }
    }
    out += s[i];
    if (s[i] == '\n') {
      out.append(static_cast<size_t>(pending), '\n');
      pending = 0;
    }
  }
  out.append(static_cast<size_t>(pending), '\n');
  return out;
}

std::string rename_foreign_macros(const std::string& s) {
  if (s.find("GL_") == std::string::npos) return s;
  std::string out;
  out.reserve(s.size());
  size_t i = 0;
  while (i < s.size()) {
    if (s.compare(i, 3, "GL_") == 0 && (i == 0 || !ident_char(s[i - 1]))) {
      size_t j = i;
      while (j < s.size() && ident_char(s[j]))
        ++j;
      const std::string_view word(s.data() + i, j - i);
      const bool foreign =
          std::any_of(std::begin(kForeignExtensionMacros), std::end(kForeignExtensionMacros),
                      [&](const char* m) { return word == m; });
      if (foreign) out += kRenamePrefix;
      out.append(word);
      i = j;
      continue;
    }
    out += s[i++];
  }
  return out;
}

std::string restore_names(std::string log) {
  for (size_t p; (p = log.find(kRenamePrefix)) != std::string::npos;)
    log.erase(p, sizeof kRenamePrefix - 1);
  return log;
}

} // namespace

std::mutex& glslang_mutex() {
  static std::mutex m;
  return m;
}

void ensure_glslang() {
  static std::once_flag once;
  std::call_once(once, [] { glslang::InitializeProcess(); });
}

TBuiltInResource resources_for(const Limits& l) {
  TBuiltInResource r = *GetDefaultResources();
  r.maxLights = l.max_lights;
  r.maxClipPlanes = l.max_clip_planes;
  r.maxTextureUnits = l.max_texture_units;
  r.maxTextureCoords = l.max_texture_coords;
  r.maxVertexAttribs = l.max_vertex_attribs;
  r.maxVertexUniformComponents = l.max_vertex_uniform_components;
  r.maxVaryingFloats = l.max_varying_floats;
  r.maxVertexTextureImageUnits = l.max_vertex_texture_image_units;
  r.maxCombinedTextureImageUnits = l.max_combined_texture_image_units;
  r.maxTextureImageUnits = l.max_texture_image_units;
  r.maxFragmentUniformComponents = l.max_fragment_uniform_components;
  r.maxDrawBuffers = l.max_draw_buffers;
  return r;
}

std::unique_ptr<glslang::TShader> parse_shader(const Shader::Impl& impl, std::string& log) {
  auto sh = std::make_unique<glslang::TShader>(impl.stage == ShaderStage::Vertex ? EShLangVertex
                                                                                 : EShLangFragment);
  std::vector<const char*> ptrs;
  for (const std::string& s : impl.sources)
    ptrs.push_back(s.c_str());
  sh->setStrings(ptrs.data(), static_cast<int>(ptrs.size()));
  // glslang refuses texture*Lod in vertex shaders without GL_ARB_shader_texture_lod, but they
  // are core GLSL 1.10 vertex shader functions (§8.7).
  if (impl.stage == ShaderStage::Vertex)
    sh->setPreamble("#extension GL_ARB_shader_texture_lod : enable\n");
  // Desktop GLSL with no client or target: an OpenGL client would make glslang parse the
  // ARB_gl_spirv dialect.
  const bool ok = sh->parse(&impl.resources, 110, ENoProfile, false, false, EShMsgDefault);
  log = restore_names(sh->getInfoLog());
  if (!ok) return nullptr;
  return sh;
}

Shader::~Shader() = default;

std::shared_ptr<Shader> Shader::compile(ShaderStage stage, const std::vector<std::string>& strings,
                                        const Limits& limits) {
  std::shared_ptr<Shader> s(new Shader());
  s->stage_ = stage;
  s->impl_ = std::make_unique<Impl>();
  Impl& impl = *s->impl_;
  impl.stage = stage;
  impl.limits = limits;
  impl.resources = resources_for(limits);
  for (const std::string& src : strings)
    impl.sources.push_back(rename_foreign_macros(splice_lines(src)));
  if (!check_version_directive(impl.sources, s->log_)) return s;
  ensure_glslang();
  std::lock_guard<std::mutex> lock(glslang_mutex());
  std::string log;
  impl.parsed = parse_shader(impl, log);
  // Constants glslang could not fold, folded by Pineda (const_eval.h), then parsed again
  // (glslang stops at its first error: one line at a time).
  for (int tries = 0; !impl.parsed && tries < 64 && fold_unfolded_constants(impl.sources, log);
       ++tries)
    impl.parsed = parse_shader(impl, log);
  s->log_ = log;
  if (!impl.parsed) return s;
  std::string errors;
  check_compiled(*impl.parsed->getIntermediate(), stage, limits, errors);
  if (!errors.empty()) {
    s->log_ += errors;
    impl.parsed.reset();
    return s;
  }
  s->compiled_ = true;
  return s;
}

std::unique_ptr<glslang::TShader> Shader::Impl::take_or_parse() {
  if (parsed) return std::move(parsed);
  std::string log;
  return parse_shader(*this, log);
}

} // namespace pineda::glsl
