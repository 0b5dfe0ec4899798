#pragma once
// Whether the advice held on the bundle (docs/ensembles.md, "Advice checked on the bundle"):
// the sizing statistics of an advice-check study (specs/advice_check_study.h), one group per
// clearance state and rung of the ladder, read per zone family an engineer sizes (the hottest
// wire, duct pad, pin-wrapper contact). The ladder has converged at the coarsest rung every finer
// rung agrees with at every state and family (analysis/ensemble_sizing.h Agrees: their intervals of
// the sizing quantile, widened by the tolerance, overlap); the advice holds at a state and
// family when its rung agrees with the converged one and every finer rung.

#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "analysis/ensemble_sizing.h"

namespace shockmap {

// Where a ladder of one zone's sizing statistics (coarsest first) stops moving.
struct LadderConvergence {
  std::optional<int> rung;  // The coarsest rung every finer rung agrees with.
  bool undecided = false;   // An interval is unbounded: too few members to judge.
};
// Needs a finer rung to confirm a rung: nullopt with fewer than two rungs.
LadderConvergence ConvergedRung(const std::vector<ZoneSizing>& rungs, double tolerance);

// One clearance state and zone family along the ladder.
struct FamilyLadder {
  std::string state;
  ZoneFamily family = ZoneFamily::kOther;
  std::string zone;               // The family's hottest zone at the finest rung.
  std::vector<ZoneSizing> rungs;  // Coarsest first.
  LadderConvergence convergence;
};

struct AdviceCheck {
  std::vector<double> factors;  // Of each rung on the advised truncations, coarsest first.
  int advised = 1;              // The rung at factor 1.
  double tolerance = 0.0;
  std::vector<FamilyLadder> families;
  std::optional<int> converged;  // The finest rung any family needs; nullopt: not converged.
  bool undecided = false;        // Some family cannot be judged: too few members.
  std::vector<double> cpu_s_per_member;  // Per rung, the mean over its states' members.
};

// `rung_settings`: the study's "settings" list, each rung's setting in the order of `factors`.
// Throws InputError when a state lacks a rung's members.
AdviceCheck CheckAdvice(const EnsembleSizing& sizing, const nlohmann::json& rung_settings,
                        const std::vector<double>& factors, int advised);

// Whether `rung` agrees at a family with the converged rung and every finer one (nullopt:
// undecided, or the ladder has not converged).
std::optional<bool> RungHolds(const AdviceCheck& check, const FamilyLadder& family, int rung);
// RungHolds of the advised rung: the advice gives what the converged settings give.
std::optional<bool> AdviceHolds(const AdviceCheck& check, const FamilyLadder& family);

}  // namespace shockmap
