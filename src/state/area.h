// The table through which each area of GL state tells the rest of Pineda what it has (GL 2.1
// §6.2 groups the state the same way): its capabilities (glEnable, glDisable, glIsEnabled and
// ENABLE_BIT), its queries (glGet*, glGetPointerv), its attribute groups (glPushAttrib,
// glPopAttrib, glPushClientAttrib, glPopClientAttrib, glXCopyContext) and its derived state
// (validation before a draw). enable.cpp, get.cpp, attrib.cpp and validate.cpp loop over
// state_areas() (areas.cpp); a new area fills in a StateArea next to its commands and adds
// one line to areas.cpp.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <memory>
#include <span>
#include <type_traits>
#include <utility>

namespace pineda {

struct Context;

// ---- capabilities (GL 2.1 §2.11.4 Enable/Disable, §6.1.1 IsEnabled) ----

enum class CapabilityKind : uint8_t {
  kServer,  // Enable/Disable/IsEnabled; saved by ENABLE_BIT
  kPerUnit, // one flag per texture unit: Enable acts on the active unit (§3.8.15, §2.11.4),
            // ENABLE_BIT saves every unit's
  kClient,  // EnableClientState/DisableClientState (§2.8); also taken by Enable/Disable, as
            // Mesa does; saved by CLIENT_VERTEX_ARRAY_BIT with the arrays, not ENABLE_BIT
};

// One capability, or `count` of them with consecutive enums (LIGHT0..7, CLIP_PLANE0..5).
struct Capability {
  GLenum cap;
  uint8_t count;
  CapabilityKind kind;
  uint32_t dirty; // derived state a change invalidates (DirtyBit)
  // The flag of capability cap + index; for kPerUnit capabilities that of texture unit `unit`.
  bool* (*flag)(Context& ctx, unsigned index, unsigned unit);
  // Called after the flag changed through Enable or Disable (not when it is restored).
  void (*changed)(Context& ctx, bool value) = nullptr;
};

// ---- queries (GL 2.1 §6.1.1, §6.1.2) ----

// How glGet converts a value (GL 2.1 §6.1.2).
enum class QueryKind : uint8_t {
  kInt,        // integer state: GetFloatv/GetDoublev give the integer, GetBooleanv != 0
  kBool,       // boolean state
  kFloat,      // floating-point state: GetIntegerv rounds to the nearest integer
  kNormalized, // colours, normals, depth values: GetIntegerv maps [-1, 1] to the integer range
};

// Up to 16 values of one kind: what an area answers for one pname.
struct QueryValues {
  QueryKind kind = QueryKind::kInt;
  int n = 0;
  double v[16] = {};
  // A query of state the active texture unit lacks (GL 2.1 §6.1.2): INVALID_OPERATION, no values.
  GLenum error = GL_NO_ERROR;

  void add(double x) { v[n++] = x; }
  void ints(std::initializer_list<double> xs) {
    kind = QueryKind::kInt;
    for (double x : xs)
      add(x);
  }
  void boolean(bool b) {
    kind = QueryKind::kBool;
    add(b ? 1.0 : 0.0);
  }
  void floats(const float* x, int count) {
    kind = QueryKind::kFloat;
    for (int i = 0; i < count; ++i)
      add(x[i]);
  }
  void floats(std::initializer_list<double> xs) {
    kind = QueryKind::kFloat;
    for (double x : xs)
      add(x);
  }
  void normalized(const float* x, int count) {
    kind = QueryKind::kNormalized;
    for (int i = 0; i < count; ++i)
      add(x[i]);
  }
  void normalized(std::initializer_list<double> xs) {
    kind = QueryKind::kNormalized;
    for (double x : xs)
      add(x);
  }
  void booleans(const bool* b, int count) {
    kind = QueryKind::kBool;
    for (int i = 0; i < count; ++i)
      add(b[i] ? 1.0 : 0.0);
  }
};

// ---- attribute groups (GL 2.1 §6.1.14, the "attribute" column of the §6.2 tables) ----

// A saved copy of one group, which puts itself back.
class SavedAttrib {
public:
  virtual ~SavedAttrib() = default;
  virtual void restore(Context& ctx) const = 0;
};

// One attribute group of an area.
struct AttribGroup {
  GLbitfield bit; // GL_*_BIT of glPushAttrib, or GL_CLIENT_*_BIT when `client`
  bool client;    // saved by glPushClientAttrib
  // The group names objects of the share group (texture bindings): glXCopyContext between
  // contexts of different share groups leaves the destination's (GLX 1.4 §3.3.7).
  bool shared_objects;
  uint32_t dirty; // derived state a restore invalidates (DirtyBit)
  std::unique_ptr<SavedAttrib> (*save)(const Context& ctx);
};

// A group that is one struct member of Context, saved and restored by copying it whole.
template <auto Member> class SavedMember final : public SavedAttrib {
public:
  explicit SavedMember(const Context& ctx) : value_(ctx.*Member) {}
  void restore(Context& ctx) const override { ctx.*Member = value_; }

private:
  std::remove_cvref_t<decltype(std::declval<Context&>().*Member)> value_;
};
template <auto Member> std::unique_ptr<SavedAttrib> save_member(const Context& ctx) {
  return std::make_unique<SavedMember<Member>>(ctx);
}
// The AttribGroup of the Context member `Member`.
template <auto Member>
constexpr AttribGroup member_group(GLbitfield bit, uint32_t dirty, bool client = false) {
  return AttribGroup{bit, client, false, dirty, &save_member<Member>};
}

// ---- the area ----

struct StateArea {
  const char* name; // for messages: the GL 2.1 section or state table
  std::span<const Capability> capabilities;
  // glGet*: fills `out` for pname and returns true, or returns false when pname is not this
  // area's. `out` starts empty with kind kInt.
  bool (*get)(Context& ctx, GLenum pname, QueryValues& out) = nullptr;
  // glGetPointerv: as get.
  bool (*get_pointer)(Context& ctx, GLenum pname, void** out) = nullptr;
  std::span<const AttribGroup> groups;
  // After glPopAttrib, glPopClientAttrib or glXCopyContext restored the groups of `mask`:
  // what follows from state of several groups together; returns the dirty bits.
  uint32_t (*restored)(Context& ctx, GLbitfield mask) = nullptr;
  // Derived state, made before a draw when one of `derive_on` is dirty (validate.cpp), in the
  // order of the table. `stale` returns dirty bits for changes the context's bits do not see:
  // it is asked when objects of the share group changed since the last validation
  // (SharedObjects::texture_generation moved, through this context or another of the group).
  uint32_t derive_on = 0;
  void (*derive)(Context& ctx, uint32_t dirty) = nullptr;
  uint32_t (*stale)(const Context& ctx) = nullptr;
};

// Every area, in the order validation derives their state (areas.cpp).
std::span<const StateArea* const> state_areas();

// The flag behind capability `cap` (for a per-unit capability, the active unit's) and, in
// `found` when given, its Capability; nullptr when no area has `cap`.
bool* capability_flag(Context& ctx, GLenum cap, const Capability** found = nullptr);

} // namespace pineda
