// libFuzzer target: any bytes as a scene file. The parser must accept the scene or refuse it
// with InputError; anything else (a crash, a sanitizer report, another exception, a timeout, an
// allocation past the fuzzer's limit) is a bug.

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "formats/scene_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto json = nlohmann::json::parse(data, data + size, nullptr, false);
  if (json.is_discarded()) return 0;  // Not JSON: ReadJsonFile refuses it before the parser.
  try {
    shockmap::ParseScene(json, "fuzz/scene.json");
  } catch (const shockmap::InputError&) {
  }
  return 0;
}
