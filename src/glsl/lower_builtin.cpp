// Lowering: GLSL 1.20's built-in functions (§8) and texture lookups (§8.7).
#include <glslang/MachineIndependent/localintermediate.h>

#include "glsl/lower_internal.h"
#include "shader/io.h"

namespace pineda::glsl {

using namespace glslang;

namespace {

ValueId at(const Comps& c, size_t k) {
  return c.size() == 1 ? c[0] : c[k];
}

} // namespace

ValueId Lowerer::dot(const Comps& a, const Comps& b) {
  ValueId acc = kNoValue;
  for (size_t k = 0; k < a.size(); ++k) {
    const ValueId p = op(Op::Mul, Type::Float, a[k], at(b, k));
    acc = acc == kNoValue ? p : op(Op::Add, Type::Float, acc, p);
  }
  return acc;
}

Comps Lowerer::builtin(TOperator o, const std::vector<TIntermTyped*>& args, const TType& result_t) {
  if (o > EOpTextureGuardBegin && o < EOpTextureGuardEnd) return texture(o, args);
  std::vector<Comps> a;
  for (TIntermTyped* t : args)
    a.push_back(expr(t));
  const auto fl = [&](Op x, size_t arg = 0) {
    Comps out = a[arg];
    for (ValueId& v : out)
      v = op(x, f.type(v), v);
    return out;
  };
  const auto fl2 = [&](Op x) {
    const size_t n = std::max(a[0].size(), a[1].size());
    Comps out(n);
    const bool compare =
        x == Op::Lt || x == Op::Le || x == Op::Gt || x == Op::Ge || x == Op::Eq || x == Op::Ne;
    for (size_t k = 0; k < n; ++k)
      out[k] = op(x, compare ? Type::Bool : f.type(at(a[0], k)), at(a[0], k), at(a[1], k));
    return out;
  };
  const auto scale = [&](const Comps& v, float s) {
    Comps out = v;
    for (ValueId& x : out)
      x = op(Op::Mul, Type::Float, x, f.const_f(s));
    return out;
  };
  const ValueId one = f.const_f(1.0f), zero = f.const_f(0.0f);
  switch (o) {
  // §8.1 angle and trigonometry
  case EOpRadians:
    return scale(a[0], 0.017453292519943295f);
  case EOpDegrees:
    return scale(a[0], 57.29577951308232f);
  case EOpSin:
    return fl(Op::Sin);
  case EOpCos:
    return fl(Op::Cos);
  case EOpTan:
    return fl(Op::Tan);
  case EOpAsin:
    return fl(Op::Asin);
  case EOpAcos:
    return fl(Op::Acos);
  case EOpAtan:
    return a.size() == 2 ? fl2(Op::Atan2) : fl(Op::Atan);
  // §8.2 exponential
  case EOpPow:
    return fl2(Op::Pow);
  case EOpExp:
    return fl(Op::Exp);
  case EOpLog:
    return fl(Op::Log);
  case EOpExp2:
    return fl(Op::Exp2);
  case EOpLog2:
    return fl(Op::Log2);
  case EOpSqrt:
    return fl(Op::Sqrt);
  case EOpInverseSqrt:
    return fl(Op::Rsq);
  // §8.3 common
  case EOpAbs:
    return fl(Op::Abs);
  case EOpSign:
    return fl(Op::Sign);
  case EOpFloor:
    return fl(Op::Floor);
  case EOpCeil:
    return fl(Op::Ceil);
  case EOpFract:
    return fl(Op::Fract);
  case EOpMod: {
    // x - y * floor(x / y)
    const size_t n = a[0].size();
    Comps out(n);
    for (size_t k = 0; k < n; ++k) {
      const ValueId x = a[0][k], y = at(a[1], k);
      const ValueId q = op(Op::Floor, Type::Float, op(Op::Div, Type::Float, x, y));
      out[k] = op(Op::Sub, Type::Float, x, op(Op::Mul, Type::Float, y, q));
    }
    return out;
  }
  case EOpMin:
    return fl2(Op::Min);
  case EOpMax:
    return fl2(Op::Max);
  case EOpClamp: {
    Comps out = a[0];
    for (size_t k = 0; k < out.size(); ++k) {
      const Type t = f.type(out[k]);
      out[k] = op(Op::Min, t, op(Op::Max, t, out[k], at(a[1], k)), at(a[2], k));
    }
    return out;
  }
  case EOpMix: {
    // x * (1 - a) + y * a (GLSL 1.20 §8.3)
    Comps out = a[0];
    for (size_t k = 0; k < out.size(); ++k) {
      const ValueId w = at(a[2], k);
      out[k] = op(Op::Add, Type::Float,
                  op(Op::Mul, Type::Float, a[0][k], op(Op::Sub, Type::Float, one, w)),
                  op(Op::Mul, Type::Float, at(a[1], k), w));
    }
    return out;
  }
  case EOpStep: {
    const size_t n = std::max(a[0].size(), a[1].size());
    Comps out(n);
    for (size_t k = 0; k < n; ++k)
      out[k] = select(op(Op::Lt, Type::Bool, at(a[1], k), at(a[0], k)), zero, one);
    return out;
  }
  case EOpSmoothStep: {
    // t = clamp((x - e0) / (e1 - e0), 0, 1); t * t * (3 - 2 t)
    const size_t n = a[2].size();
    Comps out(n);
    for (size_t k = 0; k < n; ++k) {
      const ValueId e0 = at(a[0], k), e1 = at(a[1], k);
      ValueId t = op(Op::Div, Type::Float, op(Op::Sub, Type::Float, a[2][k], e0),
                     op(Op::Sub, Type::Float, e1, e0));
      t = op(Op::Min, Type::Float, op(Op::Max, Type::Float, t, zero), one);
      const ValueId p =
          op(Op::Sub, Type::Float, f.const_f(3.0f), op(Op::Mul, Type::Float, f.const_f(2.0f), t));
      out[k] = op(Op::Mul, Type::Float, op(Op::Mul, Type::Float, t, t), p);
    }
    return out;
  }
  // §8.4 geometric
  case EOpLength:
    return {op(Op::Sqrt, Type::Float, dot(a[0], a[0]))};
  case EOpDistance: {
    Comps d(a[0].size());
    for (size_t k = 0; k < d.size(); ++k)
      d[k] = op(Op::Sub, Type::Float, a[0][k], a[1][k]);
    return {op(Op::Sqrt, Type::Float, dot(d, d))};
  }
  case EOpDot:
    return {dot(a[0], a[1])};
  case EOpCross: {
    const Comps& x = a[0];
    const Comps& y = a[1];
    const auto m = [&](int i, int j) {
      return op(Op::Mul, Type::Float, x[static_cast<size_t>(i)], y[static_cast<size_t>(j)]);
    };
    return {op(Op::Sub, Type::Float, m(1, 2), m(2, 1)), op(Op::Sub, Type::Float, m(2, 0), m(0, 2)),
            op(Op::Sub, Type::Float, m(0, 1), m(1, 0))};
  }
  case EOpNormalize: {
    const ValueId r = op(Op::Rsq, Type::Float, dot(a[0], a[0]));
    Comps out = a[0];
    for (ValueId& v : out)
      v = op(Op::Mul, Type::Float, v, r);
    return out;
  }
  case EOpFtransform: {
    // The fixed-function transform's product, in its order (GL 2.1 §2.15.3 invariance).
    TType mat(EbtFloat, EvqUniform, 4, 4, 4);
    const int w = lenv.uniform_word("gl_ModelViewProjectionMatrix", mat);
    Comps m, v;
    for (int k = 0; k < 16; ++k)
      m.push_back(f.uniform(Type::Float, w + k));
    for (int k = 0; k < 4; ++k) {
      const int id = lenv.input("gl_Vertex", k);
      v.push_back(id >= 0 ? f.input(Type::Float, id) : f.const_f(k == 3 ? 1.0f : 0.0f));
    }
    TType vec(EbtFloat, EvqTemporary, 4);
    return arith(EOpMatrixTimesVector, mat, m, vec, v, vec);
  }
  case EOpFaceForward: {
    // dot(Nref, I) < 0 ? N : -N
    const ValueId d = dot(a[2], a[1]);
    const ValueId neg = op(Op::Lt, Type::Bool, d, zero);
    Comps out = a[0];
    for (ValueId& v : out)
      v = select(neg, v, op(Op::Neg, Type::Float, v));
    return out;
  }
  case EOpReflect: {
    // I - 2 dot(N, I) N
    const ValueId d2 = op(Op::Mul, Type::Float, f.const_f(2.0f), dot(a[1], a[0]));
    Comps out = a[0];
    for (size_t k = 0; k < out.size(); ++k)
      out[k] = op(Op::Sub, Type::Float, a[0][k], op(Op::Mul, Type::Float, d2, a[1][k]));
    return out;
  }
  case EOpRefract: {
    // k = 1 - eta^2 (1 - dot(N, I)^2); k < 0 ? 0 : eta I - (eta dot(N, I) + sqrt(k)) N
    const ValueId eta = a[2][0];
    const ValueId d = dot(a[1], a[0]);
    const ValueId k = op(Op::Sub, Type::Float, one,
                         op(Op::Mul, Type::Float, op(Op::Mul, Type::Float, eta, eta),
                            op(Op::Sub, Type::Float, one, op(Op::Mul, Type::Float, d, d))));
    const ValueId tir = op(Op::Lt, Type::Bool, k, zero);
    const ValueId s =
        op(Op::Add, Type::Float, op(Op::Mul, Type::Float, eta, d), op(Op::Sqrt, Type::Float, k));
    Comps out = a[0];
    for (size_t i = 0; i < out.size(); ++i) {
      const ValueId r = op(Op::Sub, Type::Float, op(Op::Mul, Type::Float, eta, a[0][i]),
                           op(Op::Mul, Type::Float, s, a[1][i]));
      out[i] = select(tir, zero, r);
    }
    return out;
  }
  // §8.5 matrix
  case EOpMul: // matrixCompMult
    return fl2(Op::Mul);
  case EOpOuterProduct: {
    // c r^T: column j is c * r[j]
    const Comps& c = a[0];
    const Comps& r = a[1];
    Comps out;
    for (size_t j = 0; j < r.size(); ++j)
      for (size_t i = 0; i < c.size(); ++i)
        out.push_back(op(Op::Mul, Type::Float, c[i], r[j]));
    return out;
  }
  case EOpTranspose: {
    const TType& t = args[0]->getType();
    const int cols = t.getMatrixCols(), rows = t.getMatrixRows();
    Comps out(a[0].size());
    for (int c = 0; c < cols; ++c)
      for (int r = 0; r < rows; ++r)
        out[static_cast<size_t>(r * cols + c)] = a[0][static_cast<size_t>(c * rows + r)];
    return out;
  }
  // §8.6 vector relational
  case EOpLessThan:
    return fl2(Op::Lt);
  case EOpGreaterThan:
    return fl2(Op::Gt);
  case EOpLessThanEqual:
    return fl2(Op::Le);
  case EOpGreaterThanEqual:
    return fl2(Op::Ge);
  case EOpVectorEqual:
    return fl2(Op::Eq);
  case EOpVectorNotEqual:
    return fl2(Op::Ne);
  case EOpAny: {
    ValueId r = f.const_b(false);
    for (ValueId v : a[0])
      r = or_(r, v);
    return {r};
  }
  case EOpAll: {
    ValueId r = f.const_b(true);
    for (ValueId v : a[0])
      r = and_(r, v);
    return {r};
  }
  case EOpVectorLogicalNot:
  case EOpLogicalNot: {
    Comps out = a[0];
    for (ValueId& v : out)
      v = not_(v);
    return out;
  }
  // §8.8 fragment processing
  case EOpDPdx:
  case EOpDPdy:
  case EOpFwidth: {
    if (stage != shader::Stage::Fragment) {
      fail("derivatives outside a fragment shader");
      return a[0];
    }
    Comps out = a[0];
    for (ValueId& v : out) {
      if (o == EOpDPdx) {
        v = op(Op::Ddx, Type::Float, v);
      } else if (o == EOpDPdy) {
        v = op(Op::Ddy, Type::Float, v);
      } else {
        v = op(Op::Add, Type::Float, op(Op::Abs, Type::Float, op(Op::Ddx, Type::Float, v)),
               op(Op::Abs, Type::Float, op(Op::Ddy, Type::Float, v)));
      }
    }
    return out;
  }
  // §8.9 noise: zero, as Mesa
  case EOpNoise: {
    std::vector<Type> ts;
    flat_types(result_t, ts);
    return Comps(ts.size(), zero);
  }
  default:
    fail("unsupported built-in function (operator " + std::to_string(static_cast<int>(o)) + ")");
    std::vector<Type> ts;
    flat_types(result_t, ts);
    Comps z;
    for (Type t : ts)
      z.push_back(t == kSamplerType ? kNoValue : f.constant(t, 0));
    return z;
  }
}

Comps Lowerer::texture(TOperator o, const std::vector<TIntermTyped*>& args) {
  const Comps zero4(4, f.const_f(0.0f));
  if (args.size() < 2) {
    fail("texture lookup without coordinates");
    return zero4;
  }
  const TSampler& sampler = args[0]->getType().getSampler();
  const Comps s = expr(args[0]);
  if (s.empty() || !is_sampler(s[0])) {
    fail("texture lookup without a sampler uniform");
    return zero4;
  }
  shader::TexKind kind;
  switch (sampler.dim) {
  case Esd1D:
    kind.target = shader::TexTarget::Tex1D;
    break;
  case Esd2D:
    kind.target = shader::TexTarget::Tex2D;
    break;
  case Esd3D:
    kind.target = shader::TexTarget::Tex3D;
    break;
  case EsdCube:
    kind.target = shader::TexTarget::Cube;
    break;
  default:
    fail("unsupported sampler type");
    return zero4;
  }
  kind.shadow = sampler.shadow;
  const bool proj = o == EOpTextureProj || o == EOpTextureProjLod;
  const bool lod = o == EOpTextureLod || o == EOpTextureProjLod;
  if (o != EOpTexture && !proj && !lod) {
    fail("unsupported texture function");
    return zero4;
  }
  const Comps c = expr(args[1]);
  ValueId st[3] = {kNoValue, kNoValue, kNoValue};
  const size_t n = c.size();
  switch (kind.target) {
  case shader::TexTarget::Tex1D:
    st[0] = c[0];
    if (kind.shadow) st[2] = c[2];
    break;
  case shader::TexTarget::Tex2D:
    st[0] = c[0], st[1] = c[1];
    if (kind.shadow) st[2] = c[2];
    break;
  default:
    st[0] = c[0], st[1] = c[1], st[2] = c[2];
    break;
  }
  if (proj) {
    // The coordinates divided by q, the last component (§8.7).
    const ValueId q = c[n - 1];
    for (ValueId& x : st)
      if (x != kNoValue) x = op(Op::Div, Type::Float, x, q);
  }
  ValueId l = kNoValue;
  if (lod) {
    kind.lod = shader::LodMode::Explicit;
    l = expr(args[2])[0];
  } else if (stage == shader::Stage::Vertex) {
    // Vertex shaders have no derivatives: the non-Lod lookups use level 0 (§8.7).
    kind.lod = shader::LodMode::Explicit;
    l = f.const_f(0.0f);
  } else if (args.size() > 2) {
    kind.lod = shader::LodMode::Bias;
    l = expr(args[2])[0];
  }
  const ValueId tex = f.emit(*cur, Op::Tex, Type::Float, st[0], st[1], st[2], l);
  f.insts[tex].imm[0] = static_cast<int32_t>(s[0] & ~kSamplerTag);
  f.insts[tex].imm[1] = kind.pack();
  Comps out;
  for (int k = 0; k < 4; ++k)
    out.push_back(f.emit_imm(*cur, Op::TexComp, Type::Float, k, 0, 0, tex));
  return out;
}

} // namespace pineda::glsl
