#pragma once
// The HTML report of a stored study: a folder with index.html (header, contents, sortable
// tables, figures with their data and scripts linked, interactive validity maps) and, for a
// study of the paper's problem, one page per point under points/. The page needs nothing from
// the network; its figures are embedded, so index.html also reads alone.
//
// A study kind contributes its sections (CanonicalSections, SceneSections, EnsembleSections
// here; another kind adds its own function beside them), and WriteReportIndex writes the page
// around them.

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/scene.h"
#include "db/ensemble_members.h"
#include "db/study_database.h"
#include "specs/scene_study_spec.h"
#include "specs/study_spec.h"
#include "validation/validity_criteria.h"
#include "views/point_page.h"
#include "views/report_page.h"

namespace shockmap {

// What every report states in its header.
struct ReportContext {
  std::string database_path, study, kind;
  CriteriaOptions thresholds;
  Provenance writer;  // The code writing the report.
  std::filesystem::path dir;
};

// The points of a canonical study whose Fig. 3 the report also writes as files (histories as
// CSV, the figure by gnuplot), by point_id: at every studied R_k and
// its finest time step, the smallest passing truncation and the one below it (where the study
// turns from failing to passing), and at the R_k nearest the paper's Fig. 3 (3000) the smallest
// and largest truncation. At most two per R_k and two more.
std::vector<std::int64_t> PointsWorthFig3(const std::vector<ScoredPoint>& points,
                                          const CriteriaOptions& thresholds);

// A canonical study: outcomes, criteria, interactive maps, the gnuplot maps, Fig. 4, the cost
// front, the points table, provenance and the study file; writes the figures into ctx.dir and
// the point pages into ctx.dir/points. `figures`: every point's Fig. 3, by point_id.
std::vector<ReportSection> CanonicalSections(const ReportContext& ctx, const StudySpec& spec,
                                             const std::map<std::int64_t, PointFigure>& figures);

// The points whose Fig. 3 the report could not draw, each with why (a corrupt stored
// reference: the database's message).
ReportSection SkippedFigures(const std::map<std::int64_t, std::string>& reasons);

// A contact-force map drawn for a scene study: what it shows, and the map's image.
struct SceneForceMap {
  std::string label;
  std::filesystem::path png;
};

// A scene study: outcomes, the points with their parameters as columns, Err and SRf against
// each swept parameter, the contact-force maps, provenance and the study file.
std::vector<ReportSection> SceneSections(const ReportContext& ctx, const SceneStudySpec& spec,
                                         const std::vector<SceneForceMap>& maps);

// An ensemble study (docs/ensembles.md): at the default options of `shockmap sizing`, the
// hottest zone's and every zone's sizing statistics per clearance state and setting, the
// settings against the refined one, the mean impact statistics, the sizing pictures (drawn into
// ctx.dir/sizing), provenance and the study file. Throws InputError when no member is computed.
std::vector<ReportSection> EnsembleSections(const ReportContext& ctx, const StoredEnsemble& stored,
                                            const Scene& scene);

// Writes ctx.dir/index.html: the header (study, kind, date, code versions, database,
// thresholds) and the sections. Returns its path.
std::filesystem::path WriteReportIndex(const ReportContext& ctx,
                                       const std::vector<ReportSection>& sections);

}  // namespace shockmap
