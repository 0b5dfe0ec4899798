#pragma once
// What the study engine (engine/study_engine.h) asks of a kind of study. The paper's problem
// (engine/canonical_study.h) and scene sweeps (engine/scene_study.h) are two kinds; a new kind
// is a new class that meets this concept, with no change to the engine's loop.
//
// A kind has three types:
//   Point     one point of the study, as the spec describes it (what a worker needs);
//   Reference what its points are scored against, computed once per database and shared;
//   Outcome   one point's result, as it will be stored: a PointOutcome of the kind's score row.
// The Compute/Score members run on workers: they are const, thread-safe and never touch the
// database. Everything that takes a StudyDatabase runs on the one writer. A worker may be
// another process (an MPI rank) that parsed the same study file: a point travels as its index
// in Points(), a reference and an outcome as the bytes of their Encode/Decode pair.

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/run_status.h"
#include "db/study_database.h"
#include "engine/byte_codec.h"
#include "specs/setting_change.h"
#include "specs/study_file.h"

namespace shockmap {

// What every study has: the file it came from, its name, and the spec stored with it.
struct StudyHeader {
  std::string file;
  std::string name;
  std::string spec_json;
};

// One point's result as stored: its status, a message, and the kind's score row when it was
// computed.
template <typename Score>
struct PointOutcome {
  RunStatus status = RunStatus::kFailed;
  std::string message;
  std::optional<Score> score;
};

// A status as it travels between ranks: its text. Throws std::runtime_error on an unknown one.
inline RunStatus DecodeStatus(ByteReader& in) {
  const std::string text = in.GetString();
  if (const auto status = RunStatusFromString(text)) return *status;
  throw std::runtime_error("message with an unknown status \"" + text + "\"");
}

// A reference as found in the database, with its id.
template <typename Reference>
struct StoredReference {
  std::int64_t id = 0;
  Reference value;
};

template <typename K>
concept StudyKind = requires(const K& kind, StudyDatabase& db, const typename K::Point& point,
                             const typename K::Reference& reference,
                             const typename K::Outcome& outcome, const std::string& text,
                             std::int64_t id, const PointOrigin& origin, ByteWriter& writer,
                             ByteReader& reader, const nlohmann::json& stored) {
  { kind.Header() } -> std::same_as<const StudyHeader&>;
  { kind.Table() } -> std::same_as<const PointTable&>;
  // The study file kind it reads and what may change under a study's name ("grid axes").
  { K::kFileKind } -> std::convertible_to<StudyFileKind>;
  { K::kChangeableSettings } -> std::convertible_to<std::string_view>;
  // The first lifelong setting (what the stored scores depend on, declared as the kind's
  // settings key; specs/setting_change.h) in which a stored spec of this kind (parsed JSON;
  // `text` names the database) differs from this one; nullopt when it keeps them all. May
  // throw InputError when the stored spec is unreadable.
  { kind.ChangedSetting(stored, text) } -> std::same_as<std::optional<SettingChange>>;
  { kind.Points() } -> std::same_as<const std::vector<typename K::Point>&>;
  // The point's keys and parameter row.
  { kind.Describe(point) } -> std::same_as<NewPoint>;

  // Relative cost of the point's reference: references are computed longest first.
  { kind.ReferenceCost(point) } -> std::convertible_to<double>;
  // May throw: the points that need it then fail with the message.
  { kind.ComputeReference(point) } -> std::same_as<typename K::Reference>;
  {
    kind.FindReference(db, text)
    } -> std::same_as<std::optional<StoredReference<typename K::Reference>>>;
  // Returns the stored reference's id.
  { kind.StoreReference(db, reference, id) } -> std::same_as<std::int64_t>;

  // Must not throw (a failure is a 'failed' outcome). The id is the reference's stored id.
  { kind.Score(point, reference, id) } -> std::same_as<typename K::Outcome>;
  { outcome.status } -> std::convertible_to<RunStatus>;
  // The score row's writer in db/ (found by its type): StoreOutcomes below calls it inside the
  // transaction that stores the point's status.
  WriteScore(db.Raw(), id, outcome.score);

  // Decode(Encode(x)) scores and stores exactly as x does. Decode throws std::runtime_error
  // on a truncated message.
  kind.EncodeReference(reference, writer);
  { kind.DecodeReference(reader) } -> std::same_as<typename K::Reference>;
  kind.EncodeScore(*outcome.score, writer);
  { kind.DecodeScore(reader) } -> std::same_as<typename decltype(outcome.score)::value_type>;
};

// A finished point as the writer holds it until its group is stored.
template <StudyKind Kind>
struct FinishedPoint {
  std::int64_t point_id = 0;
  PointOrigin origin;
  typename Kind::Outcome outcome;
};

// One transaction for the group: each point's status, origin and score row.
template <StudyKind Kind>
void StoreOutcomes(const Kind& kind, StudyDatabase& db, std::int64_t run_id,
                   std::span<const FinishedPoint<Kind>> group) {
  StorePointOutcomes(db, kind.Table(), run_id, group.size(), [&](Connection& c, std::size_t i) {
    const FinishedPoint<Kind>& p = group[i];
    WriteScore(c, p.point_id, p.outcome.score);
    return PointStatus{p.point_id, p.origin, ToString(p.outcome.status), p.outcome.message};
  });
}

// An outcome as it travels between ranks: status, message, then the kind's score row if any.
template <StudyKind Kind>
void EncodeOutcome(const Kind& kind, const typename Kind::Outcome& outcome, ByteWriter& out) {
  out.Put(ToString(outcome.status));
  out.Put(outcome.message);
  out.Put(static_cast<std::uint8_t>(outcome.score.has_value()));
  if (outcome.score) kind.EncodeScore(*outcome.score, out);
}

template <StudyKind Kind>
typename Kind::Outcome DecodeOutcome(const Kind& kind, ByteReader& in) {
  typename Kind::Outcome outcome;
  outcome.status = DecodeStatus(in);
  outcome.message = in.GetString();
  if (in.Get<std::uint8_t>() != 0) outcome.score = kind.DecodeScore(in);
  return outcome;
}

}  // namespace shockmap
