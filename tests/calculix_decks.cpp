#include "tests/calculix_decks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace shockmap::testing {
namespace {

// Corners of the reference brick in ccx's order, as (i, j, k) offsets of 0 or 2 half steps.
constexpr int kCorner[8][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0},
                               {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2}};
// Mid-edge nodes 9-20: the corners each edge joins.
constexpr int kEdge[12][2] = {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {4, 5}, {5, 6},
                              {6, 7}, {7, 4}, {0, 4}, {1, 5}, {2, 6}, {3, 7}};

std::string Number(double v) { return fmt::format("{:.15g}", v); }

std::string NodeLines(const std::map<int, Eigen::Vector3d>& nodes) {
  std::string text = "*NODE, NSET=NALL\n";
  for (const auto& [id, x] : nodes)
    text += fmt::format("{}, {}, {}, {}\n", id, Number(x.x()), Number(x.y()), Number(x.z()));
  return text;
}

// Ids in lines of at most 8, as ccx's set and element cards want them.
std::string IdLines(const std::vector<int>& ids) {
  std::string text;
  for (std::size_t i = 0; i < ids.size(); ++i)
    text += std::to_string(ids[i]) + ((i + 1) % 8 == 0 || i + 1 == ids.size() ? ",\n" : ", ");
  return text;
}

std::string ModelLines(const DeckModel& model) {
  std::string text =
      "*HEADING\nshockmap peer check\n" + NodeLines(model.nodes) + model.element_lines +
      "*NSET, NSET=CLAMP\n" + IdLines(model.clamped) +
      fmt::format("*NSET, NSET=OBSERVED\n{},\n", model.observed_node) +
      "*MATERIAL, NAME=M\n*ELASTIC\n" +
      fmt::format("{}, {}\n", Number(model.material.young_pa), Number(model.material.poisson)) +
      "*DENSITY\n" + Number(model.material.density_kg_per_m3) + "\n" + model.section_lines;
  text += fmt::format("*BOUNDARY\nCLAMP, 1, {}\n", model.clamped_dofs);
  return text;
}

std::string BrickElementLines(const BrickMesh& mesh, const std::string& element_type) {
  std::string text = "*ELEMENT, TYPE=" + element_type + ", ELSET=EALL\n";
  int id = 1;
  for (const std::array<int, 20>& nodes : mesh.Elements()) {
    text += std::to_string(id++);
    for (int i = 0; i < 20; ++i) text += (i == 15 ? ",\n" : ", ") + std::to_string(nodes[i]);
    text += "\n";
  }
  return text;
}

Elastic CantileverMaterial(const BeamProperties& beam, const CantileverSection& section) {
  const double area = section.depth_y_m * section.width_z_m;
  const double inertia_z = section.width_z_m * std::pow(section.depth_y_m, 3) / 12.0;
  return Elastic{beam.ei_n_m2 / inertia_z, 0.0, beam.rho_a_kg_per_m / area};
}

}  // namespace

bool BrickMesh::HasNode(int i, int j, int k) const { return (i % 2) + (j % 2) + (k % 2) <= 1; }

int BrickMesh::NodeId(int i, int j, int k) const {
  return 1 + i + (2 * nx + 1) * (j + (2 * ny + 1) * k);
}

Eigen::Vector3d BrickMesh::Position(int i, int j, int k) const {
  return {lx * i / (2.0 * nx), ly * j / (2.0 * ny), lz * k / (2.0 * nz)};
}

std::map<int, Eigen::Vector3d> BrickMesh::Nodes() const {
  std::map<int, Eigen::Vector3d> nodes;
  for (int k = 0; k <= 2 * nz; ++k)
    for (int j = 0; j <= 2 * ny; ++j)
      for (int i = 0; i <= 2 * nx; ++i)
        if (HasNode(i, j, k)) nodes[NodeId(i, j, k)] = Position(i, j, k);
  return nodes;
}

std::vector<std::array<int, 20>> BrickMesh::Elements() const {
  std::vector<std::array<int, 20>> elements;
  for (int ez = 0; ez < nz; ++ez)
    for (int ey = 0; ey < ny; ++ey)
      for (int ex = 0; ex < nx; ++ex) {
        std::array<int, 20> e{};
        for (int c = 0; c < 8; ++c)
          e[c] = NodeId(2 * ex + kCorner[c][0], 2 * ey + kCorner[c][1], 2 * ez + kCorner[c][2]);
        for (int m = 0; m < 12; ++m) {
          const int* a = kCorner[kEdge[m][0]];
          const int* b = kCorner[kEdge[m][1]];
          e[8 + m] = NodeId(2 * ex + (a[0] + b[0]) / 2, 2 * ey + (a[1] + b[1]) / 2,
                            2 * ez + (a[2] + b[2]) / 2);
        }
        elements.push_back(e);
      }
  return elements;
}

std::vector<int> BrickMesh::NodesAtXZero() const {
  std::vector<int> ids;
  for (int k = 0; k <= 2 * nz; ++k)
    for (int j = 0; j <= 2 * ny; ++j)
      if (HasNode(0, j, k)) ids.push_back(NodeId(0, j, k));
  return ids;
}

DeckModel SolidCantilever(const BeamProperties& beam, const CantileverSection& section,
                          int elements_along, const std::string& element_type) {
  const BrickMesh mesh{beam.length_m, section.depth_y_m, section.width_z_m, elements_along, 1, 1};
  DeckModel model;
  model.nodes = mesh.Nodes();
  model.element_lines = BrickElementLines(mesh, element_type);
  model.element_count = elements_along;
  model.section_lines = "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n";
  model.material = CantileverMaterial(beam, section);
  model.clamped = mesh.NodesAtXZero();
  model.observed_node = mesh.NodeId(2 * elements_along, 0, 1);
  return model;
}

DeckModel BeamCantilever(const BeamProperties& beam, const CantileverSection& section,
                         int elements_along) {
  DeckModel model;
  const int n_nodes = 2 * elements_along + 1;
  for (int i = 0; i < n_nodes; ++i)
    model.nodes[i + 1] = Eigen::Vector3d(beam.length_m * i / (n_nodes - 1), 0.0, 0.0);
  model.element_lines = "*ELEMENT, TYPE=B32R, ELSET=EALL\n";
  for (int e = 0; e < elements_along; ++e)
    model.element_lines += fmt::format("{}, {}, {}, {}\n", e + 1, 2 * e + 1, 2 * e + 2, 2 * e + 3);
  model.element_count = elements_along;
  // RECT: thickness along the section's 1-direction (given on the next line), then along its
  // 2-direction; the 1-direction is y here, so the first thickness is the depth in the bending
  // plane.
  model.section_lines =
      fmt::format("*BEAM SECTION, ELSET=EALL, MATERIAL=M, SECTION=RECT\n{}, {}\n0., 1., 0.\n",
                  Number(section.depth_y_m), Number(section.width_z_m));
  model.material = CantileverMaterial(beam, section);
  model.clamped = {1};
  model.clamped_dofs = 6;
  model.observed_node = n_nodes;
  return model;
}

DeckModel ClampedPlate(const PlateGeometry& plate, int nx, int ny,
                       const std::string& element_type) {
  const BrickMesh mesh{plate.lx_m, plate.ly_m, plate.thickness_m, nx, ny, 1};
  DeckModel model;
  model.nodes = mesh.Nodes();
  model.element_lines = BrickElementLines(mesh, element_type);
  model.element_count = nx * ny;
  model.section_lines = "*SOLID SECTION, ELSET=EALL, MATERIAL=M\n";
  model.material = plate.material;
  model.clamped = mesh.NodesAtXZero();
  model.observed_node = mesh.NodeId(2 * nx, 2 * ny, 1);
  return model;
}

int StopNodeOf(const DeckModel& model) { return model.nodes.rbegin()->first + 1; }

std::string FrequencyDeck(const DeckModel& model, const FrequencyStep& step) {
  std::string text = ModelLines(model) + "*STEP\n*FREQUENCY";
  if (step.matrix_storage) text += ", SOLVER=MATRIXSTORAGE";
  text += fmt::format("\n{}\n", step.modes);
  if (step.print_shapes) text += "*NODE PRINT, NSET=NALL\nU\n";
  return text + "*END STEP\n";
}

std::string StaticDeck(const DeckModel& model, const Eigen::Vector3d& force_n) {
  std::string text = ModelLines(model) + "*STEP\n*STATIC\n*CLOAD\n";
  for (int d = 0; d < 3; ++d)
    if (force_n[d] != 0.0)
      text += fmt::format("{}, {}, {}\n", model.observed_node, d + 1, Number(force_n[d]));
  return text + "*NODE PRINT, NSET=OBSERVED\nU\n*END STEP\n";
}

std::string TransientDeck(const DeckModel& model, const TransientStep& step) {
  const int stop = StopNodeOf(model);
  const Eigen::Vector3d at = model.nodes.at(model.observed_node);
  const Eigen::Vector3d& n = step.stop.normal;
  std::string text = ModelLines(model);
  text += fmt::format("*NODE, NSET=STOP\n{}, {}, {}, {}\n", stop, Number(at.x()), Number(at.y()),
                      Number(at.z()));
  // Numbered next to the model's: ccx sizes its arrays by the largest element number, and an
  // element numbered 1e6 made every increment of the plate's transient 60 times slower
  // (1.5 s of CPU, mostly in the kernel, instead of 0.03 s; measured).
  const int gap_element = model.element_count + 1;
  text += fmt::format("*ELEMENT, TYPE=GAPUNI, ELSET=EGAP\n{}, {}, {}\n", gap_element,
                      model.observed_node, stop);
  text +=
      fmt::format("*GAP, ELSET=EGAP\n{}, {}, {}, {}, , {}\n", Number(step.stop.clearance_m),
                  Number(n.x()), Number(n.y()), Number(n.z()), Number(step.stop.stiffness_n_per_m));
  text += "*BOUNDARY\nSTOP, 1, 3\n";
  // NLGEOM makes the steps nonlinear, which the gap needs: in a linear step ccx keeps the gap's
  // stiffness at zero clearance, k/2, on both sides (measured with ccx 2.20 on a static step).
  // At the checks' amplitudes (1e-4 of the span) the geometric nonlinearity is of order 1e-8.
  // A nonlinear dynamic step after another step needs energy output from the first one.
  text += "*STEP, NLGEOM\n*STATIC\n*CLOAD\n";
  for (int d = 0; d < 3; ++d)
    if (step.release_force_n[d] != 0.0)
      text +=
          fmt::format("{}, {}, {}\n", model.observed_node, d + 1, Number(step.release_force_n[d]));
  text += "*EL FILE\nENER\n*END STEP\n";
  const long increments = std::lround(step.end_s / step.dt_s);
  text += fmt::format("*STEP, NLGEOM, INC={}\n*DYNAMIC, DIRECT, ALPHA=0\n{}, {}\n", increments + 10,
                      Number(step.dt_s), Number(step.end_s));
  text += fmt::format("*CLOAD, OP=NEW\n*EL FILE, FREQUENCY={}\nENER\n", increments + 10);
  text += fmt::format("*NODE PRINT, NSET=OBSERVED, FREQUENCY={}\nU\n", step.print_every);
  text += fmt::format("*NODE PRINT, NSET=STOP, FREQUENCY={}\nRF\n", step.print_every);
  return text + "*END STEP\n";
}

void WriteDeck(const std::filesystem::path& inp, const std::string& text) {
  std::ofstream out(inp);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + inp.string());
}

std::vector<double> ReadEigenfrequenciesHz(const std::filesystem::path& dat) {
  std::ifstream in(dat);
  std::vector<double> hz;
  std::string line;
  bool in_table = false;
  while (std::getline(in, line)) {
    if (line.find("E I G E N V A L U E   O U T P U T") != std::string::npos) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    std::istringstream fields(line);
    int mode = 0;
    double eigenvalue = 0.0, omega = 0.0, cycles = 0.0;
    if (fields >> mode >> eigenvalue >> omega >> cycles) {
      hz.push_back(cycles);
    } else if (!hz.empty() && line.find_first_not_of(" \t\r") != std::string::npos) {
      break;  // The first line after the table that is not a mode's.
    }
  }
  return hz;
}

std::vector<NodeBlock> ReadNodeBlocks(const std::filesystem::path& dat, const std::string& quantity,
                                      const std::string& set) {
  std::ifstream in(dat);
  std::vector<NodeBlock> blocks;
  std::string line;
  const std::string heading = " " + quantity + " (";
  const std::string of_set = "for set " + set + " and time";
  bool reading = false;
  while (std::getline(in, line)) {
    if (line.find(" and time") != std::string::npos) {
      reading = line.find(heading) == 0 && line.find(of_set) != std::string::npos;
      if (reading) {
        blocks.emplace_back();
        blocks.back().time = std::stod(line.substr(line.rfind("time") + 4));
      }
      continue;
    }
    if (!reading) continue;
    std::istringstream fields(line);
    int node = 0;
    Eigen::Vector3d v;
    if (fields >> node >> v.x() >> v.y() >> v.z()) blocks.back().values[node] = v;
  }
  return blocks;
}

History HistoryAlong(const std::vector<NodeBlock>& blocks, int node, const Eigen::Vector3d& n) {
  History h;
  for (const NodeBlock& block : blocks) {
    const auto it = block.values.find(node);
    if (it == block.values.end()) continue;
    h.t.push_back(block.time);
    h.value.push_back(n.dot(it->second));
  }
  return h;
}

double ContactImpulse(const History& force, double dt, double threshold_n) {
  double impulse = 0.0;
  for (const double f : force.value)
    if (f > threshold_n) impulse += f * dt;
  return impulse;
}

double FirstDownCrossing(const History& h) {
  for (std::size_t i = 1; i < h.value.size(); ++i)
    if (h.value[i - 1] > 0.0 && h.value[i] <= 0.0)
      return h.t[i - 1] + (h.t[i] - h.t[i - 1]) * h.value[i - 1] / (h.value[i - 1] - h.value[i]);
  return std::nan("");
}

}  // namespace shockmap::testing
