#pragma once
// The study kind of scene sweeps (paper §3): the points are one scene file with some numeric
// parameters set; each is scored with Err (eq. 8) on a named displacement and SRf (eq. 9) on a
// named zone's first shock, against the same scene run with the study's refined settings.

#include "db/scene_points.h"
#include "engine/study_kind.h"
#include "specs/study_file.h"

namespace shockmap {

class SceneStudy {
 public:
  using Point = SceneParameters;
  using Reference = SceneReferenceRow;  // Stored whatever its status, with its histories.
  using Outcome = PointOutcome<SceneScoreRow>;

  explicit SceneStudy(SceneStudySpec spec);

  const StudyHeader& Header() const { return header_; }
  const PointTable& Table() const { return kScenePoints; }
  static constexpr StudyFileKind kFileKind = StudyFileKind::kSceneSweep;
  static constexpr std::string_view kChangeableSettings = "the sweep";
  std::optional<SettingChange> ChangedSetting(const nlohmann::json& stored,
                                              const std::string& database_path) const;
  const std::vector<Point>& Points() const { return spec_.points; }
  // Keyed by its parameters' JSON; its reference (the scene with the refined settings over it)
  // by the reference's parameters' JSON, a few bytes: the reference's own key, which holds the
  // whole scene, is stored once, in scene_references (schema 13).
  NewPoint Describe(const Point& point) const;

  double ReferenceCost(const Point&) const { return 1.0; }  // Every reference is the same run.
  // The point's scene with the study's reference settings applied over its parameters.
  Reference ComputeReference(const Point& point) const;
  // The stored reference of the point whose Describe gave `reference_parameters`.
  std::optional<StoredReference<Reference>> FindReference(
      StudyDatabase& db, const std::string& reference_parameters) const;
  std::int64_t StoreReference(StudyDatabase& db, const Reference& reference,
                              std::int64_t run_id) const;

  // The point's scene scored against the reference's histories (compare/scene_scoring.h); a
  // failed reference fails the point.
  Outcome Score(const Point& point, const Reference& reference, std::int64_t reference_id) const;

  void EncodeReference(const Reference& reference, ByteWriter& out) const;
  Reference DecodeReference(ByteReader& in) const;
  void EncodeScore(const SceneScoreRow& score, ByteWriter& out) const;
  SceneScoreRow DecodeScore(ByteReader& in) const;

 private:
  SceneStudySpec spec_;
  StudyHeader header_;
};

static_assert(StudyKind<SceneStudy>);

}  // namespace shockmap
