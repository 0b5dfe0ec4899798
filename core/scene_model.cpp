#include "core/scene_model.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <numbers>
#include <sstream>
#include <string>

#include "core/beam_fe.h"
#include "core/fe_structure.h"
#include "core/input_error.h"
#include "core/modal_basis.h"
#include "core/modal_basis_cache.h"
#include "core/preload_equilibrium.h"
#include "core/scene_structure_modes.h"
#include "core/structure_modes_cache.h"

namespace shockmap {
namespace {

// Dense eigenvalues up to this size (exact, matches the canonical problem's bound); power
// iteration beyond.
constexpr int kDenseBoundLimit = 600;
constexpr double kPowerIterationMargin = 1e-3;

struct BeamModes {
  FeBeamModel fe;
  ModalBasis basis;
  double f_trunc_hz = 0.0;
  Eigen::VectorXd participation;  // Phi^T M r, r the unit translation of the deflections.

  int N() const { return basis.NumModes(); }
  std::vector<double> At(double height_m) const {
    const Eigen::VectorXd phi = basis.shapes.transpose() * fe.DeflectionRow(height_m);
    return {phi.data(), phi.data() + phi.size()};
  }
};

// The truncation of one beam: its own, or the solver's; absolute, or a ratio of f1.
struct Truncation {
  std::optional<double> hz;
  double ratio = 0.0;

  // A beam's or a structure's.
  template <typename Part>
  static Truncation Of(const Part& b, const SceneSolver& solver) {
    if (b.f_trunc_hz) return {b.f_trunc_hz, 0.0};
    if (b.r_ftrunc) return {std::nullopt, *b.r_ftrunc};
    if (solver.f_trunc_hz) return {solver.f_trunc_hz, 0.0};
    return {std::nullopt, solver.r_ftrunc};
  }
  double Hz(double f1_hz) const { return hz ? *hz : ratio * f1_hz; }
};

// Beams with equal keys have one FE model: the key names everything AssembleSceneBeam reads.
std::string ModelKey(const SceneBeam& b) {
  std::ostringstream key;
  key.precision(17);
  key << b.length_m << ' ' << b.ei_n_m2 << ' ' << b.rho_a_kg_per_m << ' ' << b.n_elements << ' '
      << ToString(b.at_zero) << ' ' << ToString(b.at_length) << ' ' << b.spring_at_zero_n_per_m
      << ' ' << b.spring_at_length_n_per_m;
  if (!b.sections.empty()) key << " sections";
  for (const BeamSection& s : b.sections)
    key << ' ' << s.length_m << ' ' << s.ei_n_m2 << ' ' << s.rho_a_kg_per_m;
  if (!b.point_masses.empty()) key << " point_masses";
  for (const BeamPointMass& m : b.point_masses)
    key << ' ' << m.height_m << ' ' << m.mass_kg << ' ' << m.rotary_inertia_kg_m2;
  return key.str();
}

// Beams with equal keys share one modal basis.
std::string BasisKey(const SceneBeam& b, const Truncation& t,
                     const std::vector<double>& static_heights) {
  std::ostringstream key;
  key.precision(17);
  key << ModelKey(b) << ' ' << (t.hz ? "hz " : "ratio ") << (t.hz ? *t.hz : t.ratio);
  for (double h : static_heights) key << ' ' << h;
  return key.str();
}

// The lowest frequency of a deforming mode: a beam free at both ends also has two rigid-body
// modes at zero frequency (translation, rotation), which are kept but do not set the scale.
// `omega_rad_s`: every mode of the beam, ascending; the lowest three decide.
double FirstElasticFrequencyHz(const Eigen::VectorXd& omega_rad_s) {
  const int lowest = std::min<int>(3, static_cast<int>(omega_rad_s.size()));
  const double scale = omega_rad_s[lowest - 1];
  for (int i = 0; i < lowest; ++i) {
    if (omega_rad_s[i] > 1e-6 * scale) return omega_rad_s[i] / (2.0 * std::numbers::pi);
  }
  return scale / (2.0 * std::numbers::pi);
}

BeamModes MakeModes(const SceneBeam& b, const Truncation& truncation,
                    const std::vector<double>& static_heights) {
  BeamModes m;
  m.fe = AssembleSceneBeam(b);
  // One eigensolution (per mesh and thread) gives the first elastic frequency and the
  // truncated basis.
  const std::shared_ptr<const ModalBasis> solved = AllModesCached(ModelKey(b), m.fe);
  const ModalBasis& all = *solved;
  const double f1 = FirstElasticFrequencyHz(all.omega_rad_s);
  m.f_trunc_hz = truncation.Hz(f1);
  m.basis = ModesBelow(all, m.f_trunc_hz);
  if (m.basis.NumModes() == 0) m.basis = FirstModes(all, 1);
  if (!static_heights.empty()) {
    std::vector<Eigen::VectorXd> rows;
    for (double h : static_heights) rows.push_back(m.fe.DeflectionRow(h));
    m.basis = WithStaticCorrection(m.fe, m.basis, rows);
  }
  // Rigid-body modes have no stiffness: the solver's round-off would otherwise give them one.
  for (double& w : m.basis.omega_rad_s) {
    if (w < 1e-6 * 2.0 * std::numbers::pi * f1) w = 0.0;
  }
  Eigen::VectorXd translation = Eigen::VectorXd::Zero(m.fe.Size());
  for (int i = 0; i < m.fe.Size(); ++i) translation[i] = m.fe.global_dof[i] % 2 == 0 ? 1.0 : 0.0;
  m.participation = m.basis.shapes.transpose() * (m.fe.mass * translation);
  return m;
}

// Sorts `values` ascending and keeps one of each.
template <typename T>
void SortDistinct(std::vector<T>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

// Distinct heights of the zones touching each beam, when static correction is asked.
std::vector<std::vector<double>> StaticHeights(const Scene& scene) {
  std::vector<std::vector<double>> heights(scene.beams.size());
  if (!scene.solver.static_correction) return heights;
  for (const SceneZone& z : scene.zones) {
    if (z.beam_a >= 0) heights[z.beam_a].push_back(z.height_m);
    if (z.beam_b >= 0) heights[z.beam_b].push_back(z.height_m);
  }
  for (auto& h : heights) SortDistinct(h);
  return heights;
}

// The distinct nodes of the zones at each structure's nodes, when static correction is asked.
std::vector<std::vector<int>> StaticNodes(const Scene& scene) {
  std::vector<std::vector<int>> nodes(scene.structures.size());
  if (!scene.solver.static_correction) return nodes;
  for (const SceneZone& z : scene.zones) {
    if (z.structure_a >= 0) nodes[z.structure_a].push_back(z.node_a);
    if (z.structure_b >= 0) nodes[z.structure_b].push_back(z.node_b);
  }
  for (auto& n : nodes) SortDistinct(n);
  return nodes;
}

// Where each beam's modes sit in the scene's coordinates: beam b's block in direction d (y, z)
// starts at offset[b] + d * modes[b]->N(); each structure's one block follows the beams'.
struct Layout {
  int dirs = 1;
  int n = 0;
  std::vector<std::shared_ptr<const BeamModes>> modes;
  std::vector<int> offset;
  std::vector<SceneStructureModes> structures;
  std::vector<int> structure_offset;
  int distinct_bases = 0;

  // -1 when the direction is absent (planar scenes).
  int Block(int beam, int direction) const {
    return direction < dirs ? offset[beam] + direction * modes[beam]->N() : -1;
  }
  int Block(std::size_t beam, int direction) const {
    return Block(static_cast<int>(beam), direction);
  }
};

// One basis per distinct beam, shared by identical ones, and the blocks in beam order.
Layout LayOut(const Scene& scene) {
  Layout layout;
  layout.dirs = scene.Directions();
  std::map<std::string, std::shared_ptr<const BeamModes>> cache;
  const auto static_heights = StaticHeights(scene);
  for (std::size_t i = 0; i < scene.beams.size(); ++i) {
    const SceneBeam& b = scene.beams[i];
    const Truncation truncation = Truncation::Of(b, scene.solver);
    auto& slot = cache[BasisKey(b, truncation, static_heights[i])];
    if (!slot) {
      slot = std::make_shared<const BeamModes>(MakeModes(b, truncation, static_heights[i]));
    }
    layout.modes.push_back(slot);
    layout.offset.push_back(layout.n);
    layout.n += layout.dirs * slot->N();
  }
  layout.distinct_bases = static_cast<int>(cache.size());
  const auto static_nodes = StaticNodes(scene);
  for (std::size_t i = 0; i < scene.structures.size(); ++i) {
    const SceneStructure& s = scene.structures[i];
    const Truncation truncation = Truncation::Of(s, scene.solver);
    layout.structures.push_back(
        StructureModesCached(s.fe, truncation.hz, truncation.ratio, static_nodes[i]));
    layout.structure_offset.push_back(layout.n);
    layout.n += layout.structures.back().N();
  }
  layout.distinct_bases += static_cast<int>(scene.structures.size());
  return layout;
}

Eigen::VectorXd Frequencies(const Layout& layout) {
  Eigen::VectorXd omega(layout.n);
  for (std::size_t b = 0; b < layout.modes.size(); ++b) {
    for (int d = 0; d < layout.dirs; ++d) {
      omega.segment(layout.Block(b, d), layout.modes[b]->N()) = layout.modes[b]->basis.omega_rad_s;
    }
  }
  for (std::size_t s = 0; s < layout.structures.size(); ++s) {
    omega.segment(layout.structure_offset[s], layout.structures[s].N()) =
        layout.structures[s].basis.omega_rad_s;
  }
  return omega;
}

// The highest truncation, or the highest mode kept when static correction modes lie above it.
double HighestTruncationHz(const Layout& layout) {
  double f_trunc_max = 0.0;
  for (const auto& m : layout.modes) {
    f_trunc_max = std::max({f_trunc_max, m->f_trunc_hz, m->basis.HighestFrequencyHz()});
  }
  for (const auto& s : layout.structures) {
    f_trunc_max = std::max({f_trunc_max, s.f_trunc_hz, s.basis.HighestFrequencyHz()});
  }
  return f_trunc_max;
}

// 2 xi_i Omega_i per coordinate: alpha for mass-proportional damping (C = alpha M), or from
// the ratios given per mode.
std::optional<Eigen::VectorXd> ModalDamping(const Scene& scene, const Layout& layout,
                                            const Eigen::VectorXd& omega) {
  if (!scene.modal_damping) return std::nullopt;
  const auto& md = *scene.modal_damping;
  Eigen::VectorXd damping = Eigen::VectorXd::Constant(layout.n, md.mass_proportional_per_s);
  if (md.ratios.empty()) return damping;
  for (std::size_t b = 0; b < layout.modes.size(); ++b) {
    for (int d = 0; d < layout.dirs; ++d) {
      for (int i = 0; i < layout.modes[b]->N(); ++i) {
        const double xi = md.ratios[std::min<std::size_t>(i, md.ratios.size() - 1)];
        const int k = layout.Block(b, d) + i;
        damping[k] = 2.0 * xi * omega[k];
      }
    }
  }
  for (std::size_t s = 0; s < layout.structures.size(); ++s) {
    for (int i = 0; i < layout.structures[s].N(); ++i) {
      const double xi = md.ratios[std::min<std::size_t>(i, md.ratios.size() - 1)];
      const int k = layout.structure_offset[s] + i;
      damping[k] = 2.0 * xi * omega[k];
    }
  }
  return damping;
}

std::vector<double> Values(const Eigen::VectorXd& v) { return {v.data(), v.data() + v.size()}; }

// The tangent of a zone at a node: x × n normalized, or y × n when n lies along x.
std::array<double, 3> NodeZoneTangent(const std::array<double, 3>& n) {
  std::array<double, 3> t{0.0, -n[2], n[1]};
  if (std::hypot(t[1], t[2]) < 1e-12) t = {n[2], 0.0, -n[0]};
  const double norm = std::hypot(t[0], t[1], t[2]);
  for (double& c : t) c /= norm;
  return t;
}

// One side of a zone at a node in the zone's frame: a structure's node, or a beam at the zone's
// height (its y and z blocks weighted by the normal's and the tangent's y and z components).
std::vector<FrameSegment> FrameSide(const Layout& layout, int beam, int structure, int node,
                                    double height_m, const std::array<double, 3>& n,
                                    const std::array<double, 3>& t) {
  if (structure >= 0) {
    const SceneStructureModes& m = layout.structures[structure];
    return {
        {layout.structure_offset[structure], Values(m.AtNode(node, n)), Values(m.AtNode(node, t))}};
  }
  if (beam < 0) return {};
  const std::vector<double> phi = layout.modes[beam]->At(height_m);
  std::vector<FrameSegment> side;
  for (int d = 0; d < layout.dirs; ++d) {
    FrameSegment s{layout.Block(beam, d), phi, phi};
    for (double& v : s.normal) v *= n[1 + d];
    for (double& v : s.tangent) v *= t[1 + d];
    side.push_back(std::move(s));
  }
  return side;
}

// A zone with a side at a structure's node, in its own frame (core/contact_stations.h).
ZoneTerm NodeZoneTerm(const SceneZone& z, const Layout& layout) {
  ZoneTerm t;
  const std::array<double, 3> n = *z.normal_xyz, tangent = NodeZoneTangent(n);
  t.frame_a = FrameSide(layout, z.beam_a, z.structure_a, z.node_a, z.height_m, n, tangent);
  t.frame_b = FrameSide(layout, z.beam_b, z.structure_b, z.node_b, z.height_m, n, tangent);
  t.normal_y = 1.0, t.normal_z = 0.0;
  t.gap_m = z.gap_m;
  t.law = z.Law();
  return t;
}

std::vector<ZoneTerm> ZoneTerms(const Scene& scene, const Layout& layout) {
  std::vector<ZoneTerm> zones;
  for (const auto& z : scene.zones) {
    if (z.AtNode()) {
      zones.push_back(NodeZoneTerm(z, layout));
      continue;
    }
    ZoneTerm t;
    t.a_y = layout.Block(z.beam_a, 0);
    t.a_z = layout.Block(z.beam_a, 1);
    t.phi_a = layout.modes[z.beam_a]->At(z.height_m);
    if (z.beam_b >= 0) {
      t.b_y = layout.Block(z.beam_b, 0);
      t.b_z = layout.Block(z.beam_b, 1);
      t.phi_b = layout.modes[z.beam_b]->At(z.height_m);
    }
    t.normal_y = z.normal_y;
    t.normal_z = layout.dirs == 2 ? z.normal_z : 0.0;
    t.gap_m = z.gap_m;
    t.law = z.Law();
    if (layout.dirs == 1) t.law.friction.reset();  // No tangential motion in a planar scene.
    zones.push_back(std::move(t));
  }
  return zones;
}

// Base motion loads every beam through its participation; a point force through its modes at
// the force's height.
std::vector<TimeLoad> TimeLoads(const Scene& scene, const Layout& layout) {
  std::vector<TimeLoad> loads;
  if (scene.base_motion) {
    TimeLoad base;
    base.base = &*scene.base_motion;
    base.shape = Eigen::VectorXd::Zero(layout.n);
    const double dir[2] = {scene.base_motion->dir_y, scene.base_motion->dir_z};
    for (std::size_t b = 0; b < layout.modes.size(); ++b) {
      for (int d = 0; d < layout.dirs; ++d) {
        base.shape.segment(layout.Block(b, d), layout.modes[b]->N()) =
            dir[d] * layout.modes[b]->participation;
      }
    }
    // -phi^T M r a(t), r the support's unit motion along (0, dir_y, dir_z) on every
    // translational DOF (one rigid support).
    for (std::size_t s = 0; s < layout.structures.size(); ++s) {
      base.shape.segment(layout.structure_offset[s], layout.structures[s].N()) =
          layout.structures[s].Participation({0.0, dir[0], dir[1]});
    }
    loads.push_back(std::move(base));
  }
  for (const auto& f : scene.static_forces) {
    TimeLoad load;
    load.point_force = &f;
    load.shape = Eigen::VectorXd::Zero(layout.n);
    const auto phi = layout.modes[f.beam]->At(f.height_m);
    const double dir[2] = {f.dir_y, f.dir_z};
    for (int d = 0; d < layout.dirs; ++d) {
      for (std::size_t i = 0; i < phi.size(); ++i) {
        load.shape[layout.Block(f.beam, d) + static_cast<int>(i)] = dir[d] * phi[i];
      }
    }
    loads.push_back(std::move(load));
  }
  return loads;
}

// The coordinate of `mode` (1-based) that gives its largest deflection node the value tip_m, as
// a displacement output at that node's height reads it.
double ModeCoordinate(const BeamModes& m, int mode, double tip_m) {
  const Eigen::VectorXd shape = m.basis.shapes.col(mode - 1);
  int node = 0;
  double largest = 0.0;
  for (int i = 0; i < m.fe.Size(); ++i) {
    if (m.fe.global_dof[i] % 2 == 0 && std::abs(shape[i]) > largest) {
      largest = std::abs(shape[i]);
      node = m.fe.global_dof[i] / 2;
    }
  }
  return tip_m / m.At(m.fe.NodeHeightM(node))[mode - 1];
}

// A structure's initial state: a retained mode scaled so that the node moves tip_m along d
// (none when the mode is not retained, as a beam's); q_i = phi_i(node, d) F / omega_i^2, the
// static deflection under F along d at the node in the retained basis (exact there with static
// correction); and a uniform velocity along d.
void AddStructureInitialState(const InitialStateEffect& s, const Layout& layout,
                              SceneModel& model) {
  const SceneStructureModes& m = layout.structures[s.structure];
  const int offset = layout.structure_offset[s.structure];
  if (s.tip_m != 0.0 && s.mode - 1 < m.N()) {
    const double at_node = m.AtNode(s.node, s.direction_xyz)[s.mode - 1];
    if (std::abs(at_node) <= 1e-9 * m.basis.shapes.col(s.mode - 1).cwiseAbs().maxCoeff()) {
      throw InputError("effects.initial_state: mode " + std::to_string(s.mode) +
                       " of structure \"" + m.fe->name + "\" does not move node " +
                       std::to_string(s.node) +
                       " along the direction given (less than 1e-9 of its largest DOF); give "
                       "another node, direction or mode");
    }
    model.x0[offset + s.mode - 1] = s.tip_m / at_node;
  }
  if (s.static_force_n != 0.0) {
    const Eigen::VectorXd phi = m.AtNode(s.node, s.direction_xyz);
    model.x0.segment(offset, m.N()) +=
        (s.static_force_n * phi.array() / m.basis.omega_rad_s.array().square()).matrix();
  }
  if (s.velocity_m_s != 0.0) {
    model.v0.segment(offset, m.N()) += s.velocity_m_s * m.Participation(s.direction_xyz);
  }
}

// The declared initial state, over the static equilibrium of the preloaded zones if any.
void SetInitialState(const Scene& scene, const Layout& layout, SceneModel& model) {
  model.x0 = HasPreloadedZones(*model.system) ? PreloadEquilibrium(*model.system)
                                              : Eigen::VectorXd::Zero(layout.n);
  model.v0 = Eigen::VectorXd::Zero(layout.n);
  for (const auto& s : scene.initial_state) {
    if (s.structure >= 0) {
      AddStructureInitialState(s, layout, model);
      continue;
    }
    const BeamModes& m = *layout.modes[s.beam];
    const int offset = layout.Block(s.beam, s.direction);
    if (s.tip_m != 0.0 && s.mode - 1 < m.N()) {
      model.x0[offset + s.mode - 1] = ModeCoordinate(m, s.mode, s.tip_m);
    }
    if (s.static_force_n != 0.0) {
      // q_i = phi_i(h) F / omega_i^2: the static deflection projected on the retained modes
      // (exact at the zones' heights with static correction).
      const auto phi = m.At(s.height_m);
      for (int i = 0; i < m.N(); ++i) {
        assert(m.basis.omega_rad_s[i] > 0.0 && "a static load needs a supported beam");
        model.x0[offset + i] += phi[i] * s.static_force_n / std::pow(m.basis.omega_rad_s[i], 2);
      }
    }
    if (s.velocity_m_s != 0.0) {
      model.v0.segment(offset, m.N()) += s.velocity_m_s * m.participation;
    }
  }
}

// The observed displacements, and per direction the momentum of all beams.
void SetRows(const Scene& scene, const Layout& layout, SceneModel& model) {
  for (const auto& o : scene.outputs.displacements) {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(layout.n);
    if (o.structure >= 0) {
      const SceneStructureModes& m = layout.structures[o.structure];
      row.segment(layout.structure_offset[o.structure], m.N()) = m.AtNode(o.node, o.direction_xyz);
      model.observed_rows.push_back(std::move(row));
      continue;
    }
    const auto phi = layout.modes[o.beam]->At(o.height_m);
    const int offset = layout.Block(o.beam, o.direction);
    for (std::size_t i = 0; i < phi.size(); ++i) row[offset + static_cast<int>(i)] = phi[i];
    model.observed_rows.push_back(std::move(row));
  }
  for (int d = 0; d < layout.dirs; ++d) {
    Eigen::VectorXd row = Eigen::VectorXd::Zero(layout.n);
    for (std::size_t b = 0; b < layout.modes.size(); ++b)
      row.segment(layout.Block(b, d), layout.modes[b]->N()) = layout.modes[b]->participation;
    for (std::size_t s = 0; s < layout.structures.size(); ++s) {
      row.segment(layout.structure_offset[s], layout.structures[s].N()) =
          layout.structures[s].Participation({0.0, d == 0 ? 1.0 : 0.0, d == 1 ? 1.0 : 0.0});
    }
    model.momentum_rows.push_back(std::move(row));
  }
}

}  // namespace

double SharpOmegaSquared(const SceneModalSystem& system, std::span<const double> normal_stiffness) {
  const int n = system.Size();
  // Power iteration approaches the top of the spectrum from below; the margin keeps the bound
  // on the safe side (checked against the dense solver in the tests).
  if (n > kDenseBoundLimit) {
    return (1.0 + kPowerIterationMargin) * system.StiffestOmegaSquared(normal_stiffness);
  }
  Eigen::MatrixXd k = system.OmegaSquared().asDiagonal();
  for (std::size_t i = 0; i < system.Zones().size(); ++i) {
    const ZoneTerm& z = system.Zones()[i];
    const Eigen::VectorXd r = ZoneRow(z, n, z.normal_y, z.normal_z);
    k.noalias() += normal_stiffness[i] * r * r.transpose();
    if (!z.law.friction) continue;
    const Eigen::VectorXd t = ZoneRow(z, n, -z.normal_z, z.normal_y);
    k.noalias() += z.law.friction->tangential_stiffness_n_per_m * t * t.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(k, Eigen::EigenvaluesOnly);
  return eig.eigenvalues().maxCoeff();
}

SectionedBeam SectionsOf(const SceneBeam& b) {
  if (!b.sections.empty()) return {b.length_m, b.sections, b.point_masses};
  return {b.length_m, {{b.length_m, b.ei_n_m2, b.rho_a_kg_per_m}}, b.point_masses};
}

FeBeamModel AssembleSceneBeam(const SceneBeam& b) {
  FeBeamModel fe = AssembleBeam(SectionsOf(b), b.n_elements, b.at_zero, b.at_length);
  AddDeflectionSpring(fe, 0, b.spring_at_zero_n_per_m);
  AddDeflectionSpring(fe, b.n_elements, b.spring_at_length_n_per_m);
  return fe;
}

double LocalBendingStiffness(const SceneBeam& beam, double height_m) {
  const FeBeamModel fe = AssembleSceneBeam(beam);
  const Eigen::VectorXd row = fe.DeflectionRow(height_m);
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(fe.stiffness);
  return 1.0 / row.dot(ldlt.solve(row));
}

SceneModel BuildSceneModel(const Scene& scene) {
  const Layout layout = LayOut(scene);
  SceneModel model;
  model.beam_offset = layout.offset;
  for (const auto& m : layout.modes) model.modes_per_beam.push_back(m->N());
  for (const auto& s : layout.structures) model.modes_per_structure.push_back(s.N());
  model.distinct_bases = layout.distinct_bases;

  const Eigen::VectorXd omega = Frequencies(layout);
  model.system =
      std::make_unique<SceneModalSystem>(omega, ModalDamping(scene, layout, omega),
                                         ZoneTerms(scene, layout), TimeLoads(scene, layout));
  SetInitialState(scene, layout, model);
  SetRows(scene, layout, model);

  model.bounds.dt_paper_s = 1.0 / (4.0 * HighestTruncationHz(layout));
  model.bounds.omega_max_rad_s =
      std::sqrt(SharpOmegaSquared(*model.system, model.system->Contacts().BoundStiffnesses()));
  model.bounds.dt_sharp_s = 2.0 / model.bounds.omega_max_rad_s;
  return model;
}

}  // namespace shockmap
