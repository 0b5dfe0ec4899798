#include "formats/acceleration_csv.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "formats/json_reader.h"

namespace shockmap {

void ParseAccelerationCsv(std::istream& in, const std::string& name, BaseMotionEffect& base) {
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (number == 1) {
      if (line != "t_s,a_m_s2")
        FailAt(name, "line 1", "expected the header \"t_s,a_m_s2\", got \"" + Excerpt(line) + "\"");
      continue;
    }
    if (line.empty()) continue;
    std::istringstream fields(line);
    std::string t_text, a_text, extra;
    if (!std::getline(fields, t_text, ',') || !std::getline(fields, a_text, ',') ||
        std::getline(fields, extra, ',')) {
      FailAt(name, "line " + std::to_string(number),
             "expected two values \"t,a\", got \"" + Excerpt(line) + "\"");
    }
    double t = 0, a = 0;
    try {
      std::size_t used_t = 0, used_a = 0;
      t = std::stod(t_text, &used_t);
      a = std::stod(a_text, &used_a);
      if (used_t != t_text.size() || used_a != a_text.size())
        throw std::invalid_argument("trailing");
    } catch (const std::exception&) {
      FailAt(name, "line " + std::to_string(number), "not two numbers: \"" + Excerpt(line) + "\"");
    }
    if (!std::isfinite(t) || !std::isfinite(a))
      FailAt(name, "line " + std::to_string(number), "values must be finite");
    if (!base.table_t_s.empty() && t <= base.table_t_s.back()) {
      FailAt(name, "line " + std::to_string(number), "times must increase strictly");
    }
    if (base.table_t_s.size() >= 10'000'000)
      FailAt(name, "line " + std::to_string(number), "more than 1e7 rows");
    base.table_t_s.push_back(t);
    base.table_a_m_s2.push_back(a);
  }
  if (base.table_t_s.size() < 2) FailAt(name, "(file)", "needs at least two rows after the header");
}

}  // namespace shockmap
