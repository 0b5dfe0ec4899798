#include "analysis/advice_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/input_error.h"

namespace shockmap {
namespace {

// The group of `state` at `setting` (compared by value, as the study matched it).
const GroupSizing& GroupAt(const EnsembleSizing& sizing, const std::string& state,
                           const nlohmann::json& setting) {
  for (const GroupSizing& g : sizing.groups) {
    if (g.state == state && nlohmann::json::parse(g.setting_json) == setting) return g;
  }
  throw InputError(fmt::format("study {}: state {} has no computed member at the setting {}",
                               sizing.study, state, setting.dump()));
}

}  // namespace

LadderConvergence ConvergedRung(const std::vector<ZoneSizing>& rungs, double tolerance) {
  LadderConvergence c;
  for (const ZoneSizing& z : rungs) {
    c.undecided = c.undecided || !z.sizing.lower_bounded || !z.sizing.upper_bounded;
  }
  if (c.undecided) return c;
  for (std::size_t r = 0; r + 1 < rungs.size(); ++r) {
    bool every_finer_agrees = true;
    for (std::size_t j = r + 1; j < rungs.size(); ++j) {
      every_finer_agrees = every_finer_agrees && *Agrees(rungs[r], rungs[j], tolerance);
    }
    if (every_finer_agrees) {
      c.rung = static_cast<int>(r);
      return c;
    }
  }
  return c;
}

AdviceCheck CheckAdvice(const EnsembleSizing& sizing, const nlohmann::json& settings,
                        const std::vector<double>& factors, int advised) {
  AdviceCheck check;
  check.factors = factors;
  check.advised = advised;
  check.tolerance = sizing.options.tolerance;
  check.cpu_s_per_member.assign(settings.size(), 0.0);
  std::vector<std::string> states;
  for (const GroupSizing& g : sizing.groups) {
    if (std::ranges::find(states, g.state) == states.end()) states.push_back(g.state);
  }
  bool all_converged = true;
  int finest_needed = 0;
  for (const std::string& state : states) {
    const GroupSizing& finest = GroupAt(sizing, state, settings.back());
    for (std::size_t k = 0; k < settings.size(); ++k) {
      check.cpu_s_per_member[k] += GroupAt(sizing, state, settings[k]).mean_cpu_s / states.size();
    }
    for (const FamilyHottest& f : finest.families) {
      FamilyLadder ladder{state, f.family, finest.zones[f.zone].name, {}, {}};
      for (const nlohmann::json& s : settings) {
        ladder.rungs.push_back(GroupAt(sizing, state, s).zones[f.zone]);
      }
      ladder.convergence = ConvergedRung(ladder.rungs, check.tolerance);
      check.undecided = check.undecided || ladder.convergence.undecided;
      all_converged = all_converged && ladder.convergence.rung.has_value();
      if (ladder.convergence.rung)
        finest_needed = std::max(finest_needed, *ladder.convergence.rung);
      check.families.push_back(std::move(ladder));
    }
  }
  if (all_converged && !check.undecided) check.converged = finest_needed;
  return check;
}

std::optional<bool> RungHolds(const AdviceCheck& check, const FamilyLadder& family, int rung) {
  if (!check.converged || family.convergence.undecided) return std::nullopt;
  for (std::size_t k = *check.converged; k < family.rungs.size(); ++k) {
    if (!*Agrees(family.rungs[rung], family.rungs[k], check.tolerance)) return false;
  }
  return true;
}

std::optional<bool> AdviceHolds(const AdviceCheck& check, const FamilyLadder& family) {
  return RungHolds(check, family, check.advised);
}

}  // namespace shockmap
