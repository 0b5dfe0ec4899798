#include "formats/sparse_entries.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include "core/input_error.h"

namespace shockmap {
namespace {

std::string LineOf(const std::string& file, long line) {
  return file + ": line " + std::to_string(line);
}

std::string Value(double v) { return fmt::format("{}", v); }

bool ByPosition(const SparseEntry& a, const SparseEntry& b) {
  return a.column != b.column ? a.column < b.column : a.row < b.row;
}

// Entries in the lower triangle (row >= column), sorted by position, none given twice.
std::vector<SparseEntry> LowerTriangle(std::vector<SparseEntry> entries, const std::string& file,
                                       const std::function<std::string(int)>& row_label) {
  for (SparseEntry& e : entries) {
    if (e.row < e.column) std::swap(e.row, e.column);
  }
  std::stable_sort(entries.begin(), entries.end(), ByPosition);
  for (std::size_t k = 1; k < entries.size(); ++k) {
    const SparseEntry& a = entries[k - 1];
    const SparseEntry& b = entries[k];
    if (a.row == b.row && a.column == b.column) {
      throw InputError(LineOf(file, b.line) + ": " + row_label(a.row) + ", column " +
                       std::to_string(a.column + 1) + " = " + Value(b.value) +
                       " is given again (line " + std::to_string(a.line) + ": " + Value(a.value) +
                       "); each entry of the triangle may appear once");
    }
  }
  return entries;
}

// Pairs (i, j) and (j, i) of a file with both triangles, checked equal; the lower one kept at
// their mean. An entry without its mirror is compared with zero.
std::vector<SparseEntry> MergedTriangles(std::vector<SparseEntry> entries, const std::string& file,
                                         const std::function<std::string(int)>& row_label) {
  std::vector<SparseEntry> lower, upper;
  for (const SparseEntry& e : entries) (e.row >= e.column ? lower : upper).push_back(e);
  lower = LowerTriangle(std::move(lower), file, row_label);
  upper = LowerTriangle(std::move(upper), file, row_label);  // mirrored into the lower triangle
  std::vector<SparseEntry> merged;
  std::size_t i = 0, j = 0;
  const SparseEntry zero{};
  while (i < lower.size() || j < upper.size()) {
    const bool take_lower =
        j == upper.size() || (i < lower.size() && !ByPosition(upper[j], lower[i]));
    const bool take_upper =
        i == lower.size() || (j < upper.size() && !ByPosition(lower[i], upper[j]));
    const SparseEntry& l = take_lower ? lower[i] : zero;
    const SparseEntry& u = take_upper ? upper[j] : zero;
    const SparseEntry& at = take_lower ? l : u;
    const bool diagonal = at.row == at.column;
    if (!diagonal && std::abs(l.value - u.value) >
                         kSymmetryTolerance * std::max(std::abs(l.value), std::abs(u.value))) {
      // The upper entry was mirrored: in the file it stands at (column, row).
      const std::string lower_at = row_label(at.row) + ", column " + std::to_string(at.column + 1);
      const std::string upper_at = row_label(at.column) + ", column " + std::to_string(at.row + 1);
      const std::string found =
          take_lower && take_upper
              ? lower_at + " = " + Value(l.value) + " but " + upper_at + " = " + Value(u.value) +
                    " (line " + std::to_string(l.line) + ")"
              : (take_lower ? lower_at + " = " + Value(l.value) + " but " + upper_at
                            : upper_at + " = " + Value(u.value) + " but " + lower_at) +
                    " is not given";
      throw InputError(LineOf(file, take_upper ? u.line : l.line) + ": not symmetric: " + found +
                       "; the matrix must be symmetric to a relative " + Value(kSymmetryTolerance));
    }
    SparseEntry kept = at;
    kept.value = diagonal ? at.value : 0.5 * (l.value + u.value);
    merged.push_back(kept);
    if (take_lower) ++i;
    if (take_upper) ++j;
  }
  return merged;
}

}  // namespace

Eigen::SparseMatrix<double> SymmetricMatrix(std::vector<SparseEntry> entries, int n,
                                            bool one_triangle, const std::string& file,
                                            const std::function<std::string(int)>& row_label) {
  const std::vector<SparseEntry> lower = one_triangle
                                             ? LowerTriangle(std::move(entries), file, row_label)
                                             : MergedTriangles(std::move(entries), file, row_label);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(2 * lower.size());
  std::vector<bool> row_has_entry(n, false);
  for (const SparseEntry& e : lower) {
    triplets.emplace_back(e.row, e.column, e.value);
    if (e.row != e.column) triplets.emplace_back(e.column, e.row, e.value);
    if (e.value != 0.0) row_has_entry[e.row] = row_has_entry[e.column] = true;
  }
  const auto empty = std::find(row_has_entry.begin(), row_has_entry.end(), false);
  if (empty != row_has_entry.end()) {
    throw InputError(file + ": " + row_label(static_cast<int>(empty - row_has_entry.begin())) +
                     " has no nonzero entry; every DOF of the table must have one (a DOF the "
                     "model does not use must be left out of the table and the matrices)");
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(triplets.begin(), triplets.end());
  return matrix;
}

}  // namespace shockmap
