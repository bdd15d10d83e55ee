// EGLConfigs (EGL 1.5 §3.4): the configs of a display, their attributes, and eglChooseConfig's
// selection (Table 3.4) and sorting (§3.4.1.2).
#include <algorithm>
#include <array>

#include "winsys/egl/egl_internal.h"

namespace pineda::egl {

namespace {

// Largest pbuffer: the largest viewport Pineda accepts.
constexpr EGLint kMaxPbufferDim = kMaxViewportDim;
constexpr EGLint kMaxSwapInterval = 64;

void add_configs(EglDisplay* d, const x11::Format* visual, ColorFormat format,
                 std::initializer_list<EGLint> depths) {
  for (EGLint alpha : {8, 0})
    for (EGLint depth : depths)
      for (EGLint stencil : {8, 0}) {
        auto c = std::make_unique<EglConfig>();
        c->display = d;
        c->id = static_cast<EGLint>(d->configs.size()) + 1;
        c->format = format;
        c->alpha = alpha;
        c->depth = depth;
        c->stencil = stencil;
        if (visual != nullptr) {
          c->x = *visual;
          c->native_visual_id = static_cast<EGLint>(visual->visual_id);
          c->native_visual_type = TrueColor;
          c->native_renderable = true;
          // Pineda keeps a window's back buffer across swaps (x11::swap_images), so
          // EGL_BUFFER_PRESERVED can be asked for.
          c->surface_type =
              EGL_WINDOW_BIT | EGL_PIXMAP_BIT | EGL_PBUFFER_BIT | EGL_SWAP_BEHAVIOR_PRESERVED_BIT;
        } else {
          c->surface_type = EGL_PBUFFER_BIT;
        }
        d->configs.push_back(std::move(c));
      }
}

// ---- eglChooseConfig (Table 3.4) ----

enum class Match { AtLeast, Exact, Mask, Ignored, Special };

struct Criterion {
  EGLint attribute;
  Match match;
  EGLint default_value;
};

// Every attribute of Table 3.4 with its selection rule and default.
constexpr Criterion kCriteria[] = {
    {EGL_ALPHA_MASK_SIZE, Match::AtLeast, 0},
    {EGL_ALPHA_SIZE, Match::AtLeast, 0},
    {EGL_BIND_TO_TEXTURE_RGB, Match::Exact, EGL_DONT_CARE},
    {EGL_BIND_TO_TEXTURE_RGBA, Match::Exact, EGL_DONT_CARE},
    {EGL_BLUE_SIZE, Match::AtLeast, 0},
    {EGL_BUFFER_SIZE, Match::AtLeast, 0},
    {EGL_COLOR_BUFFER_TYPE, Match::Exact, EGL_RGB_BUFFER},
    {EGL_CONFIG_CAVEAT, Match::Exact, EGL_DONT_CARE},
    {EGL_CONFIG_ID, Match::Exact, EGL_DONT_CARE},
    {EGL_CONFORMANT, Match::Mask, 0},
    {EGL_DEPTH_SIZE, Match::AtLeast, 0},
    {EGL_GREEN_SIZE, Match::AtLeast, 0},
    {EGL_LEVEL, Match::Exact, 0},
    {EGL_LUMINANCE_SIZE, Match::AtLeast, 0},
    {EGL_MATCH_NATIVE_PIXMAP, Match::Special, EGL_NONE},
    {EGL_NATIVE_RENDERABLE, Match::Exact, EGL_DONT_CARE},
    {EGL_MAX_SWAP_INTERVAL, Match::Exact, EGL_DONT_CARE},
    {EGL_MIN_SWAP_INTERVAL, Match::Exact, EGL_DONT_CARE},
    {EGL_RED_SIZE, Match::AtLeast, 0},
    {EGL_SAMPLE_BUFFERS, Match::AtLeast, 0},
    {EGL_SAMPLES, Match::AtLeast, 0},
    {EGL_STENCIL_SIZE, Match::AtLeast, 0},
    {EGL_RENDERABLE_TYPE, Match::Mask, EGL_OPENGL_ES_BIT},
    {EGL_SURFACE_TYPE, Match::Mask, EGL_WINDOW_BIT},
    {EGL_TRANSPARENT_TYPE, Match::Exact, EGL_NONE},
    {EGL_TRANSPARENT_RED_VALUE, Match::Exact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_GREEN_VALUE, Match::Exact, EGL_DONT_CARE},
    {EGL_TRANSPARENT_BLUE_VALUE, Match::Exact, EGL_DONT_CARE},
    {EGL_NATIVE_VISUAL_TYPE, Match::Exact, EGL_DONT_CARE},
    {EGL_MAX_PBUFFER_WIDTH, Match::Ignored, 0},
    {EGL_MAX_PBUFFER_HEIGHT, Match::Ignored, 0},
    {EGL_MAX_PBUFFER_PIXELS, Match::Ignored, 0},
    {EGL_NATIVE_VISUAL_ID, Match::Ignored, 0},
};
constexpr size_t kCriteriaCount = std::size(kCriteria);

int criterion_index(EGLint attribute) {
  for (size_t i = 0; i < kCriteriaCount; ++i)
    if (kCriteria[i].attribute == attribute) return static_cast<int>(i);
  return -1;
}

struct Request {
  std::array<EGLint, kCriteriaCount> value{};
  EGLint get(EGLint attribute) const {
    return value[static_cast<size_t>(criterion_index(attribute))];
  }
};

// The value a config has for an attribute of Table 3.4.
EGLint attrib_or_zero(const EglConfig& c, EGLint attribute) {
  EGLint v = 0;
  config_attrib(c, attribute, &v);
  return v;
}

bool matches(const EglConfig& c, const Request& r, int pixmap_depth) {
  if (r.get(EGL_CONFIG_ID) != EGL_DONT_CARE) return c.id == r.get(EGL_CONFIG_ID);
  for (size_t i = 0; i < kCriteriaCount; ++i) {
    const EGLint want = r.value[i];
    const Criterion& k = kCriteria[i];
    if (want == EGL_DONT_CARE || k.match == Match::Ignored || k.match == Match::Special) continue;
    const EGLint have = attrib_or_zero(c, k.attribute);
    switch (k.match) {
    case Match::AtLeast:
      if (have < want) return false;
      break;
    case Match::Exact:
      if (have != want) return false;
      break;
    case Match::Mask:
      if ((have & want) != want) return false;
      break;
    default:
      break;
    }
  }
  // EGL_MATCH_NATIVE_PIXMAP: configs that can render to that pixmap.
  if (pixmap_depth >= 0 && ((c.surface_type & EGL_PIXMAP_BIT) == 0 || c.x.visual == nullptr ||
                            c.x.depth != pixmap_depth))
    return false;
  return true;
}

// §3.4.1.2: the sort keys in priority order; smaller sorts first.
std::array<long long, 10> sort_key(const EglConfig& c, const Request& r) {
  // Larger total colour bits first, counting only the components the request asks for with a
  // positive size (EGL_DONT_CARE and 0 do not count).
  long long color = 0;
  for (EGLint a : {EGL_RED_SIZE, EGL_GREEN_SIZE, EGL_BLUE_SIZE, EGL_ALPHA_SIZE}) {
    const EGLint want = r.get(a);
    if (want != EGL_DONT_CARE && want > 0) color += attrib_or_zero(c, a);
  }
  auto caveat_rank = [](EGLint v) { return v == EGL_NONE ? 0 : v == EGL_SLOW_CONFIG ? 1 : 2; };
  return {caveat_rank(attrib_or_zero(c, EGL_CONFIG_CAVEAT)),
          attrib_or_zero(c, EGL_COLOR_BUFFER_TYPE) == EGL_RGB_BUFFER ? 0 : 1, -color,
          attrib_or_zero(c, EGL_BUFFER_SIZE), attrib_or_zero(c, EGL_SAMPLE_BUFFERS),
          attrib_or_zero(c, EGL_SAMPLES), attrib_or_zero(c, EGL_DEPTH_SIZE),
          attrib_or_zero(c, EGL_STENCIL_SIZE), attrib_or_zero(c, EGL_ALPHA_MASK_SIZE),
          // EGL_NATIVE_VISUAL_TYPE's order is implementation-defined: it is left out, and
          // EGL_CONFIG_ID makes the order total.
          c.id};
}

// Whether `value` is acceptable for `attribute` in an eglChooseConfig list.
bool valid_value(EGLint attribute, EGLint value) {
  if (value == EGL_DONT_CARE) return attribute != EGL_LEVEL && attribute != EGL_MATCH_NATIVE_PIXMAP;
  switch (attribute) {
  case EGL_COLOR_BUFFER_TYPE:
    return value == EGL_RGB_BUFFER || value == EGL_LUMINANCE_BUFFER;
  case EGL_CONFIG_CAVEAT:
    return value == EGL_NONE || value == EGL_SLOW_CONFIG || value == EGL_NON_CONFORMANT_CONFIG;
  case EGL_TRANSPARENT_TYPE:
    return value == EGL_NONE || value == EGL_TRANSPARENT_RGB;
  case EGL_BIND_TO_TEXTURE_RGB:
  case EGL_BIND_TO_TEXTURE_RGBA:
  case EGL_NATIVE_RENDERABLE:
    return value == EGL_TRUE || value == EGL_FALSE;
  case EGL_SURFACE_TYPE:
  case EGL_RENDERABLE_TYPE:
  case EGL_CONFORMANT:
  case EGL_MATCH_NATIVE_PIXMAP:
  case EGL_LEVEL:
  case EGL_CONFIG_ID:
  case EGL_NATIVE_VISUAL_TYPE:
  case EGL_TRANSPARENT_RED_VALUE:
  case EGL_TRANSPARENT_GREEN_VALUE:
  case EGL_TRANSPARENT_BLUE_VALUE:
  case EGL_MAX_PBUFFER_WIDTH:
  case EGL_MAX_PBUFFER_HEIGHT:
  case EGL_MAX_PBUFFER_PIXELS:
  case EGL_NATIVE_VISUAL_ID:
    return true;
  default:
    // Sizes and intervals: no negative values.
    return value >= 0;
  }
}

EGLBoolean list_configs(EglDisplay* d, std::vector<const EglConfig*>& list, EGLConfig* configs,
                        EGLint config_size, EGLint* num_config) {
  // §3.4.1: with configs NULL only the count is returned.
  if (configs == nullptr) {
    *num_config = static_cast<EGLint>(list.size());
  } else {
    const size_t n = std::min(list.size(), static_cast<size_t>(std::max(config_size, 0)));
    for (size_t i = 0; i < n; ++i)
      configs[i] = const_cast<EglConfig*>(list[i]);
    *num_config = static_cast<EGLint>(n);
  }
  (void)d;
  succeed();
  return EGL_TRUE;
}

} // namespace

void build_configs(EglDisplay* d) {
  if (!d->configs.empty()) return;
  if (d->platform == Platform::Surfaceless) {
    // No window system: pbuffers in Pineda's RGBA layout, with the depth buffers OSMesa
    // offers (16, 24 and 32 bits).
    add_configs(d, nullptr, ColorFormat::RGBA8, {24, 16, 32, 0});
    return;
  }
  XVisualInfo tmpl{};
  tmpl.screen = d->screen;
  tmpl.c_class = TrueColor;
  int n = 0;
  XVisualInfo* vis = XGetVisualInfo(d->dpy, VisualScreenMask | VisualClassMask, &tmpl, &n);
  std::vector<x11::Format> usable;
  for (int i = 0; i < n; ++i) {
    x11::Format f;
    if (x11::usable_visual(d->dpy, vis[i], &f) &&
        std::none_of(usable.begin(), usable.end(),
                     [&](const x11::Format& u) { return u.depth == f.depth; }))
      usable.push_back(f);
  }
  if (vis != nullptr) XFree(vis);
  // Depth-24 visuals first so that the first config is an ordinary opaque window's.
  std::stable_sort(usable.begin(), usable.end(),
                   [](const x11::Format& a, const x11::Format& b) { return a.depth < b.depth; });
  for (const x11::Format& f : usable)
    add_configs(d, &f, f.color, {24, 16, 0});
}

const EglConfig* find_config(EglDisplay* d, EGLConfig handle) {
  if (handle == nullptr) return nullptr;
  for (const auto& c : d->configs)
    if (static_cast<EGLConfig>(c.get()) == handle) return c.get();
  return nullptr;
}

bool config_attrib(const EglConfig& c, EGLint attribute, EGLint* value) {
  EGLint v = 0;
  switch (attribute) {
  case EGL_BUFFER_SIZE:
    v = 24 + c.alpha;
    break;
  case EGL_RED_SIZE:
  case EGL_GREEN_SIZE:
  case EGL_BLUE_SIZE:
    v = 8;
    break;
  case EGL_ALPHA_SIZE:
    v = c.alpha;
    break;
  case EGL_LUMINANCE_SIZE:
  case EGL_ALPHA_MASK_SIZE:
    v = 0;
    break;
  case EGL_BIND_TO_TEXTURE_RGB:
  case EGL_BIND_TO_TEXTURE_RGBA:
    v = EGL_FALSE;
    break;
  case EGL_COLOR_BUFFER_TYPE:
    v = EGL_RGB_BUFFER;
    break;
  case EGL_CONFIG_CAVEAT:
    v = EGL_NONE;
    break;
  case EGL_CONFIG_ID:
    v = c.id;
    break;
  case EGL_CONFORMANT:
  case EGL_RENDERABLE_TYPE:
    v = EGL_OPENGL_BIT;
    break;
  case EGL_DEPTH_SIZE:
    v = c.depth;
    break;
  case EGL_STENCIL_SIZE:
    v = c.stencil;
    break;
  case EGL_LEVEL:
    v = 0;
    break;
  case EGL_MAX_PBUFFER_WIDTH:
  case EGL_MAX_PBUFFER_HEIGHT:
    v = kMaxPbufferDim;
    break;
  case EGL_MAX_PBUFFER_PIXELS:
    v = kMaxPbufferDim * kMaxPbufferDim;
    break;
  case EGL_MAX_SWAP_INTERVAL:
    v = kMaxSwapInterval;
    break;
  case EGL_MIN_SWAP_INTERVAL:
    v = 0;
    break;
  case EGL_NATIVE_RENDERABLE:
    v = c.native_renderable ? EGL_TRUE : EGL_FALSE;
    break;
  case EGL_NATIVE_VISUAL_ID:
    v = c.native_visual_id;
    break;
  case EGL_NATIVE_VISUAL_TYPE:
    v = c.native_visual_type;
    break;
  case EGL_SAMPLE_BUFFERS:
    v = c.sample_buffers;
    break;
  case EGL_SAMPLES:
    v = c.samples;
    break;
  case EGL_SURFACE_TYPE:
    v = c.surface_type;
    break;
  case EGL_TRANSPARENT_TYPE:
    v = EGL_NONE;
    break;
  case EGL_TRANSPARENT_RED_VALUE:
  case EGL_TRANSPARENT_GREEN_VALUE:
  case EGL_TRANSPARENT_BLUE_VALUE:
    v = 0;
    break;
  default:
    return false;
  }
  *value = v;
  return true;
}

} // namespace pineda::egl

using namespace pineda::egl;

EGL_EXPORT EGLBoolean EGLAPIENTRY eglGetConfigs(EGLDisplay dpy, EGLConfig* configs,
                                                EGLint config_size, EGLint* num_config) {
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, "eglGetConfigs");
  if (d == nullptr) return EGL_FALSE;
  if (num_config == nullptr) return fail(EGL_BAD_PARAMETER, "eglGetConfigs", EGL_FALSE);
  std::vector<const EglConfig*> list;
  for (const auto& c : d->configs)
    list.push_back(c.get());
  return list_configs(d, list, configs, config_size, num_config);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglChooseConfig(EGLDisplay dpy, const EGLint* attrib_list,
                                                  EGLConfig* configs, EGLint config_size,
                                                  EGLint* num_config) {
  const char* fn = "eglChooseConfig";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  if (num_config == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  Request r;
  for (size_t i = 0; i < kCriteriaCount; ++i)
    r.value[i] = kCriteria[i].default_value;
  for (int i = 0; attrib_list != nullptr && attrib_list[i] != EGL_NONE; i += 2) {
    const int k = criterion_index(attrib_list[i]);
    if (k < 0 || !valid_value(attrib_list[i], attrib_list[i + 1]))
      return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
    r.value[static_cast<size_t>(k)] = attrib_list[i + 1];
  }
  // EGL_MATCH_NATIVE_PIXMAP names an X pixmap; only its depth matters for Pineda's configs.
  int pixmap_depth = -1;
  const EGLint pixmap = r.get(EGL_MATCH_NATIVE_PIXMAP);
  if (pixmap != EGL_NONE) {
    int w = 0, h = 0;
    if (d->platform != Platform::X11 ||
        !x11::geometry(d->dpy, static_cast<Drawable>(static_cast<unsigned>(pixmap)), &w, &h,
                       &pixmap_depth, nullptr))
      return fail(EGL_BAD_NATIVE_PIXMAP, fn, EGL_FALSE);
  }
  std::vector<const EglConfig*> list;
  for (const auto& c : d->configs)
    if (matches(*c, r, pixmap_depth)) list.push_back(c.get());
  std::stable_sort(list.begin(), list.end(), [&](const EglConfig* a, const EglConfig* b) {
    return sort_key(*a, r) < sort_key(*b, r);
  });
  return list_configs(d, list, configs, config_size, num_config);
}

EGL_EXPORT EGLBoolean EGLAPIENTRY eglGetConfigAttrib(EGLDisplay dpy, EGLConfig config,
                                                     EGLint attribute, EGLint* value) {
  const char* fn = "eglGetConfigAttrib";
  std::lock_guard<std::mutex> lock(egl_mutex());
  EglDisplay* d = initialized_display(dpy, fn);
  if (d == nullptr) return EGL_FALSE;
  const EglConfig* c = find_config(d, config);
  if (c == nullptr) return fail(EGL_BAD_CONFIG, fn, EGL_FALSE);
  EGLint v = 0;
  if (!config_attrib(*c, attribute, &v)) return fail(EGL_BAD_ATTRIBUTE, fn, EGL_FALSE);
  if (value == nullptr) return fail(EGL_BAD_PARAMETER, fn, EGL_FALSE);
  *value = v;
  succeed();
  return EGL_TRUE;
}
