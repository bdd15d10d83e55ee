// GLXFBConfigs and visuals (GLX 1.4 §3.3.3, §3.4.1): the per-display bookkeeping, the configs
// derived from the screen's TrueColor visuals, their attributes, glXChooseFBConfig's selection
// and sorting and glXChooseVisual's.
#include <algorithm>
#include <cstdlib>
#include <cstring>

#include "winsys/glx/glx_internal.h"

// XESetCloseDisplay is declared only here; this header also defines min and max macros.
#include <X11/Xlibint.h>
#undef min
#undef max

#define GLX_EXPORT extern "C" __attribute__((visibility("default")))

namespace pineda::glx {

namespace {

std::vector<std::unique_ptr<DisplayState>>& displays() {
  // Never destroyed, like contexts() in glx_api.cpp: exit handlers may still call GLX.
  static auto* list = new std::vector<std::unique_ptr<DisplayState>>;
  return *list;
}

// Largest pbuffer: the largest viewport Pineda accepts.
constexpr int kMaxPbufferDim = kMaxViewportDim;

void build_configs(DisplayState* ds) {
  Display* dpy = ds->dpy;
  int next_id = 1;
  for (int screen = 0; screen < ScreenCount(dpy); ++screen) {
    XVisualInfo tmpl{};
    tmpl.screen = screen;
    tmpl.c_class = TrueColor;
    int n = 0;
    XVisualInfo* vis = XGetVisualInfo(dpy, VisualScreenMask | VisualClassMask, &tmpl, &n);
    // Depth-24 visuals first so that the first config is an ordinary opaque window's.
    std::vector<x11::Format> usable;
    for (int i = 0; i < n; ++i) {
      x11::Format f;
      if (x11::usable_visual(dpy, vis[i], &f)) usable.push_back(f);
    }
    std::stable_sort(usable.begin(), usable.end(),
                     [](const x11::Format& a, const x11::Format& b) { return a.depth < b.depth; });
    for (const x11::Format& v : usable) {
      // Native order: the most capable config first (what glXGetFBConfigs lists).
      for (bool db : {true, false})
        for (int alpha : {8, 0})
          for (int depth : {24, 16, 0})
            for (int stencil : {8, 0})
              // An accumulation buffer only next to depth 24 and stencil 8, so that the list
              // grows by one config per buffering and alpha choice rather than doubling.
              for (int accum : {0, 16}) {
                if (accum != 0 && (depth != 24 || stencil != 8)) continue;
                auto c = std::make_unique<Config>();
                c->id = next_id++;
                c->screen = screen;
                c->x = v;
                c->double_buffer = db;
                c->alpha_bits = alpha;
                c->depth_bits = depth;
                c->stencil_bits = stencil;
                c->accum_bits = accum;
                ds->configs.push_back(std::move(c));
              }
    }
    if (vis != nullptr) XFree(vis);
  }
}

// XCloseDisplay hook: forget everything about the connection.
int on_close_display(Display* dpy, XExtCodes*) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  auto& list = displays();
  for (auto it = list.begin(); it != list.end(); ++it) {
    if ((*it)->dpy == dpy) {
      for (auto& [id, surface] : (*it)->surfaces) orphan_surface(*surface);
      (*it)->surfaces.clear();
      list.erase(it);
      break;
    }
  }
  return 0;
}

} // namespace

std::mutex& registry_mutex() {
  static std::mutex m;
  return m;
}

DisplayState* display_state(Display* dpy) {
  if (dpy == nullptr) return nullptr;
  auto& list = displays();
  for (auto& d : list)
    if (d->dpy == dpy) return d.get();
  auto ds = std::make_unique<DisplayState>();
  ds->dpy = dpy;
  int first_event = 0;
  ds->server_glx =
      XQueryExtension(dpy, GLX_EXTENSION_NAME, &ds->glx_opcode, &first_event, &ds->error_base);
  if (ds->server_glx) {
    ds->event_base = first_event;
  } else {
    // Without a server GLX there is no assigned error range; errors are then reported with
    // the nearest core error code instead (see report_error).
    ds->error_base = 0;
    ds->event_base = 0;
  }
  ds->shm = x11::shm_available(dpy);
  build_configs(ds.get());
  if (XExtCodes* codes = XAddExtension(dpy)) XESetCloseDisplay(dpy, codes->extension, on_close_display);
  list.push_back(std::move(ds));
  return list.back().get();
}

const Config* find_config(DisplayState* ds, GLXFBConfig handle) {
  if (ds == nullptr || handle == nullptr) return nullptr;
  for (const auto& c : ds->configs)
    if (reinterpret_cast<GLXFBConfig>(c.get()) == handle) return c.get();
  return nullptr;
}

const Config* config_for_visual(DisplayState* ds, const XVisualInfo* vis) {
  if (ds == nullptr || vis == nullptr) return nullptr;
  auto it = ds->visual_choice.find(vis->visualid);
  if (it != ds->visual_choice.end() && it->second->screen == vis->screen) return it->second;
  for (const auto& c : ds->configs)
    if (c->x.visual_id == vis->visualid && c->screen == vis->screen) return c.get();
  return nullptr;
}

bool config_attrib(const Config& c, int attribute, int* value) {
  int v = 0;
  switch (attribute) {
  case GLX_USE_GL: v = True; break;
  case GLX_BUFFER_SIZE: v = 24 + c.alpha_bits; break;
  case GLX_LEVEL: v = 0; break;
  case GLX_RGBA: v = True; break;
  case GLX_DOUBLEBUFFER: v = c.double_buffer ? True : False; break;
  case GLX_STEREO: v = False; break;
  case GLX_AUX_BUFFERS: v = 0; break;
  case GLX_RED_SIZE:
  case GLX_GREEN_SIZE:
  case GLX_BLUE_SIZE: v = 8; break;
  case GLX_ALPHA_SIZE: v = c.alpha_bits; break;
  case GLX_DEPTH_SIZE: v = c.depth_bits; break;
  case GLX_STENCIL_SIZE: v = c.stencil_bits; break;
  case GLX_ACCUM_RED_SIZE:
  case GLX_ACCUM_GREEN_SIZE:
  case GLX_ACCUM_BLUE_SIZE:
  case GLX_ACCUM_ALPHA_SIZE: v = c.accum_bits; break;
  case GLX_SAMPLE_BUFFERS:
  case GLX_SAMPLES: v = 0; break;
  case GLX_FBCONFIG_ID: v = c.id; break;
  case GLX_RENDER_TYPE: v = GLX_RGBA_BIT; break;
  case GLX_DRAWABLE_TYPE: v = GLX_WINDOW_BIT | GLX_PIXMAP_BIT | GLX_PBUFFER_BIT; break;
  case GLX_X_RENDERABLE: v = True; break;
  case GLX_X_VISUAL_TYPE: v = GLX_TRUE_COLOR; break;
  case GLX_CONFIG_CAVEAT: v = GLX_NONE; break;
  case GLX_TRANSPARENT_TYPE: v = GLX_NONE; break;
  case GLX_TRANSPARENT_INDEX_VALUE:
  case GLX_TRANSPARENT_RED_VALUE:
  case GLX_TRANSPARENT_GREEN_VALUE:
  case GLX_TRANSPARENT_BLUE_VALUE:
  case GLX_TRANSPARENT_ALPHA_VALUE: v = 0; break;
  case GLX_VISUAL_ID: v = static_cast<int>(c.x.visual_id); break;
  case GLX_SCREEN: v = c.screen; break;
  case GLX_MAX_PBUFFER_WIDTH:
  case GLX_MAX_PBUFFER_HEIGHT: v = kMaxPbufferDim; break;
  case GLX_MAX_PBUFFER_PIXELS: v = kMaxPbufferDim * kMaxPbufferDim / 4; break;
  default: return false;
  }
  *value = v;
  return true;
}

namespace {

constexpr int kDontCare = static_cast<int>(GLX_DONT_CARE);

enum class Match { Exact, AtLeast, Mask, Ignore };

Match match_kind(int attribute) {
  switch (attribute) {
  case GLX_BUFFER_SIZE:
  case GLX_AUX_BUFFERS:
  case GLX_RED_SIZE:
  case GLX_GREEN_SIZE:
  case GLX_BLUE_SIZE:
  case GLX_ALPHA_SIZE:
  case GLX_DEPTH_SIZE:
  case GLX_STENCIL_SIZE:
  case GLX_ACCUM_RED_SIZE:
  case GLX_ACCUM_GREEN_SIZE:
  case GLX_ACCUM_BLUE_SIZE:
  case GLX_ACCUM_ALPHA_SIZE:
  case GLX_SAMPLE_BUFFERS:
  case GLX_SAMPLES: return Match::AtLeast;
  case GLX_RENDER_TYPE:
  case GLX_DRAWABLE_TYPE: return Match::Mask;
  // §3.3.3: these are ignored when present (their value must still follow).
  case GLX_MAX_PBUFFER_WIDTH:
  case GLX_MAX_PBUFFER_HEIGHT:
  case GLX_MAX_PBUFFER_PIXELS:
  case GLX_VISUAL_ID: return Match::Ignore;
  default: return Match::Exact;
  }
}

// A parsed attribute list: every attribute of Table 3.4 with its requested or default value.
struct Criteria {
  std::vector<std::pair<int, int>> wanted; // (attribute, value), defaults included
  bool color_asked[4] = {};
  bool accum_asked[4] = {};
  int fbconfig_id = kDontCare;
};

void set(Criteria& c, int attribute, int value) {
  for (auto& [a, v] : c.wanted)
    if (a == attribute) {
      v = value;
      return;
    }
  c.wanted.emplace_back(attribute, value);
}

int get(const Criteria& c, int attribute) {
  for (const auto& [a, v] : c.wanted)
    if (a == attribute) return v;
  return kDontCare;
}

bool known_attribute(int attribute) {
  int dummy = 0;
  Config probe;
  return attribute != GLX_USE_GL && attribute != GLX_RGBA && config_attrib(probe, attribute, &dummy);
}

// Table 3.4 defaults, then the list. The GLX 1.2 visual list has boolean attributes without
// values (§3.4.1); `visual_list` selects that syntax and Table 3.8's defaults.
bool parse(const int* list, bool visual_list, Criteria* out) {
  Criteria& c = *out;
  set(c, GLX_BUFFER_SIZE, 0);
  set(c, GLX_LEVEL, 0);
  set(c, GLX_DOUBLEBUFFER, visual_list ? False : kDontCare);
  set(c, GLX_STEREO, False);
  set(c, GLX_AUX_BUFFERS, 0);
  for (int a : {GLX_RED_SIZE, GLX_GREEN_SIZE, GLX_BLUE_SIZE, GLX_ALPHA_SIZE, GLX_DEPTH_SIZE,
                GLX_STENCIL_SIZE, GLX_ACCUM_RED_SIZE, GLX_ACCUM_GREEN_SIZE, GLX_ACCUM_BLUE_SIZE,
                GLX_ACCUM_ALPHA_SIZE, GLX_SAMPLE_BUFFERS, GLX_SAMPLES})
    set(c, a, 0);
  // A visual list without GLX_RGBA asks for colour index, which Pineda does not provide.
  set(c, GLX_RENDER_TYPE, visual_list ? GLX_COLOR_INDEX_BIT : GLX_RGBA_BIT);
  set(c, GLX_DRAWABLE_TYPE, GLX_WINDOW_BIT);
  set(c, GLX_TRANSPARENT_TYPE, GLX_NONE);
  bool drawable_type_given = false;
  for (int i = 0; list != nullptr && list[i] != None;) {
    const int attribute = list[i];
    if (visual_list) {
      if (attribute == GLX_USE_GL) {
        ++i;
        continue;
      }
      if (attribute == GLX_RGBA) {
        set(c, GLX_RENDER_TYPE, GLX_RGBA_BIT);
        ++i;
        continue;
      }
      if (attribute == GLX_DOUBLEBUFFER || attribute == GLX_STEREO) {
        set(c, attribute, True);
        ++i;
        continue;
      }
    }
    if (!known_attribute(attribute)) return false;
    const int value = list[i + 1];
    i += 2;
    if (attribute == GLX_FBCONFIG_ID) {
      // §3.4.1: glXChooseVisual ignores it.
      if (!visual_list) c.fbconfig_id = value;
      continue;
    }
    if (attribute == GLX_DRAWABLE_TYPE) drawable_type_given = true;
    set(c, attribute, value);
    const int color_index = attribute - GLX_RED_SIZE;
    if (color_index >= 0 && color_index < 4) c.color_asked[color_index] = value != 0 && value != kDontCare;
    const int accum_index = attribute - GLX_ACCUM_RED_SIZE;
    if (accum_index >= 0 && accum_index < 4) c.accum_asked[accum_index] = value != 0 && value != kDontCare;
  }
  // §3.3.3: without GLX_WINDOW_BIT in an explicit drawable type the visual type is ignored.
  if (drawable_type_given && (get(c, GLX_DRAWABLE_TYPE) & GLX_WINDOW_BIT) == 0)
    set(c, GLX_X_VISUAL_TYPE, kDontCare);
  // §3.3.3: transparent values are ignored unless a transparent type is asked for.
  if (get(c, GLX_TRANSPARENT_TYPE) == GLX_NONE)
    for (int a = GLX_TRANSPARENT_INDEX_VALUE; a <= GLX_TRANSPARENT_ALPHA_VALUE; ++a)
      set(c, a, kDontCare);
  return true;
}

bool matches(const Config& config, const Criteria& c) {
  for (const auto& [attribute, wanted] : c.wanted) {
    // §3.3.3: GLX_DONT_CARE is allowed for every attribute except GLX_LEVEL.
    if (wanted == kDontCare && attribute != GLX_LEVEL) continue;
    int have = 0;
    config_attrib(config, attribute, &have);
    switch (match_kind(attribute)) {
    case Match::Exact:
      if (have != wanted) return false;
      break;
    case Match::AtLeast:
      if (have < wanted) return false;
      break;
    case Match::Mask:
      if ((have & wanted) != wanted) return false;
      break;
    case Match::Ignore: break;
    }
  }
  return true;
}

// GLX 1.4 §3.3.3 "Sorting of GLXFBConfigs", rules 1 to 11; true if a sorts before b.
bool better(const Config& a, const Config& b, const Criteria& c) {
  auto attr = [](const Config& x, int attribute) {
    int v = 0;
    config_attrib(x, attribute, &v);
    return v;
  };
  auto caveat_rank = [&](const Config& x) {
    const int v = attr(x, GLX_CONFIG_CAVEAT);
    return v == GLX_NONE ? 0 : v == GLX_SLOW_CONFIG ? 1 : 2;
  };
  if (caveat_rank(a) != caveat_rank(b)) return caveat_rank(a) < caveat_rank(b); // 1
  auto color_sum = [&](const Config& x, int first, const bool* asked) {
    int sum = 0;
    for (int i = 0; i < 4; ++i)
      if (asked[i]) sum += attr(x, first + i);
    return sum;
  };
  const int ca = color_sum(a, GLX_RED_SIZE, c.color_asked);
  const int cb = color_sum(b, GLX_RED_SIZE, c.color_asked);
  if (ca != cb) return ca > cb; // 2
  for (int attribute : {GLX_BUFFER_SIZE, GLX_DOUBLEBUFFER, GLX_AUX_BUFFERS, GLX_SAMPLE_BUFFERS,
                        GLX_SAMPLES}) { // 3-7: smaller first (single- before double-buffered)
    if (attr(a, attribute) != attr(b, attribute)) return attr(a, attribute) < attr(b, attribute);
  }
  if (attr(a, GLX_DEPTH_SIZE) != attr(b, GLX_DEPTH_SIZE))
    return attr(a, GLX_DEPTH_SIZE) > attr(b, GLX_DEPTH_SIZE); // 8
  if (attr(a, GLX_STENCIL_SIZE) != attr(b, GLX_STENCIL_SIZE))
    return attr(a, GLX_STENCIL_SIZE) < attr(b, GLX_STENCIL_SIZE); // 9
  const int aa = color_sum(a, GLX_ACCUM_RED_SIZE, c.accum_asked);
  const int ab = color_sum(b, GLX_ACCUM_RED_SIZE, c.accum_asked);
  if (aa != ab) return aa > ab; // 10
  return false; // 11: every config is TrueColor
}

std::vector<const Config*> select(DisplayState* ds, int screen, const Criteria& c) {
  std::vector<const Config*> out;
  for (const auto& config : ds->configs) {
    if (config->screen != screen) continue;
    if (c.fbconfig_id != kDontCare) {
      // §3.3.3: with GLX_FBCONFIG_ID every other attribute is ignored.
      if (config->id == c.fbconfig_id) out.push_back(config.get());
      continue;
    }
    if (matches(*config, c)) out.push_back(config.get());
  }
  std::stable_sort(out.begin(), out.end(),
                   [&](const Config* a, const Config* b) { return better(*a, *b, c); });
  return out;
}

GLXFBConfig* to_handles(const std::vector<const Config*>& list, int* count) {
  if (count != nullptr) *count = static_cast<int>(list.size());
  if (list.empty()) return nullptr;
  // Returned to the application, which frees it with XFree (§3.3.3), i.e. free().
  auto* out = static_cast<GLXFBConfig*>(std::malloc(sizeof(GLXFBConfig) * list.size()));
  if (out == nullptr) {
    if (count != nullptr) *count = 0;
    return nullptr;
  }
  for (size_t i = 0; i < list.size(); ++i)
    out[i] = reinterpret_cast<GLXFBConfig>(const_cast<Config*>(list[i]));
  return out;
}

XVisualInfo* visual_info(Display* dpy, const Config& c) {
  XVisualInfo tmpl{};
  tmpl.visualid = c.x.visual_id;
  tmpl.screen = c.screen;
  int n = 0;
  return XGetVisualInfo(dpy, VisualIDMask | VisualScreenMask, &tmpl, &n);
}

bool valid_screen(Display* dpy, int screen) { return screen >= 0 && screen < ScreenCount(dpy); }

} // namespace
} // namespace pineda::glx

using namespace pineda::glx;

GLX_EXPORT GLXFBConfig* glXGetFBConfigs(Display* dpy, int screen, int* nelements) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  if (nelements != nullptr) *nelements = 0;
  if (ds == nullptr || !valid_screen(dpy, screen)) return nullptr;
  std::vector<const Config*> list;
  for (const auto& c : ds->configs)
    if (c->screen == screen) list.push_back(c.get());
  return to_handles(list, nelements);
}

GLX_EXPORT GLXFBConfig* glXChooseFBConfig(Display* dpy, int screen, const int* attribList,
                                          int* nitems) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  if (nitems != nullptr) *nitems = 0;
  Criteria criteria;
  // §3.3.3: an undefined attribute or an invalid screen gives NULL.
  if (ds == nullptr || !valid_screen(dpy, screen) || !parse(attribList, false, &criteria))
    return nullptr;
  return to_handles(select(ds, screen, criteria), nitems);
}

GLX_EXPORT int glXGetFBConfigAttrib(Display* dpy, GLXFBConfig config, int attribute, int* value) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return GLX_NO_EXTENSION;
  const Config* c = find_config(ds, config);
  if (c == nullptr) return GLX_BAD_VALUE;
  // GLX_USE_GL and GLX_RGBA are glXGetConfig's (Table 3.7), not config attributes (Table 3.1).
  if (attribute == GLX_USE_GL || attribute == GLX_RGBA || value == nullptr)
    return GLX_BAD_ATTRIBUTE;
  return config_attrib(*c, attribute, value) ? Success : GLX_BAD_ATTRIBUTE;
}

GLX_EXPORT XVisualInfo* glXGetVisualFromFBConfig(Display* dpy, GLXFBConfig config) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  const Config* c = find_config(ds, config);
  if (c == nullptr) return nullptr;
  // Later glXGetConfig and glXCreateContext calls on this visual describe this config.
  ds->visual_choice[c->x.visual_id] = c;
  return visual_info(dpy, *c);
}

GLX_EXPORT XVisualInfo* glXChooseVisual(Display* dpy, int screen, int* attribList) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  Criteria criteria;
  if (ds == nullptr || !valid_screen(dpy, screen) || !parse(attribList, true, &criteria))
    return nullptr;
  const std::vector<const Config*> list = select(ds, screen, criteria);
  if (list.empty()) return nullptr;
  ds->visual_choice[list.front()->x.visual_id] = list.front();
  return visual_info(dpy, *list.front());
}

GLX_EXPORT int glXGetConfig(Display* dpy, XVisualInfo* visual, int attrib, int* value) {
  std::lock_guard<std::mutex> lock(registry_mutex());
  DisplayState* ds = display_state(dpy);
  if (ds == nullptr) return GLX_NO_EXTENSION;
  if (visual == nullptr || value == nullptr) return GLX_BAD_VALUE;
  if (!valid_screen(dpy, visual->screen)) return GLX_BAD_SCREEN;
  const Config* c = config_for_visual(ds, visual);
  if (c == nullptr) {
    // §3.4.1: a visual without GL support answers GLX_USE_GL with False, anything else fails.
    if (attrib == GLX_USE_GL) {
      *value = False;
      return Success;
    }
    return GLX_BAD_VISUAL;
  }
  return config_attrib(*c, attrib, value) ? Success : GLX_BAD_ATTRIBUTE;
}
