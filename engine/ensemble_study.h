#pragma once
// The study kind of ensembles of a scene (docs/ensembles.md): each point is one member, the
// scene under its own draws for one clearance state and one numerical setting, run for the
// largest force of every zone; its reference is the state's nominal run (every draw at its
// centre, the refined setting), stored beside the members for the sizing view.

#include "db/ensemble_members.h"
#include "engine/study_kind.h"
#include "specs/study_file.h"

namespace shockmap {

class EnsembleStudy {
 public:
  using Point = EnsembleMember;
  using Reference = EnsembleReferenceRow;  // Stored whatever its status.
  using Outcome = PointOutcome<EnsembleMemberRow>;

  explicit EnsembleStudy(EnsembleStudySpec spec);

  const StudyHeader& Header() const { return header_; }
  const PointTable& Table() const { return kEnsembleMembers; }
  static constexpr StudyFileKind kFileKind = StudyFileKind::kSceneEnsemble;
  static constexpr std::string_view kChangeableSettings =
      "the member count, the settings and new clearance states";
  std::optional<SettingChange> ChangedSetting(const nlohmann::json& stored,
                                              const std::string& database_path) const;
  const std::vector<Point>& Points() const { return spec_.points; }
  // Keyed by state, setting and index; its reference key is its state's name, a few bytes in
  // each of up to a million rows (the nominal run's own key, NominalKey, holds the whole scene
  // and is stored once, in its ensemble_references row).
  NewPoint Describe(const Point& point) const;

  double ReferenceCost(const Point&) const { return 1.0; }
  // The state's nominal scene at the refined setting.
  Reference ComputeReference(const Point& point) const;
  // The stored nominal run of the state named `state` (a member's reference key).
  std::optional<StoredReference<Reference>> FindReference(StudyDatabase& db,
                                                          const std::string& state) const;
  std::int64_t StoreReference(StudyDatabase& db, const Reference& reference,
                              std::int64_t run_id) const;

  // The member's run: its largest force per zone. Never throws.
  Outcome Score(const Point& point, const Reference& reference, std::int64_t reference_id) const;

  void EncodeReference(const Reference& reference, ByteWriter& out) const;
  Reference DecodeReference(ByteReader& in) const;
  void EncodeScore(const EnsembleMemberRow& score, ByteWriter& out) const;
  EnsembleMemberRow DecodeScore(ByteReader& in) const;

  const EnsembleStudySpec& Spec() const { return spec_; }

 private:
  EnsembleStudySpec spec_;
  StudyHeader header_;
};

static_assert(StudyKind<EnsembleStudy>);

}  // namespace shockmap
