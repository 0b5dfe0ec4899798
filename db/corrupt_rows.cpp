#include "db/corrupt_rows.h"

#include <algorithm>
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

namespace {

// At most 40 bytes of a stored text, quoted, control and non-ASCII bytes escaped.
std::string QuotedText(const std::string& text) {
  constexpr std::size_t kShown = 40;
  std::string out = "\"";
  for (std::size_t i = 0; i < std::min(text.size(), kShown); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20 || c >= 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + (text.size() > kShown ? "\"..." : "\"");
}

std::string_view TypeWord(SqlType type) {
  switch (type) {
    case SqlType::kInteger:
      return "an integer";
    case SqlType::kReal:
      return "a number";
    case SqlType::kText:
      return "text";
    case SqlType::kBlob:
      return "a blob of doubles";
  }
  return "";
}

// "(it must be a number, finite and > 0)" for a value of another type, "(it must be finite and
// > 0)" for a number out of the range.
std::string MustBe(const StoredColumn& column, bool typed) {
  if (typed) return "(it must be " + std::string(Allowed(column.range)) + ")";
  std::string must = "(it must be " + std::string(TypeWord(column.type));
  if (column.range != ValueRange::kAny) must += ", " + std::string(Allowed(column.range));
  return must + (column.nullable ? " or NULL)" : ")");
}

std::string Problem(const StoredColumn& column, const std::string& held, bool typed = false) {
  return std::string(column.name) + " is " + held + " " + MustBe(column, typed);
}

}  // namespace

std::optional<std::string> StoredValueProblem(const TableCell& cell, const StoredColumn& column) {
  if (std::holds_alternative<std::monostate>(cell)) {
    if (column.nullable) return std::nullopt;
    return Problem(column, "NULL");
  }
  if (const auto* text = std::get_if<std::string>(&cell)) {
    if (column.type == SqlType::kText) return std::nullopt;
    return Problem(column, "the text " + QuotedText(*text));
  }
  const auto* integer = std::get_if<std::int64_t>(&cell);
  const double value = integer != nullptr ? static_cast<double>(*integer) : std::get<double>(cell);
  const std::string held = integer != nullptr ? std::to_string(*integer) : fmt::format("{}", value);
  const bool typed =
      column.type == SqlType::kReal || (column.type == SqlType::kInteger && integer != nullptr);
  if (!typed) return Problem(column, held);
  if (!Contains(column.range, value)) return Problem(column, held, true);
  return std::nullopt;
}

std::optional<std::string> StoredValueProblem(const Statement& s, int i,
                                              const StoredColumn& column) {
  const int type = s.ColumnType(i);
  if (column.type == SqlType::kBlob) {
    if (type == SQLITE_BLOB || (type == SQLITE_NULL && column.nullable)) return std::nullopt;
    return Problem(column, type == SQLITE_NULL ? "NULL" : "not a blob");
  }
  switch (type) {
    case SQLITE_NULL:
      return StoredValueProblem(TableCell(), column);
    case SQLITE_INTEGER:
      return StoredValueProblem(TableCell(s.GetInt(i)), column);
    case SQLITE_FLOAT:
      return StoredValueProblem(TableCell(s.GetDouble(i)), column);
    case SQLITE_BLOB:
      return Problem(column, "a blob");
    default:
      if (column.type == SqlType::kText) return std::nullopt;  // Not copied to be checked.
      return StoredValueProblem(TableCell(s.GetText(i)), column);
  }
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
