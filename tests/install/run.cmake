# cmake -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -P run.cmake: installs the build into
# WORK_DIR/prefix, builds tests/install against it (with BUILD_TYPE and CONSUMER_FLAGS, the
# sanitizer flags of a sanitized build, and MPI hidden) with find_package(shockmap) and runs it;
# then, in an empty folder, runs the installed `shockmap advise` on an installed scene with its
# default criteria, loads the installed bash completion and, when HELP2MAN is set, reads the
# installed man page.
file(REMOVE_RECURSE ${WORK_DIR})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out
                  WORKING_DIRECTORY ${WORK_DIR}/empty)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "failed (${rc}): ${ARGN}\n${out}")
  endif()
  message("${out}")
  set(out "${out}" PARENT_SCOPE)
endfunction()
# Fails unless the last step's output matches `regex`.
function(expect regex what)
  if(NOT out MATCHES "${regex}")
    message(FATAL_ERROR "${what}: no match for ${regex}")
  endif()
endfunction()
file(MAKE_DIRECTORY ${WORK_DIR}/empty)
set(prefix ${WORK_DIR}/prefix)
step(${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix})
step(${CMAKE_COMMAND} -S ${SOURCE_DIR}/tests/install -B ${WORK_DIR}/build
     -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_BUILD_TYPE=${BUILD_TYPE}
     -DCMAKE_DISABLE_FIND_PACKAGE_MPI=ON
     "-DCMAKE_CXX_FLAGS=${CONSUMER_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${CONSUMER_FLAGS}")
step(${CMAKE_COMMAND} --build ${WORK_DIR}/build)
step(${WORK_DIR}/build/compare_once)
step(${prefix}/bin/shockmap --version)

# The installed advice on an installed scene, its criteria from the installed baseline.
step(${prefix}/bin/shockmap advise ${prefix}/share/shockmap/scenes/bundle_hex_7.json)
expect("^criteria from ${prefix}/share/shockmap/studies/baselines/modes_fig4_peak_force.json\n.*R_k"
       "advise with the default criteria")
# The installed bundle's advice with its check on the bundle's ensemble, from the installed
# outcomes.
step(${prefix}/bin/shockmap advise ${prefix}/share/shockmap/scenes/bundle_row.json)
expect("checked      on the scene's ensemble: the advice held.*recorded in ${prefix}/share/shockmap/studies/baselines/advice_checks.json"
       "advise with the default checks")
file(GLOB leftovers ${WORK_DIR}/empty/*)
if(leftovers)
  message(FATAL_ERROR "advise wrote into the working folder: ${leftovers}")
endif()

# The installed completion loads in bash and lists --y's values.
set(completion ${prefix}/share/bash-completion/completions/shockmap)
step(bash -c "source ${completion} && complete -p shockmap && COMP_WORDS=(shockmap map --y '') \
COMP_CWORD=3 && _shockmap && echo \"values: \${COMPREPLY[*]}\"")
expect("complete -o default -F _shockmap shockmap\nvalues: rftrunc dt\n"
       "the installed completion of map --y")

if(HELP2MAN)
  set(man_page ${prefix}/share/man/man1/shockmap.1)
  if(NOT EXISTS ${man_page})
    message(FATAL_ERROR "help2man is installed but ${man_page} is not")
  endif()
  file(READ ${man_page} out)
  expect("\\.SH COMMANDS.*shockmap advise.*--criteria" "the man page's commands")
endif()

# The Python package from the prefix, in an empty folder: the README's Err of
# `compare --rk 3000 --rftrunc 300` to its four decimals, from the installed module (not the
# build's).
if(PYTHON_EXECUTABLE)
  set(site ${prefix}/${PYTHON_PACKAGE_DIR})
  execute_process(
    COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${site} ${PYTHON_EXECUTABLE} -c
            "import shockmap; print(shockmap.__file__); print(f\"{shockmap.compare(rk=3000, rftrunc=300).err:.4f}\")"
    WORKING_DIRECTORY ${WORK_DIR}/empty RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  message("${out}")
  if(NOT rc EQUAL 0 OR NOT out MATCHES "^${site}/shockmap/__init__.py\n0\\.0355")
    message(FATAL_ERROR "the installed Python module did not print Err 0.0355... from ${site}")
  endif()
endif()
