# Unity builds: each target's sources compiled SHOCKMAP_UNITY_BATCH at a time as one translation
# unit, so that what they share (the templates of Eigen, nlohmann-json, fmt and CLI11 they
# instantiate, the inline functions they emit) is compiled once per batch instead of once per
# file. Sources with options of their own (the vector kernels' clones in core/) stay apart, as
# CMake leaves them. Helpers in a source's anonymous namespace must therefore be unique in their
# target. -DSHOCKMAP_UNITY_BUILD=OFF builds file by file, which checks that every file includes
# what it uses.
option(SHOCKMAP_UNITY_BUILD "Compile each target's sources in batches" ON)
set(SHOCKMAP_UNITY_BATCH 12 CACHE STRING "Sources per unity batch")
set(CMAKE_UNITY_BUILD ${SHOCKMAP_UNITY_BUILD})
set(CMAKE_UNITY_BUILD_BATCH_SIZE ${SHOCKMAP_UNITY_BATCH})
