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

// The sections' ends from the base, the last one at the beam's length.
std::vector<double> SectionEnds(const SectionedBeam& beam) {
  std::vector<double> ends;
  double end = 0.0;
  for (std::size_t i = 0; i + 1 < beam.sections.size(); ++i) {
    end += beam.sections[i].length_m;
    ends.push_back(end);
  }
  ends.push_back(beam.length_m);
  return ends;
}

// Elements per piece: one each, then one at a time to the piece whose elements are longest
// (the first such), until `n_elements` are given.
std::vector<int> ElementsPerPiece(const std::vector<double>& breaks, int n_elements) {
  const std::size_t pieces = breaks.size() - 1;
  std::vector<int> count(pieces, 1);
  for (int given = static_cast<int>(pieces); given < n_elements; ++given) {
    std::size_t longest = 0;
    for (std::size_t p = 1; p < pieces; ++p) {
      if ((breaks[p + 1] - breaks[p]) / count[p] >
          (breaks[longest + 1] - breaks[longest]) / count[longest])
        longest = p;
    }
    ++count[longest];
  }
  return count;
}

// The mesh's pieces, each with the section holding its middle.
std::vector<FeBeamModel::Piece> Pieces(const SectionedBeam& beam, int n_elements) {
  const std::vector<double> breaks = MeshBreaks(beam);
  const std::vector<double> ends = SectionEnds(beam);
  const std::vector<int> count = ElementsPerPiece(breaks, n_elements);
  std::vector<FeBeamModel::Piece> pieces;
  int node = 0;
  for (std::size_t p = 0; p + 1 < breaks.size(); ++p) {
    const double middle = 0.5 * (breaks[p] + breaks[p + 1]);
    std::size_t s = 0;
    while (s + 1 < ends.size() && middle > ends[s]) ++s;
    const BeamSection& section = beam.sections[s];
    pieces.push_back(
        {breaks[p], breaks[p + 1], count[p], node, section.ei_n_m2, section.rho_a_kg_per_m});
    node += count[p];
  }
  return pieces;
}

// The node at the break nearest `height_m`.
int NodeNearest(const std::vector<FeBeamModel::Piece>& pieces, double height_m) {
  int node = 0;
  double distance = std::abs(height_m);
  for (const FeBeamModel::Piece& p : pieces) {
    if (std::abs(p.to_m - height_m) < distance) {
      distance = std::abs(p.to_m - height_m);
      node = p.first_node + p.elements;
    }
  }
  return node;
}

// The piece holding height x: the first that ends at or above it.
const FeBeamModel::Piece& PieceAt(const std::vector<FeBeamModel::Piece>& pieces, double x_m) {
  for (const FeBeamModel::Piece& p : pieces) {
    if (x_m <= p.to_m) return p;
  }
  return pieces.back();
}

}  // namespace

std::vector<double> MeshBreaks(const SectionedBeam& beam) {
  assert(!beam.sections.empty());
  std::vector<double> breaks = SectionEnds(beam);
  breaks.insert(breaks.begin(), 0.0);
  const double tolerance = kSameNodeFraction * beam.length_m;
  for (const BeamPointMass& m : beam.point_masses) {
    const bool at_break = std::ranges::any_of(
        breaks, [&](double b) { return std::abs(b - m.height_m) <= tolerance; });
    if (!at_break) breaks.push_back(m.height_m);
  }
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

FeBeamModel AssembleBeam(const SectionedBeam& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length) {
  assert(n_elements >= static_cast<int>(MeshBreaks(beam).size()) - 1);
  const int n_nodes = n_elements + 1;
  const auto constrained = ConstrainedDofs(n_nodes, at_zero, at_length);

  FeBeamModel model;
  model.pieces = Pieces(beam, n_elements);
  model.n_elements = n_elements;
  std::vector<int> unknown_of(2 * n_nodes, -1);
  for (int g = 0; g < 2 * n_nodes; ++g) {
    if (!constrained[g]) {
      unknown_of[g] = model.Size();
      model.global_dof.push_back(g);
    }
  }

  std::vector<Eigen::Triplet<double>> k_entries, m_entries;
  for (const FeBeamModel::Piece& piece : model.pieces) {
    const double h = piece.ElementLength();
    const Eigen::Matrix4d ke = ElementStiffness(piece.ei_n_m2, h);
    const Eigen::Matrix4d me = ElementMass(piece.rho_a_kg_per_m, h);
    for (int e = piece.first_node; e < piece.first_node + piece.elements; ++e) {
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
  }
  for (const BeamPointMass& m : beam.point_masses) {
    const int node = NodeNearest(model.pieces, m.height_m);
    const int w = unknown_of[2 * node], theta = unknown_of[2 * node + 1];
    if (w >= 0) m_entries.emplace_back(w, w, m.mass_kg);
    if (theta >= 0 && m.rotary_inertia_kg_m2 != 0.0)
      m_entries.emplace_back(theta, theta, m.rotary_inertia_kg_m2);
  }
  model.stiffness.resize(model.Size(), model.Size());
  model.mass.resize(model.Size(), model.Size());
  model.stiffness.setFromTriplets(k_entries.begin(), k_entries.end());
  model.mass.setFromTriplets(m_entries.begin(), m_entries.end());
  return model;
}

FeBeamModel AssembleBeam(const BeamProperties& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length) {
  const SectionedBeam uniform{
      beam.length_m, {{beam.length_m, beam.ei_n_m2, beam.rho_a_kg_per_m}}, {}};
  return AssembleBeam(uniform, n_elements, at_zero, at_length);
}

double FeBeamModel::NodeHeightM(int node) const {
  assert(node >= 0 && node <= n_elements);
  for (const Piece& p : pieces) {
    const int j = node - p.first_node;
    if (j < p.elements) return p.from_m + (p.to_m - p.from_m) * j / p.elements;
  }
  return LengthM();
}

Eigen::VectorXd FeBeamModel::DeflectionRow(double x_m) const {
  assert(x_m >= 0.0 && x_m <= LengthM());
  const Piece& piece = PieceAt(pieces, x_m);
  const double h = piece.ElementLength();
  const double local = (x_m - piece.from_m) / h;
  const int k = std::min(static_cast<int>(std::floor(local)), piece.elements - 1);
  const int e = piece.first_node + k;
  const double s = local - k;
  // Hermite cubic shape functions on [0, 1] for (w_e, theta_e, w_e+1, theta_e+1).
  const double n[4] = {1 - 3 * s * s + 2 * s * s * s, h * (s - 2 * s * s + s * s * s),
                       3 * s * s - 2 * s * s * s, h * (s * s * s - s * s)};
  Eigen::VectorXd row = Eigen::VectorXd::Zero(Size());
  for (int i = 0; i < Size(); ++i) {
    const int dof = global_dof[i] - 2 * e;
    if (dof >= 0 && dof < 4) row[i] = n[dof];
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
  double sum = 0.0;
  for (const FeBeamModel::Piece& piece : model.pieces) {
    const double h = piece.ElementLength();
    const double ei_over_h = piece.ei_n_m2 / h;
    for (int e = piece.first_node; e < piece.first_node + piece.elements; ++e) {
      const double psi = (global[2 * e + 2] - global[2 * e]) / h;
      const double a = global[2 * e + 1] - psi;
      const double c = global[2 * e + 3] - psi;
      sum += ei_over_h * (3.0 * (a + c) * (a + c) + (a - c) * (a - c));
    }
  }
  for (const FeBeamModel::Spring& s : model.springs) {
    sum += s.stiffness_n_per_m * u[s.unknown] * u[s.unknown];
  }
  return sum;
}

}  // namespace shockmap
