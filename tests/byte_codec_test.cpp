// What travels between MPI ranks: each study kind's references and outcomes come back from their
// bytes field for field, and a truncated or overlong message is refused, never read past.

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "engine/canonical_study.h"
#include "engine/ensemble_study.h"
#include "engine/scene_study.h"

namespace shockmap {
namespace {

std::string Source(const std::string& relative) {
  return std::string(SHOCKMAP_SOURCE_DIR) + "/" + relative;
}

const CanonicalStudy& Quick() {
  static const CanonicalStudy kind(
      std::get<StudySpec>(ReadStudyFile(Source("studies/quick.json"))));
  return kind;
}

CanonicalStudy::Outcome ScoredOutcome() {
  ScoreRow s;
  s.reference_id = 7;
  s.err = 0.25;
  s.n_modes = 12;
  s.steps = 123456789012;
  s.first_shock_start_s = 1e-3;
  s.first_shock_impulse_n_s = 2e-2;
  s.first_shock_peak_n = 150.0;
  s.first_shock_duration_s = 1e-4;
  s.first_shock_rebounds = 3;
  s.shocks_json = R"([{"rebounds":3}])";
  s.srf_definition = "reference_window";
  return {RunStatus::kOk, "message", s};
}

TEST(ByteCodec, CanonicalOutcomeComesBackFieldForField) {
  const CanonicalStudy::Outcome sent = ScoredOutcome();
  ByteWriter out;
  EncodeOutcome(Quick(), sent, out);
  ByteReader in(out.Bytes());
  const CanonicalStudy::Outcome got = DecodeOutcome(Quick(), in);
  in.ExpectEnd();
  EXPECT_EQ(got.status, RunStatus::kOk);
  EXPECT_EQ(got.message, "message");
  ASSERT_TRUE(got.score.has_value());
  EXPECT_EQ(got.score->reference_id, 7);
  EXPECT_EQ(got.score->err, 0.25);
  EXPECT_FALSE(got.score->srf.has_value());
  EXPECT_EQ(got.score->n_modes, 12);
  EXPECT_EQ(got.score->steps, 123456789012);
  EXPECT_EQ(got.score->first_shock_rebounds, 3);
  EXPECT_EQ(got.score->first_shock_peak_n, 150.0);
  EXPECT_EQ(got.score->first_shock_duration_s, 1e-4);
  EXPECT_EQ(got.score->shocks_json, sent.score->shocks_json);
  EXPECT_EQ(got.score->srf_definition, "reference_window");
}

TEST(ByteCodec, CanonicalReferenceComesBackSampleForSample) {
  ReferenceRun run;
  run.tip_m = {0.0, 1e-5, {0.1, -0.2, 0.30000000000000004}};
  run.force_n = {0.0, 1e-5, {0.0, 5.0, 0.0}};
  run.shocks.push_back(Shock{1e-5, 2e-5, 5.0, 1e-5, 5e-5, 1, false});
  run.summary.n_transitions = 4;
  run.convergence.difference = 1e-4;
  const CanonicalStudy::Reference sent{"key", 1000.0, 0.05,
                                       std::make_shared<const ReferenceRun>(run)};
  ByteWriter out;
  Quick().EncodeReference(sent, out);
  ByteReader in(out.Bytes());
  const CanonicalStudy::Reference got = Quick().DecodeReference(in);
  in.ExpectEnd();
  EXPECT_EQ(got.key, "key");
  EXPECT_EQ(got.run->tip_m.values, run.tip_m.values);
  EXPECT_EQ(got.run->force_n.values, run.force_n.values);
  ASSERT_EQ(got.run->shocks.size(), 1u);
  EXPECT_EQ(got.run->shocks[0].impulse_n_s, 5e-5);
  EXPECT_EQ(got.run->summary.n_transitions, 4);
  EXPECT_EQ(got.run->convergence.difference, 1e-4);
}

TEST(ByteCodec, SceneOutcomeComesBackFieldForField) {
  const SceneStudy scene(
      std::get<SceneStudySpec>(ReadStudyFile(Source("studies/bundle_row_truncation.json"))));
  SceneScoreRow s;
  s.srf = 1.5;
  s.largest_force_zone = "pin_2";
  s.first_shock_impulse_n_s = 0.03;
  ByteWriter out;
  EncodeOutcome(scene, {RunStatus::kDiverged, "why", s}, out);
  ByteReader in(out.Bytes());
  const SceneStudy::Outcome got = DecodeOutcome(scene, in);
  in.ExpectEnd();
  EXPECT_EQ(got.status, RunStatus::kDiverged);
  ASSERT_TRUE(got.score.has_value());
  EXPECT_EQ(got.score->srf, 1.5);
  EXPECT_FALSE(got.score->err.has_value());
  EXPECT_EQ(got.score->largest_force_zone, "pin_2");
  EXPECT_EQ(got.score->first_shock_impulse_n_s, 0.03);
}

TEST(ByteCodec, EnsembleOutcomeComesBackZoneForZoneAndImpactForImpact) {
  const EnsembleStudy ensemble(
      std::get<EnsembleStudySpec>(ReadStudyFile(Source("studies/bundle_hex_ensemble.json"))));
  EnsembleMemberRow s;
  s.member_seed = "0x00000000000000ff";
  s.steps = 7;
  s.zones.resize(2);
  s.zones[0].max_force_n = 12.5;
  s.zones[1].max_force_n = 0.0;
  s.zones[1].impacts = 3;
  s.zones[1].wear_work_rate_w = 0.25;
  s.zones[1].wear_volume_m3 = 7.5e-14;
  s.impacts.resize(2);
  s.impacts[0].zone = 1;
  s.impacts[0].impact = 1;
  s.impacts[0].impulse_n_s = 0.125;
  s.impacts[1].zone = 1;
  s.impacts[1].impact = 2;
  s.impacts[1].impact_speed_m_s = 0.5;
  s.impacts[1].rebounds = 4;
  ByteWriter out;
  EncodeOutcome(ensemble, {RunStatus::kOk, "", s}, out);
  ByteReader in(out.Bytes());
  const EnsembleStudy::Outcome got = DecodeOutcome(ensemble, in);
  in.ExpectEnd();
  ASSERT_TRUE(got.score.has_value());
  EXPECT_EQ(got.score->member_seed, s.member_seed);
  EXPECT_EQ(got.score->steps, 7);
  ASSERT_EQ(got.score->zones.size(), 2u);
  EXPECT_EQ(got.score->zones[0].max_force_n, 12.5);
  EXPECT_FALSE(got.score->zones[0].impacts.has_value());
  EXPECT_EQ(got.score->zones[1].impacts, 3);
  EXPECT_EQ(got.score->zones[1].wear_work_rate_w, 0.25);
  EXPECT_FALSE(got.score->zones[1].rms_force_n.has_value());
  EXPECT_EQ(got.score->zones[1].wear_volume_m3, 7.5e-14);
  EXPECT_FALSE(got.score->zones[1].friction_power_w.has_value());
  ASSERT_EQ(got.score->impacts.size(), 2u);
  EXPECT_EQ(got.score->impacts[0].impulse_n_s, 0.125);
  EXPECT_FALSE(got.score->impacts[0].impact_speed_m_s.has_value());
  EXPECT_EQ(got.score->impacts[1].impact, 2);
  EXPECT_EQ(got.score->impacts[1].impact_speed_m_s, 0.5);
  EXPECT_EQ(got.score->impacts[1].rebounds, 4);
}

TEST(ByteCodec, TruncatedOrOverlongMessagesAreRefused) {
  ByteWriter out;
  EncodeOutcome(Quick(), ScoredOutcome(), out);
  const std::string bytes = out.Bytes();
  for (std::size_t cut : {std::size_t{0}, std::size_t{5}, bytes.size() / 2, bytes.size() - 1}) {
    ByteReader in(std::string_view(bytes).substr(0, cut));
    EXPECT_THROW(DecodeOutcome(Quick(), in), std::runtime_error) << "cut at " << cut;
  }
  const std::string longer = bytes + "x";
  ByteReader in(longer);
  DecodeOutcome(Quick(), in);
  EXPECT_THROW(in.ExpectEnd(), std::runtime_error);
  // A length prefix larger than the message.
  ByteWriter huge;
  huge.Put(std::uint64_t{1} << 60);
  ByteReader h(huge.Bytes());
  EXPECT_THROW(h.GetDoubles(), std::runtime_error);
}

}  // namespace
}  // namespace shockmap
