#pragma once
// Euler-Bernoulli beam finite elements: Hermite cubic deflection, consistent mass (paper eq. 4),
// element by element along a beam of sections and point masses (core/beam_sections.h).

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

#include "core/beam_properties.h"
#include "core/beam_sections.h"
#include "core/end_condition.h"

namespace shockmap {

// A point mass closer than this fraction of the beam's length to a section's end (or to another
// point mass) sits at that node.
inline constexpr double kSameNodeFraction = 1e-6;

// Assembled beam with the constrained degrees of freedom removed. Node j (from the base, at
// height 0) carries deflection w_j (m) and rotation theta_j (rad). Unknowns are the free degrees
// of freedom in node order.
struct FeBeamModel {
  // The mesh between two consecutive breaks (MeshBreaks): `elements` equal elements of one
  // section's EI and rho A, joining nodes first_node .. first_node + elements.
  struct Piece {
    double from_m = 0.0, to_m = 0.0;
    int elements = 0;
    int first_node = 0;
    double ei_n_m2 = 0.0;
    double rho_a_kg_per_m = 0.0;

    double ElementLength() const { return (to_m - from_m) / elements; }
  };
  std::vector<Piece> pieces;  // From the base up.
  int n_elements = 0;
  Eigen::SparseMatrix<double> mass;       // kg (and kg m, kg m^2 for rotational terms)
  Eigen::SparseMatrix<double> stiffness;  // N/m (and N, N m)
  std::vector<int> global_dof;            // unknown index -> global dof 2*node + {0: w, 1: theta}
  // Grounded springs on deflections (AddDeflectionSpring), already in `stiffness`.
  struct Spring {
    int unknown = 0;
    double stiffness_n_per_m = 0.0;
  };
  std::vector<Spring> springs;

  int Size() const { return static_cast<int>(global_dof.size()); }
  double LengthM() const { return pieces.back().to_m; }
  // Height of node j (m). Precondition: 0 <= j <= n_elements.
  double NodeHeightM(int node) const;
  // Row r with r . u = deflection at abscissa x (m), from the Hermite shape functions.
  // Precondition: 0 <= x <= L.
  Eigen::VectorXd DeflectionRow(double x_m) const;
};

// The heights where the mesh of `beam` has a node between pieces, ascending from 0 to
// length_m: the sections' ends and the point masses' heights (one within kSameNodeFraction of
// the length of a break already there is that break). Each piece between two needs at least
// one element.
std::vector<double> MeshBreaks(const SectionedBeam& beam);

// `n_elements` elements over the pieces between MeshBreaks, each piece given its share so that
// the longest element is as short as it can be (a uniform beam: n_elements equal elements);
// element matrices per section, point masses (and their rotary inertia) on their node's
// deflection (and rotation). Precondition: n_elements >= MeshBreaks(beam).size() - 1.
FeBeamModel AssembleBeam(const SectionedBeam& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length);

// The uniform beam: one section.
FeBeamModel AssembleBeam(const BeamProperties& beam, int n_elements, EndCondition at_zero,
                         EndCondition at_length);

// Adds a grounded spring of stiffness k (N/m) on the deflection of `node`, when k != 0 and the
// deflection is not constrained.
void AddDeflectionSpring(FeBeamModel& model, int node, double k_n_per_m);

// u^T K u, summed element by element in the chord-relative rotations a = theta_1 - psi,
// c = theta_2 - psi (psi = (w_2 - w_1) / h) as (EI / h)(3 (a + c)^2 + (a - c)^2), plus the
// springs' k w^2: a sum of non-negative terms, accurate to about eps n_elements^2 where the
// assembled product loses eps |K| |u| to cancellation (the lowest modes of a fine mesh).
double StiffnessForm(const FeBeamModel& model, const Eigen::VectorXd& u);

}  // namespace shockmap
