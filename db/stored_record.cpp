#include "db/stored_record.h"

namespace shockmap {

std::string Placeholders(std::size_t n) {
  std::string list;
  for (std::size_t i = 0; i < n; ++i) list += i == 0 ? "?" : ", ?";
  return list;
}

}  // namespace shockmap
