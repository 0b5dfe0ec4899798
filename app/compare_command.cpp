#include "app/compare_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>

#include "app/flag_checks.h"
#include "compare/comparison.h"
#include "compare/comparison_limits.h"
#include "core/modal_basis.h"
#include "core/transient_run.h"
#include "formats/comparison_json.h"
#include "formats/counted.h"
#include "formats/history_csv.h"
#include "formats/output_file.h"
#include "specs/study_spec.h"
#include "views/comparison_plot.h"

namespace shockmap {
namespace {

struct CompareFlags {
  CantileverImpact problem;
  ComparisonOptions options;
  double dt_s = 0.0;
  std::string dt_rule;  // The declared defaults, as AddDeclaredOption sets them.
  std::string scheme;
  std::string out_dir;
  bool json = false;
  bool plot = false;
};

// A score's value, or why it has none: its reference does not decide it, or it was not scored.
std::string Scored(const ComparisonResult& r, std::string_view score) {
  if (const std::optional<double> v = r.scores[score]) return fmt::format("{:.4f}", *v);
  return std::ranges::find(r.undecided, score) != r.undecided.end() ? "undecided by the reference"
                                                                    : "not scored";
}

void PrintShock(const char* label, const std::vector<Shock>& shocks) {
  if (shocks.empty()) {
    fmt::print("  first shock, {:<9} none in the window\n", label);
    return;
  }
  const Shock& s = shocks.front();
  fmt::print(
      "  first shock, {:<9} t = {:.5f} s, impulse {:.4g} N s, peak {:.4g} N, {:.3g} ms, {}\n",
      label, s.start_s, s.impulse_n_s, s.peak_force_n, 1e3 * s.Duration(),
      Counted(s.Rebounds(), "rebound"));
}

void PrintHuman(const CompareFlags& f, const ComparisonResult& r) {
  const auto& ref = *r.reference;
  fmt::print("shockmap compare: R_k = {:g}, R_ftrunc = {:g}, {}, window [0, {:g}] s\n",
             f.problem.r_k, f.options.r_ftrunc, ToString(f.options.scheme), f.options.window_s);
  fmt::print("  status            {}{}\n", ToString(r.status),
             r.message.empty() ? "" : " (" + r.message + ")");
  for (const ScoreDefinition& score : Scores()) {
    fmt::print("  {:<18}{}  ({}: {})\n", score.label, Scored(r, score.name), score.source,
               score.meaning);
  }
  if (f.options.scheme == Scheme::kExplicitModal) {
    fmt::print("  modes kept        {} below f_trunc = {:.1f} Hz ({} elements, {} unknowns)\n",
               r.n_modes, f.options.r_ftrunc * f.problem.F1Hz(), r.n_elements, r.n_dofs);
  } else {
    fmt::print("  model             the full FE model, {} elements, {} unknowns (no modal basis)\n",
               r.n_elements, r.n_dofs);
  }
  fmt::print("  dt used           {:.4g} s (asked {:.4g} s), {} steps\n", r.numerical.dt_used_s,
             r.numerical.dt_requested_s, r.numerical.steps_taken);
  fmt::print("  stability bounds  paper 1/(4 f_trunc) = {:.4g} s, sharp 2/omega_max = {:.4g} s\n",
             r.bounds.dt_paper_s, r.bounds.dt_sharp_s);
  const ReferenceConvergence& c = ref.convergence;
  fmt::print(
      "  reference         R_fref = {:g} ({} free / {} contact modes, {}), "
      "estimated error {:.2e} (tip {:.2e} of the amplitude, first-shock impulse {:.2e}, induced "
      "Err {:.2e}; checked up to R_fref = {:g})\n",
      c.r_fref, ref.summary.n_modes_free, ref.summary.n_modes_contact,
      Counted(ref.summary.n_transitions, "transition"), c.difference, c.tip.error, c.impulse.error,
      c.induced_err.error, c.r_fref_check);
  PrintShock("numerical", r.shocks_numerical);
  PrintShock("reference", ref.shocks);
  fmt::print("  wall time         reference {:.4f} s, numerical {:.6f} s (CPU {:.6f} s)\n",
             ref.wall_s, r.numerical.wall_s, r.numerical.cpu_s);
}

void Run(const CompareFlags& flags) {
  CompareFlags f = flags;
  if (f.dt_s > 0.0) f.options.dt.dt_s = f.dt_s;
  if (f.options.reference.r_fref == 0.0)
    f.options.reference.r_fref = ReferenceTruncationRule{}.For(f.problem.r_k);
  f.options.dt.rule = *DtRuleFromString(f.dt_rule);
  f.options.scheme = *SchemeFromString(f.scheme);
  std::string error;
  if (!f.problem.IsValid(&error) || !f.options.IsValid(&error)) throw InputError(error);
  CheckComparisonAffordable(
      f.problem, f.options,
      {"--rftrunc", "--rfref", "--window", "--elements", "--dt", "--dt-factor"});
  // The outputs are checked before the run and written before anything is reported.
  if (!f.out_dir.empty()) PrepareOutputDirectory(f.out_dir, "--out");
  const ComparisonResult result = RunComparison(f.problem, f.options);
  std::optional<std::filesystem::path> png;
  if (!f.out_dir.empty()) {
    WriteComparisonCsv(result, f.out_dir);
    if (f.plot) png = PlotComparison(result, f.problem, f.options, f.out_dir);
  }
  if (f.json) {
    std::cout << ComparisonToJson(f.problem, f.options, result).dump(2) << '\n';
    return;
  }
  PrintHuman(f, result);
  if (png) fmt::print("  plot              {}\n", png->string());
  if (!f.out_dir.empty()) {
    fmt::print("  histories         {}/numerical.csv, reference.csv\n", f.out_dir);
  }
}

}  // namespace

void AddCompareCommand(CLI::App& app) {
  auto flags = std::make_shared<CompareFlags>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Run the numerical solver and the semi-analytical reference on the paper's "
      "beam-impact problem and score them (Err, SRf)");
  AddDeclaredOption(cmd, kRkOption, flags->problem.r_k)->required();
  AddDeclaredOption(cmd, kRftruncOption, flags->options.r_ftrunc)->required();
  auto* dt = AddDeclaredOption(cmd, kDtOption, flags->dt_s);
  AddDeclaredOption(cmd, kDtFactorOption, flags->options.dt.factor)->excludes(dt);
  AddDeclaredOption(cmd, kDtRuleOption, flags->dt_rule)->excludes(dt);
  AddDeclaredOption(cmd, kWindowOption, flags->options.window_s);
  AddDeclaredOption(cmd, kSchemeOption, flags->scheme);
  flags->options.reference.r_fref = 0.0;  // The studies' rule unless given.
  AddDeclaredOption(cmd, kRfrefOption, flags->options.reference.r_fref);
  AddDeclaredOption(cmd, kElementsOption, flags->options.n_elements);
  cmd->add_option("--out", flags->out_dir, "directory for the CSV histories (and the plot)");
  cmd->add_flag("--json", flags->json, "print the result as one JSON object");
  cmd->add_flag("--plot", flags->plot,
                "draw the histories as the paper's Fig. 3 (PNG, needs --out)");
  cmd->callback([flags] {
    if (flags->plot && flags->out_dir.empty()) {
      throw CLI::ValidationError("--plot", "needs --out DIR to write the CSV files and PNG into");
    }
    Run(*flags);
  });
}

}  // namespace shockmap
