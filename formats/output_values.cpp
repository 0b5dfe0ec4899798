#include "formats/output_values.h"

#include "formats/output_file.h"

namespace shockmap {

nlohmann::json JsonOf(const OutputValue& value) {
  return std::visit(
      [](const auto& v) -> nlohmann::json {
        if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::monostate>) {
          return nullptr;
        } else {
          return v;
        }
      },
      value);
}

void WriteCsvFields(std::ostream& out, const std::vector<OutputValue>& values) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out << ',';
    std::visit(
        [&](const auto& v) {
          using V = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<V, bool>) {
            out << (v ? 1 : 0);
          } else if constexpr (std::is_same_v<V, std::string>) {
            out << CsvField(v);
          } else if constexpr (!std::is_same_v<V, std::monostate>) {
            out << v;
          }
        },
        values[i]);
  }
}

}  // namespace shockmap
