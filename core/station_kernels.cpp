#include "core/station_kernels.h"

#include <cstring>

#include "core/contact_law.h"
#include "core/vector_clones.h"

namespace shockmap {
namespace {

// W doubles side by side (GCC and Clang vector extension: lane-wise IEEE arithmetic, split into
// narrower instructions where the target has no register that wide).
// (Spelled per width: the attribute does not take a template's parameter.)
template <int W>
struct LanesOf;
template <>
struct LanesOf<2> {
  using type = double __attribute__((vector_size(16)));
};
template <>
struct LanesOf<4> {
  using type = double __attribute__((vector_size(32)));
};
template <>
struct LanesOf<8> {
  using type = double __attribute__((vector_size(64)));
};
template <int W>
using Lanes = typename LanesOf<W>::type;

template <int W>
[[gnu::always_inline]] inline Lanes<W> Load(const double* p) {
  Lanes<W> r;
  std::memcpy(&r, p, sizeof r);
  return r;
}

template <int W>
[[gnu::always_inline]] inline void Store(double* p, Lanes<W> v) {
  std::memcpy(p, &v, sizeof v);
}

// The W terms s[i * stride + h] p[i] of one mode i. (No lambda returns a vector in this file: a
// lambda is compiled for the baseline target, and a wide vector crossing into a clone that was
// not inlined, as under UBSan, changes the ABI: the upper lanes are lost.)
template <int W>
[[gnu::always_inline]] inline Lanes<W> Term(const double* s, int stride, int i, const double* p) {
  return Load<W>(s + i * stride) * (Lanes<W>{} + p[i]);
}

// sum_i s[i * stride + h] p[i] for the W stations h of one group, each lane summed in
// StationDot's order: lane h computes exactly what StationDot of its row gives.
template <int W>
[[gnu::always_inline]] inline Lanes<W> SumGroup(const double* s, int stride, int n,
                                                const double* p) {
  if (n < 2) return n == 1 ? Term<W>(s, stride, 0, p) : Lanes<W>{};
  const int pairs_end = n & ~1, quads_end = n & ~3;
  Lanes<W> s0 = Term<W>(s, stride, 0, p), s1 = Term<W>(s, stride, 1, p);
  if (pairs_end > 2) {
    Lanes<W> t0 = Term<W>(s, stride, 2, p), t1 = Term<W>(s, stride, 3, p);
    for (int i = 4; i < quads_end; i += 4) {
      s0 += Term<W>(s, stride, i, p);
      s1 += Term<W>(s, stride, i + 1, p);
      t0 += Term<W>(s, stride, i + 2, p);
      t1 += Term<W>(s, stride, i + 3, p);
    }
    s0 += t0;
    s1 += t1;
    if (pairs_end > quads_end) {
      s0 += Term<W>(s, stride, quads_end, p);
      s1 += Term<W>(s, stride, quads_end + 1, p);
    }
  }
  s0 += s1;
  for (int i = pairs_end; i < n; ++i) s0 += Term<W>(s, stride, i, p);
  return s0;
}

// The W stations' (y, z) stored as pairs: y0 z0 y1 z1 ...
template <int W>
[[gnu::always_inline]] inline void StorePairs(double* out, Lanes<W> y, Lanes<W> z) {
  if constexpr (W == 8) {
    Store<8>(out, __builtin_shufflevector(y, z, 0, 8, 1, 9, 2, 10, 3, 11));
    Store<8>(out + 8, __builtin_shufflevector(y, z, 4, 12, 5, 13, 6, 14, 7, 15));
  } else if constexpr (W == 4) {
    Store<4>(out, __builtin_shufflevector(y, z, 0, 4, 1, 5));
    Store<4>(out + 4, __builtin_shufflevector(y, z, 2, 6, 3, 7));
  } else {
    static_assert(W == 2);
    Store<2>(out, __builtin_shufflevector(y, z, 0, 2));
    Store<2>(out + 2, __builtin_shufflevector(y, z, 1, 3));
  }
}

[[gnu::always_inline]] inline double Dot(const double* f, const double* p, int n) {
  if (n < 2) return n == 1 ? f[0] * p[0] : 0.0;
  const int pairs_end = n & ~1, quads_end = n & ~3;
  Lanes<2> s = Load<2>(f) * Load<2>(p);
  if (pairs_end > 2) {
    Lanes<2> t = Load<2>(f + 2) * Load<2>(p + 2);
    for (int i = 4; i < quads_end; i += 4) {
      s += Load<2>(f + i) * Load<2>(p + i);
      t += Load<2>(f + i + 2) * Load<2>(p + i + 2);
    }
    s += t;
    if (pairs_end > quads_end) s += Load<2>(f + quads_end) * Load<2>(p + quads_end);
  }
  double sum = s[0] + s[1];
  for (int i = pairs_end; i < n; ++i) sum += f[i] * p[i];
  return sum;
}

// The stations [g, g + W) of one beam, both directions (0 in a direction the beam does not bend
// in), stored as pairs from out + 2 g.
template <int W>
[[gnu::always_inline]] inline void EvaluateGroup(const StationBlock& b, const double* shapes,
                                                 const double* x, int g, double* out) {
  const Lanes<W> y = b.y >= 0 ? SumGroup<W>(shapes + g, b.width, b.modes, x + b.y) : Lanes<W>{};
  const Lanes<W> z = b.z >= 0 ? SumGroup<W>(shapes + g, b.width, b.modes, x + b.z) : Lanes<W>{};
  StorePairs<W>(out + 2 * g, y, z);
}

// One beam's stations: a single one summed alone, else groups of 8, 4 or 2.
[[gnu::always_inline]] inline void EvaluateBlock(const StationBlock& b, const double* shapes,
                                                 const double* x, double* out) {
  if (b.modes == 0) {  // No modes, no motion (and no shapes to point into).
    for (int h = 0; h < 2 * b.width; ++h) out[h] = 0.0;
    return;
  }
  if (b.width == 1) {
    out[0] = b.y >= 0 ? Dot(shapes, x + b.y, b.modes) : 0.0;
    out[1] = b.z >= 0 ? Dot(shapes, x + b.z, b.modes) : 0.0;
    return;
  }
  if (b.width == 2) return EvaluateGroup<2>(b, shapes, x, 0, out);
  int g = 0;
  for (; g + 8 <= b.width; g += 8) EvaluateGroup<8>(b, shapes, x, g, out);
  if (g < b.width) EvaluateGroup<4>(b, shapes, x, g, out);
}

// The (y, z) pairs of slots slot[0] and slot[1], side by side.
[[gnu::always_inline]] inline Lanes<4> TwoPairs(const double* u, const int* slot) {
  return __builtin_shufflevector(Load<2>(u + 2 * slot[0]), Load<2>(u + 2 * slot[1]), 0, 1, 2, 3);
}

// The (y, z) pairs of the 8 slots slot[0 .. 8) as a register of y and one of z.
[[gnu::always_inline]] inline void GatherPairs(const double* u, const int* slot, Lanes<8>& y,
                                               Lanes<8>& z) {
  const Lanes<8> low =
      __builtin_shufflevector(TwoPairs(u, slot), TwoPairs(u, slot + 2), 0, 1, 2, 3, 4, 5, 6, 7);
  const Lanes<8> high =
      __builtin_shufflevector(TwoPairs(u, slot + 4), TwoPairs(u, slot + 6), 0, 1, 2, 3, 4, 5, 6, 7);
  y = __builtin_shufflevector(low, high, 0, 2, 4, 6, 8, 10, 12, 14);
  z = __builtin_shufflevector(low, high, 1, 3, 5, 7, 9, 11, 13, 15);
}

}  // namespace

double StationDot(const double* f, const double* p, int n) { return Dot(f, p, n); }

int StationWidth(int count) { return count <= 2 ? count : (count + 3) / 4 * 4; }

SHOCKMAP_VECTOR_CLONES void EvaluateStations(std::span<const StationBlock> blocks,
                                             const double* shapes, const double* x, double* out) {
  for (const StationBlock& b : blocks) EvaluateBlock(b, shapes + b.shapes, x, out + 2 * b.first);
}

// The forces of zones [i, i + 8) and the closed ones among them appended to `closed`: the
// stations' pairs gathered, the arithmetic eight zones at a time, each lane as the scalar
// formula orders it.
[[gnu::always_inline]] inline void PenaltyGroup(const PenaltyZones& z, int i, const double* u,
                                                double* f, int* closed, int& n_closed) {
  Lanes<8> ya, za, yb, zb;
  GatherPairs(u, z.slot_a + i, ya, za);
  GatherPairs(u, z.slot_b + i, yb, zb);
  const Lanes<8> ny = Load<8>(z.normal_y + i), nz = Load<8>(z.normal_z + i);
  const Lanes<8> d = ny * ya + nz * za - ny * yb - nz * zb - Load<8>(z.gap + i);
  const auto is_closed = d > 0.0;  // -1 in a closed lane, 0 in an open or NaN one.
  // k max(0, d): 0 for a NaN d, as LinearPenaltyForce gives.
  Store<8>(f + i, Load<8>(z.stiffness + i) * (is_closed ? d : Lanes<8>{}));
  for (int l = 0; l < 8; ++l) {
    closed[n_closed] = i + l;
    n_closed -= static_cast<int>(is_closed[l]);
  }
}

SHOCKMAP_VECTOR_CLONES int LinearPenaltyForces(const PenaltyZones& zones, const double* u,
                                               double* force, int* closed) {
  // Without a branch on contact: zones open and close at random.
  int n_closed = 0, i = 0;
  for (; i + 8 <= zones.count; i += 8) PenaltyGroup(zones, i, u, force, closed, n_closed);
  for (; i < zones.count; ++i) {
    const double* ua = u + 2 * zones.slot_a[i];
    const double* ub = u + 2 * zones.slot_b[i];
    const double ny = zones.normal_y[i], nz = zones.normal_z[i];
    const double d = ny * ua[0] + nz * ua[1] - ny * ub[0] - nz * ub[1] - zones.gap[i];
    force[i] = LinearPenaltyForce(zones.stiffness[i], d);
    closed[n_closed] = i;
    n_closed += static_cast<int>(d > 0.0);
  }
  return n_closed;
}

// out[i] += f row[i], i < n (a beam's modes never overlap the rows).
[[gnu::always_inline]] inline void AddRow(double* __restrict out, double f,
                                          const double* __restrict row, int n) {
  for (int i = 0; i < n; ++i) out[i] += f * row[i];
}

SHOCKMAP_VECTOR_CLONES void AddStationForces(std::span<const StationForce> forces,
                                             const StationLayout& layout, double* a) {
  for (const StationForce& f : forces) {
    const double* row = layout.rows + layout.row[f.slot];
    const int n = layout.modes[f.slot];
    if (layout.y[f.slot] >= 0) AddRow(a + layout.y[f.slot], f.y, row, n);
    if (layout.z[f.slot] >= 0) AddRow(a + layout.z[f.slot], f.z, row, n);
  }
}

}  // namespace shockmap
