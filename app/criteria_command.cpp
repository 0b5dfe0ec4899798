#include "app/criteria_command.h"

#include <filesystem>
#include <iostream>
#include <memory>

#include "analysis/baseline_check.h"
#include "analysis/scored_points.h"
#include "app/exit_codes.h"
#include "app/flag_checks.h"
#include "app/thresholds.h"
#include "core/input_error.h"
#include "db/study_database.h"
#include "formats/criteria_json.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "views/criteria_report.h"

namespace shockmap {
namespace {

struct CriteriaFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  ThresholdFlags thresholds;
  std::string out;
  std::string baseline;
};

void Derive(const CriteriaFlags& f) {
  if (!f.out.empty()) CheckPathLength(f.out, "--out");
  const std::string study = ResolveCanonicalStudy(f.database_path, f.study, "criteria derive");
  const CriteriaOptions options = ThresholdsFor(f.thresholds, f.database_path, study);
  const auto points = LoadCriteriaPoints(f.database_path, study);
  const ValidityCriteria criteria = DeriveCriteria(points, options);
  if (!f.out.empty()) {
    const std::filesystem::path file(f.out);
    if (file.has_parent_path()) CreateOutputDirectory(file.parent_path());
    WriteFileAtomically(file, CriteriaToJson(study, criteria).dump(2) + '\n');
  }
  std::cout << CriteriaSummary(study, criteria, points);
  if (!f.out.empty()) std::cout << "  written     " << f.out << '\n';
}

void Check(const CriteriaFlags& f) {
  CriteriaTolerances tolerances;
  const ValidityCriteria baseline =
      CriteriaFromJson(ReadJsonFile(f.baseline), f.baseline, &tolerances);
  const std::string study = ResolveCanonicalStudy(f.database_path, f.study, "criteria check");
  const auto points = LoadCriteriaPoints(f.database_path, study);
  const ValidityCriteria current = DeriveCriteria(points, baseline.options);
  const BaselineCheck check = CheckAgainstBaseline(baseline, tolerances, current, points);
  if (check.contradictions.empty()) {
    std::cout << "criteria check: study " << study << " agrees with " << f.baseline << " ("
              << points.size() << " points)"
              << (check.not_comparable.empty() ? "" : " wherever their grids compare") << "\n";
  } else {
    std::cout << "criteria check: study " << study << " contradicts " << f.baseline << ":\n";
    for (const auto& p : check.contradictions) std::cout << "  " << p << '\n';
  }
  for (const auto& n : check.not_comparable) std::cout << "  " << n << '\n';
  // The data contradicts the baseline.
  if (!check.contradictions.empty()) throw CLI::RuntimeError(kExitFailure);
}

}  // namespace

void AddCriteriaCommand(CLI::App& app) {
  auto flags = std::make_shared<CriteriaFlags>();
  CLI::App* criteria = app.add_subcommand(
      "criteria", "Validity criteria of the explicit modal scheme, from a study's scores");
  criteria->require_subcommand(1);

  CLI::App* derive = criteria->add_subcommand(
      "derive",
      "For each R_k the smallest R_ftrunc and largest dt meeting the thresholds, a "
      "log-log fit of the boundary, set against the paper's rules");
  derive->add_option("STUDY", flags->study, "study name (default: the database's only study)");
  AddDatabaseFlag(derive, flags->database_path);
  AddThresholdFlags(derive, flags->thresholds);
  derive->add_option("--out", flags->out, "write the criteria as JSON (a baseline for check)");
  derive->callback([flags] { Derive(*flags); });

  CLI::App* check = criteria->add_subcommand(
      "check",
      "Regression check: exit 0 when the study agrees with the baseline criteria within "
      "their tolerances and no stored point contradicts them, else exit 1");
  check->add_option("STUDY", flags->study, "study name (default: the database's only study)");
  check->add_option("--baseline", flags->baseline, "criteria JSON written by derive --out")
      ->required();
  AddDatabaseFlag(check, flags->database_path);
  check->callback([flags] { Check(*flags); });
}

}  // namespace shockmap
