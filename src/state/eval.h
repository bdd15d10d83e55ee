// Evaluator state (GL 2.1 §5.1; Table 6.28 "Evaluators", the "eval" attribute group): the nine
// one-dimensional and nine two-dimensional maps, their enables, AUTO_NORMAL and the grids.
// Commands in eval.cpp.
#pragma once

#include <GL/gl.h>

#include <vector>
#include "core/limits.h"

namespace pineda {

// The map kinds in the order of their enums: MAP1_COLOR_4 (0x0D90) .. MAP1_VERTEX_4 (0x0D98),
// and likewise MAP2_COLOR_4 (0x0DB0) .. MAP2_VERTEX_4 (0x0DB8).
enum EvalKind : int {
  kEvalColor4 = 0,
  kEvalIndex,
  kEvalNormal,
  kEvalTex1,
  kEvalTex2,
  kEvalTex3,
  kEvalTex4,
  kEvalVertex3,
  kEvalVertex4,
  kEvalKindCount
};

struct EvalMap1 {
  GLint order = 1;
  float u1 = 0.0f, u2 = 1.0f;
  std::vector<float> points; // order blocks of k values, packed
};

struct EvalMap2 {
  GLint uorder = 1, vorder = 1;
  float u1 = 0.0f, u2 = 1.0f, v1 = 0.0f, v2 = 1.0f;
  std::vector<float> points; // R_ij at (i * vorder + j) * k, packed
};

// EVAL_BIT: Table 6.28 (the map enables and AUTO_NORMAL are also "enable").
struct EvalGroup {
  EvalGroup();
  EvalMap1 map1[kEvalKindCount];
  EvalMap2 map2[kEvalKindCount];
  bool map1_enabled[kEvalKindCount] = {};
  bool map2_enabled[kEvalKindCount] = {};
  bool auto_normal = false;
  // MapGrid1 / MapGrid2 (Table 6.28): domains and partition counts.
  float grid1_u1 = 0.0f, grid1_u2 = 1.0f;
  GLint grid1_n = 1;
  float grid2_u1 = 0.0f, grid2_u2 = 1.0f, grid2_v1 = 0.0f, grid2_v2 = 1.0f;
  GLint grid2_un = 1, grid2_vn = 1;
};

struct StateArea;
extern const StateArea kEvalArea; // eval.cpp

} // namespace pineda
