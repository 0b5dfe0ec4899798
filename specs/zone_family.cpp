#include "specs/zone_family.h"

#include <algorithm>
#include <cctype>

namespace shockmap {
namespace {

// "pin_" followed by a whole number: a pin of a generated bundle.
bool IsPin(std::string_view beam) {
  constexpr std::string_view kPrefix = "pin_";
  if (!beam.starts_with(kPrefix) || beam.size() == kPrefix.size()) return false;
  return std::all_of(beam.begin() + kPrefix.size(), beam.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

}  // namespace

ZoneFamily FamilyOfZone(std::string_view beam_a, std::string_view beam_b) {
  const bool pin_a = IsPin(beam_a), pin_b = IsPin(beam_b);
  if (pin_a && pin_b) return ZoneFamily::kPinPinWire;
  if ((pin_a && beam_b == "wrapper") || (pin_b && beam_a == "wrapper"))
    return ZoneFamily::kPinWrapper;
  if ((beam_a == "wrapper" && beam_b == "stop") || (beam_a == "stop" && beam_b == "wrapper"))
    return ZoneFamily::kDuctPad;
  return ZoneFamily::kOther;
}

std::string FamilyName(ZoneFamily family) {
  switch (family) {
    case ZoneFamily::kPinPinWire:
      return "pin-pin wire";
    case ZoneFamily::kDuctPad:
      return "duct pad";
    case ZoneFamily::kPinWrapper:
      return "pin-wrapper";
    case ZoneFamily::kOther:
      break;
  }
  return "other";
}

}  // namespace shockmap
