// libFuzzer target: any bytes as a scene file. The parser must accept the scene or refuse it
// with InputError; anything else (a crash, a sanitizer report, another exception, a timeout, an
// allocation past the fuzzer's limit) is a bug.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "formats/json_reader.h"
#include "formats/scene_file.h"

// The bytes go through the text parser every scene file goes through (nesting depth, repeated
// keys, syntax), then the scene parser.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const std::string text(reinterpret_cast<const char*>(data), size);
    shockmap::ParseScene(shockmap::ParseJsonText(text, "fuzz/scene.json"), "fuzz/scene.json");
  } catch (const shockmap::InputError&) {
  }
  return 0;
}
