#pragma once
// The study kind of the paper's problem (paper §2): a grid of (R_k, R_ftrunc, dt, scheme)
// points on the cantilever, each scored with Err (eq. 8) and SRf (eq. 9) against the
// semi-analytical reference of its R_k and window.

#include <memory>

#include "compare/comparison.h"
#include "db/canonical_points.h"
#include "engine/study_kind.h"
#include "specs/study_file.h"

namespace shockmap {

class CanonicalStudy {
 public:
  using Point = StudyPoint;
  // A reference with what identifies it in the database.
  struct Reference {
    std::string key;
    double r_k = 0.0, window_s = 0.0;
    std::shared_ptr<const ReferenceRun> run;  // Shared by every point scored against it.
  };
  using Outcome = PointOutcome<ScoreRow>;

  explicit CanonicalStudy(StudySpec spec);

  const StudyHeader& Header() const { return header_; }
  const PointTable& Table() const { return kCanonicalPoints; }
  static constexpr StudyFileKind kFileKind = StudyFileKind::kCanonical;
  static constexpr std::string_view kChangeableSettings = "grid axes";
  std::optional<SettingChange> ChangedSetting(const nlohmann::json& stored,
                                              const std::string& database_path) const;
  const std::vector<Point>& Points() const { return spec_.points; }
  // Keyed by its parameters; its reference by the problem, window and reference settings.
  NewPoint Describe(const Point& point) const;

  // The reference's truncation R_fref: the number of modes and transitions grow with it.
  double ReferenceCost(const Point& point) const;
  // The piecewise-modal solution at R_fref and its check at R_fref / 3 (docs/physics.md §2).
  Reference ComputeReference(const Point& point) const;
  std::optional<StoredReference<Reference>> FindReference(StudyDatabase& db,
                                                          const std::string& key) const;
  std::int64_t StoreReference(StudyDatabase& db, const Reference& reference,
                              std::int64_t run_id) const;
  // Its two truncations agree within the study's reference tolerance (docs/physics.md §2);
  // progress counts the references that do not.
  bool ReferenceConverged(const Reference& reference) const;

  // The point's scheme on the canonical scene, Err and SRf against the reference; nothing
  // scored when the reference is unconverged (docs/physics.md §4).
  Outcome Score(const Point& point, const Reference& reference, std::int64_t reference_id) const;

  void EncodeReference(const Reference& reference, ByteWriter& out) const;
  Reference DecodeReference(ByteReader& in) const;
  void EncodeScore(const ScoreRow& score, ByteWriter& out) const;
  ScoreRow DecodeScore(ByteReader& in) const;

 private:
  StudySpec spec_;
  StudyHeader header_;
};

static_assert(StudyKind<CanonicalStudy>);

}  // namespace shockmap
