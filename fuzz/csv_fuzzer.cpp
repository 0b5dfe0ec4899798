// libFuzzer target: any bytes as a base-motion CSV table. Parsed or refused with InputError;
// anything else is a bug.

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "core/input_error.h"
#include "formats/acceleration_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  shockmap::BaseMotionEffect base;
  try {
    shockmap::ParseAccelerationCsv(in, "fuzz.csv", base);
  } catch (const shockmap::InputError&) {
  }
  return 0;
}
