#include "core/scene_structure_modes.h"

#include <numbers>

#include "core/structure_modes.h"

namespace shockmap {
namespace {

constexpr std::array<DofComponent, 3> kTranslations{DofComponent::kUx, DofComponent::kUy,
                                                    DofComponent::kUz};

}  // namespace

Eigen::VectorXd NodeForce(const FeStructure& s, int node, const std::array<double, 3>& d) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(s.Size());
  for (int c = 0; c < 3; ++c) {
    if (const auto row = s.DofIndex(node, kTranslations[c])) f[*row] = d[c];
  }
  return f;
}

Eigen::VectorXd SceneStructureModes::AtNode(int node, const std::array<double, 3>& d) const {
  return basis.shapes.transpose() * NodeForce(*fe, node, d);
}

Eigen::VectorXd SceneStructureModes::Participation(const std::array<double, 3>& d) const {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(fe->Size());
  for (int i = 0; i < fe->Size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (fe->dofs[i].component == kTranslations[c]) r[i] = d[c];
    }
  }
  return basis.shapes.transpose() * (fe->mass * r);
}

SceneStructureModes MakeStructureModes(std::shared_ptr<const FeStructure> fe,
                                       std::optional<double> f_trunc_hz, double ratio,
                                       const std::vector<int>& static_nodes) {
  SceneStructureModes m;
  m.fe = std::move(fe);
  const ModalBasis lowest = LowestStructureModes(*m.fe, 1);
  m.f1_hz = lowest.omega_rad_s[0] / (2.0 * std::numbers::pi);
  m.f_trunc_hz = f_trunc_hz ? *f_trunc_hz : ratio * m.f1_hz;
  m.basis = m.f_trunc_hz >= m.f1_hz ? StructureModesBelow(*m.fe, m.f_trunc_hz) : lowest;
  if (m.basis.NumModes() == 0) m.basis = lowest;
  if (!static_nodes.empty()) {
    std::vector<Eigen::VectorXd> rows;
    for (int node : static_nodes) {
      for (int c = 0; c < 3; ++c) {
        if (const auto row = m.fe->DofIndex(node, kTranslations[c])) {
          rows.push_back(Eigen::VectorXd::Unit(m.fe->Size(), *row));
        }
      }
    }
    m.basis = WithStaticCorrection(m.fe->stiffness, m.fe->mass, m.basis, rows);
  }
  return m;
}

}  // namespace shockmap
