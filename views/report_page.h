#pragma once
// The frame of the report's pages: a header of facts, a table of contents, the sections, and the
// embedded styles and scripts (the vendored table sort, the map's hover box), so that a page
// needs nothing from the network.

#include <string>
#include <utility>
#include <vector>

namespace shockmap {

// One part of a page; `html` is already HTML (its data escaped), `title` and `id` are text.
struct ReportSection {
  std::string id, title, html;
};

// What the header states, as label and value texts (escaped by the page).
struct ReportHeader {
  std::string title;
  std::vector<std::pair<std::string, std::string>> facts;
};

// A whole page. With more than one section it opens with a table of contents linking each.
// A <select class="metric-switch" data-maps="ID"> shows only the .metric-map inside #ID whose
// data-metric it names (views/html_validity_map.h). Every <table class="sortable"> sorts on a
// click of a header, its filter box hides rows and
// its CSV link downloads the rows shown (views/html_text.h); a print stylesheet drops the
// boxes and links and prints every table whole. When the page has loaded,
// <body> carries data-images-loaded="LOADED/TOTAL" and data-sortable-tables="N" (the tables
// the sort script took), which the test suite reads in headless Chromium.
std::string ReportPage(const ReportHeader& header, const std::vector<ReportSection>& sections);

}  // namespace shockmap
