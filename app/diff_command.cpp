#include "app/diff_command.h"

#include <iostream>
#include <memory>

#include "app/flag_checks.h"
#include "app/thresholds.h"
#include "db/study_database.h"
#include "formats/output_file.h"
#include "formats/table_output.h"
#include "views/study_diff_map.h"
#include "views/study_diff_text.h"

namespace shockmap {
namespace {

struct DiffFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string database_b;
  std::string study_a, study_b;
  ThresholdFlags thresholds;
  double tolerance = 1e-6;
  std::string format = "table";
  std::string out;
};

void Diff(const DiffFlags& f) {
  if (!f.out.empty()) CheckPathLength(f.out, "--out");
  const std::string& database_b = f.database_b.empty() ? f.database_path : f.database_b;
  const DiffedStudy a = LoadDiffedStudy(f.database_path, f.study_a, f.thresholds.given, "A");
  const DiffedStudy b = LoadDiffedStudy(database_b, f.study_b, f.thresholds.given, "B");
  const StudyDiff diff = DiffStudies(a, b, f.tolerance);
  if (!f.out.empty()) DrawDiffMap(a, b, f.out);  // Before any output: a bad --out prints none.
  if (f.format == "json") {
    std::cout << DiffToJson(a, b, diff).dump(2) << '\n';
  } else if (f.format == "csv") {
    WriteTable(DiffPointTable(a, b, diff), TableFormat::kCsv, std::cout);
  } else {
    std::cout << DiffText(a, b, diff);
  }
  if (f.out.empty()) return;
  (f.format == "table" ? std::cout : std::cerr) << "map written to " << f.out << '\n';
}

}  // namespace

void AddDiffCommand(CLI::App& app) {
  auto flags = std::make_shared<DiffFlags>();
  CLI::App* diff = app.add_subcommand(
      "diff",
      "Compare two studies of the paper's problem: the settings they differ in, their criteria "
      "at each R_k, the points whose outcome changed and those studied in one only, and (--out) "
      "both validity boundaries on one map");
  diff->add_option("A", flags->study_a, "the first study's name")->required()->type_name("STUDY");
  diff->add_option("B", flags->study_b, "the second study's name")->required()->type_name("STUDY");
  AddDatabaseFlag(diff, flags->database_path);
  diff->add_option("--db-b", flags->database_b,
                   "the database of study B, when not --db's (a study compared across databases)");
  AddThresholdFlags(diff, flags->thresholds);
  diff->add_option("--tolerance", flags->tolerance,
                   "relative tolerance within which the numbers of two points (R_k, R_ftrunc, dt, "
                   "window, damping) are the same")
      ->capture_default_str()
      ->check(FiniteIn(0.0, false, 0.1));
  diff->add_option("--format", flags->format,
                   "standard output: the report as text and tables, every point as CSV, or the "
                   "whole report as JSON")
      ->capture_default_str()
      ->check(CLI::IsMember({"table", "csv", "json"}));
  diff->add_option("--out", flags->out,
                   "draw both validity boundaries on one map into this image, .png or .svg");
  diff->callback([flags] { Diff(*flags); });
}

}  // namespace shockmap
