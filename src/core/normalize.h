// GL 2.1 Table 2.9: the conversion of integer colour and normal components to floating point,
// [0,1] for unsigned and [-1,1] for signed types; shared by the immediate-mode commands and
// their display-list savers.
#pragma once

#include <GL/gl.h>

#include <type_traits>

namespace pineda {

inline float norm(GLubyte c) {
  return static_cast<float>(c) * (1.0f / 255.0f);
}
inline float norm(GLbyte c) {
  return (2.0f * c + 1.0f) * (1.0f / 255.0f);
}
inline float norm(GLushort c) {
  return static_cast<float>(c) * (1.0f / 65535.0f);
}
inline float norm(GLshort c) {
  return (2.0f * c + 1.0f) * (1.0f / 65535.0f);
}
inline float norm(GLuint c) {
  return static_cast<float>(static_cast<double>(c) / 4294967295.0);
}
inline float norm(GLint c) {
  return static_cast<float>((2.0 * c + 1.0) / 4294967295.0);
}
inline float norm(GLfloat c) {
  return c;
}
inline float norm(GLdouble c) {
  return static_cast<float>(c);
}

// The same conversions by division rather than by a reciprocal, as the generic vertex attribute
// commands (glVertexAttrib*N*, GL 2.1 §2.7), their normalized arrays and their display-list
// savers take them; the two can differ in the last bit, so each path keeps its own.
template <typename T> float norm_divided(T v) {
  if constexpr (std::is_same_v<T, GLubyte>) return static_cast<float>(v) / 255.0f;
  if constexpr (std::is_same_v<T, GLbyte>) return (2.0f * v + 1.0f) / 255.0f;
  if constexpr (std::is_same_v<T, GLushort>) return static_cast<float>(v) / 65535.0f;
  if constexpr (std::is_same_v<T, GLshort>) return (2.0f * v + 1.0f) / 65535.0f;
  if constexpr (std::is_same_v<T, GLuint>)
    return static_cast<float>(static_cast<double>(v) / 4294967295.0);
  if constexpr (std::is_same_v<T, GLint>) return static_cast<float>((2.0 * v + 1.0) / 4294967295.0);
  return static_cast<float>(v);
}

} // namespace pineda
