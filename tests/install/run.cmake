# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P run.cmake: installs the build into
# WORK_DIR/prefix, builds tests/install against it (with BUILD_TYPE and CONSUMER_FLAGS, the
# sanitizer flags of a sanitized build) with find_package(shockmap) and runs it.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  message("${out}")
endfunction()
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install -B ${WORK_DIR}/build
     -DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
     "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}")
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${WORK_DIR}/build/compare_once)
step(${WORK_DIR}/prefix/bin/shockmap --version)
# The Python package from the prefix, in an empty folder: the README's Err of
# `compare --rk 3000 --rftrunc 300` to its four decimals, from the installed module (not the
# build's).
if(PYTHON_EXECUTABLE)
  file(MAKE_DIRECTORY ${WORK_DIR}/empty)
  set(site ${WORK_DIR}/prefix/${PYTHON_PACKAGE_DIR})
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON_EXECUTABLE} -c
            "import shockmap; print(shockmap.__file__); print(f\"{shockmap.compare(rk=3000, rftrunc=300).err:.4f}\")"
    WORKING_DIRECTORY ${WORK_DIR}/empty RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^${site}/shockmap/__init__.py\n0\\.0355")
    message(FATAL_ERROR "the installed Python module did not print Err 0.0355... from ${site}")
  endif()
endif()
