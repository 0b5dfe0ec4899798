#pragma once
// A structure's modes kept for the process as beams' bases are (core/modal_basis_cache.h,
// docs/structures.md "Modes kept for the process"): every point of a scene study and every
// member of an ensemble parses its scene again, reading the structure's files again, so the
// key is the structure's content (K, M and the DOF table as stored, and its name), never its
// files' paths, with the truncation and the static-correction nodes. Two structures share a
// solution only when their content is equal entry for entry (a hash finds the candidates; the
// content decides).

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/fe_structure.h"
#include "core/scene_structure_modes.h"

namespace shockmap {

// The most recently used solutions kept, by their shapes' and their structure's size.
inline constexpr double kStructureModesCacheBytes = 256e6;

// MakeStructureModes(fe, f_trunc_hz, ratio, static_nodes), the same bit for bit, solved once per
// process for each content, truncation and static nodes (thread-safe: the first thread that asks
// solves while the others wait; what the solve throws, every thread waiting for it throws).
// The result's `fe` is the caller's.
SceneStructureModes StructureModesCached(std::shared_ptr<const FeStructure> fe,
                                         std::optional<double> f_trunc_hz, double ratio,
                                         const std::vector<int>& static_nodes);

// How many times this process has solved a structure's modes in StructureModesCached (the
// solves the cache did not spare).
std::int64_t StructureModeSolves();

// A hash of what the structure's modes depend on: K's and M's stored entries (their pattern
// and values' bits), the DOF table and the name (it names the structure in the solve's errors).
std::uint64_t StructureContentHash(const FeStructure& s);
// Whether the modes of a and b are the same: equal stored K and M, entry for entry and bit for
// bit, equal DOF tables and names. Node coordinates do not enter the modes.
bool SameStructureContent(const FeStructure& a, const FeStructure& b);

}  // namespace shockmap
