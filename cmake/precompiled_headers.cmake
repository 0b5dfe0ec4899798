# Precompiled headers: Eigen, nlohmann-json and fmt take most of a translation unit's compile
# time (a view parses ~7 s of headers before its own code); compiled once per target they make
# the whole build about a third shorter, which is what keeps CI's three builds inside its limit.
# Each source is still written with its own includes; a build with
# -DSHOCKMAP_PRECOMPILED_HEADERS=OFF checks that they are complete.
option(SHOCKMAP_PRECOMPILED_HEADERS "Compile the common headers once per target" ON)
if(SHOCKMAP_PRECOMPILED_HEADERS AND CMAKE_CXX_COMPILER_ID STREQUAL "GNU"
   AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  # With the headers precompiled, GCC 12 inlines std::string's concatenations differently and
  # misreads about twenty of them (json_reader, sizing_tables, tests' command lines, ...) as
  # copies of 2^63 bytes (GCC bugs 105329 and 105651, fixed in 13); the same files compile
  # without a warning when the headers are not precompiled.
  add_compile_options(-Wno-stringop-overflow -Wno-stringop-overread -Wno-array-bounds)
endif()

# shockmap_precompile_headers(TARGET [EIGEN] [JSON] [FMT] [GTEST]): the standard headers the
# sources share, and each named library the target can include.
function(shockmap_precompile_headers target)
  if(NOT SHOCKMAP_PRECOMPILED_HEADERS)
    return()
  endif()
  cmake_parse_arguments(ARG "EIGEN;JSON;FMT;GTEST" "" "" ${ARGN})
  set(headers <algorithm> <cmath> <cstdint> <filesystem> <functional> <map> <memory> <optional>
              <string> <variant> <vector>)
  if(ARG_EIGEN)
    list(APPEND headers <Eigen/Dense>)
  endif()
  if(ARG_JSON)
    list(APPEND headers <nlohmann/json.hpp>)
  endif()
  if(ARG_FMT)
    list(APPEND headers <fmt/format.h>)
  endif()
  if(ARG_GTEST)
    list(APPEND headers <gtest/gtest.h>)
  endif()
  target_precompile_headers(${target} PRIVATE ${headers})
endfunction()

# shockmap_reuse_precompiled_headers(TARGET DONOR): TARGET, built with the same flags as DONOR,
# uses DONOR's compiled headers (for the one-file test executables, where a header compiled per
# target would cost what it saves).
function(shockmap_reuse_precompiled_headers target donor)
  if(SHOCKMAP_PRECOMPILED_HEADERS AND NOT target STREQUAL donor)
    target_precompile_headers(${target} REUSE_FROM ${donor})
  endif()
endfunction()
