#include "core/preload_equilibrium.h"

#include <Eigen/SparseCholesky>
#include <set>
#include <vector>

#include "core/input_error.h"

namespace shockmap {
namespace {

constexpr int kMaxActiveSetIterations = 100;

// The zone's row as (coordinate, coefficient) pairs: its penetration is row . x - gap.
std::vector<std::pair<int, double>> ZoneRow(const ZoneTerm& z) {
  std::vector<std::pair<int, double>> row;
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

double Penetration(const std::vector<std::pair<int, double>>& row, double gap,
                   const Eigen::VectorXd& x) {
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
// bracket is exactly 0 and x' is the minimum of the closed set's quadratic.
// Only the lower triangle is assembled: the factorization reads no other (SimplicialLDLT's Lower),
// and each entry's terms are summed in the same order as in the full matrix.
Eigen::VectorXd SolveWithActive(const SceneModalSystem& system,
                                const std::vector<std::vector<std::pair<int, double>>>& rows,
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

// E(x) = 1/2 sum omega_i^2 x_i^2 + sum_z E_z(r_z . x - g_z), E_z the elastic energy of the
// zone's normal law, whose minimum is the equilibrium, and its gradient.
struct Energy {
  const SceneModalSystem& system;
  const std::vector<std::vector<std::pair<int, double>>>& rows;

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

}  // namespace

bool HasPreloadedZones(const SceneModalSystem& system) {
  for (const ZoneTerm& z : system.Zones()) {
    if (z.gap_m < 0.0) return true;
  }
  return false;
}

// Newton's method on the convex energy, damped by backtracking (Armijo) so that the energy
// decreases at every step: the closed set cannot cycle. With linear laws the energy is
// piecewise quadratic, and a full step lands on the minimum of the quadratic of its closed set:
// when that set holds there, it is the equilibrium. A power law's zones need further steps,
// until a full one moves x by a relative 1e-12.
Eigen::VectorXd PreloadEquilibrium(const SceneModalSystem& system) {
  std::vector<std::vector<std::pair<int, double>>> rows;
  for (const ZoneTerm& z : system.Zones()) rows.push_back(ZoneRow(z));
  const Energy energy{system, rows};
  Eigen::VectorXd x = Eigen::VectorXd::Zero(system.Size());
  std::set<std::size_t> closed;
  for (std::size_t z = 0; z < rows.size(); ++z) {
    if (system.Zones()[z].gap_m < 0.0) closed.insert(z);
  }
  for (int iteration = 0; iteration < kMaxActiveSetIterations; ++iteration) {
    Eigen::VectorXd next = SolveWithActive(system, rows, closed, x);
    const Eigen::VectorXd step = next - x;
    const double e0 = energy(x), slope = energy.Gradient(x).dot(step);
    double t = 1.0;
    while (t > 1e-12 && energy(x + t * step) > e0 + 1e-4 * t * slope) t *= 0.5;
    if (t < 1.0) next = x + t * step;
    x = std::move(next);
    const std::set<std::size_t> now = energy.Closed(x);
    if (t == 1.0 && now == closed && Converged(system, closed, step, x)) return x;
    closed = now;
  }
  throw InputError(
      "zones with a negative gap (preloaded contacts): the static equilibrium was "
      "not found within " +
      std::to_string(kMaxActiveSetIterations) + " Newton steps");
}

}  // namespace shockmap
