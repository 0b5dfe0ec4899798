#include "views/point_page.h"

#include <fmt/format.h>

#include <array>
#include <string_view>
#include <utility>
#include <variant>

#include "db/corrupt_rows.h"
#include "db/report_queries.h"
#include "views/html_text.h"
#include "views/report_page.h"

namespace shockmap {
namespace {

// The study's settings that `compare` cannot set, where they differ from its defaults.
std::vector<std::string> Unmatched(const StudySpec& spec, const StudyPoint& point) {
  const ComparisonOptions study = OptionsOf(spec, point), compare;
  std::vector<std::string> out;
  auto differs = [&](bool same, const std::string& what, const std::string& value,
                     const std::string& default_value) {
    if (!same) out.push_back(fmt::format("{} {} (compare: {})", what, value, default_value));
  };
  differs(point.mass_damping_per_s == 0.0, "mass damping",
          fmt::format("{} /s", point.mass_damping_per_s), "0 /s");
  differs(study.psd.n_samples == compare.psd.n_samples, "PSD samples",
          std::to_string(study.psd.n_samples), std::to_string(compare.psd.n_samples));
  differs(study.psd.zero_padding_factor == compare.psd.zero_padding_factor, "PSD zero padding",
          std::to_string(study.psd.zero_padding_factor),
          std::to_string(compare.psd.zero_padding_factor));
  differs(study.psd.window == compare.psd.window && study.psd.one_sided == compare.psd.one_sided,
          "PSD window or sidedness", "as in the study file", "Hann, one-sided");
  differs(study.rest_duration_t1 == compare.rest_duration_t1, "shock rest duration",
          fmt::format("{} T1", study.rest_duration_t1),
          fmt::format("{} T1", compare.rest_duration_t1));
  differs(study.srf_definition == compare.srf_definition, "SRf definition",
          ToString(study.srf_definition), ToString(compare.srf_definition));
  differs(
      study.reference.crossing_samples_per_period == compare.reference.crossing_samples_per_period,
      "reference crossing samples", std::to_string(study.reference.crossing_samples_per_period),
      std::to_string(compare.reference.crossing_samples_per_period));
  differs(study.reference_tolerance == compare.reference_tolerance, "reference tolerance",
          fmt::format("{}", study.reference_tolerance),
          fmt::format("{}", compare.reference_tolerance));
  return out;
}

std::string DtFlags(const TimeStepRequest& dt) {
  if (dt.dt_s) return fmt::format("--dt {}", *dt.dt_s);
  return fmt::format("--dt-factor {} --dt-rule {}", dt.factor, ToString(dt.rule));
}

std::string StoredValues(const PointPageInput& in) {
  Table values;
  values.columns = {"column", "value"};
  for (std::size_t i = 0; i < in.columns->size(); ++i) {
    values.rows.push_back({(*in.columns)[i], (*in.row)[i]});
  }
  return SortableTable(values, "stored-table", "Its row of the results view");
}

// The point's stored value of `score` (NULL: none).
std::optional<double> StoredScore(const PointPageInput& in, std::string_view score) {
  for (std::size_t i = 0; i < in.columns->size(); ++i) {
    if ((*in.columns)[i] != score) continue;
    if (const double* v = std::get_if<double>(&(*in.row)[i])) return *v;
  }
  return std::nullopt;
}

// "Err = 0.0123, SRf = 0.9876: the stored scores, exactly", or each recomputed score beside its
// stored value where they differ.
std::string RecomputedScores(const PointPageInput& in) {
  std::string scores;
  bool same = true;
  for (const ScoreDefinition& score : Scores()) {
    const std::optional<double> v = in.figure->scores[score.name];
    const std::optional<double> stored = StoredScore(in, score.name);
    same = same && v == stored;
    scores += fmt::format("{}{} = {}", scores.empty() ? "" : ", ", score.label,
                          v ? fmt::format("{:.4f}", *v) : std::string("not scored"));
    if (v != stored) {
      scores += fmt::format(" (stored: {})",
                            stored ? fmt::format("{}", *stored) : std::string("not scored"));
    }
  }
  return HtmlEscaped(scores) +
         (same ? ": <span class=\"scores-agree\">the stored scores, exactly</span>"
               : ": <span class=\"scores-differ\">not the stored scores</span>");
}

std::string FigureLinks(const std::filesystem::path& files) {
  const std::string dir = files.filename().generic_string();
  std::string links;
  constexpr std::array<std::pair<const char*, const char*>, 4> kFiles = {
      {{"numerical history (CSV)", "numerical.csv"},
       {"reference history (CSV)", "reference.csv"},
       {"the figure by gnuplot (PNG)", "fig3.png"},
       {"gnuplot script", "fig3.gp"}}};
  for (const auto& [label, file] : kFiles) {
    links += fmt::format(" <a href=\"{}/{}\">{}</a>", HtmlEscaped(dir), file, label);
  }
  return " <span class=\"files\">files:" + links + "</span>";
}

std::string FigureSection(const PointPageInput& in) {
  if (!in.figure) {
    return "<p id=\"fig3-absent\">No Fig. 3 for this point: the database stores each run's "
           "scores and shocks, not its histories, and the point or its reference is not stored "
           "any more, so the report could not compute it again.</p>\n";
  }
  const std::string note =
      in.figure->note.empty() ? "" : "<p class=\"fig3-note\">" + in.figure->note + "</p>\n";
  return fmt::format(
      "{}<figure class=\"fig3\">{}<figcaption>Tip displacement and contact force against the "
      "stored reference, the run computed again: {}{}</figcaption></figure>\n",
      note, in.figure->svg, RecomputedScores(in),
      in.figure->files ? FigureLinks(*in.figure->files) : "");
}

}  // namespace

std::map<std::int64_t, StoredStudyPoint> StudyPointsById(const std::string& database_path,
                                                         const std::string& study,
                                                         const StudySpec& spec) {
  std::map<std::string, const StudyPoint*> by_key;
  for (const StudyPoint& p : spec.points) by_key[PointKey(p)] = &p;
  std::map<std::int64_t, StoredStudyPoint> points;
  const Table keys = PointKeys(database_path, study);
  for (std::size_t i = 0; i < keys.rows.size(); ++i) {
    const NamedRow row(keys, i);
    const std::int64_t id = std::get<std::int64_t>(row["point_id"]);  // INTEGER PRIMARY KEY.
    const std::string what = "point " + std::to_string(id);
    const auto found = by_key.find(StoredText(row["point_key"], database_path, what, "point_key"));
    if (found == by_key.end()) continue;
    points[id] = {*found->second,
                  StoredText(row["reference_key"], database_path, what, "reference_key")};
  }
  return points;
}

std::string CompareCommand(const StudySpec& spec, const StudyPoint& point,
                           const std::string& out_dir, std::vector<std::string>* unmatched) {
  if (unmatched != nullptr) *unmatched = Unmatched(spec, point);
  const ComparisonOptions o = OptionsOf(spec, point);
  return fmt::format(
      "shockmap compare --rk {} --rftrunc {} --scheme {} {} --window {} --rfref {}{} --out {} "
      "--plot",
      point.r_k, point.r_ftrunc, ToString(point.scheme), DtFlags(point.dt), point.window_s,
      o.reference.r_fref,
      point.n_elements > 0 ? fmt::format(" --elements {}", point.n_elements) : "", out_dir);
}

std::string PointPage(const PointPageInput& in) {
  std::vector<ReportSection> sections;
  std::string command = "(the point is not in the stored study file: no command)";
  std::string caveats;
  if (in.point && in.spec != nullptr) {
    std::vector<std::string> unmatched;
    command = CompareCommand(*in.spec, *in.point, fmt::format("points/point_{}", in.point_id),
                             &unmatched);
    for (const std::string& u : unmatched) caveats += "<li>" + HtmlEscaped(u) + "</li>";
  }
  sections.push_back({"fig3", "Fig. 3: the run against its reference", FigureSection(in)});
  sections.push_back(
      {"reproduce", "Reproduce it",
       "<pre>" + HtmlEscaped(command) + "</pre>\n" +
           (caveats.empty() ? "<p>It sets every setting of the study this point depends on.</p>\n"
                            : "<p>compare has no flag for these settings of the study; its "
                              "result can differ from the stored one by them:</p><ul>" +
                                  caveats + "</ul>\n")});
  sections.push_back({"values", "Stored values", StoredValues(in)});
  ReportHeader header{fmt::format("{}: point {}", in.study, in.point_id),
                      {{"study", in.study}, {"point", std::to_string(in.point_id)}}};
  std::string page = ReportPage(header, sections);
  const std::string back = "<p><a href=\"../index.html\">back to the report</a></p>\n";
  return page.insert(page.find("</header>") + 9, back);
}

}  // namespace shockmap
