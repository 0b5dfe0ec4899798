#include "formats/structure_files.h"

#include <fmt/format.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "core/sparse_cholesky.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/sparse_entries.h"

namespace shockmap {
namespace {

// A text file read line by line, its line numbers counted for messages.
class LineFile {
 public:
  explicit LineFile(std::string path) : path_(std::move(path)), in_(path_) {
    if (!in_) throw InputError(path_ + ": cannot be opened for reading");
  }
  bool Next(std::string& line) {
    if (!std::getline(in_, line)) return false;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    return true;
  }
  [[noreturn]] void Fail(const std::string& message) const {
    throw InputError(path_ + ": line " + std::to_string(number_) + ": " + message);
  }
  const std::string& Path() const { return path_; }
  long Number() const { return number_; }

 private:
  std::string path_;
  std::ifstream in_;
  long number_ = 0;
};

std::vector<std::string> Split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  if (separator == ' ') {
    std::istringstream words(line);
    for (std::string w; words >> w;) fields.push_back(w);
    return fields;
  }
  std::size_t start = 0;
  for (std::size_t end; (end = line.find(separator, start)) != std::string::npos; start = end + 1) {
    fields.push_back(line.substr(start, end - start));
  }
  fields.push_back(line.substr(start));
  for (std::string& f : fields) {
    f.erase(0, f.find_first_not_of(" \t"));
    f.erase(f.find_last_not_of(" \t") + 1);
  }
  return fields;
}

// The share of its diagonal added to M before its factorization checks it positive
// semi-definite (rounding of a singular M stays above -1e-10 of its diagonal).
constexpr double kMassLift = 1e-10;

std::string Quoted(const std::string& text) { return "\"" + Excerpt(text) + "\""; }

// `text` as a whole integer, or the line's failure naming `what`.
long ParseInteger(const LineFile& file, const std::string& text, const std::string& what) {
  long value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    file.Fail(what + " " + Quoted(text) + " is not an integer");
  }
  return value;
}

// `text` as a whole finite number (Fortran's "1.5D+03" read as 1.5e+03).
double ParseFinite(const LineFile& file, std::string text, const std::string& what) {
  std::replace(text.begin(), text.end(), 'D', 'e');
  std::replace(text.begin(), text.end(), 'd', 'e');
  double value = 0.0;
  const char* begin = text.data() + (text.starts_with('+') ? 1 : 0);
  const auto [end, error] = std::from_chars(begin, text.data() + text.size(), value);
  if (error == std::errc::result_out_of_range || (error == std::errc() && !std::isfinite(value))) {
    file.Fail(what + " " + Quoted(text) + " is not a finite number");
  }
  if (error != std::errc() || end != text.data() + text.size() || text.empty()) {
    file.Fail(what + " " + Quoted(text) + " is not a number");
  }
  return value;
}

int ParseIndex(const LineFile& file, const std::string& text, const std::string& what, int n) {
  const long index = ParseInteger(file, text, what);
  if (index < 1 || index > n) {
    file.Fail(what + " " + text + " is outside 1.." + std::to_string(n));
  }
  return static_cast<int>(index - 1);
}

std::function<std::string(int)> RowLabel(const std::vector<StructureDof>& dofs) {
  return [&dofs](int row) {
    return fmt::format("row {} (node {} {})", row + 1, dofs[row].node,
                       DofComponentName(dofs[row].component));
  };
}

// --- Matrix Market -------------------------------------------------------------------------

struct MarketEntries {
  std::vector<SparseEntry> entries;
  int size = 0;
  bool symmetric = false;
};

MarketEntries ReadMarketEntries(const std::string& path) {
  LineFile file(path);
  std::string line;
  if (!file.Next(line)) file.Fail("empty; expected a Matrix Market header");
  std::vector<std::string> header = Split(line, ' ');
  for (std::string& word : header) {
    std::transform(word.begin(), word.end(), word.begin(), ::tolower);
  }
  if (header.size() != 5 || header[0] != "%%matrixmarket" || header[1] != "matrix" ||
      header[2] != "coordinate" || (header[3] != "real" && header[3] != "integer") ||
      (header[4] != "general" && header[4] != "symmetric")) {
    file.Fail("header " + Quoted(line) +
              "; allowed: \"%%MatrixMarket matrix coordinate real general\" or \"... real "
              "symmetric\"");
  }
  MarketEntries market;
  market.symmetric = header[4] == "symmetric";
  long announced = -1;
  while (file.Next(line)) {
    if (line.starts_with('%') || line.find_first_not_of(" \t") == std::string::npos) continue;
    const std::vector<std::string> fields = Split(line, ' ');
    if (announced < 0) {
      if (fields.size() != 3)
        file.Fail("size line " + Quoted(line) + "; expected \"rows columns entries\"");
      const long rows = ParseInteger(file, fields[0], "rows");
      const long columns = ParseInteger(file, fields[1], "columns");
      announced = ParseInteger(file, fields[2], "entries");
      if (rows != columns || rows < 1 || rows > 100'000'000 || announced < 0) {
        file.Fail("size " + fields[0] + " x " + fields[1] + " with " + fields[2] +
                  " entries; the matrix must be square, 1 to 1e8 rows");
      }
      market.size = static_cast<int>(rows);
      market.entries.reserve(std::min<long>(announced, 50'000'000));
      continue;
    }
    if (fields.size() != 3) file.Fail("entry " + Quoted(line) + "; expected \"row column value\"");
    if (static_cast<long>(market.entries.size()) == announced) {
      file.Fail("more entries than the " + std::to_string(announced) + " the size line announces");
    }
    SparseEntry e;
    e.row = ParseIndex(file, fields[0], "row", market.size);
    e.column = ParseIndex(file, fields[1], "column", market.size);
    e.value = ParseFinite(file, fields[2],
                          fmt::format("row {} column {}: value", e.row + 1, e.column + 1));
    e.line = file.Number();
    if (market.symmetric && e.row < e.column) {
      file.Fail(
          fmt::format("row {} column {} is above the diagonal; a \"symmetric\" file holds "
                      "the lower triangle only",
                      e.row + 1, e.column + 1));
    }
    market.entries.push_back(e);
  }
  if (announced < 0) file.Fail("no size line \"rows columns entries\"");
  if (static_cast<long>(market.entries.size()) != announced) {
    file.Fail(fmt::format("ends after {} entries; its size line announces {}",
                          market.entries.size(), announced));
  }
  return market;
}

std::vector<StructureDof> ReadDofTable(const std::string& path) {
  LineFile file(path);
  std::string line;
  if (!file.Next(line) || line != "node,component") {
    file.Fail("expected the header \"node,component\", got " + Quoted(line));
  }
  std::vector<StructureDof> dofs;
  while (file.Next(line)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = Split(line, ',');
    if (fields.size() != 2) file.Fail("expected \"node,component\", got " + Quoted(line));
    const long node = ParseInteger(file, fields[0], "node");
    const auto component = DofComponentNamed(fields[1]);
    if (!component) {
      file.Fail("component " + Quoted(fields[1]) + "; allowed: ux, uy, uz, rx, ry, rz");
    }
    if (node < 1 || node > 2'000'000'000) file.Fail("node " + fields[0] + " outside 1..2e9");
    dofs.push_back({static_cast<int>(node), *component});
  }
  if (dofs.empty()) file.Fail("no DOF after the header");
  return dofs;
}

std::map<int, Eigen::Vector3d> ReadNodeTable(const std::string& path) {
  LineFile file(path);
  std::string line;
  if (!file.Next(line) || line != "node,x,y,z") {
    file.Fail("expected the header \"node,x,y,z\", got " + Quoted(line));
  }
  std::map<int, Eigen::Vector3d> nodes;
  while (file.Next(line)) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = Split(line, ',');
    if (fields.size() != 4) file.Fail("expected \"node,x,y,z\", got " + Quoted(line));
    const long node = ParseInteger(file, fields[0], "node");
    if (node < 1 || node > 2'000'000'000) file.Fail("node " + fields[0] + " outside 1..2e9");
    Eigen::Vector3d x;
    for (int axis = 0; axis < 3; ++axis) {
      x[axis] = ParseFinite(file, fields[axis + 1], std::string(1, "xyz"[axis]));
    }
    if (!nodes.emplace(static_cast<int>(node), x).second) {
      file.Fail("node " + fields[0] + " is given again; each node once");
    }
  }
  return nodes;
}

// --- checks of the whole structure ---------------------------------------------------------

void CheckSize(const std::string& matrix_path, int size, const std::string& dofs_path, int dofs) {
  if (size != dofs) {
    throw InputError(
        fmt::format("{}: {} rows, but {} names {} DOFs; the matrices' rows are the "
                    "DOF table's rows, one for one",
                    matrix_path, size, dofs_path, dofs));
  }
}

void CheckNodesHaveCoordinates(const FeStructure& s, const std::string& dofs_path,
                               const std::string& nodes_path) {
  for (std::size_t i = 0; i < s.dofs.size(); ++i) {
    if (!s.node_coordinates_m.contains(s.dofs[i].node)) {
      throw InputError(
          fmt::format("{}: row {}: node {} has no coordinates in {}; every node of "
                      "the DOF table must be there",
                      dofs_path, i + 1, s.dofs[i].node, nodes_path));
    }
  }
}

// Refuses a mass with a diagonal entry <= 0, or that is not positive semi-definite: the
// Cholesky factorization of M + 1e-10 diag(M) breaks down (its LDL^T has a pivot <= 0). A singular
// M is allowed: 20-node bricks with reduced integration (CalculiX's C3D20R) give one, whose null
// combinations have no finite frequency and never enter a truncated basis.
void CheckMassPositiveSemidefinite(const FeStructure& s, const std::string& mass_path) {
  const Eigen::VectorXd diagonal = s.mass.diagonal();
  for (int i = 0; i < s.Size(); ++i) {
    if (!(diagonal[i] > 0.0)) {
      throw InputError(
          fmt::format("{}: {} has the mass {} on its diagonal; every DOF needs a "
                      "positive mass or inertia",
                      mass_path, RowLabel(s.dofs)(i), diagonal[i]));
    }
  }
  Eigen::SparseMatrix<double> lifted = s.mass;
  lifted.diagonal() += kMassLift * diagonal;
  if (SparseCholesky(lifted).Succeeded()) return;
  // Refused: the slower LDL^T names the row and its pivot.
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(lifted);
  const auto& permutation = factor.permutationP().indices();
  for (int i = 0; i < s.Size(); ++i) {
    const double pivot = factor.info() == Eigen::Success ? factor.vectorD()[permutation[i]] : 0.0;
    if (!(pivot > 0.0)) {
      throw InputError(fmt::format(
          "{}: the mass is not positive semi-definite: at {} (diagonal {}) the pivot of the "
          "factorization of M + {} diag(M) is {}; no combination of DOFs may have a negative "
          "kinetic energy",
          mass_path, RowLabel(s.dofs)(i), diagonal[i], kMassLift, pivot));
    }
  }
}

// --- CalculiX's matrix storage ------------------------------------------------------------

// CalculiX's direction (1-3 translations, 4-6 rotations) as a component.
std::vector<StructureDof> ReadCalculixDofs(const std::string& path) {
  LineFile file(path);
  std::string line;
  std::vector<StructureDof> dofs;
  while (file.Next(line)) {
    const std::vector<std::string> fields = Split(line, ' ');
    if (fields.empty()) continue;
    const std::size_t dot = fields[0].find('.');
    if (fields.size() != 1 || dot == std::string::npos) {
      file.Fail("expected \"node.direction\", got " + Quoted(line));
    }
    const long node = ParseInteger(file, fields[0].substr(0, dot), "node");
    const long direction = ParseInteger(file, fields[0].substr(dot + 1), "direction");
    if (node < 1 || node > 2'000'000'000 || direction < 1 || direction > 6) {
      file.Fail("DOF " + Quoted(fields[0]) + "; allowed: a node >= 1 and a direction 1..6");
    }
    dofs.push_back({static_cast<int>(node), static_cast<DofComponent>(direction - 1)});
  }
  if (dofs.empty()) file.Fail("no DOF");
  return dofs;
}

// The upper triangle of a .sti or .mas file as 1-based "row column value" lines.
std::vector<SparseEntry> ReadCalculixMatrix(const std::string& path, int n) {
  LineFile file(path);
  std::string line;
  std::vector<SparseEntry> entries;
  while (file.Next(line)) {
    const std::vector<std::string> fields = Split(line, ' ');
    if (fields.empty()) continue;
    if (fields.size() != 3) file.Fail("entry " + Quoted(line) + "; expected \"row column value\"");
    SparseEntry e;
    e.row = ParseIndex(file, fields[0], "row", n);
    e.column = ParseIndex(file, fields[1], "column", n);
    e.value = ParseFinite(file, fields[2],
                          fmt::format("row {} column {}: value", e.row + 1, e.column + 1));
    e.line = file.Number();
    if (e.row > e.column) {
      file.Fail(
          fmt::format("row {} column {} is below the diagonal; CalculiX stores the upper "
                      "triangle only",
                      e.row + 1, e.column + 1));
    }
    entries.push_back(e);
  }
  return entries;
}

bool IsKeyword(const std::string& line, std::string_view keyword) {
  if (line.size() < keyword.size()) return false;
  for (std::size_t i = 0; i < keyword.size(); ++i) {
    if (std::toupper(static_cast<unsigned char>(line[i])) != keyword[i]) return false;
  }
  return line.size() == keyword.size() || line[keyword.size()] == ',' ||
         line[keyword.size()] == ' ';
}

// The INPUT= parameter of an *INCLUDE line, relative to the including deck's folder.
std::string IncludedPath(const LineFile& file, const std::string& line) {
  std::string upper = line;
  std::transform(upper.begin(), upper.end(), upper.begin(), ::toupper);
  const std::size_t at = upper.find("INPUT=");
  if (at == std::string::npos) file.Fail("*INCLUDE without INPUT=");
  std::string name = line.substr(at + 6);
  name = name.substr(0, name.find(','));
  name.erase(std::remove(name.begin(), name.end(), '"'), name.end());
  const std::filesystem::path path(name);
  return path.is_absolute() ? name
                            : (std::filesystem::path(file.Path()).parent_path() / path).string();
}

// The nodes of the deck's *NODE blocks (and of the decks it includes).
void ReadDeckNodes(const std::string& path, std::map<int, Eigen::Vector3d>& nodes, int depth) {
  LineFile file(path);
  if (depth > 10) file.Fail("*INCLUDE nested deeper than 10");
  std::string line;
  bool in_nodes = false;
  while (file.Next(line)) {
    if (line.starts_with("**") || line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.starts_with('*')) {
      in_nodes = IsKeyword(line, "*NODE");
      if (IsKeyword(line, "*INCLUDE")) ReadDeckNodes(IncludedPath(file, line), nodes, depth + 1);
      continue;
    }
    if (!in_nodes) continue;
    std::vector<std::string> fields = Split(line, ',');
    while (!fields.empty() && fields.back().empty()) fields.pop_back();
    if (fields.empty() || fields.size() > 4)
      file.Fail("expected \"node, x, y, z\", got " + Quoted(line));
    const long node = ParseInteger(file, fields[0], "node");
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (std::size_t axis = 0; axis + 1 < fields.size(); ++axis) {
      x[axis] = ParseFinite(file, fields[axis + 1], std::string(1, "xyz"[axis]));
    }
    nodes[static_cast<int>(node)] = x;
  }
}

}  // namespace

FeStructure ReadMatrixMarketStructure(const std::string& stiffness_path,
                                      const std::string& mass_path, const std::string& dofs_path,
                                      const std::string& nodes_path) {
  FeStructure s;
  s.name = std::filesystem::path(stiffness_path).parent_path().filename().string();
  s.dofs = ReadDofTable(dofs_path);
  s.node_coordinates_m = ReadNodeTable(nodes_path);
  CheckNodesHaveCoordinates(s, dofs_path, nodes_path);
  MarketEntries k = ReadMarketEntries(stiffness_path);
  CheckSize(stiffness_path, k.size, dofs_path, s.Size());
  s.stiffness =
      SymmetricMatrix(std::move(k.entries), k.size, k.symmetric, stiffness_path, RowLabel(s.dofs));
  MarketEntries m = ReadMarketEntries(mass_path);
  CheckSize(mass_path, m.size, dofs_path, s.Size());
  s.mass = SymmetricMatrix(std::move(m.entries), m.size, m.symmetric, mass_path, RowLabel(s.dofs));
  CheckMassPositiveSemidefinite(s, mass_path);
  return s;
}

}  // namespace shockmap

namespace shockmap {

FeStructure ReadCalculixMatrixStorage(const std::string& stem, const std::string& deck_path) {
  FeStructure s;
  s.name = std::filesystem::path(stem).filename().string();
  const std::string dofs_path = stem + ".dof";
  s.dofs = ReadCalculixDofs(dofs_path);
  ReadDeckNodes(deck_path, s.node_coordinates_m, 0);
  CheckNodesHaveCoordinates(s, dofs_path, deck_path);
  const std::string stiffness_path = stem + ".sti";
  s.stiffness = SymmetricMatrix(ReadCalculixMatrix(stiffness_path, s.Size()), s.Size(), true,
                                stiffness_path, RowLabel(s.dofs));
  const std::string mass_path = stem + ".mas";
  s.mass = SymmetricMatrix(ReadCalculixMatrix(mass_path, s.Size()), s.Size(), true, mass_path,
                           RowLabel(s.dofs));
  CheckMassPositiveSemidefinite(s, mass_path);
  return s;
}

namespace {

void WriteMarket(const Eigen::SparseMatrix<double>& matrix, const std::filesystem::path& path) {
  AtomicFile file(path);
  std::ostream& out = file.Stream();
  const Eigen::SparseMatrix<double> lower = matrix.triangularView<Eigen::Lower>();
  out << "%%MatrixMarket matrix coordinate real symmetric\n";
  out << matrix.rows() << " " << matrix.cols() << " " << lower.nonZeros() << "\n";
  for (int j = 0; j < lower.outerSize(); ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(lower, j); it; ++it) {
      out << fmt::format("{} {} {}\n", it.row() + 1, it.col() + 1, it.value());
    }
  }
  file.Commit();
}

}  // namespace

void WriteMatrixMarketStructure(const FeStructure& s, const std::string& dir) {
  const std::filesystem::path folder(dir);
  WriteMarket(s.stiffness, folder / "stiffness.mtx");
  WriteMarket(s.mass, folder / "mass.mtx");
  AtomicFile dofs(folder / "dofs.csv");
  dofs.Stream() << "node,component\n";
  for (const StructureDof& d : s.dofs) {
    dofs.Stream() << d.node << "," << DofComponentName(d.component) << "\n";
  }
  dofs.Commit();
  AtomicFile nodes(folder / "nodes.csv");
  nodes.Stream() << "node,x,y,z\n";
  for (const auto& [node, x] : s.node_coordinates_m) {
    nodes.Stream() << fmt::format("{},{},{},{}\n", node, x[0], x[1], x[2]);
  }
  nodes.Commit();
}

}  // namespace shockmap
