#include "bench/cluster_model/task_costs.h"

#include <algorithm>
#include <functional>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "core/cpu_timer.h"
#include "engine/study_run.h"

namespace shockmap {
namespace {

// Wall seconds of f() on this thread (the machine otherwise idle).
template <typename F>
double SecondsOf(F&& f) {
  const CpuTimer timer;
  f();
  return timer.WallSeconds();
}

// Group size and wall seconds of each stored group; the points' first 16 are stored one per
// transaction (a point arriving alone), the others in groups of kMaxGroup.
template <StudyKind Kind>
std::vector<std::pair<double, double>> StoreInGroups(const Kind& kind, StudyDatabase& db,
                                                     std::int64_t run_id,
                                                     const std::vector<FinishedPoint<Kind>>& all) {
  std::vector<std::pair<double, double>> groups;
  const std::span<const FinishedPoint<Kind>> points(all);
  std::size_t i = 0;
  while (i < points.size()) {
    const std::size_t n = std::min(i < 16 ? std::size_t{1} : kMaxGroup, points.size() - i);
    const double s =
        SecondsOf([&] { StoreOutcomes<Kind>(kind, db, run_id, points.subspan(i, n)); });
    groups.push_back({static_cast<double>(n), s});
    i += n;
  }
  return groups;
}

// Least squares of seconds = group_s + size x stored_point_s, with group_s >= 0 (through the
// origin when the free fit's is negative: a transaction costs no less than nothing).
void FitGroupCost(const std::vector<std::pair<double, double>>& groups, StudyCosts& costs) {
  double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  for (const auto& [x, y] : groups) {
    n += 1.0, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  costs.stored_point_s = det > 0.0 ? (n * sxy - sx * sy) / det : sy / std::max(sx, 1.0);
  costs.group_s = det > 0.0 ? (sy - costs.stored_point_s * sx) / n : 0.0;
  if (costs.group_s < 0.0) {
    costs.group_s = 0.0;
    costs.stored_point_s = sxy / sxx;
  }
}

template <StudyKind Kind>
MeasuredCosts Measure(const Kind& kind, const std::string& path, std::size_t points_to_measure) {
  StudyDatabase db(path);
  const StudyHeader& header = kind.Header();
  std::vector<NewPoint> rows;
  std::map<std::string, std::size_t> index_of;  // Point key -> index in Points().
  for (std::size_t i = 0; i < kind.Points().size(); ++i) {
    rows.push_back(kind.Describe(kind.Points()[i]));
    index_of[rows.back().point_key] = i;
  }
  const RegisteredRun registered =
      db.RegisterRun({header.name, header.spec_json, kind.Table(), rows, CurrentProvenance(1)});
  const std::int64_t study_id = registered.study_id, run_id = registered.run_id;
  std::vector<PendingPoint> pending = db.PointsToCompute(kind.Table(), study_id, false);
  MeasuredCosts m;
  m.points = pending.size();
  m.points_measured = points_to_measure == 0 ? m.points : std::min(points_to_measure, m.points);
  const auto point_of = [&](const PendingPoint& p) -> const auto& {
    return kind.Points()[index_of.at(p.point_key)];
  };

  // The references the measured points need, longest first (the engine's MissingReferences).
  std::vector<std::size_t> first_user;  // Index in `pending` of a point needing each.
  std::map<std::string, std::size_t> task_of;
  for (std::size_t j = 0; j < m.points_measured; ++j) {
    if (task_of.emplace(pending[j].reference_key, first_user.size()).second)
      first_user.push_back(j);
  }
  std::ranges::stable_sort(first_user, std::greater{},
                           [&](std::size_t j) { return kind.ReferenceCost(point_of(pending[j])); });
  std::map<std::string, std::pair<std::int64_t, typename Kind::Reference>> stored;
  for (std::size_t k = 0; k < first_user.size(); ++k) {
    const PendingPoint& p = pending[first_user[k]];
    task_of[p.reference_key] = k;
    TaskCost t;
    t.reference = true;
    std::optional<typename Kind::Reference> reference;
    t.compute_s = SecondsOf([&] { reference.emplace(kind.ComputeReference(point_of(p))); });
    ByteWriter out;
    kind.EncodeReference(*reference, out);
    const std::string bytes = out.Take();
    t.answer_bytes = static_cast<double>(bytes.size() + p.reference_key.size() + 25);
    std::int64_t id = 0;
    t.consume_s = SecondsOf([&] {
      ByteReader in(bytes);
      id = kind.StoreReference(db, kind.DecodeReference(in), run_id);
    });
    stored.emplace(p.reference_key, std::make_pair(id, std::move(*reference)));
    m.costs.tasks.push_back(t);
  }
  m.references = first_user.size();

  // The measured points, scored and their answers read back as rank 0 reads them.
  std::vector<FinishedPoint<Kind>> finished;
  double task_bytes = 0.0;
  for (std::size_t j = 0; j < m.points_measured; ++j) {
    const PendingPoint& p = pending[j];
    const auto& [id, reference] = stored.at(p.reference_key);
    TaskCost t;
    t.after = task_of.at(p.reference_key);
    typename Kind::Outcome outcome;
    t.compute_s = SecondsOf([&] { outcome = kind.Score(point_of(p), reference, id); });
    ByteWriter out;
    EncodeOutcome(kind, outcome, out);
    const std::string bytes = out.Take();
    t.answer_bytes = static_cast<double>(bytes.size() + 8);
    t.consume_s = SecondsOf([&] {
      ByteReader in(bytes);
      finished.push_back({p.point_id, PointOrigin{"bench", 1}, DecodeOutcome(kind, in)});
    });
    m.costs.tasks.push_back(t);
    // [type][index][reference key][its id][error][reference sent?], framed by the index.
    task_bytes += static_cast<double>(1 + 8 + 8 + p.reference_key.size() + 8 + 8 + 1 + 8);
  }
  m.costs.task_bytes = task_bytes / std::max<double>(1.0, static_cast<double>(m.points_measured));
  for (std::size_t j = m.points_measured; j < m.points; ++j) {  // Their outcomes repeat too.
    finished.push_back(
        {pending[j].point_id, PointOrigin{"bench", 1}, finished[j % m.points_measured].outcome});
  }
  FitGroupCost(StoreInGroups(kind, db, run_id, finished), m.costs);
  db.EndRun(run_id, RunEnd::kCompleted);
  for (std::size_t j = m.points_measured; j < m.points; ++j) {
    m.costs.tasks.push_back(m.costs.tasks[m.references + j % m.points_measured]);
  }
  return m;
}

}  // namespace

MeasuredCosts MeasureStudy(const StudyFile& study, const std::string& scratch_database,
                           std::size_t points_to_measure) {
  return WithStudyKind(
      study, [&](const auto& kind) { return Measure(kind, scratch_database, points_to_measure); });
}

}  // namespace shockmap
