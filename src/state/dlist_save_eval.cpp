// Display-list savers (GL 2.1 §5.4) for Map1 and Map2, whose control points have a size
// computed from the target, orders and strides: the points are copied, packed, when the
// command is compiled, so the list keeps working after the application reuses its memory.
// Arguments the command will reject are compiled as they are (without points); the command's
// error then comes when the list executes (§5.4).
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include "state/api_util.h"
#include "dispatch.h"
#include "state/dlist_internal.h"
#include "state/eval.h"

namespace pineda {

namespace {

// Values per control point of a MAP1_* or MAP2_* target, or 0 (§5.1 Table 5.1).
int target_components(GLenum target) {
  static constexpr int k[kEvalKindCount] = {4, 1, 3, 1, 2, 3, 4, 3, 4};
  if (target >= GL_MAP1_COLOR_4 && target <= GL_MAP1_VERTEX_4) return k[target - GL_MAP1_COLOR_4];
  if (target >= GL_MAP2_COLOR_4 && target <= GL_MAP2_VERTEX_4) return k[target - GL_MAP2_COLOR_4];
  return 0;
}

// The arguments of Map1 (vorder 0) or Map2. `copied` values of type T follow in the record;
// has_points tells a null pointer from points that were not copied because the command fails.
template <typename T> struct alignas(16) MapHeader {
  GLenum target;
  T u1, u2, v1, v2;
  GLint ustride, uorder, vstride, vorder;
  bool has_points;
  size_t copied;
};

template <typename T> void replay_map(const void* p) {
  MapHeader<T> h;
  std::memcpy(&h, p, sizeof h);
  std::vector<T> points(h.copied);
  if (h.copied != 0)
    std::memcpy(points.data(), static_cast<const char*>(p) + sizeof h, h.copied * sizeof(T));
  // When nothing was copied the command fails before it reads any point: a dummy will do.
  static const T dummy[1] = {};
  const T* data = h.copied != 0 ? points.data() : h.has_points ? dummy : nullptr;
  if (h.vorder == 0) {
    if constexpr (std::is_same_v<T, GLfloat>)
      exec::Map1f(h.target, h.u1, h.u2, h.ustride, h.uorder, data);
    else
      exec::Map1d(h.target, h.u1, h.u2, h.ustride, h.uorder, data);
  } else {
    if constexpr (std::is_same_v<T, GLfloat>)
      exec::Map2f(h.target, h.u1, h.u2, h.ustride, h.uorder, h.v1, h.v2, h.vstride, h.vorder, data);
    else
      exec::Map2d(h.target, h.u1, h.u2, h.ustride, h.uorder, h.v1, h.v2, h.vstride, h.vorder, data);
  }
}

bool valid_order(GLint order) {
  return order >= 1 && order <= kMaxEvalOrder;
}

// Compiles Map1 (dim 1) or Map2; returns whether the command must also execute now. The
// points are copied packed (strides k and vorder * k) when the command can succeed.
template <typename T>
bool save_map(int dim, GLenum target, T u1, T u2, GLint ustride, GLint uorder, T v1, T v2,
              GLint vstride, GLint vorder, const T* points) {
  if (compiling_list() == nullptr) return true;
  const int k = target_components(target);
  const bool target_dim = dim == 1 ? target <= GL_MAP1_VERTEX_4 : target >= GL_MAP2_COLOR_4;
  MapHeader<T> h{
      target, u1, u2, v1, v2, ustride, uorder, vstride, dim == 1 ? 0 : vorder, points != nullptr,
      0};
  std::vector<T> packed;
  const bool ok = k != 0 && target_dim && points != nullptr && valid_order(uorder) &&
                  ustride >= k && (dim == 1 || (valid_order(vorder) && vstride >= k));
  if (ok) {
    const GLint vn = dim == 1 ? 1 : vorder;
    packed.reserve(size_t(uorder) * vn * k);
    for (ptrdiff_t i = 0; i < uorder; ++i)
      for (ptrdiff_t j = 0; j < vn; ++j)
        for (int c = 0; c < k; ++c)
          packed.push_back(points[i * ustride + j * vstride + c]);
    h.copied = packed.size();
    h.ustride = vn * k;
    h.vstride = k;
  }
  const size_t head = sizeof h, size = packed.size() * sizeof(T);
  const auto buf = std::make_unique<char[]>(head + size);
  std::memcpy(buf.get(), &h, head);
  if (size != 0) std::memcpy(buf.get() + head, packed.data(), size);
  return dlist_record(&replay_map<T>, buf.get(), head + size);
}

} // namespace

namespace saver {

void GLAPIENTRY Map1f(GLenum target, GLfloat u1, GLfloat u2, GLint stride, GLint order,
                      const GLfloat* points) {
  if (save_map<GLfloat>(1, target, u1, u2, stride, order, 0, 0, 0, 0, points))
    exec::Map1f(target, u1, u2, stride, order, points);
}
void GLAPIENTRY Map1d(GLenum target, GLdouble u1, GLdouble u2, GLint stride, GLint order,
                      const GLdouble* points) {
  if (save_map<GLdouble>(1, target, u1, u2, stride, order, 0, 0, 0, 0, points))
    exec::Map1d(target, u1, u2, stride, order, points);
}
void GLAPIENTRY Map2f(GLenum target, GLfloat u1, GLfloat u2, GLint ustride, GLint uorder,
                      GLfloat v1, GLfloat v2, GLint vstride, GLint vorder, const GLfloat* points) {
  if (save_map<GLfloat>(2, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    exec::Map2f(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}
void GLAPIENTRY Map2d(GLenum target, GLdouble u1, GLdouble u2, GLint ustride, GLint uorder,
                      GLdouble v1, GLdouble v2, GLint vstride, GLint vorder,
                      const GLdouble* points) {
  if (save_map<GLdouble>(2, target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points))
    exec::Map2d(target, u1, u2, ustride, uorder, v1, v2, vstride, vorder, points);
}

} // namespace saver
} // namespace pineda
