#include "app/export_command.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "analysis/scored_points.h"
#include "app/flag_checks.h"
#include "core/input_error.h"
#include "db/ensemble_members.h"
#include "db/report_queries.h"
#include "db/stored_signals.h"
#include "db/study_database.h"
#include "engine/point_replay.h"
#include "formats/history_csv.h"
#include "formats/json_reader.h"
#include "formats/output_file.h"
#include "formats/table_output.h"
#include "specs/study_file.h"
#include "views/signal_csv.h"

namespace shockmap {
namespace {

struct ExportFlags {
  std::string database_path;
  std::string study;
  double r_k = 0.0;
  std::int64_t point_id = 0;
  std::string out;
};

StudyFileKind KindOf(const std::string& database_path, const std::string& study) {
  const auto json = StoredStudySpec(database_path, study);
  if (!json) throw InputError("no study named \"" + study + "\" in " + database_path);
  return StudyKindOf(ParseJsonText(*json, database_path + ": stored study " + study),
                     database_path);
}

// The studied R_k nearest to --rk (by ratio), as `cost --rk` and `advise --rk` take it.
double NearestScoredRk(const ExportFlags& f, const std::string& study) {
  const std::vector<double> studied = ScoredRks(f.database_path, study);
  if (studied.empty()) throw InputError("--rk: study " + study + " has no scored point");
  return *std::ranges::min_element(studied, {},
                                   [&](double r_k) { return std::abs(std::log(r_k / f.r_k)); });
}

// The one reference of the study at `r_k`; refused when several match.
std::int64_t ReferenceAtRk(const ExportFlags& f, const std::string& study, double r_k) {
  const auto ids = ReferenceIdsAt(f.database_path, study, r_k);
  if (ids.size() > 1) {
    throw InputError(fmt::format(
        "--rk: the points of study {} at R_k = {} are scored against {} references (windows or "
        "reference settings differ); name one point with --point ID",
        study, r_k, ids.size()));
  }
  return ids.front();
}

void ExportReference(const ExportFlags& f) {
  CheckPathLength(f.out, "--out");
  const std::string study = ResolveStudyName(f.database_path, f.study);
  const StudyFileKind kind = KindOf(f.database_path, study);
  if (kind == StudyFileKind::kSceneSweep && f.r_k > 0) {
    throw InputError("--rk: study " + study + " is a scene study; name a point with --point ID");
  }
  std::int64_t id = 0;
  std::string nearest;
  if (f.r_k > 0) {
    const double r_k = NearestScoredRk(f, study);
    if (std::abs(r_k - f.r_k) > 1e-9 * r_k) {
      nearest = fmt::format(" (R_k = {}, the studied value nearest to --rk {:g})", r_k, f.r_k);
    }
    id = ReferenceAtRk(f, study, r_k);
  } else if (const auto of_point = ReferenceOfPoint(f.database_path, study, f.point_id)) {
    id = *of_point;
  } else {
    throw InputError(fmt::format("--point: study {} has no scored point {}", study, f.point_id));
  }
  std::optional<StoredSignals> signals;
  if (kind == StudyFileKind::kCanonical) {
    if (const auto row = ReadReference(f.database_path, id)) signals = SignalsOf(*row);
  } else {
    signals = ReadSceneReferenceSignals(f.database_path, id);
  }
  if (!signals)
    throw InputError(fmt::format("reference {} is missing from {}", id, f.database_path));
  WriteSignalsCsv(*signals, f.out);
  fmt::print("reference {} of study {}{}: {} samples every {} s written to {}\n", id, study,
             nearest, signals->values.front().size(), signals->output_dt_s, f.out);
}

// The folder is created once the point is computed again, so that a refusal leaves none, and
// removed again when the histories cannot be written (a full disk).
void ExportPoint(const ExportFlags& f) {
  CheckPathLength(std::filesystem::path(f.out) / "reference.csv", "--out");
  const std::string study = ResolveStudyName(f.database_path, f.study);
  const ReplayedPoint replay = ReplayCanonicalPoint(f.database_path, study, f.point_id);
  WriteIntoDirectory(f.out, "--out", [&] { WriteComparisonCsv(replay.result, f.out); });
  const auto score = [](const std::optional<double>& v) {
    return v ? fmt::format("{}", *v) : std::string("not scored");
  };
  std::string scores;
  for (const ScoreDefinition& s : Scores()) {
    scores += fmt::format(", {} {}", s.label, score(replay.result.scores[s.name]));
  }
  fmt::print("point {} of study {} computed again: status {}{}\n", f.point_id, study,
             ToString(replay.result.status), scores);
  fmt::print("  histories {}/numerical.csv, reference.csv (the stored reference)\n", f.out);
}

// The listed impacts of an ensemble study's members, one CSV row each.
void ExportImpacts(const ExportFlags& f) {
  CheckPathLength(f.out, "--out");
  const std::string study = ResolveStudyName(f.database_path, f.study);
  if (KindOf(f.database_path, study) != StudyFileKind::kSceneEnsemble) {
    throw InputError("STUDY: study " + study +
                     " is not an ensemble study (\"kind\": \"scene_ensemble\"): only ensemble "
                     "members store their impacts one by one");
  }
  const Table impacts = EnsembleImpacts(f.database_path, study);
  AtomicFile file(f.out);
  WriteTable(impacts, TableFormat::kCsv, file.Stream());
  file.Commit();
  fmt::print("{} impacts of study {} written to {}\n", impacts.rows.size(), study, f.out);
  if (impacts.rows.empty()) {
    fmt::print(
        "  (none stored: the study file has no impact_statistics, or its scene lists no zone in "
        "outputs.impact_statistics.impact_table)\n");
  }
}

void AddStudyArgument(CLI::App* command, ExportFlags& f) {
  command->add_option("STUDY", f.study, "study name (default: the database's only study)");
  AddDatabaseFlag(command, f.database_path);
}

}  // namespace

void AddExportCommand(CLI::App& app) {
  auto flags = std::make_shared<ExportFlags>();
  CLI::App* cmd = app.add_subcommand(
      "export",
      "Write stored signals as CSV: a reference's, or a point's histories, or an ensemble's "
      "impacts");
  cmd->require_subcommand(1);

  CLI::App* reference = cmd->add_subcommand(
      "reference",
      "The stored signals of a reference (t_s, tip displacement or the scored displacement, "
      "contact force), chosen by R_k or by a point scored against it");
  AddStudyArgument(reference, *flags);
  CLI::Option* rk =
      reference->add_option("--rk", flags->r_k, "R_k of the study's points (the nearest studied)")
          ->check(Positive());
  CLI::Option* point =
      reference->add_option("--point", flags->point_id, "id of a point scored against it")
          ->check(WholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
  rk->excludes(point);
  reference->add_option("--out", flags->out, "CSV file to write")->required();
  reference->callback([flags, rk, point] {
    if (rk->count() + point->count() == 0) {
      throw CLI::ValidationError("--rk", "give --rk R_K or --point ID to choose the reference");
    }
    ExportReference(*flags);
  });

  CLI::App* one_point = cmd->add_subcommand(
      "point",
      "A point of a study of the paper's problem computed again against its stored reference: "
      "DIR/numerical.csv (tip displacement, velocity, contact force, energies) and "
      "DIR/reference.csv");
  AddStudyArgument(one_point, *flags);
  one_point->add_option("--id", flags->point_id, "point id (column point_id of `results`)")
      ->required()
      ->check(WholeNumberIn(1, std::numeric_limits<std::int64_t>::max()));
  one_point->add_option("--out", flags->out, "directory to write into")->required();
  one_point->callback([flags] { ExportPoint(*flags); });

  CLI::App* impacts = cmd->add_subcommand(
      "impacts",
      "The impacts an ensemble study stored one by one (the zones its scene lists in "
      "outputs.impact_statistics.impact_table), one CSV row per impact of each member: point_id, "
      "state, setting_json, member, zone_name and the columns of ensemble_member_impacts");
  AddStudyArgument(impacts, *flags);
  impacts->add_option("--out", flags->out, "CSV file to write")->required();
  impacts->callback([flags] { ExportImpacts(*flags); });
}

}  // namespace shockmap
