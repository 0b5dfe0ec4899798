#include "reference/reference_convergence.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace shockmap {

std::string ToString(ReferenceCheck check) {
  return check == ReferenceCheck::kCoarser ? "coarser" : "finer";
}

std::optional<ReferenceCheck> ReferenceCheckFromString(std::string_view name) {
  if (name == "finer") return ReferenceCheck::kFiner;
  if (name == "coarser") return ReferenceCheck::kCoarser;
  return std::nullopt;
}

double FinerTruncation(double r_fref) { return kReferenceCheckRatio * r_fref; }

double CoarserTruncation(double r_fref) { return std::max(1.0, r_fref / kReferenceCheckRatio); }

namespace {

std::optional<double> ProgressOrder(const std::vector<double>& differences) {
  std::size_t best = 0;
  for (std::size_t k = 1; k < differences.size(); ++k) {
    if (std::abs(differences[k]) < std::abs(differences[best])) best = k;
  }
  if (best == 0 || differences[best] == 0.0) return std::nullopt;
  return std::log(std::abs(differences.front() / differences[best])) /
         std::log(kReferenceCheckRatio) / static_cast<double>(best);
}

}  // namespace

QuantityConvergence GridConvergenceIndex(const std::vector<double>& differences) {
  QuantityConvergence q;
  if (differences.empty()) return q;
  q.difference = std::abs(differences.back());
  bool asymptotic = differences.size() >= 3;
  double order = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; asymptotic && k + 1 < differences.size(); ++k) {
    const double ratio = differences[k] / differences[k + 1];
    asymptotic = ratio > 0.0 && std::isfinite(ratio);
    if (asymptotic) order = std::min(order, std::log(ratio) / std::log(kReferenceCheckRatio));
  }
  if (asymptotic && order >= kLowestRegularOrder) q.order = order;
  const double fs = q.order ? kSafetyFactorObserved : kSafetyFactorUnobserved;
  const double r_p = std::pow(kReferenceCheckRatio, q.order.value_or(kLowestRegularOrder));
  q.error = fs * q.difference * r_p / (r_p - 1.0);
  q.progress_order = ProgressOrder(differences);
  return q;
}

const QuantityConvergence& ReferenceConvergence::Deciding() const {
  const QuantityConvergence* deciding = &tip;
  for (const QuantityConvergence* q : {&impulse, &induced_err}) {
    if (q->error > deciding->error) deciding = q;
  }
  return *deciding;
}

}  // namespace shockmap
