#pragma once
// Pieces of the HTML report built from data: every text that comes from a user's file or the
// database (study names, paths, messages, cells) goes through HtmlEscaped.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "db/read_only_query.h"

namespace shockmap {

// `text` with & < > " ' as character references: safe as element content and as a quoted
// attribute value.
std::string HtmlEscaped(std::string_view text);

// `text` in a <pre> block, escaped.
std::string Preformatted(std::string_view text);

// RFC 4648 base64 of `bytes`, for data: URIs.
std::string Base64(std::string_view bytes);

// A cell as the report's tables show it: integers and text as they are, reals with 6
// significant digits (the full value in the cell's data-sort and title), NULL empty.
std::string CellText(const TableCell& cell);

// A <table class="sortable"> of `result` with a <caption>: a click on a header sorts by that
// column (the page's vendored tablesort), numerically where every value of the column is a
// number. `id` names the table in the page. With `row_links` (one per row), each row's first
// cell links to its entry. Above the table, a filter box (class table-filter: the rows not
// holding every word typed are hidden) and a CSV link (class table-csv: the rows shown, reals
// at full precision, built by the page's script on a click); the table sits in a
// <div class="table-wrap"> that scrolls sideways only when wider than the page.
std::string SortableTable(const Table& result, const std::string& id, const std::string& caption,
                          const std::vector<std::string>& row_links = {});

// A file of the report linked for download: the path relative to the page.
struct FileLink {
  std::string label;
  std::filesystem::path relative;
};

// A <figure> with the PNG embedded as a data: URI (the page stays whole when moved alone), its
// caption and links to the files beside it (the image, its data, its gnuplot script).
std::string EmbeddedFigure(const std::filesystem::path& png, const std::string& caption,
                           const std::vector<FileLink>& links);

// The links to the image, .dat and .gp files gnuplot drew `image` from, relative to `page_dir`;
// only the files that exist.
std::vector<FileLink> PlotFiles(const std::filesystem::path& image,
                                const std::filesystem::path& page_dir);

}  // namespace shockmap
