#pragma once
// Third-party scripts embedded into the HTML report (views/vendor/README.md), with their
// licence texts, as the files in views/vendor/ hold them.

#include <string_view>

namespace shockmap {

// tablesort 5.7.1 (MIT): sorts an HTML table when a header is clicked.
std::string_view TablesortScript();
std::string_view TablesortLicence();

}  // namespace shockmap
