#pragma once
// The family of a contact zone, as an engineer sizes it (docs/ensembles.md, "Sizing by zone
// family"): the wires between pins, the duct pad, the pins against the wrapper. Known from the
// beams the zone joins, as the bundle generator names them (formats/scene_file.h: the wrapper
// "wrapper", the pins "pin_0", "pin_1", ...; no listed beam may take these names) and a stop
// fixed to the base ("stop").

#include <string>
#include <string_view>

namespace shockmap {

enum class ZoneFamily { kPinPinWire, kDuctPad, kPinWrapper, kOther };

// Both beams pins: a pin-pin wire; a pin and the wrapper: pin-wrapper; the wrapper against a
// stop: the duct pad; any other pair: other.
ZoneFamily FamilyOfZone(std::string_view beam_a, std::string_view beam_b);

// "pin-pin wire", "duct pad", "pin-wrapper", "other".
std::string FamilyName(ZoneFamily family);

}  // namespace shockmap
