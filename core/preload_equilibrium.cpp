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

// Solves the equilibrium with the zones `active` closed.
Eigen::VectorXd SolveWithActive(const SceneModalSystem& system,
                                const std::vector<std::vector<std::pair<int, double>>>& rows,
                                const std::set<std::size_t>& active) {
  const int n = system.Size();
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < n; ++i) entries.emplace_back(i, i, system.OmegaSquared()[i]);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (const std::size_t z : active) {
    const ZoneTerm& zone = system.Zones()[z];
    for (const auto& [i, ci] : rows[z]) {
      rhs[i] += zone.stiffness_n_per_m * zone.gap_m * ci;
      for (const auto& [j, cj] : rows[z])
        entries.emplace_back(i, j, zone.stiffness_n_per_m * ci * cj);
    }
  }
  Eigen::SparseMatrix<double> a(n, n);
  a.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(a);
  if (ldlt.info() != Eigen::Success || (ldlt.vectorD().array() <= 0.0).any()) {
    throw InputError(
        "zones with a negative gap (preloaded contacts): the model has a rigid-body mode the "
        "contacts do not hold, so it has no static equilibrium; support the beams");
  }
  return ldlt.solve(rhs);
}

}  // namespace

bool HasPreloadedZones(const SceneModalSystem& system) {
  for (const ZoneTerm& z : system.Zones()) {
    if (z.gap_m < 0.0) return true;
  }
  return false;
}

Eigen::VectorXd PreloadEquilibrium(const SceneModalSystem& system) {
  std::vector<std::vector<std::pair<int, double>>> rows;
  std::set<std::size_t> active;
  for (std::size_t z = 0; z < system.Zones().size(); ++z) {
    rows.push_back(ZoneRow(system.Zones()[z]));
    if (system.Zones()[z].gap_m < 0.0) active.insert(z);
  }
  for (int iteration = 0; iteration < kMaxActiveSetIterations; ++iteration) {
    const Eigen::VectorXd x = SolveWithActive(system, rows, active);
    std::set<std::size_t> next;
    for (std::size_t z = 0; z < rows.size(); ++z) {
      if (Penetration(rows[z], system.Zones()[z].gap_m, x) > 0.0) next.insert(z);
    }
    if (next == active) return x;
    active = std::move(next);
  }
  throw InputError(
      "zones with a negative gap (preloaded contacts): the set of closed zones of "
      "the static equilibrium did not settle within " +
      std::to_string(kMaxActiveSetIterations) + " iterations");
}

}  // namespace shockmap
