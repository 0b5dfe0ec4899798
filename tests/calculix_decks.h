#pragma once
// CalculiX input decks of the structures shockmap is checked against (the paper's cantilever
// meshed in beams and in solids, a plate clamped on one edge), with the steps the checks need
// (*FREQUENCY, its matrix storage, a direct implicit transient onto a stop), and readers of
// what ccx prints into jobname.dat. Decks are in SI units.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/beam_properties.h"

namespace shockmap::testing {

// A structured mesh of 20-node bricks (C3D20 or C3D20R) over the box [0,lx] x [0,ly] x [0,lz]. Its
// nodes sit on the grid of half elements; grid point (i, j, k), 0 <= i <= 2 nx, ..., is a node
// unless two or more of i, j, k are odd (no face or body centres).
struct BrickMesh {
  double lx = 1.0, ly = 1.0, lz = 1.0;
  int nx = 1, ny = 1, nz = 1;

  bool HasNode(int i, int j, int k) const;
  int NodeId(int i, int j, int k) const;  // 1-based; numbers skip grid points without a node.
  Eigen::Vector3d Position(int i, int j, int k) const;
  std::map<int, Eigen::Vector3d> Nodes() const;
  // Each brick's 20 nodes in ccx's order: corners of the face z-, of the face z+, mid-edges of
  // the face z-, of the face z+, then the four edges along z.
  std::vector<std::array<int, 20>> Elements() const;
  // The nodes on the face x = 0 (i = 0).
  std::vector<int> NodesAtXZero() const;
};

struct Elastic {
  double young_pa = 2.0e11;
  double poisson = 0.3;
  double density_kg_per_m3 = 7800.0;
};

// A clamped structure as a deck's model part: its nodes, its elements (already as deck lines),
// its material and section, and the clamped nodes (all translations fixed; rotations too when
// the elements carry them).
struct DeckModel {
  std::map<int, Eigen::Vector3d> nodes;
  std::string element_lines;  // "*ELEMENT, ..." blocks, elements in set EALL.
  std::string section_lines;  // "*SOLID SECTION" or "*BEAM SECTION" for EALL.
  Elastic material;
  std::vector<int> clamped;
  int clamped_dofs = 3;   // 3 for solids, 6 for beams (rotations).
  int observed_node = 0;  // The tip or corner node the checks watch and the stop touches.
  int element_count = 0;  // Elements are numbered 1..element_count.
};

// The paper's cantilever (beam: length, EI, rhoA, paper §2.1) along x, bending in y, clamped
// at x = 0. Its section is a rectangle `depth_y` (in the bending plane) by `width_z`; the
// material gives E I_z = EI and rho A = rhoA exactly (E and rho follow from the section), with
// Poisson's ratio 0 so that the section does not stiffen. The observed node is on the tip
// face's edge y = 0, in the middle of its width (the stop below it causes no torsion).
// Transients need C3D20: a nonlinear (NLGEOM) static step on the C3D20R cantilever, one element
// across its section, diverged in ccx 2.20 where C3D20 converged in 3 iterations (measured).
struct CantileverSection {
  double depth_y_m = 0.02;
  double width_z_m = 0.04;  // Wider than deep: bending in z is stiffer, the first mode is in y.
};
DeckModel SolidCantilever(const BeamProperties& beam, const CantileverSection& section,
                          int elements_along, const std::string& element_type = "C3D20R");
// The same in B32R beam elements (3 nodes each; ccx expands them into bricks). The observed node
// is the tip's.
DeckModel BeamCantilever(const BeamProperties& beam, const CantileverSection& section,
                         int elements_along);

// A plate lx by ly by thickness h in 20-node bricks (one through the thickness), clamped on its
// edge x = 0; the observed node is the corner (lx, ly) at mid-thickness.
struct PlateGeometry {
  double lx_m = 0.4, ly_m = 0.3, thickness_m = 0.01;
  Elastic material;  // Steel by default.
};
DeckModel ClampedPlate(const PlateGeometry& plate, int nx, int ny,
                       const std::string& element_type = "C3D20");

// The steps a deck ends with.
struct FrequencyStep {
  int modes = 10;
  bool matrix_storage = false;  // SOLVER=MATRIXSTORAGE: ccx writes .sti .mas .dof and stops.
  bool print_shapes = false;    // *NODE PRINT of every node's displacement for each mode.
};
// A unilateral stop at the observed node: a GAPUNI element to a fixed node at the same place,
// closing when the node moves along `normal` by more than `clearance_m`; stiffness `k` when closed.
struct GapStop {
  Eigen::Vector3d normal{0.0, -1.0, 0.0};
  double clearance_m = 0.0;
  double stiffness_n_per_m = 1e9;
};
// Released from rest from the static deflection under `release_force_n` on the observed node
// (a first, static step), then *DYNAMIC, DIRECT, ALPHA=0 at a fixed step `dt_s` for `end_s`
// with that force removed; prints the observed node's U and the stop's reaction force every
// `print_every` steps. Step times: the static step ends at 1, so the dynamic step's time t is
// printed as 1 + t. (*INITIAL CONDITIONS, TYPE=DISPLACEMENT does not serve: from a 1e-4 m
// first-mode shape ccx 2.20 moved the tip by metres in the first steps of a linear step and
// diverged at the first increment of a nonlinear one; measured on the plate and the cantilever.)
struct TransientStep {
  double dt_s = 1e-4;
  double end_s = 0.01;
  int print_every = 1;
  GapStop stop;
  Eigen::Vector3d release_force_n = Eigen::Vector3d::Zero();
};

// The deck (model, then the step). Node ids of the stop: the largest model node + 1.
std::string FrequencyDeck(const DeckModel& model, const FrequencyStep& step);
std::string TransientDeck(const DeckModel& model, const TransientStep& step);
int StopNodeOf(const DeckModel& model);
// A static step with the force `force_n` on the observed node; prints its U.
std::string StaticDeck(const DeckModel& model, const Eigen::Vector3d& force_n);

void WriteDeck(const std::filesystem::path& inp, const std::string& text);

// What ccx printed into jobname.dat.
// The eigenfrequencies (Hz) of its "E I G E N V A L U E   O U T P U T" table, in order.
std::vector<double> ReadEigenfrequenciesHz(const std::filesystem::path& dat);
// Blocks "<quantity> (..) for set <SET> and time <t>" followed by "node v1 v2 v3" lines.
struct NodeBlock {
  double time = 0.0;
  std::map<int, Eigen::Vector3d> values;
};
// Every block of `quantity` ("displacements", "forces") printed for the node set `set` (as ccx
// prints it, upper case), in order. For a *FREQUENCY step each block is one mode's shape.
std::vector<NodeBlock> ReadNodeBlocks(const std::filesystem::path& dat, const std::string& quantity,
                                      const std::string& set);

// One node's history along a direction from blocks: times and n . value.
struct History {
  std::vector<double> t, value;
};
History HistoryAlong(const std::vector<NodeBlock>& blocks, int node, const Eigen::Vector3d& n);

// The impulse of a stop's reaction (N s) over a history printed every step dt: the sum of its
// values above `threshold_n` times dt (ccx's open GAPUNI pulls with a residual 1e-3 N). dt is
// given: ccx prints times to 7 digits, and the dynamic step's start at 1.
double ContactImpulse(const History& force, double dt, double threshold_n = 0.01);
// The first time the history crosses zero from above (linear between samples), or NaN.
double FirstDownCrossing(const History& h);

}  // namespace shockmap::testing
