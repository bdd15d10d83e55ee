// Display-list state (GL 2.1 §5.4, Table 6.31 LIST_BASE, LIST_INDEX, LIST_MODE; the "list"
// attribute group): the lists of a share group and the per-context compilation and execution
// state. The command stream and
// the compiled vertex blocks are built and replayed by src/state/dlist.cpp and
// src/state/dlist_save.cpp.
#pragma once

#include <GL/gl.h>

#include <cstdint>
#include <map>
#include <memory>
#include <vector>
#include "core/limits.h"

namespace pineda {

// Data a list owns besides its command stream (compiled vertex blocks, CallLists offsets);
// the stream refers to it by address.
struct DlistObject {
  virtual ~DlistObject() = default;
};

// One display list: records of {replay function, payload size in words, payload}.
struct DisplayList {
  std::vector<uint64_t> code;
  std::vector<std::unique_ptr<DlistObject>> objects;
};

// The lists of a share group by name. Ordered, so that GenLists finds free ranges by walking
// the gaps between names.
using DisplayLists = std::map<GLuint, std::unique_ptr<DisplayList>>;

// The current attributes a list sets (GL 2.1 §2.7), one bit each.
enum ListAttribBit : uint32_t {
  kListColor = 1u << 0,
  kListColor2 = 1u << 1,
  kListNormal = 1u << 2,
  kListTex = 1u << 3, // texture unit 0 (TexCoord, MultiTexCoord(TEXTURE0))
  kListEdge = 1u << 4,
  kListTex1 = 1u << 5, // units 1..3: kListTex1 << (unit - 1)
  kListTex2 = 1u << 6,
  kListTex3 = 1u << 7,
  kListFog = 1u << 8, // the fog coordinate (GL 1.4)
};
constexpr int kListAttribCount = 9;

// The list bit of texture unit `unit` (< kMaxTexUnits).
constexpr uint32_t list_tex_bit(int unit) {
  return unit == 0 ? kListTex : kListTex1 << (unit - 1);
}

struct ListAttribs {
  float color[4];
  float color2[3];
  float normal[3];
  float tex[4][4]; // per texture unit (kMaxTexUnits)
  bool edge;
  float fog;
};

// LIST_BIT: Table 6.31.
struct ListGroup {
  GLuint base = 0; // LIST_BASE (ListBase)
};

// The lists being compiled and executed: no attribute group.
struct DisplayListState {
  GLuint index = 0; // LIST_INDEX: the list being compiled, 0 when none
  GLenum mode = 0;  // LIST_MODE: COMPILE or COMPILE_AND_EXECUTE while compiling, else 0
  int depth = 0;    // lists being executed now, nested (CallList inside lists)
  std::unique_ptr<DisplayList> list; // under construction; stored at EndList

  // Compilation of vertices: the values the list itself gave the current attributes so far
  // (`known`: set since NewList and not made unknown by a CallList or PopAttrib since), the
  // ones not yet recorded as a command (`pending`), and the Begin/End block being compiled.
  ListAttribs attribs{};
  uint32_t known = 0;
  uint32_t pending = 0;
  std::unique_ptr<DlistObject> block;
};

struct StateArea;
extern const StateArea kListArea; // dlist.cpp

} // namespace pineda
