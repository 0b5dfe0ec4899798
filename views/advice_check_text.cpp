#include "views/advice_check_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "views/sizing_text.h"

namespace shockmap {
namespace {

std::string Factor(double f) {
  return f < 1.0 ? fmt::format("1/{:.3g}", 1.0 / f) : fmt::format("{:.3g}", f);
}

std::string Families(const AdviceCheck& check, const std::vector<const FamilyLadder*>& held) {
  std::map<ZoneFamily, std::pair<int, int>> counts;  // Held, in all.
  for (const FamilyLadder& f : check.families) ++counts[f.family].second;
  for (const FamilyLadder* f : held) ++counts[f->family].first;
  std::string text;
  for (const auto& [family, n] : counts) {
    text += fmt::format("{}{} {} of {}", text.empty() ? "" : ", ", FamilyName(family), n.first,
                        n.second);
  }
  return text;
}

// What the converged setting costs beside the advised one; where they are the same rung, the
// families a rung coarser would not do for.
std::string ConvergedCost(const AdviceCheck& check, const std::string& q) {
  const std::string agreeing =
      fmt::format("every finer rung agrees within the {} intervals widened by {:g} %", q,
                  100 * check.tolerance);
  const double advised_cpu = check.cpu_s_per_member[check.advised];
  const double converged_cpu = check.cpu_s_per_member[*check.converged];
  if (*check.converged != check.advised) {
    return fmt::format(
        "the converged setting (x {} of the advised truncations, where {}) costs {:.3g} s, {:.3g} "
        "times {}",
        Factor(check.factors[*check.converged]), agreeing, converged_cpu,
        converged_cpu >= advised_cpu ? converged_cpu / advised_cpu : advised_cpu / converged_cpu,
        converged_cpu >= advised_cpu ? "as much" : "less");
  }
  std::vector<std::string> needing;
  for (const FamilyLadder& f : check.families) {
    const std::string name = FamilyName(f.family);
    if (f.convergence.rung == check.advised && std::ranges::find(needing, name) == needing.end())
      needing.push_back(name);
  }
  std::string names;
  for (std::size_t k = 0; k < needing.size(); ++k)
    names += (k == 0 ? "" : k + 1 == needing.size() ? " and " : ", ") + needing[k];
  return fmt::format("it is the converged setting ({}){}", agreeing,
                     check.advised > 0
                         ? fmt::format("; x {} of it is not enough for the {}",
                                       Factor(check.factors[check.advised - 1]), names)
                         : std::string());
}

}  // namespace

std::string AdviceVerdict(const AdviceCheck& check, double quantile) {
  const std::string q = fmt::format("P{:g}", 100 * quantile);
  if (check.undecided) {
    return fmt::format(
        "Undecided: some {} interval is unbounded, too few members to judge the advice; run "
        "more members (a two-sided 95 % interval of a P95 needs about 100).",
        q);
  }
  if (!check.converged) {
    std::string moving;
    for (const FamilyLadder& f : check.families) {
      if (f.convergence.rung) continue;
      moving += fmt::format("{}{} {} ({}: {} {} N at x {}, {} N at x {})",
                            moving.empty() ? "" : "; ", f.state, FamilyName(f.family), f.zone, q,
                            fmt::format("{:.4g}", f.rungs[f.rungs.size() - 2].sizing.estimate),
                            Factor(check.factors[f.rungs.size() - 2]),
                            fmt::format("{:.4g}", f.rungs.back().sizing.estimate),
                            Factor(check.factors.back()));
    }
    std::string verdict = fmt::format(
        "Not converged: the finest rungs still differ beyond their intervals at {}; the advice "
        "cannot be confirmed until a finer rung agrees.",
        moving);
    for (const FamilyLadder& f : check.families) {
      const QuantileInterval& a = f.rungs[check.advised].sizing;
      const QuantileInterval& finest = f.rungs.back().sizing;
      if (*Agrees(f.rungs[check.advised], f.rungs.back(), check.tolerance)) continue;
      verdict += fmt::format(
          " It failed already at {} {} ({}): advised {} N against {} N at x {} ({:+.1f} %).",
          f.state, FamilyName(f.family), f.zone, IntervalText(a), IntervalText(finest),
          Factor(check.factors.back()), 100 * (a.estimate / finest.estimate - 1));
    }
    return verdict;
  }
  std::vector<const FamilyLadder*> held, failed;
  for (const FamilyLadder& f : check.families)
    (*AdviceHolds(check, f) ? held : failed).push_back(&f);
  std::string verdict = fmt::format(
      "Advice held at {} of {} state and zone family pairs ({}) at {:.3g} s of CPU per member; "
      "{}.",
      held.size(), check.families.size(), Families(check, held),
      check.cpu_s_per_member[check.advised], ConvergedCost(check, q));
  for (const FamilyLadder* f : failed) {
    // The first converged rung the advised one disagrees with.
    std::size_t k = *check.converged;
    while (*Agrees(f->rungs[check.advised], f->rungs[k], check.tolerance)) ++k;
    const QuantileInterval& a = f->rungs[check.advised].sizing;
    const QuantileInterval& c = f->rungs[k].sizing;
    verdict += fmt::format(
        " It failed at {} {} ({}): advised {} N against {} N at x {} ({:+.1f} %); x {} of the "
        "advised truncations would do.",
        f->state, FamilyName(f->family), f->zone, IntervalText(a), IntervalText(c),
        Factor(check.factors[k]), 100 * (a.estimate / c.estimate - 1),
        Factor(check.factors[*f->convergence.rung]));
  }
  return verdict;
}

Table AdviceCheckTable(const AdviceCheck& check) {
  Table t;
  t.columns = {"state", "family", "hottest zone"};
  for (std::size_t k = 0; k < check.factors.size(); ++k) {
    const bool advised = static_cast<int>(k) == check.advised;
    const bool converged = check.converged && static_cast<int>(k) == *check.converged;
    const std::string role = advised && converged ? ", advised, converged"
                             : advised            ? ", advised"
                             : converged          ? ", converged"
                                                  : "";
    t.columns.push_back(fmt::format("x {}{} (N)", Factor(check.factors[k]), role));
  }
  for (const char* column : {"holds", "coarser holds", "suffices from"})
    t.columns.push_back(column);
  auto yes_no = [](std::optional<bool> b) { return std::string(!b ? "-" : *b ? "yes" : "no"); };
  for (const FamilyLadder& f : check.families) {
    const std::optional<bool> coarser =
        check.advised > 0 ? RungHolds(check, f, check.advised - 1) : std::nullopt;
    std::vector<TableCell> row{f.state, FamilyName(f.family), f.zone};
    for (std::size_t k = 0; k < check.factors.size(); ++k) {
      row.emplace_back(k < f.rungs.size() ? IntervalText(f.rungs[k].sizing) : std::string("-"));
    }
    row.emplace_back(yes_no(AdviceHolds(check, f)));
    row.emplace_back(yes_no(coarser));
    row.emplace_back(f.convergence.rung ? "x " + Factor(check.factors[*f.convergence.rung])
                                        : std::string("-"));
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace shockmap
