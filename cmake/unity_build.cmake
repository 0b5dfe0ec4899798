# Unity builds: each target's sources compiled as one translation unit (SHOCKMAP_UNITY_BATCH at
# a time when not 0), so that what they share (the templates of Eigen, nlohmann-json, fmt and
# CLI11 they instantiate, the inline functions they emit) is compiled once per target instead of
# once per file. Sources with options of their own (the vector kernels' clones in core/) stay
# apart, as CMake leaves them. Helpers in a source's anonymous namespace must therefore be
# unique in their target. -DSHOCKMAP_UNITY_BUILD=OFF builds file by file, which checks that
# every file includes what it uses.
option(SHOCKMAP_UNITY_BUILD "Compile each target's sources in batches" ON)
# The executable alone from a clean clone on 2 cores: file by file (Make, precompiled headers)
# 610 s of wall time, 1 062 s of CPU; with Ninja, batches of 16 287 s (497 s), whole targets
# 220 s (397 s).
set(SHOCKMAP_UNITY_BATCH 0 CACHE STRING "Sources per unity batch (0: all of a target's)")
set(CMAKE_UNITY_BUILD ${SHOCKMAP_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${SHOCKMAP_UNITY_BATCH})
