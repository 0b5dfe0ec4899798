#include "core/increment_stepper.h"

#include <algorithm>
#include <cassert>
#include <utility>

#include "core/vector_clones.h"

namespace shockmap {
namespace {

constexpr int kLookahead = IncrementStepper::kLookahead;
constexpr int kMaxZones = IncrementStepper::kMaxZones;

// Four doubles: one AVX2 register (AVX-512 adds registers and masks, not width here: the
// models' few modes would leave most of eight lanes padding), two SSE2 ones. Loaded and stored
// by copy, at any double's alignment.
using Lanes = double __attribute__((vector_size(32)));
using HalfLanes = double __attribute__((vector_size(16)));
constexpr int kLanes = 4;

[[gnu::always_inline]] inline Lanes Load(const double* p) {
  Lanes v;
  __builtin_memcpy(&v, p, sizeof v);
  return v;
}

[[gnu::always_inline]] inline void Store(double* p, Lanes v) { __builtin_memcpy(p, &v, sizeof v); }

// (v0 + v2) + (v1 + v3).
[[gnu::always_inline]] inline double Sum(Lanes v) {
  const HalfLanes h = __builtin_shufflevector(v, v, 0, 1) + __builtin_shufflevector(v, v, 2, 3);
  return h[0] + h[1];
}

// The stepper's arrays as the pass reads them (IncrementStepper's members of the same names).
struct Pass {
  int padded, zones, dot_rows, rows;
  const double *c, *b, *ra, *rb, *o, *mu, *kg;
  const int* row_zone;
  const double *row_scale, *row_offset;
  double *q, *d, *predictions, *forces;
};

// `steps` steps of the pass. kZones fixes the number of zones at compile time (0: the pass's),
// kDotRows that of observed rows summed in the pass (-1: the pass's), kChunks that of lanes of
// modes (0: the pass's). With kChunks, the state stays in registers from step to step, as the
// predictions and forces of the last K steps always do: a state stored and loaded again at
// every step would put the store's forwarding on its dependency chain.
template <int kZones, int kDotRows, int kChunks>
[[gnu::always_inline]] inline void AdvanceSteps(const Pass& p, int steps, double* observed,
                                                double* forces_out) {
  constexpr int kZ = kZones > 0 ? kZones : kMaxZones;
  constexpr int kR = kDotRows >= 0 ? std::max(kDotRows, 1) : kMaxZones;
  constexpr bool kInRegisters = kChunks > 0;
  const int zones = kZones > 0 ? kZones : p.zones;
  const int dot_rows = kDotRows >= 0 ? kDotRows : p.dot_rows;
  const int padded = kInRegisters ? kChunks * kLanes : p.padded, rows = p.rows;
  const double* __restrict c = p.c, * __restrict b = p.b, * __restrict ra = p.ra, * __restrict rb = p.rb, * __restrict o = p.o;
  double* __restrict q = p.q, * __restrict d = p.d;
  Lanes q_lanes[std::max(kChunks, 1)], d_lanes[std::max(kChunks, 1)];
  if constexpr (kInRegisters) {
    for (int ch = 0; ch < kChunks; ++ch) q_lanes[ch] = Load(q + ch * kLanes);
    for (int ch = 0; ch < kChunks; ++ch) d_lanes[ch] = Load(d + ch * kLanes);
  }
  int row_zone[kMaxZones];
  double row_scale[kMaxZones], row_offset[kMaxZones], kg[kZ];
  for (int j = 0; j < rows; ++j) {
    row_zone[j] = p.row_zone[j], row_scale[j] = p.row_scale[j], row_offset[j] = p.row_offset[j];
  }
  for (int z = 0; z < zones; ++z) kg[z] = p.kg[z];
  double predictions[kLookahead][kZ], forces[kLookahead][kZ], mu[kLookahead][kZ][kZ];
  for (int l = 0; l < kLookahead; ++l) {
    for (int z = 0; z < zones; ++z) {
      predictions[l][z] = p.predictions[l * zones + z];
      forces[l][z] = p.forces[l * zones + z];
      for (int w = 0; w < zones; ++w) mu[l][z][w] = p.mu[(l * zones + z) * zones + w];
    }
  }
  for (int s = 0; s < steps; ++s) {
    // k_z (r_z . q_{n+1} - g_z): the older forces' terms, then the prediction, then the newest
    // force's, so that the chains from each hold as few operations as they can.
    double u[kZ];
    for (int z = 0; z < zones; ++z) {
      double older = 0.0;
      for (int l = kLookahead - 1; l > 0; --l) {
        for (int w = 0; w < zones; ++w) older += mu[l][z][w] * forces[l][w];
      }
      u[z] = predictions[0][z] + older;
      for (int w = 0; w < zones; ++w) u[z] += mu[0][z][w] * forces[0][w];
    }
    // The predictions' two sums (over q and over Δ) kept apart: two chains of half the length.
    Lanes predicted_q[kZ] = {}, predicted_d[kZ] = {}, seen[kR] = {};
    for (int i = 0, ch = 0; i < padded; i += kLanes, ++ch) {
      Lanes q0, di;
      if constexpr (kInRegisters) {
        q0 = q_lanes[ch], di = d_lanes[ch];
      } else {
        q0 = Load(q + i), di = Load(d + i);
      }
      // Δ += b F, then += c q: the state's own chain holds one multiply-add and one add.
      for (int w = 0; w < zones; ++w) di += Load(b + w * padded + i) * forces[0][w];
      di += Load(c + i) * q0;
      const Lanes qi = q0 + di;
      if constexpr (kInRegisters) {
        q_lanes[ch] = qi, d_lanes[ch] = di;
      } else {
        Store(d + i, di), Store(q + i, qi);
      }
      for (int z = 0; z < zones; ++z) {
        predicted_q[z] += Load(ra + z * padded + i) * qi;
        predicted_d[z] += Load(rb + z * padded + i) * di;
      }
      for (int j = 0; j < dot_rows; ++j) seen[j] += Load(o + j * padded + i) * qi;
    }
    for (int l = 0; l + 1 < kLookahead; ++l) {
      for (int z = 0; z < zones; ++z) predictions[l][z] = predictions[l + 1][z];
    }
    for (int l = kLookahead - 1; l > 0; --l) {
      for (int z = 0; z < zones; ++z) forces[l][z] = forces[l - 1][z];
    }
    for (int z = 0; z < zones; ++z) {
      forces[0][z] = std::max(0.0, u[z]);  // 0 when open (or not a number).
      forces_out[s * zones + z] = forces[0][z];
      predictions[kLookahead - 1][z] = Sum(predicted_q[z] + predicted_d[z]) - kg[z];
    }
    for (int j = 0, dot = 0; j < rows; ++j) {
      const int z = row_zone[j];
      observed[s * rows + j] = z >= 0 ? u[z] * row_scale[j] + row_offset[j] : Sum(seen[dot++]);
    }
  }
  if constexpr (kInRegisters) {
    for (int ch = 0; ch < kChunks; ++ch) Store(q + ch * kLanes, q_lanes[ch]);
    for (int ch = 0; ch < kChunks; ++ch) Store(d + ch * kLanes, d_lanes[ch]);
  }
  for (int l = 0; l < kLookahead; ++l) {
    for (int z = 0; z < zones; ++z) {
      p.predictions[l * zones + z] = predictions[l][z];
      p.forces[l * zones + z] = forces[l][z];
    }
  }
}

// The pass of a model with one zone whose state fits kMaxChunks lanes: the instantiation for
// its number of lanes (a fold over 1 .. kMaxChunks).
constexpr int kMaxChunks = 16;  // 64 modes: their state fits AVX-512's 32 registers.

template <int... kChunks>
[[gnu::always_inline]] inline void AdvanceOneZoneIn(std::integer_sequence<int, kChunks...>,
                                                    const Pass& p, int steps, double* observed,
                                                    double* forces) {
  const int chunks = p.padded / kLanes;
  ((chunks == kChunks + 1 ? AdvanceSteps<1, 0, kChunks + 1>(p, steps, observed, forces) : void()),
   ...);
}

// The paper's problem: one zone, the tip read off it, the state in registers.
SHOCKMAP_VECTOR_CLONES void AdvanceOneZone(const Pass& p, int steps, double* observed,
                                           double* forces) {
  AdvanceOneZoneIn(std::make_integer_sequence<int, kMaxChunks>(), p, steps, observed, forces);
}

SHOCKMAP_VECTOR_CLONES void AdvanceAny(const Pass& p, int steps, double* observed, double* forces) {
  AdvanceSteps<0, -1, 0>(p, steps, observed, forces);
}

bool Qualifies(const SceneModalSystem& system, std::span<const Eigen::VectorXd> observed) {
  if (system.Dissipates() || system.HasExternalLoads()) return false;
  const auto& zones = system.Zones();
  if (zones.empty() || zones.size() > kMaxZones || observed.size() > kMaxZones) return false;
  return std::ranges::all_of(zones, [](const ZoneTerm& z) {
    return z.law.normal.IsLinear() && !z.law.normal.HasBoundPenetration() &&
           z.law.normal.stiffness > 0.0 && !z.law.friction;
  });
}

// (1 - dt²ω², 1; -dt²ω², 1) per mode: the step without forces on (q, Δ).
struct Propagator {
  const Eigen::VectorXd& one_c;
  const Eigen::VectorXd& c;
  // [A s]_q and [A s]_Δ.
  void Apply(Eigen::VectorXd& q, Eigen::VectorXd& d) const {
    const Eigen::VectorXd q_next = one_c.cwiseProduct(q) + d;
    d += c.cwiseProduct(q);
    q = q_next;
  }
};

}  // namespace

std::unique_ptr<IncrementStepper> IncrementStepper::For(const SecondOrderSystem& system,
                                                        double dt_s,
                                                        std::span<const Eigen::VectorXd> observed) {
  const auto* modal = dynamic_cast<const SceneModalSystem*>(&system);
  if (modal == nullptr || !Qualifies(*modal, observed)) return nullptr;
  return std::unique_ptr<IncrementStepper>(new IncrementStepper(*modal, dt_s, observed));
}

std::vector<double> IncrementStepper::Padded(const Eigen::VectorXd& v) const {
  std::vector<double> out(static_cast<std::size_t>(padded_), 0.0);
  std::copy(v.begin(), v.end(), out.begin());
  return out;
}

IncrementStepper::IncrementStepper(const SceneModalSystem& system, double dt_s,
                                   std::span<const Eigen::VectorXd> observed)
    : modes_(system.Size()),
      padded_((modes_ + kLanes - 1) / kLanes * kLanes),
      zones_(static_cast<int>(system.Zones().size())),
      dt_(dt_s) {
  const double dt2 = dt_s * dt_s;
  c_ = -dt2 * system.OmegaSquared();
  one_c_ = (1.0 + c_.array()).matrix();
  c_padded_ = Padded(c_);
  const Propagator a{one_c_, c_};
  // The first row of A^K: (α_K, β_K) with [A^K s]_q = α_K q + β_K Δ, from A^T applied K times.
  Eigen::VectorXd alpha = Eigen::VectorXd::Ones(modes_), beta = Eigen::VectorXd::Zero(modes_);
  for (int l = 0; l < kLookahead; ++l) {
    const Eigen::VectorXd alpha_next = alpha.cwiseProduct(one_c_) + beta.cwiseProduct(c_);
    beta += alpha;
    alpha = alpha_next;
  }
  auto append = [&](std::vector<double>& to, const Eigen::VectorXd& v) {
    const std::vector<double> padded = Padded(v);
    to.insert(to.end(), padded.begin(), padded.end());
  };
  for (const ZoneTerm& z : system.Zones()) {
    rows_.push_back(ZoneRow(z, modes_, z.normal_y, z.normal_z));
    const double k = z.law.normal.stiffness;
    k_.push_back(k);
    kg_.push_back(k * z.gap_m);
    append(b_, -dt2 * rows_.back());
    append(ra_, k * rows_.back().cwiseProduct(alpha));
    append(rb_, k * rows_.back().cwiseProduct(beta));
  }
  // μ_l,zw = k_z r_z . [A^l e_w]_q, e_w = (-dt² r_w, -dt² r_w).
  mu_.assign(static_cast<std::size_t>(kLookahead * zones_ * zones_), 0.0);
  for (int w = 0; w < zones_; ++w) {
    Eigen::VectorXd q = -dt2 * rows_[w], d = q;
    for (int l = 0; l < kLookahead; ++l) {
      for (int z = 0; z < zones_; ++z) mu_[(l * zones_ + z) * zones_ + w] = k_[z] * rows_[z].dot(q);
      a.Apply(q, d);
    }
  }
  for (const Eigen::VectorXd& row : observed) {
    assert(row.size() == modes_);
    int zone = -1;
    double sign = 1.0;
    for (int z = 0; z < zones_ && zone < 0; ++z) {
      if (row == rows_[z]) zone = z;
      if (row == -rows_[z]) zone = z, sign = -1.0;
    }
    // row . q = sign (u / k + g), u = k (r . q - g) as the pass computes it.
    row_zone_.push_back(zone);
    row_scale_.push_back(zone >= 0 ? sign / k_[zone] : 0.0);
    row_offset_.push_back(zone >= 0 ? sign * kg_[zone] / k_[zone] : 0.0);
    if (zone < 0) append(dot_rows_padded_, row), ++dot_rows_;
  }
}

void IncrementStepper::DtSquaredAcceleration(Eigen::VectorXd& out) const {
  out = c_.cwiseProduct(Eigen::Map<const Eigen::VectorXd>(q_.data(), modes_));
  for (int w = 0; w < zones_; ++w) out -= (dt_ * dt_ * forces_[w]) * rows_[w];
}

void IncrementStepper::Init(const Eigen::VectorXd& x0, const Eigen::VectorXd& v0) {
  assert(x0.size() == modes_ && v0.size() == modes_);
  steps_ = 0;
  // F_0, and no force before it.
  forces_.assign(static_cast<std::size_t>(kLookahead * zones_), 0.0);
  for (int z = 0; z < zones_; ++z) {
    forces_[z] = std::max(0.0, k_[z] * rows_[z].dot(x0) - kg_[z]);  // As the pass computes it.
  }
  q_ = Padded(x0);
  DtSquaredAcceleration(v_);
  const Eigen::VectorXd d0 = dt_ * v0 - 0.5 * v_;
  d_ = Padded(d0);
  // P_{1-K} .. P_0 of the state continued backwards without forces: P_{l-K} = k (r . [A^l s_0]_q
  // - g).
  predictions_.assign(static_cast<std::size_t>(kLookahead * zones_), 0.0);
  const Propagator a{one_c_, c_};
  Eigen::VectorXd q = x0, d = d0;
  for (int l = 1; l <= kLookahead; ++l) {
    a.Apply(q, d);
    for (int z = 0; z < zones_; ++z) {
      predictions_[(l - 1) * zones_ + z] = k_[z] * rows_[z].dot(q) - kg_[z];
    }
  }
}

void IncrementStepper::Advance(int steps, double* observed, double* forces) {
  const Pass p{padded_,
               zones_,
               dot_rows_,
               Rows(),
               c_padded_.data(),
               b_.data(),
               ra_.data(),
               rb_.data(),
               dot_rows_padded_.data(),
               mu_.data(),
               kg_.data(),
               row_zone_.data(),
               row_scale_.data(),
               row_offset_.data(),
               q_.data(),
               d_.data(),
               predictions_.data(),
               forces_.data()};
  if (zones_ == 1 && dot_rows_ == 0 && padded_ / kLanes <= kMaxChunks) {
    AdvanceOneZone(p, steps, observed, forces);
  } else {
    AdvanceAny(p, steps, observed, forces);
  }
  steps_ += steps;
}

const Eigen::VectorXd& IncrementStepper::X() {
  x_ = Eigen::Map<const Eigen::VectorXd>(q_.data(), modes_);
  return x_;
}

const Eigen::VectorXd& IncrementStepper::V() {
  DtSquaredAcceleration(v_);
  v_ = (Eigen::Map<const Eigen::VectorXd>(d_.data(), modes_) + 0.5 * v_) / dt_;
  return v_;
}

}  // namespace shockmap
