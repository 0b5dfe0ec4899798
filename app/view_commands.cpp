#include "app/view_commands.h"

#include <fmt/format.h>

#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "analysis/cost_front.h"
#include "analysis/scored_points.h"
#include "app/flag_checks.h"
#include "app/shared_data.h"
#include "app/thresholds.h"
#include "core/input_error.h"
#include "db/report_queries.h"
#include "db/study_database.h"
#include "formats/criteria_json.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/scene_file.h"
#include "specs/advice_check_outcomes.h"
#include "specs/study_spec.h"
#include "views/advice_summary.h"
#include "views/cost_front.h"
#include "views/fig4_plot.h"
#include "views/scene_advice_summary.h"
#include "workflows/advice_check_ladder.h"

namespace shockmap {
namespace {

struct ViewFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  ThresholdFlags thresholds;
  std::string out;
  double r_k = 0.0;
  bool json = false;
  std::string criteria = kSceneCriteria;
  std::string checks = kAdviceChecks;
  bool every_zone = false;
  SceneFileAccess access;
};

void AddCommon(CLI::App* cmd, ViewFlags& f, bool thresholds) {
  cmd->add_option("STUDY", f.study, "study name (default: the database's only study)");
  AddDatabaseFlag(cmd, f.database_path);
  if (thresholds) AddThresholdFlags(cmd, f.thresholds);
}

StudySpec StoredSpec(const std::string& database_path, const std::string& study) {
  const auto json = StoredStudySpec(database_path, study);
  if (!json) throw InputError("no study named \"" + study + "\" in " + database_path);
  return ParseStudySpec(ParseJsonText(*json, database_path + ": stored study " + study),
                        database_path);
}

// Throws InputError naming --out when the plot or the files beside it could not be named.
void CheckPlotPath(const std::string& out) {
  if (!out.empty()) CheckPathLength(out, "--out");
}

// `advise SCENE.json`: a scene file rather than a study's name.
bool IsSceneFile(const std::string& argument) {
  return argument.ends_with(".json") && std::filesystem::is_regular_file(argument);
}

// Each zone's R_k and each beam's truncation from the criteria file, with the outcome of its
// check on the scene's ensemble when one is recorded for this scene and criteria
// (docs/ensembles.md).
void AdviseForScene(const ViewFlags& f, const std::string& criteria_file,
                    const std::string& checks_file) {
  const nlohmann::json scene_json = ReadJsonFile(f.study);
  const Scene scene = ParseScene(scene_json, f.study, f.access);
  const nlohmann::json criteria_json = ReadJsonFile(criteria_file);
  CriteriaTolerances tolerances;
  const ValidityCriteria criteria = CriteriaFromJson(criteria_json, criteria_file, &tolerances);
  const std::vector<AdviceCheckOutcome> checks =
      ParseAdviceCheckOutcomes(ReadJsonFile(checks_file), checks_file);
  const AdviceCheckOutcome* check =
      OutcomeFor(checks, SceneDigest(scene_json, scene), JsonDigest(criteria_json));
  std::cout << "criteria from " << criteria_file << '\n'
            << SceneAdviceSummary(scene, AdviseScene(scene, criteria), f.every_zone, check,
                                  checks_file);
}

}  // namespace

namespace {

using Flags = std::shared_ptr<ViewFlags>;

void AddPlotCommand(CLI::App& app, const Flags& flags) {
  CLI::App* plot = app.add_subcommand("plot", "Plots of a stored study");
  plot->require_subcommand(1);
  CLI::App* fig4 = plot->add_subcommand(
      "fig4", "Err and SRf against R_k, one curve per R_ftrunc and the implicit scheme");
  AddCommon(fig4, *flags, true);
  fig4->add_option("--out", flags->out, "image, .png or .svg (default: out/STUDY_fig4.png)");
  fig4->callback([flags] {
    CheckPlotPath(flags->out);
    const std::string study =
        ResolveCanonicalStudy(flags->database_path, flags->study, "plot fig4");
    const std::string out = flags->out.empty() ? "out/" + study + "_fig4.png" : flags->out;
    DrawFig4(study, LoadScoredPoints(flags->database_path, study, "explicit-modal"),
             LoadScoredPoints(flags->database_path, study, "implicit-full"),
             ThresholdsFor(flags->thresholds, flags->database_path, study), out);
    std::cout << "Fig. 4 written to " << out << '\n';
  });
}

void AddCostCommand(CLI::App& app, const Flags& flags) {
  CLI::App* cost = app.add_subcommand(
      "cost",
      "Err against wall time for every point, Pareto front, implicit/explicit time "
      "ratio at equal accuracy");
  AddCommon(cost, *flags, true);
  cost->add_option("--rk", flags->r_k, "one R_k (the nearest studied)")->check(Positive());
  cost->add_option("--out", flags->out,
                   "plot of the R_k given by --rk (default: out/STUDY_cost_rkX.png, X to six "
                   "significant digits)");
  cost->callback([flags] {
    if (!flags->out.empty() && flags->r_k <= 0) {
      throw CLI::ValidationError("--out",
                                 "names the plot of one R_k, which --rk gives; without "
                                 "--rk only the table is printed");
    }
    CheckPlotPath(flags->out);
    const std::string study = ResolveCanonicalStudy(flags->database_path, flags->study, "cost");
    const auto tables =
        BuildCostTables(LoadScoredPoints(flags->database_path, study, "explicit-modal"),
                        LoadScoredPoints(flags->database_path, study, "implicit-full"),
                        flags->r_k > 0 ? std::optional<double>(flags->r_k) : std::nullopt,
                        ThresholdsFor(flags->thresholds, flags->database_path, study));
    std::cout << CostSummary(tables);
    if (flags->r_k > 0 && !tables.empty()) {
      const std::string out =
          flags->out.empty() ? fmt::format("out/{}_cost_rk{:.6g}.png", study, tables.front().r_k)
                             : flags->out;
      DrawCost(study, tables.front(), out);
      std::cout << "plot written to " << out << '\n';
    }
  });
}

void AddAdviseCommand(CLI::App& app, const Flags& flags) {
  CLI::App* advise = app.add_subcommand(
      "advise",
      "Recommended R_ftrunc and dt for a new R_k from a study's derived criteria, with the "
      "predicted cost; or, for a scene file, each zone's R_k against the local bending "
      "stiffness of its beams and the truncation per beam and dt the criteria require");
  AddCommon(advise, *flags, true);
  advise->add_option("--rk", flags->r_k, "stiffness ratio to advise for (a study's advice)")
      ->check(Positive());
  advise->add_flag("--json", flags->json, "print the advice as one JSON object");
  CLI::Option* criteria =
      advise
          ->add_option("--criteria", flags->criteria,
                       "with a scene file for STUDY: criteria JSON written by `criteria derive "
                       "--out`; the default, the peak-force criteria a zone is sized with "
                       "(docs/physics.md §5.1), is looked up in the working folder, then in the "
                       "shared data installed with shockmap (share/shockmap)")
          ->capture_default_str();
  CLI::Option* checks =
      advise
          ->add_option("--checks", flags->checks,
                       "with a scene file for STUDY: the outcomes `check-advice --record` wrote; "
                       "the one recorded for this scene and criteria says whether the advice "
                       "held on the scene's ensemble (the default, the shipped bundles' checks, "
                       "is looked up as --criteria is)")
          ->capture_default_str();
  advise->add_flag("--zones", flags->every_zone, "with a scene file: also list every zone");
  AddAllowPathFlag(advise, flags->access);
  advise->callback([flags, criteria, checks] {
    if (IsSceneFile(flags->study)) {
      const std::string criteria_file =
          criteria->count() > 0 ? flags->criteria : DefaultDataFile(flags->criteria, "--criteria");
      const std::string checks_file =
          checks->count() > 0 ? flags->checks : DefaultDataFile(flags->checks, "--checks");
      return AdviseForScene(*flags, criteria_file, checks_file);
    }
    if (flags->r_k <= 0.0) {
      throw InputError(
          "--rk: required to advise from a study (or give a scene file, *.json, "
          "for STUDY)");
    }
    const std::string study = ResolveCanonicalStudy(flags->database_path, flags->study, "advise");
    const auto points = LoadScoredPoints(flags->database_path, study, "explicit-modal");
    const StudySpec spec = StoredSpec(flags->database_path, study);
    const Advice a = Advise(
        spec.problem, spec.scoring.window_s,
        DeriveCriteria(points, ThresholdsFor(flags->thresholds, flags->database_path, study)),
        points, flags->r_k);
    if (flags->json) {
      nlohmann::json j = AdviceToJson(a);
      j["study"] = study;
      std::cout << j.dump(2) << '\n';
    } else {
      std::cout << AdviceSummary(a);
    }
  });
}

}  // namespace

void AddViewCommands(CLI::App& app) {
  const auto flags = std::make_shared<ViewFlags>();
  AddPlotCommand(app, flags);
  AddCostCommand(app, flags);
  AddAdviseCommand(app, flags);
}

}  // namespace shockmap
