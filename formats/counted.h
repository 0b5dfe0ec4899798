#pragma once
// A number with its noun in the right number: "1 beam", "2 beams", "1 distinct modal basis".

#include <string>
#include <string_view>

namespace shockmap {

// `plural` defaults to singular + "s".
inline std::string Counted(long long n, std::string_view singular, std::string_view plural = {}) {
  std::string text = std::to_string(n) + " ";
  if (n == 1) return text.append(singular);
  if (plural.empty()) return text.append(singular).append("s");
  return text.append(plural);
}

}  // namespace shockmap
