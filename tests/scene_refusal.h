#pragma once
// The message a scene file is refused with, for the tests of the scene reader's refusals.

#include <string>

#include "core/input_error.h"
#include "formats/scene_file.h"

namespace shockmap::testing {

// The InputError LoadScene throws on `path`; empty if it accepts the file.
inline std::string SceneRefusal(const std::string& path) {
  try {
    LoadScene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace shockmap::testing
