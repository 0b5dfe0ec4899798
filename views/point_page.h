#pragma once
// The report's page of one stored point of a canonical study (points/point_ID.html): its stored
// values, the `shockmap compare` command that recomputes it, and its Fig. 3 (tip displacement
// and contact force against the reference) when the report drew it; else a sentence saying why
// it is absent (runs' histories are not stored) and, once the command has drawn
// point_ID/fig3.png beside the page, that image.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "db/read_only_query.h"
#include "formats/study_spec.h"
#include "validation/scores.h"

namespace shockmap {

// A Fig. 3 the report drew for a point, from the stored reference: the image (CSV histories and
// script beside it) and the scores of that recomputation.
struct PointFigure {
  std::filesystem::path png;
  ScoreValues scores;
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
