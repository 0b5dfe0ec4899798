// Reading a study database: read-only SQL as `shockmap query` runs it, the units of the declared
// columns, criteria as `criteria derive` derives them, sizing tables as `sizing` computes them,
// and stored reference signals as arrays.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <limits>
#include <memory>
#include <string>

#include "analysis/ensemble_sizing.h"
#include "analysis/scored_points.h"
#include "analysis/study_thresholds.h"
#include "db/ensemble_members.h"
#include "db/read_only_query.h"
#include "db/report_queries.h"
#include "db/schema.h"
#include "db/stored_signals.h"
#include "formats/criteria_json.h"
#include "python/bindings.h"
#include "python/signal_arrays.h"
#include "records/canonical_records.h"
#include "records/ensemble_records.h"
#include "records/scene_records.h"
#include "specs/study_file.h"
#include "views/sizing_tables.h"

namespace shockmap::python {
namespace {

py::object CellObject(const TableCell& cell) {
  return std::visit(
      [](const auto& v) -> py::object {
        using V = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<V, std::monostate>) {
          return py::none();
        } else {
          return py::cast(v);
        }
      },
      cell);
}

}  // namespace

// {"columns": [...], "rows": [(...), ...]}: what pandas.DataFrame.from_records takes.
py::dict TableDict(const Table& table) {
  py::list rows;
  for (const auto& row : table.rows) {
    py::tuple values(row.size());
    for (std::size_t i = 0; i < row.size(); ++i) values[i] = CellObject(row[i]);
    rows.append(std::move(values));
  }
  py::dict d;
  d["columns"] = table.columns;
  d["rows"] = std::move(rows);
  return d;
}

namespace {

// A Python int for a message: its digits, or its size when they would be too many to read.
std::string IntegerShown(const py::handle& value) {
  const auto bits = value.attr("bit_length")().cast<std::size_t>();
  return bits <= 256 ? std::string(py::str(value)) : fmt::format("an integer of {} bits", bits);
}

// A Python int bound to a parameter, refused beyond SQLite's 64-bit integers.
TableCell IntegerCell(const py::handle& value, std::size_t index) {
  int overflow = 0;
  const long long number = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (overflow != 0) {
    throw InputError(fmt::format(
        "parameters[{}]: {} is outside [{}, {}], the integers SQLite stores; bind it as a float "
        "or a str",
        index, IntegerShown(value), std::numeric_limits<std::int64_t>::min(),
        std::numeric_limits<std::int64_t>::max()));
  }
  return std::int64_t{number};
}

// A Python value bound to a parameter: None, an int, a float or a str.
TableCell ParameterCell(const py::handle& value, std::size_t index) {
  if (value.is_none()) return {};
  if (py::isinstance<py::bool_>(value)) return std::int64_t{value.cast<bool>()};
  if (py::isinstance<py::int_>(value)) return IntegerCell(value, index);
  if (py::isinstance<py::float_>(value)) return value.cast<double>();
  if (py::isinstance<py::str>(value)) return value.cast<std::string>();
  throw InputError(
      fmt::format("parameters[{}]: a {} cannot be bound; give None, an int, a float "
                  "or a str",
                  index, std::string(py::str(value.get_type().attr("__name__")))));
}

py::dict Query(const std::string& database_path, const std::string& sql,
               const py::sequence& values) {
  std::vector<TableCell> parameters;
  for (std::size_t i = 0; i < values.size(); ++i) parameters.push_back(ParameterCell(values[i], i));
  Table table;
  {
    py::gil_scoped_release release;
    table = RunReadOnlyQuery(database_path, sql, parameters);
  }
  return TableDict(table);
}

// The unit of every declared column by its SQL name ("" for counts, ratios and text).
py::dict ColumnUnits() {
  py::dict units;
  const auto add = [&units](const auto& columns) {
    for (const auto& c : columns) units[py::str(std::string(c.name))] = std::string(c.unit);
  };
  add(kPointParameterColumns);
  add(kScoreColumns);
  add(kReferenceColumns);
  add(kScenePointParameterColumns);
  add(kSceneScoreColumns);
  add(kSceneReferenceColumns);
  add(kEnsembleMemberParameterColumns);
  add(kEnsembleZoneColumns);
  add(kEnsembleImpactColumns);
  add(kEnsembleMemberColumns);
  add(kEnsembleReferenceColumns);
  return units;
}

// The study's name (the database's only one when empty) and its kind.
std::pair<std::string, std::string> StudyAndKind(const std::string& database_path,
                                                 const std::string& study) {
  const std::string name = ResolveStudyName(database_path, study);
  const auto json = StoredStudyJson(database_path, name);
  if (!json) throw InputError("no study named \"" + name + "\" in " + database_path);
  return {name, ToString(StudyKindOf(*json, database_path + ": stored study " + name))};
}

// The criteria as `criteria derive --out` writes them (JSON text), judged with the study's
// thresholds and `given` over them.
std::string CriteriaJson(const std::string& database_path, const std::string& study,
                         const std::map<std::string, double, std::less<>>& given) {
  const std::string name = ResolveCanonicalStudy(database_path, study, "criteria derive");
  const CriteriaOptions options = StudyCriteriaOptions(database_path, name, given);
  py::gil_scoped_release release;
  const auto points = LoadCriteriaPoints(database_path, name);
  return CriteriaToJson(name, DeriveCriteria(points, options)).dump();
}

void CheckFraction(double value, const char* name) {
  if (!(value > 0.0 && value < 1.0)) {
    throw InputError(fmt::format("{}: {:g} is outside (0, 1)", name, value));
  }
}

// The zone table of `sizing --format csv` (the wear table with `wear`).
py::dict Sizing(const std::string& database_path, const std::string& study, bool wear,
                double quantile, double confidence) {
  CheckFraction(quantile, "quantile");
  CheckFraction(confidence, "confidence");
  Table table;
  {
    py::gil_scoped_release release;
    Connection db(database_path, Connection::Mode::kReadOnly);
    CheckSchema(db);
    std::string name = study;
    if (name.empty()) {
      const std::vector<std::string> names = EnsembleStudies(db);
      if (names.size() != 1) {
        throw InputError(fmt::format("study: {} holds {} ensemble studies; name one", database_path,
                                     names.size()));
      }
      name = names.front();
    }
    SizingOptions options;
    options.quantile = quantile;
    options.confidence = confidence;
    const EnsembleSizing sizing =
        SizeEnsemble(CurrentMembers(ReadEnsemble(db, name)), name, options);
    table = wear ? WearTable(sizing) : ZoneTable(sizing);
  }
  return TableDict(table);
}

// A stored reference's signals, "t_s" first, by its id in reference_runs (the paper's problem)
// or scene_references (`scene`).
py::dict Reference(const std::string& database_path, std::int64_t reference_id, bool scene) {
  std::shared_ptr<const StoredSignals> signals;
  {
    py::gil_scoped_release release;
    std::optional<StoredSignals> read;
    if (scene) {
      read = ReadSceneReferenceSignals(database_path, reference_id);
    } else if (const auto row = ReadReference(database_path, reference_id)) {
      read = SignalsOf(*row);
    }
    if (!read) {
      throw InputError(fmt::format("reference_id: no {} {} in {}",
                                   scene ? "scene_references row" : "reference_runs row",
                                   reference_id, database_path));
    }
    signals = std::make_shared<const StoredSignals>(std::move(*read));
  }
  py::dict d;
  const std::size_t n = signals->values.empty() ? 0 : signals->values.front().size();
  d["t_s"] = SampleTimes(0.0, signals->output_dt_s, n);
  for (std::size_t i = 0; i < signals->names.size(); ++i) {
    d[py::str(signals->names[i])] = ArrayOver(signals, signals->values[i]);
  }
  return d;
}

}  // namespace

void BindDatabase(py::module_& m) {
  m.def("query", &Query, py::arg("db"), py::arg("sql"), py::arg("parameters"));
  m.def("column_units", &ColumnUnits);
  m.def("study_and_kind", &StudyAndKind, py::arg("db"), py::arg("study"));
  m.def("criteria_json", &CriteriaJson, py::arg("db"), py::arg("study"), py::arg("thresholds"));
  m.def("sizing", &Sizing, py::arg("db"), py::arg("study"), py::arg("wear"), py::arg("quantile"),
        py::arg("confidence"));
  m.def("reference", &Reference, py::arg("db"), py::arg("reference_id"), py::arg("scene"));
}

}  // namespace shockmap::python
