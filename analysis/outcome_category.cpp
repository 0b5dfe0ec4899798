#include "analysis/outcome_category.h"

#include <algorithm>

namespace shockmap {
namespace {

std::vector<std::string> MakeLabels() {
  std::vector<std::string> labels = {"passes", "fails thresholds", "undecided"};
  for (RunStatus s : kAllRunStatuses) {
    if (s == RunStatus::kOk) continue;
    std::string label = ToString(s);
    std::ranges::replace(label, '_', ' ');
    labels.push_back(label);
  }
  return labels;
}

}  // namespace

const std::vector<std::string>& OutcomeLabels() {
  static const std::vector<std::string> labels = MakeLabels();
  return labels;
}

int OutcomeCategoryOf(const ScoredPoint& p, const CriteriaOptions& thresholds) {
  if (p.status == RunStatus::kOk) return thresholds.Passes(p) ? 0 : thresholds.Undecided(p) ? 2 : 1;
  int index = 3;
  for (RunStatus s : kAllRunStatuses) {
    if (s == p.status) return index;
    if (s != RunStatus::kOk) ++index;
  }
  return index;  // Unreachable: every status is in kAllRunStatuses.
}

}  // namespace shockmap
