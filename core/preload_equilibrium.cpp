#include "core/preload_equilibrium.h"

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <optional>
#include <set>
#include <vector>

#include "core/input_error.h"

namespace shockmap {
namespace {

constexpr int kMaxActiveSetIterations = 100;

// A zone's row as (coordinate, coefficient) pairs: its penetration is row . x - gap.
using Row = std::vector<std::pair<int, double>>;

Row ZoneRow(const ZoneTerm& z) {
  Row row;
  auto add = [&](int offset, double sign, const std::vector<double>& phi) {
    if (offset < 0 || sign == 0.0) return;
    for (std::size_t i = 0; i < phi.size(); ++i)
      row.emplace_back(offset + static_cast<int>(i), sign * phi[i]);
  };
  add(z.a_y, z.normal_y, z.phi_a);
  add(z.a_z, z.normal_z, z.phi_a);
  add(z.b_y, -z.normal_y, z.phi_b);
  add(z.b_z, -z.normal_z, z.phi_b);
  return row;
}

std::vector<Row> ZoneRows(const SceneModalSystem& system) {
  std::vector<Row> rows;
  for (const ZoneTerm& z : system.Zones()) rows.push_back(ZoneRow(z));
  return rows;
}

double Penetration(const Row& row, double gap, const Eigen::VectorXd& x) {
  double u = 0.0;
  for (const auto& [i, c] : row) u += c * x[i];
  return u - gap;
}

const NormalLaw& LawOf(const SceneModalSystem& system, std::size_t zone) {
  return system.Zones()[zone].law.normal;
}

// The Newton step's target from x with the zones `active` closed, each zone's force linearized
// at its penetration d0 = r . x - g: F ~ K_t (r . x - g) + (F(d0) - K_t d0), so that
// (diag(omega^2) + sum K_t r r^T) x' = sum (K_t g - (F(d0) - K_t d0)) r. For a linear law the
// bracket is exactly 0 and x' is the minimum of the closed set's quadratic, whatever x.
// Only the lower triangle is assembled: the factorization reads no other (SimplicialLDLT's Lower),
// and each entry's terms are summed in the same order as in the full matrix.
Eigen::VectorXd SolveWithActive(const SceneModalSystem& system, const std::vector<Row>& rows,
                                const std::set<std::size_t>& active, const Eigen::VectorXd& x) {
  const int n = system.Size();
  std::vector<Eigen::Triplet<double>> entries;
  std::size_t count = n;
  for (const std::size_t z : active) count += rows[z].size() * (rows[z].size() + 1) / 2;
  entries.reserve(count);
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, system.OmegaSquared()[i]);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (const std::size_t z : active) {
    const ZoneTerm& zone = system.Zones()[z];
    const NormalLaw& law = zone.law.normal;
    const double d0 = Penetration(rows[z], zone.gap_m, x);
    const double k = law.TangentStiffness(d0);
    const double offset = law.ElasticForce(d0) - k * d0;
    for (const auto& [i, ci] : rows[z]) {
      rhs[i] += (k * zone.gap_m - offset) * ci;
      for (const auto& [j, cj] : rows[z]) {
        if (j <= i) entries.emplace_back(i, j, k * ci * cj);
      }
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>, Eigen::Lower> ldlt(a);
  if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0.0).any()) {
    throw InputError(
        "zones with a negative gap (preloaded contacts): the model has a rigid-body mode the "
        "contacts do not hold, so it has no static equilibrium; support the beams");
  }
  return ldlt.solve(rhs);
}

// The same target for linear laws with every omega^2 > 0, when every zone of `closed` is closed
// at the linearization point (as Minimize's sets are): with R the closed rows, K their
// stiffnesses and D = diag(omega^2), x' = D^-1 R^T mu where (K^-1 + R D^-1 R^T) mu = g
// (Woodbury's identity; mu holds the zones' forces). A dense solve of the closed zones' order
// instead of a sparse one of the modes': other roundings, so it only finds the closed set
// (PreloadEquilibrium). Nothing when the zones' matrix is not positive.
std::optional<Eigen::VectorXd> SolveByCapacitance(const SceneModalSystem& system,
                                                  const std::vector<Row>& rows,
                                                  const std::set<std::size_t>& zones) {
  const Eigen::VectorXd& omega_squared = system.OmegaSquared();
  const std::vector<std::size_t> closed(zones.begin(), zones.end());
  const int m = static_cast<int>(closed.size());
  Eigen::MatrixXd compliance = Eigen::MatrixXd::Zero(system.Size(), m);  // Column a: D^-1 r_a.
  for (int a = 0; a < m; ++a) {
    for (const auto& [i, c] : rows[closed[a]]) compliance(i, a) += c / omega_squared[i];
  }
  Eigen::MatrixXd capacitance(m, m);
  Eigen::VectorXd gaps(m);
  for (int a = 0; a < m; ++a) {
    const ZoneTerm& zone = system.Zones()[closed[a]];
    for (int b = 0; b < m; ++b) {
      double g_ab = 0.0;
      for (const auto& [i, c] : rows[closed[b]]) g_ab += c * compliance(i, a);
      capacitance(a, b) = g_ab;
    }
    capacitance(a, a) += 1.0 / zone.law.normal.stiffness;
    gaps[a] = zone.gap_m;
  }
  const Eigen::LLT<Eigen::MatrixXd> llt(capacitance);
  if (llt.info() != Eigen::Success) return std::nullopt;
  return compliance * llt.solve(gaps);
}

// E(x) = 1/2 sum omega_i^2 x_i^2 + sum_z E_z(r_z . x - g_z), E_z the elastic energy of the
// zone's normal law, whose minimum is the equilibrium, and its gradient.
struct Energy {
  const SceneModalSystem& system;
  const std::vector<Row>& rows;

  double operator()(const Eigen::VectorXd& x) const {
    double e = 0.5 * system.OmegaSquared().dot(x.cwiseProduct(x));
    for (std::size_t z = 0; z < rows.size(); ++z) {
      const double d = Penetration(rows[z], system.Zones()[z].gap_m, x);
      if (d > 0.0) e += LawOf(system, z).Energy(d);
    }
    return e;
  }
  Eigen::VectorXd Gradient(const Eigen::VectorXd& x) const {
    Eigen::VectorXd g = system.OmegaSquared().cwiseProduct(x);
    for (std::size_t z = 0; z < rows.size(); ++z) {
      const double d = Penetration(rows[z], system.Zones()[z].gap_m, x);
      if (d <= 0.0) continue;
      const double force = LawOf(system, z).ElasticForce(d);
      for (const auto& [i, c] : rows[z]) g[i] += force * c;
    }
    return g;
  }
  std::set<std::size_t> Closed(const Eigen::VectorXd& x) const {
    std::set<std::size_t> closed;
    for (std::size_t z = 0; z < rows.size(); ++z) {
      if (Penetration(rows[z], system.Zones()[z].gap_m, x) > 0.0) closed.insert(z);
    }
    return closed;
  }
};

// True when a full Newton step changed x by at most a relative 1e-12, or when every zone of the
// closed set is linear: the step then landed on the minimum of the set's quadratic.
bool Converged(const SceneModalSystem& system, const std::set<std::size_t>& closed,
               const Eigen::VectorXd& step, const Eigen::VectorXd& x) {
  bool linear = true;
  for (const std::size_t z : closed) linear = linear && LawOf(system, z).IsLinear();
  return linear || step.norm() <= 1e-12 * x.norm();
}

// Newton's method on the convex energy from x = 0 with the preloaded zones closed, damped by
// backtracking (Armijo) so that the energy decreases at every step: the closed set cannot
// cycle. With linear laws the energy is piecewise quadratic, and a full step lands on the
// minimum of the quadratic of its closed set: when that set holds there, it is the equilibrium.
// A power law's zones need further steps, until a full one moves x by a relative 1e-12.
// `solve(closed, x)` gives each step's target; nothing when it gives none or when no
// equilibrium is found within kMaxActiveSetIterations steps.
template <class Solve>
std::optional<Eigen::VectorXd> Minimize(const Energy& energy, Solve solve) {
  const SceneModalSystem& system = energy.system;
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.Size());
  std::set<std::size_t> closed;
  for (std::size_t z = 0; z < energy.rows.size(); ++z) {
    if (system.Zones()[z].gap_m < 0.0) closed.insert(z);
  }
  for (int iteration = 0; iteration < kMaxActiveSetIterations; ++iteration) {
    std::optional<Eigen::VectorXd> next = solve(closed, x);
    if (!next) return std::nullopt;
    const Eigen::VectorXd step = *next - x;
    const double e0 = energy(x), slope = energy.Gradient(x).dot(step);
    double t = 1.0;
    while (t > 1e-12 && energy(x + t * step) > e0 + 1e-4 * t * slope) t *= 0.5;
    if (t < 1.0) *next = x + t * step;
    x = std::move(*next);
    const std::set<std::size_t> now = energy.Closed(x);
    if (t == 1.0 && now == closed && Converged(system, closed, step, x)) return x;
    closed = now;
  }
  return std::nullopt;
}

// Linear laws on a model without rigid-body modes: their steps may be solved by capacitance.
bool SolvableByCapacitance(const SceneModalSystem& system) {
  return (system.OmegaSquared().array() > 0.0).all() &&
         std::ranges::all_of(system.Zones(), [](const ZoneTerm& z) {
           return z.law.normal.IsLinear() && z.law.normal.stiffness > 0.0;
         });
}

}  // namespace

bool HasPreloadedZones(const SceneModalSystem& system) {
  for (const ZoneTerm& z : system.Zones()) {
    if (z.gap_m < 0.0) return true;
  }
  return false;
}

Eigen::VectorXd PreloadEquilibriumBySparseSteps(const SceneModalSystem& system) {
  const std::vector<Row> rows = ZoneRows(system);
  auto sparse_step = [&](const std::set<std::size_t>& closed, const Eigen::VectorXd& x) {
    return std::optional(SolveWithActive(system, rows, closed, x));
  };
  if (auto x = Minimize(Energy{system, rows}, sparse_step)) return *std::move(x);
  throw InputError(
      "zones with a negative gap (preloaded contacts): the static equilibrium was "
      "not found within " +
      std::to_string(kMaxActiveSetIterations) + " Newton steps");
}

// With linear laws the equilibrium is the minimum of its closed set's quadratic, which depends
// on that set only (SolveWithActive gives it bit for bit from any x at which the set is
// closed). The set is found by steps solved by capacitance, then the minimum solved once by the
// sparse factorization: the vector the sparse steps end on, at one factorization instead of one
// per step. Should the set not hold at that minimum (a zone at zero penetration to rounding),
// and for power laws, every step is the sparse one.
Eigen::VectorXd PreloadEquilibrium(const SceneModalSystem& system) {
  if (SolvableByCapacitance(system)) {
    const std::vector<Row> rows = ZoneRows(system);
    const Energy energy{system, rows};
    auto capacitance_step = [&](const std::set<std::size_t>& closed, const Eigen::VectorXd&) {
      return SolveByCapacitance(system, rows, closed);
    };
    if (const auto found = Minimize(energy, capacitance_step)) {
      const std::set<std::size_t> closed = energy.Closed(*found);
      Eigen::VectorXd x = SolveWithActive(system, rows, closed, *found);
      if (energy.Closed(x) == closed) return x;
    }
  }
  return PreloadEquilibriumBySparseSteps(system);
}

}  // namespace shockmap
