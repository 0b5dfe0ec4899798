#pragma once
// A structure with known modes for the structure tests: a chain of n equal masses m joined by
// equal springs k, the first tied to the ground, the last free, moving along each of
// `components` (uncoupled, so that every frequency repeats once per component). Its frequencies
// are omega_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1))), j = 1..n, and the static flexibility
// between masses i and l (1-based) along a component is min(i, l) / k.

#include <Eigen/SparseCore>
#include <cmath>
#include <numbers>
#include <vector>

#include "core/fe_structure.h"

namespace shockmap::testing {

inline FeStructure SpringChain(int n, double k, double m,
                               const std::vector<DofComponent>& components) {
  FeStructure s;
  s.name = "chain";
  std::vector<Eigen::Triplet<double>> kt, mt;
  const int c = static_cast<int>(components.size());
  for (int i = 0; i < n; ++i) {
    s.node_coordinates_m[i + 1] = Eigen::Vector3d(i + 1.0, 0.0, 0.0);
    for (int a = 0; a < c; ++a) {
      const int row = i * c + a;
      s.dofs.push_back({i + 1, components[a]});
      kt.emplace_back(row, row, i + 1 < n ? 2 * k : k);
      if (i + 1 < n) {
        kt.emplace_back(row, row + c, -k);
        kt.emplace_back(row + c, row, -k);
      }
      mt.emplace_back(row, row, m);
    }
  }
  s.stiffness.resize(n * c, n * c);
  s.stiffness.setFromTriplets(kt.begin(), kt.end());
  s.mass.resize(n * c, n * c);
  s.mass.setFromTriplets(mt.begin(), mt.end());
  return s;
}

inline double ChainOmega(int n, double k, double m, int j) {
  return 2.0 * std::sqrt(k / m) * std::sin((2 * j - 1) * std::numbers::pi / (2.0 * (2 * n + 1)));
}

}  // namespace shockmap::testing
