#pragma once
// The allowed name a misspelled one most likely meant, for "did you mean ...?" in messages.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace shockmap {

// The name of `allowed` nearest to `given` in edits (a letter inserted, deleted, replaced, or
// two neighbours swapped), when it is near enough to be a slip of the keyboard: at most one edit
// per three letters of `given`, and at least one. The first of equally near names; nullopt when
// none is near enough or `given` is itself allowed.
std::optional<std::string> NearestName(std::string_view given,
                                       const std::vector<std::string>& allowed);

}  // namespace shockmap
