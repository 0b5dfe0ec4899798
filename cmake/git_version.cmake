# Writes OUTPUT with the release (VERSION, CMake's project version, the top entry of
# CHANGELOG.md) and the code version from `git describe`, run at every build so a result's
# provenance names the code that produced it. The file is rewritten only when a version changes.
execute_process(
  COMMAND git describe --always --dirty --abbrev=12
  WORKING_DIRECTORY ${SOURCE_DIR}
  OUTPUT_VARIABLE version
  OUTPUT_STRIP_TRAILING_WHITESPACE ERROR_QUIET)
if(NOT version)
  set(version "unknown")
endif()
string(CONCAT content "#pragma once\n#define SHOCKMAP_VERSION \"${VERSION}\"\n"
       "#define SHOCKMAP_GIT_VERSION \"${version}\"\n")
if(EXISTS ${OUTPUT})
  file(READ ${OUTPUT} old)
endif()
if(NOT "${old}" STREQUAL "${content}")
  file(WRITE ${OUTPUT} "${content}")
endif()
