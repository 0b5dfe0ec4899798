#pragma once
// The study kind of scene sweeps (paper §3): the points are one scene file with some numeric
// parameters set; each is scored with Err (eq. 8) on a named displacement and SRf (eq. 9) on a
// named zone's first shock, against the same scene run with the study's refined settings.

#include "db/scene_points.h"
#include "engine/study_kind.h"
#include "formats/study_file.h"

namespace shockmap {

class SceneStudy {
 public:
  using Point = SceneParameters;
  using Reference = SceneReferenceRow;  // Stored whatever its status, with its histories.
  using Outcome = PointOutcome<SceneScoreRow>;

  explicit SceneStudy(SceneStudySpec spec);

  const StudyHeader& Header() const { return header_; }
  const PointTable& Table() const { return kScenePoints; }
  void CheckStoredSpec(const std::string& stored_json, const std::string& database_path) const;
  const std::vector<Point>& Points() const { return spec_.points; }
  NewPoint Describe(const Point& point) const;

  double ReferenceCost(const Point&) const { return 1.0; }  // Every reference is the same run.
  Reference ComputeReference(const Point& point) const;
  std::optional<StoredReference<Reference>> FindReference(StudyDatabase& db,
                                                          const std::string& key) const;
  std::int64_t StoreReference(StudyDatabase& db, const Reference& reference,
                              std::int64_t run_id) const;

  Outcome Score(const Point& point, const Reference& reference, std::int64_t reference_id) const;
  void StoreOutcome(StudyDatabase& db, std::int64_t point_id, std::int64_t run_id,
                    const PointOrigin& origin, const Outcome& outcome) const;

  void EncodeReference(const Reference& reference, ByteWriter& out) const;
  Reference DecodeReference(ByteReader& in) const;
  void EncodeOutcome(const Outcome& outcome, ByteWriter& out) const;
  Outcome DecodeOutcome(ByteReader& in) const;

 private:
  SceneScoreRow Measure(const Scene& scene, const struct SceneRun& run) const;

  SceneStudySpec spec_;
  StudyHeader header_;
};

static_assert(StudyKind<SceneStudy>);

}  // namespace shockmap
