#include "views/html_text.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <sstream>

namespace shockmap {

std::string HtmlEscaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    switch (c) {
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '&':
        out += "&amp;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

std::string Preformatted(std::string_view text) { return "<pre>" + HtmlEscaped(text) + "</pre>\n"; }

std::string Base64(std::string_view bytes) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  auto byte = [&](std::size_t i) {
    return static_cast<unsigned>(static_cast<unsigned char>(bytes[i]));
  };
  std::string out;
  std::size_t i = 0;
  for (; i + 2 < bytes.size(); i += 3) {
    const unsigned n = (byte(i) << 16) | (byte(i + 1) << 8) | byte(i + 2);
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63], kAlphabet[(n >> 6) & 63],
            kAlphabet[n & 63]};
  }
  if (i < bytes.size()) {
    const bool two = i + 1 < bytes.size();
    const unsigned n = (byte(i) << 16) | (two ? byte(i + 1) << 8 : 0);
    out += {kAlphabet[(n >> 18) & 63], kAlphabet[(n >> 12) & 63],
            two ? kAlphabet[(n >> 6) & 63] : '=', '='};
  }
  return out;
}

std::string CellText(const TableCell& cell) {
  if (const auto* d = std::get_if<double>(&cell)) return fmt::format("{:.6g}", *d);
  if (const auto* i = std::get_if<std::int64_t>(&cell)) return std::to_string(*i);
  if (const auto* s = std::get_if<std::string>(&cell)) return *s;
  return "";
}

namespace {

bool IsNumberColumn(const Table& r, std::size_t column) {
  bool any = false;
  for (const auto& row : r.rows) {
    if (std::holds_alternative<std::string>(row[column])) return false;
    any = any || !std::holds_alternative<std::monostate>(row[column]);
  }
  return any;
}

std::string Cell(const TableCell& cell) {
  if (const auto* d = std::get_if<double>(&cell)) {
    // An infinite bound (an interval's side too few members bound) is shown empty and sorts
    // past every number.
    if (std::isinf(*d)) {
      return fmt::format("<td data-sort=\"{}Infinity\" title=\"unbounded\"></td>",
                         *d < 0 ? "-" : "");
    }
    // The shortest text that reads back as the stored double, to sort and to copy.
    const std::string full = fmt::format("{}", *d);
    return fmt::format("<td data-sort=\"{0}\" title=\"{0}\">{1}</td>", full, CellText(cell));
  }
  const std::string text = CellText(cell);
  // Long texts (messages) wrap; everything else stays on one line.
  return (text.size() > 40 ? "<td class=\"long\">" : "<td>") + HtmlEscaped(text) + "</td>";
}

// `html` with a line-break opportunity (<wbr>) after each underscore: a long column name
// (wilks_members_needed) may wrap in its header instead of widening its column.
std::string WithBreaksAfterUnderscores(const std::string& html) {
  std::string out;
  for (char c : html) out += c == '_' ? std::string("_<wbr>") : std::string(1, c);
  return out;
}

}  // namespace

std::string SortableTable(const Table& result, const std::string& id, const std::string& caption,
                          const std::vector<std::string>& row_links) {
  const std::string safe_id = HtmlEscaped(id);
  std::string html = fmt::format(
      "<div class=\"table-tools\"><input type=\"search\" class=\"table-filter\" "
      "data-table=\"{0}\" placeholder=\"filter rows\" aria-label=\"filter the rows of {1}\"> "
      "<a class=\"table-csv\" data-table=\"{0}\" href=\"#\" download=\"{0}.csv\">CSV</a></div>\n"
      "<div class=\"table-wrap\"><table class=\"sortable\" id=\"{0}\"><caption>{1}</caption>\n",
      safe_id, HtmlEscaped(caption));
  html += "<thead><tr>";
  for (std::size_t c = 0; c < result.columns.size(); ++c) {
    html +=
        fmt::format("<th{}>{}</th>", IsNumberColumn(result, c) ? " data-sort-method=\"real\"" : "",
                    WithBreaksAfterUnderscores(HtmlEscaped(result.columns[c])));
  }
  html += "</tr></thead>\n<tbody>\n";
  for (std::size_t r = 0; r < result.rows.size(); ++r) {
    html += "<tr>";
    for (std::size_t c = 0; c < result.rows[r].size(); ++c) {
      std::string cell = Cell(result.rows[r][c]);
      if (c == 0 && r < row_links.size()) {
        const auto open = cell.find('>') + 1, close = cell.rfind("</td>");
        cell = cell.substr(0, open) + "<a href=\"" + HtmlEscaped(row_links[r]) + "\">" +
               cell.substr(open, close - open) + "</a></td>";
      }
      html += cell;
    }
    html += "</tr>\n";
  }
  return html + "</tbody></table></div>\n";
}

std::string EmbeddedFigure(const std::filesystem::path& png, const std::string& caption,
                           const std::vector<FileLink>& links) {
  std::ifstream in(png, std::ios::binary);
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::string files;
  for (const FileLink& l : links) {
    files += fmt::format(" <a href=\"{}\">{}</a>", HtmlEscaped(l.relative.generic_string()),
                         HtmlEscaped(l.label));
  }
  return fmt::format(
      "<figure><img alt=\"{0}\" src=\"data:image/png;base64,{1}\"><figcaption>{0}{2}"
      "</figcaption></figure>\n",
      HtmlEscaped(caption), Base64(bytes.str()),
      files.empty() ? "" : " <span class=\"files\">files:" + files + "</span>");
}

std::vector<FileLink> PlotFiles(const std::filesystem::path& image,
                                const std::filesystem::path& page_dir) {
  std::vector<FileLink> links;
  auto add = [&](const std::string& label, const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(file, ec)) {
      links.push_back({label, std::filesystem::relative(file, page_dir, ec)});
    }
  };
  add("image", image);
  add("data", std::filesystem::path(image).replace_extension(".dat"));
  add("zones data", std::filesystem::path(image).replace_extension(".zones.dat"));
  add("beams data", std::filesystem::path(image).replace_extension(".beams.dat"));
  add("gnuplot script", std::filesystem::path(image).replace_extension(".gp"));
  return links;
}

}  // namespace shockmap
