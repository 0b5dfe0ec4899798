#include "db/corrupt_rows.h"

#include <cmath>

#include <fmt/format.h>

#include "db/sqlite_handle.h"

namespace shockmap {

void ThrowCorrupt(const std::string& database_path, const std::string& row,
                  const std::string& reason) {
  throw DbError(database_path + ": database corrupt: " + row + ": " + reason);
}

const std::string& StoredText(const TableCell& cell, const std::string& database_path,
                              const std::string& row, const std::string& column) {
  if (const auto* text = std::get_if<std::string>(&cell)) return *text;
  const char* held = std::holds_alternative<std::monostate>(cell) ? "NULL"
                     : std::holds_alternative<double>(cell)       ? "a real"
                                                                  : "an integer";
  ThrowCorrupt(database_path, row, column + " holds " + held + " where text belongs");
}

std::int64_t StoredCount(const TableCell& cell, const std::string& database_path,
                         const std::string& row, const std::string& column, std::int64_t max) {
  const auto* count = std::get_if<std::int64_t>(&cell);
  if (count == nullptr || *count < 0 || *count > max) {
    const std::string held = count != nullptr ? std::to_string(*count)
                             : std::holds_alternative<double>(cell)
                                 ? fmt::format("{}", std::get<double>(cell))
                                 : std::string("no integer");
    ThrowCorrupt(database_path, row,
                 fmt::format("{} holds {} (a count from 0 to {})", column, held, max));
  }
  return *count;
}

void CheckFinite(const std::string& database_path, const std::string& row,
                 const StoredSamples& signal) {
  for (std::size_t i = 0; i < signal.values.size(); ++i) {
    if (!std::isfinite(signal.values[i])) {
      ThrowCorrupt(database_path, row,
                   fmt::format("{} value {} is {} (values must be finite)", signal.column, i,
                               signal.values[i]));
    }
  }
}

void CheckEqualLengths(const std::string& database_path, const std::string& row,
                       std::initializer_list<StoredSamples> signals) {
  const StoredSamples& first = *signals.begin();
  for (const StoredSamples& s : signals) {
    if (s.values.size() != first.values.size()) {
      ThrowCorrupt(database_path, row,
                   fmt::format("{} holds {} samples, {} {} (they must be equal)", first.column,
                               first.values.size(), s.column, s.values.size()));
    }
  }
}

void CheckSampledTogether(const std::string& database_path, const std::string& row,
                          double output_dt_s, std::initializer_list<StoredSamples> signals) {
  if (!std::isfinite(output_dt_s) || output_dt_s <= 0.0) {
    ThrowCorrupt(database_path, row,
                 fmt::format("output_dt_s is {} (it must be finite and > 0)", output_dt_s));
  }
  CheckEqualLengths(database_path, row, signals);
  for (const StoredSamples& s : signals) CheckFinite(database_path, row, s);
}

void CheckReference(const std::string& database_path, const ReferenceRow& r) {
  const std::string row = "reference " + std::to_string(r.reference_id);
  CheckSampledTogether(database_path, row, r.output_dt_s,
                       {{"tip_m", r.tip_m}, {"force_n", r.force_n}});
  if (!std::isfinite(r.window_s) || r.window_s <= 0.0) {
    ThrowCorrupt(database_path, row,
                 fmt::format("window_s is {} (it must be finite and > 0)", r.window_s));
  }
  // Samples at t = 0, output_dt_s, ... up to the window's end (ReferenceSolution::Sample).
  const double expected = std::floor(r.window_s / r.output_dt_s + 1e-9) + 1.0;
  if (static_cast<double>(r.tip_m.size()) != expected) {
    ThrowCorrupt(database_path, row,
                 fmt::format("tip_m holds {} samples, but a window of {} s sampled every {} s "
                             "holds {:.0f}",
                             r.tip_m.size(), r.window_s, r.output_dt_s, expected));
  }
}

void CheckSceneReference(const std::string& database_path, const SceneReferenceRow& r) {
  const std::string row = "scene reference " + std::to_string(r.reference_id);
  if (r.status == "ok") {
    CheckSampledTogether(database_path, row, r.output_dt_s,
                         {{"displacement_m", r.displacement_m}, {"force_n", r.force_n}});
  } else {
    CheckEqualLengths(database_path, row,
                      {{"displacement_m", r.displacement_m}, {"force_n", r.force_n}});
  }
}

}  // namespace shockmap
