#include "app/compare_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <memory>

#include "app/flag_checks.h"
#include "compare/comparison.h"
#include "compare/comparison_options.h"
#include "formats/comparison_json.h"
#include "formats/counted.h"
#include "formats/history_csv.h"
#include "formats/output_file.h"
#include "views/comparison_plot.h"

namespace shockmap {
namespace {

// The declared options' values as CLI11 parses them (their defaults until given), and the
// command's own flags.
struct CompareFlags {
  std::map<const NumberOption*, double> numbers;
  std::map<const ChoiceOption*, std::string> choices;
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

void PrintHuman(const ComparisonRequest& request, const ComparisonResult& r) {
  const auto& ref = *r.reference;
  fmt::print("shockmap compare: R_k = {:g}, R_ftrunc = {:g}, {}, window [0, {:g}] s\n",
             request.problem.r_k, request.options.r_ftrunc, ToString(request.options.scheme),
             request.options.window_s);
  fmt::print("  status            {}{}\n", ToString(r.status),
             r.message.empty() ? "" : " (" + r.message + ")");
  for (const ScoreDefinition& score : Scores()) {
    fmt::print("  {:<18}{}  ({}: {})\n", score.label, Scored(r, score.name), score.source,
               score.meaning);
  }
  if (request.options.scheme == Scheme::kExplicitModal) {
    fmt::print("  modes kept        {} below f_trunc = {:.1f} Hz ({} elements, {} unknowns)\n",
               r.n_modes, request.options.r_ftrunc * request.problem.F1Hz(), r.n_elements,
               r.n_dofs);
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

// The options given on the command line, by declaration.
GivenOptions Given(const CompareFlags& flags, const CLI::App& command) {
  GivenOptions given;
  for (const auto& [option, value] : flags.numbers) {
    if (command.count(std::string(option->names.flag)) > 0) given.numbers[option] = value;
  }
  for (const auto& [option, value] : flags.choices) {
    if (command.count(std::string(option->names.flag)) > 0) given.choices[option] = value;
  }
  return given;
}

void Run(const CompareFlags& flags, const CLI::App& command) {
  const ComparisonRequest request = ComparisonAsked(Given(flags, command), &OptionNames::flag);
  // The outputs are checked before the run and written before anything is reported.
  if (!flags.out_dir.empty()) PrepareOutputDirectory(flags.out_dir, "--out");
  const ComparisonResult result = RunComparison(request.problem, request.options);
  std::optional<std::filesystem::path> png;
  if (!flags.out_dir.empty()) {
    WriteComparisonCsv(result, flags.out_dir);
    if (flags.plot) png = PlotComparison(result, request.problem, request.options, flags.out_dir);
  }
  if (flags.json) {
    std::cout << ComparisonToJson(request.problem, request.options, result).dump(2) << '\n';
    return;
  }
  PrintHuman(request, result);
  if (png) fmt::print("  plot              {}\n", png->string());
  if (!flags.out_dir.empty()) {
    fmt::print("  histories         {}/numerical.csv, reference.csv\n", flags.out_dir);
  }
}

}  // namespace

void AddCompareCommand(CLI::App& app) {
  auto flags = std::make_shared<CompareFlags>();
  CLI::App* cmd = app.add_subcommand(
      "compare",
      "Run the numerical solver and the semi-analytical reference on the paper's "
      "beam-impact problem and score them (Err, SRf)");
  for (const NumberOption* option : ComparisonNumberOptions()) {
    CLI::Option* added = AddDeclaredOption(cmd, *option, flags->numbers[option]);
    if (option->required) added->required();
  }
  for (const ChoiceOption* option : ComparisonChoiceOptions()) {
    AddDeclaredOption(cmd, *option, flags->choices[option]);
  }
  // A step given in seconds leaves no bound to take a factor of.
  CLI::Option* dt = cmd->get_option(std::string(kDtOption.names.flag));
  cmd->get_option(std::string(kDtFactorOption.names.flag))->excludes(dt);
  cmd->get_option(std::string(kDtRuleOption.names.flag))->excludes(dt);
  cmd->add_option("--out", flags->out_dir, "directory for the CSV histories (and the plot)");
  cmd->add_flag("--json", flags->json, "print the result as one JSON object");
  cmd->add_flag("--plot", flags->plot,
                "draw the histories as the paper's Fig. 3 (PNG, needs --out)");
  cmd->callback([flags, cmd] {
    if (flags->plot && flags->out_dir.empty()) {
      throw CLI::ValidationError("--plot", "needs --out DIR to write the CSV files and PNG into");
    }
    Run(*flags, *cmd);
  });
}

}  // namespace shockmap
