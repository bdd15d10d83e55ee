// The shader engine's math on lane vectors (GCC/Clang vector extensions), one template for
// every width: the engine instantiates it with 4, 8 and 16 lanes (SSE2, AVX2, AVX-512) and the
// constant folder with 4, so every SIMD level and the folder give the same bits. Only +, -, *,
// /, comparisons and bit selects are used, in a fixed order; the files that instantiate it are
// compiled with -ffp-contract=off, so no a * b + c becomes a fused multiply-add.
//
// Accuracy (measured against double precision by tests/unit/glsl/math_test.cpp): sin, cos,
// exp2 and log2 within a few float ulps on their usual ranges; the others within a few more.
// GLSL 1.20 §8 leaves the precision of these functions unspecified.
//
// The templates are defined in the namespace PINEDA_SIMD_NS (vm unless the including file says
// otherwise): a file compiled for AVX2 or AVX-512 by target pragmas includes this after its
// pragma with its own namespace, so its copies are compiled for its instruction set and are
// never merged with the baseline ones.
#pragma once

#ifndef PINEDA_SIMD_NS
#define PINEDA_SIMD_NS vm
#endif

#include <cstdint>

#if defined(__x86_64__)
#include <immintrin.h>
#endif

namespace pineda::shader::PINEDA_SIMD_NS {

template <class F> using IOf = decltype(F{} < F{});
template <class F> struct UnsignedOf {
  typedef uint32_t type __attribute__((vector_size(sizeof(F))));
};
template <class F> using UOf = typename UnsignedOf<F>::type;

template <class F> inline IOf<F> as_int(F x) {
  return (IOf<F>)x;
}
template <class F, class I> inline F as_float(I x) {
  return (F)x;
}

// m ? a : b for lane masks m (all ones or zero).
template <class F> inline F sel(IOf<F> m, F a, F b) {
  return as_float<F>((as_int(a) & m) | (as_int(b) & ~m));
}
template <class I> inline I seli(I m, I a, I b) {
  return (a & m) | (b & ~m);
}

template <class F> inline F splat(float v) {
  return F{} + v;
}

// min and max return the operand that is a number when the other is NaN (IEEE 754 minNum,
// maxNum; piglit's fs-nan-builtin-min/max check it).
template <class F> inline F vmin(F a, F b) {
  return sel((a < b) | (b != b), a, b);
}
template <class F> inline F vmax(F a, F b) {
  return sel((a > b) | (b != b), a, b);
}

template <class F> inline F vabs(F x) {
  return as_float<F>(as_int(x) & 0x7fffffff);
}

// The square root, correctly rounded (the processor's instruction at each width).
// The 8- and 16-lane forms are only instantiated by the files compiled for AVX2 and AVX-512.
template <class F> inline F vsqrt(F x) {
  constexpr int n = sizeof(F) / 4;
#if defined(__x86_64__)
  if constexpr (n == 16) {
    __m512 v;
    __builtin_memcpy(&v, &x, 64);
    v = _mm512_maskz_sqrt_ps(static_cast<__mmask16>(0xffff), v);
    __builtin_memcpy(&x, &v, 64);
    return x;
  }
  if constexpr (n == 8) {
    __m256 v;
    __builtin_memcpy(&v, &x, 32);
    v = _mm256_sqrt_ps(v);
    __builtin_memcpy(&x, &v, 32);
    return x;
  }
  if constexpr (n % 4 == 0) {
    for (int i = 0; i < n; i += 4) {
      __m128 v;
      __builtin_memcpy(&v, reinterpret_cast<const float*>(&x) + i, 16);
      v = _mm_sqrt_ps(v);
      __builtin_memcpy(reinterpret_cast<float*>(&x) + i, &v, 16);
    }
    return x;
  }
#endif
  F r;
  for (int i = 0; i < n; ++i)
    r[i] = __builtin_sqrtf(x[i] < 0.0f || x[i] != x[i] ? __builtin_nanf("") : x[i]);
  return r;
}

// Float to int toward zero; NaN gives 0 and out-of-range values saturate, so that no lane
// is undefined behaviour and every width agrees.
template <class F> inline IOf<F> f2i(F x) {
  using I = IOf<F>;
  F c = sel(x != x, F{}, x);
  c = vmax(c, splat<F>(-2147483648.0f));
  c = vmin(c, splat<F>(2147483520.0f));
  return __builtin_convertvector(c, I);
}
template <class F> inline F i2f(IOf<F> x) {
  return __builtin_convertvector(x, F);
}

template <class F> inline F vfloor(F x) {
  using I = IOf<F>;
  // |x| >= 2^23 (and infinities) are integers already; NaN stays NaN.
  const I small = vabs(x) < splat<F>(8388608.0f);
  const F xs = sel(small, x, F{});
  F t = __builtin_convertvector(__builtin_convertvector(xs, I), F);
  t = t - sel(t > xs, splat<F>(1.0f), F{});
  return sel(small, t, x);
}
template <class F> inline F vceil(F x) {
  return -vfloor(-x);
}
template <class F> inline F vfract(F x) {
  return x - vfloor(x);
}

// sin and cos share the reduction x = k * pi/2 + r, |r| <= pi/4 (Cody-Waite with three parts
// of pi/2: the first two have few enough bits that k * part is exact for |k| < 2^15).
template <class F> inline void reduce_quarter(F x, F& r, IOf<F>& quadrant) {
  using I = IOf<F>;
  const F k = vfloor(x * splat<F>(0x1.45f306p-1f) + splat<F>(0.5f));
  r = ((x - k * splat<F>(0x1.92p+0f)) - k * splat<F>(0x1.fb4p-12f)) - k * splat<F>(0x1.4442d2p-24f);
  const F kc = vmin(vmax(k, splat<F>(-1073741824.0f)), splat<F>(1073741824.0f));
  quadrant = __builtin_convertvector(sel(k != k, F{}, kc), I) & 3;
}
// Taylor polynomials on |r| <= pi/4: the first omitted terms are below 2e-9.
template <class F> inline F sin_poly(F r) {
  const F z = r * r;
  F p = splat<F>(1.0f / 362880.0f);
  p = p * z + splat<F>(-1.0f / 5040.0f);
  p = p * z + splat<F>(1.0f / 120.0f);
  p = p * z + splat<F>(-1.0f / 6.0f);
  return r + r * z * p;
}
template <class F> inline F cos_poly(F r) {
  const F z = r * r;
  F p = splat<F>(-1.0f / 3628800.0f);
  p = p * z + splat<F>(1.0f / 40320.0f);
  p = p * z + splat<F>(-1.0f / 720.0f);
  p = p * z + splat<F>(1.0f / 24.0f);
  p = p * z + splat<F>(-0.5f);
  return splat<F>(1.0f) + z * p;
}
template <class F> inline F vsin(F x) {
  using I = IOf<F>;
  F r;
  I q;
  reduce_quarter(x, r, q);
  const F s = sin_poly(r), c = cos_poly(r);
  const F v = sel((q & 1) != 0, c, s);
  return sel((q & 2) != 0, -v, v);
}
template <class F> inline F vcos(F x) {
  using I = IOf<F>;
  F r;
  I q;
  reduce_quarter(x, r, q);
  const F s = sin_poly(r), c = cos_poly(r);
  const F v = sel((q & 1) != 0, s, c);
  return sel(((q + 1) & 2) != 0, -v, v);
}
template <class F> inline F vtan(F x) {
  using I = IOf<F>;
  F r;
  I q;
  reduce_quarter(x, r, q);
  const F s = sin_poly(r), c = cos_poly(r);
  return sel((q & 1) != 0, -c / s, s / c);
}

// 2^x: x = n + f with |f| <= 1/2; 2^f by its Taylor series in f ln 2 (first omitted term
// below 6e-9); 2^n in two halves so that n = 128 overflows to infinity and small n stay normal.
template <class F> inline F vexp2(F x) {
  using I = IOf<F>;
  const I nan = x != x;
  const F xc = vmin(vmax(sel(nan, F{}, x), splat<F>(-127.0f)), splat<F>(128.0f));
  const F n = vfloor(xc + splat<F>(0.5f));
  const F f = xc - n;
  F p = splat<F>(0x1.ffcbfcp-17f); // ln2^7 / 7!
  p = p * f + splat<F>(0x1.430912p-13f);
  p = p * f + splat<F>(0x1.5d87fep-10f);
  p = p * f + splat<F>(0x1.3b2ab6p-7f);
  p = p * f + splat<F>(0x1.c6b08ep-5f);
  p = p * f + splat<F>(0x1.ebfbep-3f);
  p = p * f + splat<F>(0x1.62e43p-1f);
  p = p * f + splat<F>(1.0f);
  const I ni = __builtin_convertvector(n, I);
  const I n1 = ni >> 1, n2 = ni - n1;
  const F s1 = as_float<F>((n1 + 127) << 23), s2 = as_float<F>((n2 + 127) << 23);
  F r = p * s1 * s2;
  r = sel(x < splat<F>(-126.0f), F{}, r);
  return sel(nan, x, r);
}

// log2 x: x = 2^e * m with m in [sqrt(1/2), sqrt(2)); ln m = 2 atanh(z), z = (m-1)/(m+1),
// |z| < 0.172, by its series to z^11 (first omitted term below 2e-11).
template <class F> inline F vlog2(F x) {
  using I = IOf<F>;
  const I bits = as_int(x);
  I e = ((bits >> 23) & 0xff) - 127;
  F m = as_float<F>((bits & 0x7fffff) | 0x3f800000);
  const I big = m > splat<F>(1.41421356f);
  m = sel(big, m * splat<F>(0.5f), m);
  e = e - big; // big is -1 in its lanes
  const F z = (m - splat<F>(1.0f)) / (m + splat<F>(1.0f));
  const F z2 = z * z;
  F p = splat<F>(1.0f / 11.0f);
  p = p * z2 + splat<F>(1.0f / 9.0f);
  p = p * z2 + splat<F>(1.0f / 7.0f);
  p = p * z2 + splat<F>(1.0f / 5.0f);
  p = p * z2 + splat<F>(1.0f / 3.0f);
  p = p * z2 + splat<F>(1.0f);
  const F ln_m = splat<F>(2.0f) * z * p;
  F r = __builtin_convertvector(e, F) + ln_m * splat<F>(0x1.715476p+0f);
  // Zero and denormals: -infinity; negative: NaN; +infinity and NaN: themselves.
  const F inf = splat<F>(__builtin_inff());
  r = sel((bits & 0x7f800000) == 0, -inf, r);
  r = sel(x < F{}, splat<F>(__builtin_nanf("")), r);
  r = sel((x == inf) | (x != x), x, r);
  return r;
}
template <class F> inline F vexp(F x) {
  return vexp2(x * splat<F>(0x1.715476p+0f));
}
template <class F> inline F vlog(F x) {
  return vlog2(x) * splat<F>(0x1.62e43p-1f);
}
template <class F> inline F vpow(F x, F y) {
  return vexp2(y * vlog2(x));
}

// asin on [0, 1/2] by its Taylor series (first omitted term below 3e-8 relative).
template <class F> inline F asin_small(F a) {
  const F z = a * a;
  F p = splat<F>(46189.0f / 5505024.0f);
  p = p * z + splat<F>(12155.0f / 1245184.0f);
  p = p * z + splat<F>(6435.0f / 557056.0f);
  p = p * z + splat<F>(143.0f / 10240.0f);
  p = p * z + splat<F>(231.0f / 13312.0f);
  p = p * z + splat<F>(63.0f / 2816.0f);
  p = p * z + splat<F>(35.0f / 1152.0f);
  p = p * z + splat<F>(5.0f / 112.0f);
  p = p * z + splat<F>(3.0f / 40.0f);
  p = p * z + splat<F>(1.0f / 6.0f);
  return a + a * z * p;
}
// asin a = pi/2 - 2 asin(sqrt((1 - a) / 2)) for a > 1/2.
template <class F> inline F vasin(F x) {
  using I = IOf<F>;
  const F a = vabs(x);
  const I large = a > splat<F>(0.5f);
  const F h = vsqrt((splat<F>(1.0f) - a) * splat<F>(0.5f));
  const F s = asin_small(sel(large, h, a));
  const F r = sel(large, splat<F>(0x1.921fb6p+0f) - splat<F>(2.0f) * s, s);
  return as_float<F>(as_int(r) | (as_int(x) & static_cast<int32_t>(0x80000000u)));
}
template <class F> inline F vacos(F x) {
  using I = IOf<F>;
  const F a = vabs(x);
  const I pos = x > splat<F>(0.5f), neg = x < splat<F>(-0.5f);
  const F h = vsqrt((splat<F>(1.0f) - a) * splat<F>(0.5f));
  const F s = asin_small(sel(pos | neg, h, a));
  F r = splat<F>(0x1.921fb6p+0f) - sel(x < F{}, -s, s);
  r = sel(pos, splat<F>(2.0f) * s, r);
  r = sel(neg, splat<F>(0x1.921fb6p+1f) - splat<F>(2.0f) * s, r);
  return r;
}

// atan: |x| > 1 through pi/2 - atan(1/|x|); above tan(pi/8) through pi/4 + atan((t-1)/(t+1));
// the rest by the series to u^19 (first omitted term below 5e-10).
template <class F> inline F vatan(F x) {
  using I = IOf<F>;
  const F a = vabs(x);
  const I inv = a > splat<F>(1.0f);
  const F t = sel(inv, splat<F>(1.0f) / a, a);
  const I mid = t > splat<F>(0.41421356f);
  const F u = sel(mid, (t - splat<F>(1.0f)) / (t + splat<F>(1.0f)), t);
  const F z = u * u;
  F p = splat<F>(-1.0f / 19.0f);
  p = p * z + splat<F>(1.0f / 17.0f);
  p = p * z + splat<F>(-1.0f / 15.0f);
  p = p * z + splat<F>(1.0f / 13.0f);
  p = p * z + splat<F>(-1.0f / 11.0f);
  p = p * z + splat<F>(1.0f / 9.0f);
  p = p * z + splat<F>(-1.0f / 7.0f);
  p = p * z + splat<F>(1.0f / 5.0f);
  p = p * z + splat<F>(-1.0f / 3.0f);
  F r = u + u * z * p;
  r = sel(mid, r + splat<F>(0x1.921fb6p-1f), r);
  r = sel(inv, splat<F>(0x1.921fb6p+0f) - r, r);
  return as_float<F>(as_int(r) | (as_int(x) & static_cast<int32_t>(0x80000000u)));
}
// atan(y, x) in [-pi, pi] (GLSL 1.20 §8.1); x = 0 gives +-pi/2 by the sign of y.
template <class F> inline F vatan2(F y, F x) {
  const F pi = splat<F>(0x1.921fb6p+1f);
  F r = vatan(y / x);
  r = sel(x < F{}, r + sel(y >= F{}, pi, -pi), r);
  r = sel(x == F{}, sel(y >= F{}, splat<F>(0x1.921fb6p+0f), splat<F>(-0x1.921fb6p+0f)), r);
  return r;
}

// Integer division toward zero through doubles (exact for 32-bit operands); a zero divisor
// gives the saturated quotient (0 for 0 / 0), so no lane traps.
template <class I, class D> inline I idiv(I a, I b) {
  const D q = __builtin_convertvector(a, D) / __builtin_convertvector(b, D);
  D c = q;
  for (int i = 0; i < static_cast<int>(sizeof(D) / 8); ++i) {
    double v = q[i];
    v = v != v ? 0.0 : v;
    v = v < -2147483648.0 ? -2147483648.0 : v;
    v = v > 2147483647.0 ? 2147483647.0 : v;
    c[i] = v;
  }
  return __builtin_convertvector(c, I);
}

} // namespace pineda::shader::PINEDA_SIMD_NS
