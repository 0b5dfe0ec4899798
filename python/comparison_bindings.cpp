// compare() and point(): one run of the paper's problem scored against its reference, as
// `shockmap compare` and `shockmap export point` compute it, with its histories as arrays.

#include <pybind11/stl.h>

#include <memory>
#include <optional>
#include <string>

#include "compare/comparison.h"
#include "compare/comparison_options.h"
#include "compare/output_columns.h"
#include "engine/point_replay.h"
#include "formats/comparison_json.h"
#include "python/bindings.h"
#include "python/signal_arrays.h"

namespace shockmap::python {
namespace {

// A result shared by the Python object and every array taken from it, with what it was asked.
struct Comparison {
  std::shared_ptr<const ComparisonResult> result;
  CantileverImpact problem;
  ComparisonOptions options;
};

// A value of an output column as Python holds it: None, a bool, an int, a float or a str.
py::object PythonOf(const OutputValue& value) {
  return std::visit(
      [](const auto& v) -> py::object {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) {
          return py::none();
        } else {
          return py::cast(v);
        }
      },
      value);
}

// A member per column of kShockColumns, as ShockToJson writes it.
py::dict ShockDict(const Shock& s) {
  py::dict d;
  for (const OutputColumn<Shock>& c : kShockColumns) {
    d[py::str(std::string(c.name))] = PythonOf(c.value(s));
  }
  return d;
}

py::list ShockList(const std::vector<Shock>& shocks) {
  py::list list;
  for (const Shock& s : shocks) list.append(ShockDict(s));
  return list;
}

// The numerical run's histories, named as the columns of numerical.csv
// (formats/history_csv.h); those not recorded are left out.
py::dict NumericalHistories(const Comparison& c) {
  const TransientResult& h = c.result->histories;
  py::dict d;
  if (h.displacement_m.empty()) return d;
  d["t_s"] = TimesOf(h.displacement_m[0]);
  d["tip_displacement_m"] = ArrayOver(c.result, h.displacement_m[0].values);
  if (!h.velocity_m_s.empty())
    d["tip_velocity_m_s"] = ArrayOver(c.result, h.velocity_m_s[0].values);
  if (!h.contact_force_n.empty()) {
    d["contact_force_n"] = ArrayOver(c.result, h.contact_force_n[0].values);
  }
  const EnergyHistory& e = h.energy;
  for (const auto& [name, signal] :
       {std::pair{"kinetic_j", &e.kinetic_j}, std::pair{"strain_j", &e.strain_j},
        std::pair{"contact_j", &e.contact_j}, std::pair{"dissipated_j", &e.dissipated_j}}) {
    if (!signal->values.empty()) d[name] = ArrayOver(c.result, signal->values);
  }
  return d;
}

py::dict ReferenceHistories(const Comparison& c) {
  const ReferenceRun& r = *c.result->reference;
  py::dict d;
  d["t_s"] = TimesOf(r.tip_m);
  d["tip_displacement_m"] = ArrayOver(c.result, r.tip_m.values);
  d["contact_force_n"] = ArrayOver(c.result, r.force_n.values);
  return d;
}

py::dict ScoreDict(const ComparisonResult& r) {
  py::dict d;
  for (const ScoreDefinition& s : Scores()) d[py::str(std::string(s.name))] = r.scores[s.name];
  return d;
}

// The options given by keyword (None: not given), each read as its declaration's type; an
// unknown keyword (shockmap.compare() binds its own signature first) is an InputError.
GivenOptions GivenByKeyword(const py::dict& keywords) {
  GivenOptions given;
  for (const auto& [key, value] : keywords) {
    const std::string keyword = py::str(key);
    if (value.is_none()) continue;
    if (const NumberOption* o = ComparisonNumberOption(keyword, &OptionNames::keyword)) {
      given.numbers[o] = value.cast<double>();
    } else if (const ChoiceOption* c = ComparisonChoiceOption(keyword, &OptionNames::keyword)) {
      given.choices[c] = value.cast<std::string>();
    } else {
      throw InputError("compare(): unknown keyword \"" + keyword + "\"; see COMPARE_OPTIONS");
    }
  }
  return given;
}

// compare()'s keywords, as shockmap/__init__.py passes them (numbers as float, words as str).
Comparison Compare(const py::dict& keywords) {
  const ComparisonRequest request =
      ComparisonAsked(GivenByKeyword(keywords), &OptionNames::keyword);
  py::gil_scoped_release release;
  return {std::make_shared<const ComparisonResult>(RunComparison(request.problem, request.options)),
          request.problem, request.options};
}

Comparison Point(const std::string& database_path, const std::string& study,
                 std::int64_t point_id) {
  py::gil_scoped_release release;
  ReplayedPoint replay = ReplayCanonicalPoint(database_path, study, point_id);
  return {std::make_shared<const ComparisonResult>(std::move(replay.result)), replay.problem,
          replay.options};
}

// What every option's declaration gives Python: its three names and its help.
template <typename Option>
py::dict NamesAndHelp(const Option& o) {
  py::dict d;
  d["flag"] = o.names.flag;
  d["keyword"] = o.names.keyword;
  d["study_key"] = o.names.study_key;
  d["help"] = o.help;
  return d;
}

// An option's declaration as Python reads it: its names, unit, help, default and what it
// takes (bounds, or choices).
py::dict OptionDict(const NumberOption& o) {
  py::dict d = NamesAndHelp(o);
  d["unit"] = o.unit;
  d["default"] = o.whole && o.default_value
                     ? py::object(py::int_(static_cast<long long>(*o.default_value)))
                     : py::cast(o.default_value);
  d["low"] = o.low;
  d["low_strict"] = o.low_strict;
  d["high"] = o.high;
  d["whole"] = o.whole;
  d["required"] = o.required;
  d["allowed"] = o.Allowed();
  return d;
}

py::dict OptionDict(const ChoiceOption& o) {
  py::dict d = NamesAndHelp(o);
  d["default"] = o.default_value;
  d["choices"] = o.choices;
  d["allowed"] = o.Allowed();
  return d;
}

py::list ComparisonOptionDicts() {
  py::list list;
  for (const NumberOption* o : ComparisonNumberOptions()) list.append(OptionDict(*o));
  for (const ChoiceOption* o : ComparisonChoiceOptions()) list.append(OptionDict(*o));
  return list;
}

}  // namespace

void BindComparison(py::module_& m) {
  py::class_<Comparison>(m, "Comparison",
                         "A run of the paper's problem scored against its reference")
      .def_property_readonly("status",
                             [](const Comparison& c) { return ToString(c.result->status); })
      .def_property_readonly("message", [](const Comparison& c) { return c.result->message; })
      .def_property_readonly("summary_json",
                             [](const Comparison& c) {
                               return ComparisonToJson(c.problem, c.options, *c.result).dump();
                             })
      .def_property_readonly("scores", [](const Comparison& c) { return ScoreDict(*c.result); })
      .def_property_readonly("reference_undecided",
                             [](const Comparison& c) { return c.result->undecided; })
      .def_property_readonly("n_modes", [](const Comparison& c) { return c.result->n_modes; })
      .def_property_readonly("n_elements", [](const Comparison& c) { return c.result->n_elements; })
      .def_property_readonly("dt_used_s",
                             [](const Comparison& c) { return c.result->numerical.dt_used_s; })
      .def_property_readonly("steps",
                             [](const Comparison& c) { return c.result->numerical.steps_taken; })
      .def_property_readonly("wall_s",
                             [](const Comparison& c) { return c.result->numerical.wall_s; })
      .def_property_readonly("cpu_s", [](const Comparison& c) { return c.result->numerical.cpu_s; })
      .def_property_readonly("dt_paper_s",
                             [](const Comparison& c) { return c.result->bounds.dt_paper_s; })
      .def_property_readonly("dt_sharp_s",
                             [](const Comparison& c) { return c.result->bounds.dt_sharp_s; })
      .def_property_readonly(
          "reference_r_fref",
          [](const Comparison& c) { return c.result->reference->convergence.r_fref; })
      .def_property_readonly(
          "reference_difference",
          [](const Comparison& c) { return c.result->reference->convergence.difference; })
      .def_property_readonly(
          "shocks_numerical",
          [](const Comparison& c) { return ShockList(c.result->shocks_numerical); })
      .def_property_readonly(
          "shocks_reference",
          [](const Comparison& c) { return ShockList(c.result->reference->shocks); })
      .def_property_readonly("numerical", &NumericalHistories)
      .def_property_readonly("reference", &ReferenceHistories);
  m.def("compare", &Compare, py::arg("keywords"));
  m.def("compare_options", &ComparisonOptionDicts,
        "The options of compare() as declared once for the command line, Python and study files");
  m.def("point", &Point, py::arg("db"), py::arg("study"), py::arg("point_id"));
}

}  // namespace shockmap::python
