#include "app/map_command.h"

#include <iostream>
#include <memory>

#include "analysis/scored_points.h"
#include "app/flag_checks.h"
#include "app/thresholds.h"
#include "db/study_database.h"
#include "formats/output_file.h"
#include "views/validity_map.h"

namespace shockmap {
namespace {

struct MapFlags {
  std::string database_path = kDefaultDatabasePath;
  std::string study;
  std::string metric = "err";
  std::string y = "rftrunc";
  double r_ftrunc = 0.0;
  ThresholdFlags thresholds;
  std::string out;
};

void Draw(const MapFlags& f) {
  if (!f.out.empty()) CheckPathLength(f.out, "--out");
  const std::string study = ResolveCanonicalStudy(f.database_path, f.study, "map");
  const auto points = LoadScoredPoints(f.database_path, study, "explicit-modal");
  MapOptions options;
  options.metric = f.metric;
  options.y = *MapAxisFromString(f.y);
  if (f.r_ftrunc > 0.0) options.r_ftrunc = f.r_ftrunc;
  const std::string out = !f.out.empty() ? f.out
                                         : "out/maps/" + study + "_" + f.metric +
                                               (options.y == MapAxis::kDt ? "_dt" : "") + ".png";
  DrawValidityMap(study, points,
                  DeriveCriteria(points, ThresholdsFor(f.thresholds, f.database_path, study)),
                  options, out);
  std::cout << "map written to " << out << '\n';
}

}  // namespace

void AddMapCommand(CLI::App& app) {
  auto flags = std::make_shared<MapFlags>();
  CLI::App* map = app.add_subcommand(
      "map",
      "Validity map of a study (explicit modal scheme): a metric over log R_k and log "
      "R_ftrunc or dt/dt_sharp, with the derived boundary and the paper's rules");
  map->add_option("STUDY", flags->study, "study name (default: the database's only study)");
  AddDatabaseFlag(map, flags->database_path);
  map->add_option("--metric", flags->metric,
                  "what the colour shows: a score, the outcome or the CPU time")
      ->capture_default_str()
      ->check(CLI::IsMember(MapMetrics()));
  map->add_option("--y", flags->y, "vertical axis: truncation or time step")
      ->capture_default_str()
      ->check(CLI::IsMember({"rftrunc", "dt"}));
  map->add_option("--rftrunc", flags->r_ftrunc,
                  "truncation shown by --y dt (default: the largest studied)")
      ->check(FiniteAbove(1.0, false));
  AddThresholdFlags(map, flags->thresholds);
  map->add_option("--out", flags->out,
                  "image file, .png or .svg (default: out/maps/STUDY_METRIC.png)");
  map->callback([flags] {
    if (flags->r_ftrunc > 0.0 && flags->y != "dt") {
      throw CLI::ValidationError("--rftrunc",
                                 "chooses the truncation of a --y dt map; with --y " + flags->y +
                                     " every truncation is shown (add --y dt or drop --rftrunc)");
    }
    Draw(*flags);
  });
}

}  // namespace shockmap
