#pragma once
// The report's page of one stored point of a canonical study (points/point_ID.html): its Fig. 3
// (tip displacement and contact force against the reference, inline SVG drawn from the run the
// report computed again), the `shockmap compare` command that recomputes it, and its stored
// values.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "db/read_only_query.h"
#include "specs/study_spec.h"
#include "validation/scores.h"

namespace shockmap {

// The Fig. 3 the report drew for a point, from its run computed again against the stored
// reference (runs' histories are not stored): views/fig3_svg.h's figure and note, the scores of
// that run, and for some points a folder of files beside the page (numerical.csv,
// reference.csv, fig3.png, fig3.gp).
struct PointFigure {
  std::string svg;
  std::string note;  // HTML; empty for a run that reached its end.
  ScoreValues scores;
  std::optional<std::filesystem::path> files;
};

// A stored point of a canonical study with its point in the stored study file.
struct StoredStudyPoint {
  StudyPoint point;
  std::string reference_key;
};
// The stored points of `study` found in `spec` (its stored study file), by point_id.
std::map<std::int64_t, StoredStudyPoint> StudyPointsById(const std::string& database_path,
                                                         const std::string& study,
                                                         const StudySpec& spec);

// The command that recomputes `point` of `spec` into out_dir and draws its Fig. 3. The
// settings `compare` has no flag for, where the study differs from compare's defaults, are
// listed in `unmatched` ("PSD samples 8192 (compare: 4096)").
std::string CompareCommand(const StudySpec& spec, const StudyPoint& point,
                           const std::string& out_dir, std::vector<std::string>* unmatched);

struct PointPageInput {
  std::string study;
  std::int64_t point_id = 0;
  const std::vector<std::string>* columns = nullptr;  // The `results` view's columns.
  const std::vector<TableCell>* row = nullptr;        // And the point's row.
  std::optional<StudyPoint> point;  // Its point in the stored study file (none: not found).
  const StudySpec* spec = nullptr;
  std::optional<PointFigure> figure;
};

// The page's HTML; its links are relative to points/ (the index is ../index.html).
std::string PointPage(const PointPageInput& in);

}  // namespace shockmap
