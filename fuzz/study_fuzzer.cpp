// libFuzzer target: any bytes as a study file, of the paper's problem or of a scene (whose
// scene file is then looked for beside it, in fuzz/corpus/study). Accepted or refused with
// InputError; anything else is a bug.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "formats/study_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto json = nlohmann::json::parse(data, data + size, nullptr, false);
  if (json.is_discarded()) return 0;
  try {
    shockmap::ParseStudyFile(json, "fuzz/corpus/study/study.json");
  } catch (const shockmap::InputError&) {
  }
  return 0;
}
