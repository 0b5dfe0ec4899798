# Precompiled headers for the test executables: sixty one-file targets share the first one's
# compiled Eigen, nlohmann-json, fmt and GoogleTest headers. The libraries and the executable
# have none: their sources are compiled in unity batches (cmake/unity_build.cmake), each of
# which parses those headers once; there a precompiled header saved 1.3 of a batch's 42 s and
# cost about 10 s per target before any of its batches could start.
# Each source is still written with its own includes; a build with
# -DSHOCKMAP_PRECOMPILED_HEADERS=OFF -DSHOCKMAP_UNITY_BUILD=OFF checks that they are complete.
option(SHOCKMAP_PRECOMPILED_HEADERS "Compile the common headers once per target" ON)
if(SHOCKMAP_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU"
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # With the headers precompiled, GCC 12 inlines std::string's concatenations differently and
  # misreads about twenty of them (json_reader, sizing_tables, tests' command lines, ...) as
  # copies of 2^63 bytes (GCC bugs 105329 and 105651, fixed in 13); the same files compile
  # without a warning when the headers are not precompiled.
  add_compile_options(-Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
endif()

# shockmap_precompile_headers(TARGET): the standard headers the tests share, Eigen,
# nlohmann-json, fmt and GoogleTest.
function(shockmap_precompile_headers target)
  if(SHOCKMAP_PRECOMPILED_HEADERS)
    target_precompile_headers(${target} PRIVATE <algorithm> <cmath> <cstdint> <filesystem>
                              <functional> <map> <memory> <optional> <string> <variant> <vector>
                              <Eigen/Dense> <nlohmann/json.hpp> <fmt/format.h> <gtest/gtest.h>)
  endif()
endfunction()

# shockmap_reuse_precompiled_headers(TARGET DONOR): TARGET, built with the same flags as DONOR,
# uses DONOR's compiled headers (for the one-file test executables, where a header compiled per
# target would cost what it saves).
function(shockmap_reuse_precompiled_headers target donor)
  if(SHOCKMAP_PRECOMPILED_HEADERS AND NOT target STREQUAL donor)
    target_precompile_headers(${target} REUSE_FROM ${donor})
  endif()
endfunction()
