# Optimization by library. The numerical libraries (core, reference, validation, statistics,
# compare) are compiled as the build type says (-O3 in Release); the libraries whose run time
# is reading, writing, storing and drawing rather than arithmetic (formats, db, engine, views,
# the executable and the Python module) at -O1 in optimized builds, which takes about a third
# off their compile, most of the executable's (docs/performance.md, "Build time"). GCC keeps
# IEEE arithmetic at every level and fuses no multiply and add without FMA instructions, which
# only core's clones enable: what they compute is the same bit for bit.
option(SHOCKMAP_FAST_COMPILE_IO "Compile the libraries of files, database and views at -O1" ON)

# shockmap_optimize_for_compile_time(TARGET): -O1 for TARGET in Release and RelWithDebInfo
# builds (it follows the build type's -O3 or -O2 on the command line, and the last one counts).
function(shockmap_optimize_for_compile_time target)
  if(SHOCKMAP_FAST_COMPILE_IO)
    target_compile_options(${target} PRIVATE $<$<CONFIG:Release,RelWithDebInfo>:-O1>)
  endif()
endfunction()
