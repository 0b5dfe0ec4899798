#include "formats/nearest_name.h"

#include <algorithm>
#include <cstddef>

namespace shockmap {
namespace {

// Edits turning `a` into `b` (optimal string alignment distance: insertions, deletions,
// replacements and swaps of adjacent letters).
std::size_t EditDistance(std::string_view a, std::string_view b) {
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t replace = d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      d[i][j] = std::min({d[i - 1][j] + 1, d[i][j - 1] + 1, replace});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) {
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
      }
    }
  }
  return d[a.size()][b.size()];
}

}  // namespace

std::optional<std::string> NearestName(std::string_view given,
                                       const std::vector<std::string>& allowed) {
  const std::size_t near_enough = std::max<std::size_t>(1, given.size() / 3);
  std::optional<std::string> nearest;
  std::size_t nearest_distance = near_enough + 1;
  for (const std::string& name : allowed) {
    const std::size_t distance = EditDistance(given, name);
    if (distance == 0) return std::nullopt;
    if (distance < nearest_distance) {
      nearest = name;
      nearest_distance = distance;
    }
  }
  return nearest;
}

}  // namespace shockmap
