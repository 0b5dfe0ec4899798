#pragma once
// Where a result comes from: code version, compiler, build type, host, process.

#include <string>

#include "db/study_database.h"

namespace shockmap {

Provenance CurrentProvenance(int jobs);

// What `shockmap --version` prints: "shockmap RELEASE (git DESCRIBE, COMPILER, BUILD_TYPE)", the
// release being CMake's project version and CHANGELOG.md's top entry.
std::string VersionLine();

}  // namespace shockmap
