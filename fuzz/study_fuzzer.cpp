// libFuzzer target: any bytes as a study file, of the paper's problem or of a scene (whose
// scene file is then looked for beside it, in fuzz/corpus/study), and as the outcomes file of
// check-advice that advise reads. Accepted or refused with InputError; anything else is a bug.

#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_error.h"
#include "formats/json_reader.h"
#include "specs/advice_check_outcomes.h"
#include "specs/study_file.h"

// The bytes go through the text parser every study file goes through (nesting depth, repeated
// keys, syntax), then the study parser and the outcomes parser.
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr const char* kFile = "fuzz/corpus/study/study.json";
  try {
    const auto json =
        shockmap::ParseJsonText(std::string(reinterpret_cast<const char*>(data), size), kFile);
    try {
      shockmap::ParseStudyFile(json, kFile);
    } catch (const shockmap::InputError&) {
    }
    shockmap::ParseAdviceCheckOutcomes(json, kFile);
  } catch (const shockmap::InputError&) {
  }
  return 0;
}
