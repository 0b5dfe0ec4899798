#include "core/beam_fe.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace shockmap {
namespace {

Eigen::Matrix4d ElementStiffness(double ei, double h) {
  Eigen::Matrix4d k;
  k << 12, 6 * h, -12, 6 * h,               //
      6 * h, 4 * h * h, -6 * h, 2 * h * h,  //
      -12, -6 * h, 12, -6 * h,              //
      6 * h, 2 * h * h, -6 * h, 4 * h * h;
  return k * (ei / (h * h * h));
}

Eigen::Matrix4d ElementMass(double rho_a, double h) {
  Eigen::Matrix4d m;
  m << 156, 22 * h, 54, -13 * h,              //
      22 * h, 4 * h * h, 13 * h, -3 * h * h,  //
      54, 13 * h, 156, -22 * h,               //
      -13 * h, -3 * h * h, -22 * h, 4 * h * h;
  return m * (rho_a * h / 420.0);
}

std::vector<bool> ConstrainedDofs(int n_nodes, EndCondition at_zero, EndCondition at_length) {
  std::vector<bool> constrained(2 * n_nodes, false);
  auto apply = [&](int node, EndCondition c) {
    if (c == EndCondition::kClamped || c == EndCondition::kPinned) constrained[2 * node] = true;
    if (c == EndCondition::kClamped) constrained[2 * node + 1] = true;
  };
  apply(0, at_zero);
  apply(n_nodes - 1, at_length);
  return constrained;
}

}  // namespace

FeBeamModel AssembleBeam(const BeamProperties& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length) {
  assert(n_elements >= 1);
  const int n_nodes = n_elements + 1;
  const double h = beam.length_m / n_elements;
  const auto constrained = ConstrainedDofs(n_nodes, at_zero, at_length);

  FeBeamModel model;
  model.beam = beam;
  model.n_elements = n_elements;
  std::vector<int> unknown_of(2 * n_nodes, -1);
  for (int g = 0; g < 2 * n_nodes; ++g) {
    if (!constrained[g]) {
      unknown_of[g] = model.Size();
      model.global_dof.push_back(g);
    }
  }

  const Eigen::Matrix4d ke = ElementStiffness(beam.ei_n_m2, h);
  const Eigen::Matrix4d me = ElementMass(beam.rho_a_kg_per_m, h);
  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  for (int e = 0; e < n_elements; ++e) {
    for (int a = 0; a < 4; ++a) {
      const int ia = unknown_of[2 * e + a];
      if (ia < 0) continue;
      for (int b = 0; b < 4; ++b) {
        const int ib = unknown_of[2 * e + b];
        if (ib < 0) continue;
        k_entries.emplace_back(ia, ib, ke(a, b));
        m_entries.emplace_back(ia, ib, me(a, b));
      }
    }
  }
  model.stiffness.resize(model.Size(), model.Size());
  model.mass.resize(model.Size(), model.Size());
  model.stiffness.setFromTriplets(k_entries.begin(), k_entries.end());
  model.mass.setFromTriplets(m_entries.begin(), m_entries.end());
  return model;
}

Eigen::VectorXd FeBeamModel::DeflectionRow(double x_m) const {
  assert(x_m >= 0.0 && x_m <= beam.length_m);
  const double h = beam.length_m / n_elements;
  const int e = std::min(static_cast<int>(std::floor(x_m / h)), n_elements - 1);
  const double s = x_m / h - e;
  // Hermite cubic shape functions on [0, 1] for (w_e, theta_e, w_e+1, theta_e+1).
  const double n[4] = {1 - 3 * s * s + 2 * s * s * s, h * (s - 2 * s * s + s * s * s),
                       3 * s * s - 2 * s * s * s, h * (s * s * s - s * s)};
  Eigen::VectorXd row = Eigen::VectorXd::Zero(Size());
  for (int i = 0; i < Size(); ++i) {
    const int local = global_dof[i] - 2 * e;
    if (local >= 0 && local < 4) row[i] = n[local];
  }
  return row;
}

void AddDeflectionSpring(FeBeamModel& model, int node, double k_n_per_m) {
  if (k_n_per_m == 0.0) return;
  for (int i = 0; i < model.Size(); ++i) {
    if (model.global_dof[i] == 2 * node) {
      model.stiffness.coeffRef(i, i) += k_n_per_m;
      model.springs.push_back({i, k_n_per_m});
    }
  }
}

double StiffnessForm(const FeBeamModel& model, const Eigen::VectorXd& u) {
  Eigen::VectorXd global = Eigen::VectorXd::Zero(2 * (model.n_elements + 1));
  for (int i = 0; i < model.Size(); ++i) global[model.global_dof[i]] = u[i];
  const double h = model.beam.length_m / model.n_elements;
  const double ei_over_h = model.beam.ei_n_m2 / h;
  double sum = 0.0;
  for (int e = 0; e < model.n_elements; ++e) {
    const double psi = (global[2 * e + 2] - global[2 * e]) / h;
    const double a = global[2 * e + 1] - psi;
    const double c = global[2 * e + 3] - psi;
    sum += ei_over_h * (3.0 * (a + c) * (a + c) + (a - c) * (a - c));
  }
  for (const FeBeamModel::Spring& s : model.springs) {
    sum += s.stiffness_n_per_m * u[s.unknown] * u[s.unknown];
  }
  return sum;
}

}  // namespace shockmap
