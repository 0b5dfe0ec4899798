#include "core/station_kernels.h"

#include <algorithm>
#include <cstring>

#define SHOCKMAP_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))

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

// out[h] = sum_i s[i * stride + h] p[i] for the W stations h of one group, each lane summed in
// StationDot's order: lane h computes exactly what StationDot of its row gives.
template <int W>
[[gnu::always_inline]] inline void EvaluateGroup(const double* s, int stride, int n,
                                                 const double* p, double* out) {
  auto term = [&](int i) { return Load<W>(s + i * stride) * (Lanes<W>{} + p[i]); };
  if (n < 2) {
    Store<W>(out, n == 1 ? term(0) : Lanes<W>{});
    return;
  }
  const int pairs_end = n & ~1, quads_end = n & ~3;
  Lanes<W> s0 = term(0), s1 = term(1);
  if (pairs_end > 2) {
    Lanes<W> t0 = term(2), t1 = term(3);
    for (int i = 4; i < quads_end; i += 4) {
      s0 += term(i);
      s1 += term(i + 1);
      t0 += term(i + 2);
      t1 += term(i + 3);
    }
    s0 += t0;
    s1 += t1;
    if (pairs_end > quads_end) {
      s0 += term(quads_end);
      s1 += term(quads_end + 1);
    }
  }
  s0 += s1;
  for (int i = pairs_end; i < n; ++i) s0 += term(i);
  Store<W>(out, s0);
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

// One beam's stations in one direction.
[[gnu::always_inline]] inline void EvaluateBlock(const double* shapes, int modes, int width,
                                                 const double* p, double* out) {
  if (width == 1) {
    out[0] = Dot(shapes, p, modes);
    return;
  }
  if (width == 2) {
    EvaluateGroup<2>(shapes, width, modes, p, out);
    return;
  }
  int g = 0;
  for (; g + 8 <= width; g += 8) EvaluateGroup<8>(shapes + g, width, modes, p, out + g);
  if (g < width) EvaluateGroup<4>(shapes + g, width, modes, p, out + g);
}

}  // namespace

double StationDot(const double* f, const double* p, int n) { return Dot(f, p, n); }

int StationWidth(int count) { return count <= 2 ? count : (count + 3) / 4 * 4; }

SHOCKMAP_CLONES void EvaluateStations(std::span<const StationBlock> blocks, const double* shapes,
                                      const double* x, double* out_y, double* out_z) {
  for (const StationBlock& b : blocks) {
    const double* s = shapes + b.shapes;
    if (b.y >= 0) EvaluateBlock(s, b.modes, b.width, x + b.y, out_y + b.first);
    if (b.z >= 0) EvaluateBlock(s, b.modes, b.width, x + b.z, out_z + b.first);
  }
}

// The forces of zones [i, i + W) and the closed ones among them appended to `closed`: the
// stations' values gathered one by one, the arithmetic W zones at a time, each lane as the
// scalar formula orders it.
template <int W>
[[gnu::always_inline]] inline void PenaltyGroup(const PenaltyZones& z, int i, const double* uy,
                                                const double* uz, double* f, int* closed,
                                                int& n_closed) {
  Lanes<W> ya, za, yb, zb;
  for (int l = 0; l < W; ++l) {
    const int sa = z.slot_a[i + l], sb = z.slot_b[i + l];
    ya[l] = uy[sa];
    za[l] = uz[sa];
    yb[l] = uy[sb];
    zb[l] = uz[sb];
  }
  const Lanes<W> ny = Load<W>(z.normal_y + i), nz = Load<W>(z.normal_z + i);
  const Lanes<W> d = ny * ya + nz * za - ny * yb - nz * zb - Load<W>(z.gap + i);
  const auto is_closed = d > 0.0;  // -1 in a closed lane, 0 in an open or NaN one.
  // k max(0, d): 0 for a NaN d, as std::max(0.0, d) gives.
  Store<W>(f + i, Load<W>(z.stiffness + i) * (is_closed ? d : Lanes<W>{}));
  for (int l = 0; l < W; ++l) {
    closed[n_closed] = i + l;
    n_closed -= static_cast<int>(is_closed[l]);
  }
}

SHOCKMAP_CLONES int LinearPenaltyForces(const PenaltyZones& zones, const double* uy,
                                        const double* uz, double* force, int* closed) {
  // Without a branch on contact: zones open and close at random.
  int n_closed = 0, i = 0;
  for (; i + 8 <= zones.count; i += 8) PenaltyGroup<8>(zones, i, uy, uz, force, closed, n_closed);
  for (; i < zones.count; ++i) {
    const int sa = zones.slot_a[i], sb = zones.slot_b[i];
    const double ny = zones.normal_y[i], nz = zones.normal_z[i];
    const double d = ny * uy[sa] + nz * uz[sa] - ny * uy[sb] - nz * uz[sb] - zones.gap[i];
    force[i] = zones.stiffness[i] * std::max(0.0, d);
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

SHOCKMAP_CLONES void AddStationForces(const StationForce* forces, int count,
                                      const StationLayout& layout, double* a) {
  for (int j = 0; j < count; ++j) {
    const StationForce& f = forces[j];
    const double* row = layout.rows + layout.row[f.slot];
    const int n = layout.modes[f.slot];
    if (layout.y[f.slot] >= 0) AddRow(a + layout.y[f.slot], f.y, row, n);
    if (layout.z[f.slot] >= 0) AddRow(a + layout.z[f.slot], f.z, row, n);
  }
}

}  // namespace shockmap
