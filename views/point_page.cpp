#include "views/point_page.h"

#include <fmt/format.h>

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

// Why a point has no Fig. 3 and how to get it; once the command under "Reproduce it" has drawn
// point_ID/fig3.png beside the page, the page's script shows it here.
std::string AbsentFigure(const PointPageInput& in) {
  if (!in.point || in.spec == nullptr) {
    return "<p id=\"fig3-absent\">No Fig. 3 for this point: the database stores each run's "
           "scores and shocks, not its histories, and the point is not in the stored study file, "
           "so no command can recompute it.</p>\n";
  }
  const std::string png = fmt::format("point_{}/fig3.png", in.point_id);
  return fmt::format(
      "<p id=\"fig3-absent\">No Fig. 3 for this point: the database stores each run's scores "
      "and shocks, not its histories (only its reference's), and the report recomputes runs to "
      "draw Fig. 3 only for the points around the derived boundary. The command under "
      "<a href=\"#reproduce\">Reproduce it</a> recomputes this one and writes <code>{0}</code>; "
      "this page shows it once it is there.</p>\n<figure id=\"fig3-drawn\" hidden></figure>\n"
      "<script>(function () {{ var image = new Image(); image.alt = 'Fig. 3 of point {1}, "
      "recomputed by the command below'; image.onload = function () {{ var f = "
      "document.getElementById('fig3-drawn'); f.appendChild(image); f.hidden = false; "
      "document.getElementById('fig3-absent').hidden = true; }}; image.src = '{0}'; }})();"
      "</script>\n",
      HtmlEscaped(png), in.point_id);
}

std::string FigureSection(const PointPageInput& in) {
  if (!in.figure) return AbsentFigure(in);
  std::string scores;
  for (const ScoreDefinition& score : Scores()) {
    const std::optional<double> v = in.figure->scores[score.name];
    scores += fmt::format("{}{} = {}", scores.empty() ? "" : ", ", score.label,
                          v ? fmt::format("{:.4f}", *v) : std::string("not scored"));
  }
  const auto dir = in.figure->png.parent_path();
  return EmbeddedFigure(in.figure->png,
                        "Tip displacement and contact force against the stored reference, "
                        "recomputed: " +
                            scores,
                        {{"image", dir.filename() / "fig3.png"},
                         {"numerical history (CSV)", dir.filename() / "numerical.csv"},
                         {"reference history (CSV)", dir.filename() / "reference.csv"},
                         {"gnuplot script", dir.filename() / "fig3.gp"}});
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
