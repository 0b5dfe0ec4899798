# `cmake --install`: the executable, the libraries with their headers (include/shockmap/<folder>,
# included as <shockmap/core/scene.h>), a CMake package (find_package(shockmap) gives the targets
# shockmap::core ... shockmap::views, their dependencies found again by shockmapConfig.cmake, and
# the component mpi), the shared data, the bash completion and the man page.
include(CMakePackageConfigHelpers)

set(SHOCKMAP_LIBRARIES core records reference validation statistics compare formats specs db analysis engine views workflows)
set(SHOCKMAP_LIBRARY_TARGETS)
foreach(folder IN LISTS SHOCKMAP_LIBRARIES)
  set_target_properties(shockmap_${folder} PROPERTIES EXPORT_NAME ${folder})
  list(APPEND SHOCKMAP_LIBRARY_TARGETS shockmap_${folder})
endforeach()
install(CODE "set(SOURCE_DIR \"${CMAKE_SOURCE_DIR}\")
              set(FOLDERS \"${SHOCKMAP_LIBRARIES}\")
              set(HEADER_DIR \"${CMAKE_INSTALL_INCLUDEDIR}\")
              include(\"${CMAKE_SOURCE_DIR}/cmake/install_headers.cmake\")")

install(TARGETS shockmap RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${SHOCKMAP_LIBRARY_TARGETS} EXPORT shockmapTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
set(SHOCKMAP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shockmap)
install(EXPORT shockmapTargets NAMESPACE shockmap:: DESTINATION ${SHOCKMAP_CMAKE_DIR})
# A study's worker ranks under an MPI launcher (engine/mpi_job.h): the component mpi, the only
# target that needs MPI, loaded on request so that the others configure without MPI.
set_target_properties(shockmap_mpi PROPERTIES EXPORT_NAME mpi)
install(TARGETS shockmap_mpi EXPORT shockmapMpiTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(EXPORT shockmapMpiTargets NAMESPACE shockmap:: DESTINATION ${SHOCKMAP_CMAKE_DIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/shockmapConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/shockmapConfig.cmake
                              INSTALL_DESTINATION ${SHOCKMAP_CMAKE_DIR})
# Before 1.0 a minor release may change the interfaces: only the same minor version matches.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/shockmapConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/shockmapConfig.cmake
              ${CMAKE_BINARY_DIR}/shockmapConfigVersion.cmake ${CMAKE_SOURCE_DIR}/cmake/FindCHOLMOD.cmake
        DESTINATION ${SHOCKMAP_CMAKE_DIR})
install(FILES ${CMAKE_SOURCE_DIR}/LICENSE ${CMAKE_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})

# The data the commands name by default (app/shared_data.h) and the examples, in
# share/shockmap; the build tree's build/share/shockmap links to the sources, so that
# build/app/shockmap finds them the same way, beside itself.
foreach(folder studies scenes examples)
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${folder} DESTINATION ${CMAKE_INSTALL_DATADIR}/shockmap)
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/share/shockmap)
  file(CREATE_LINK ${CMAKE_SOURCE_DIR}/${folder} ${CMAKE_BINARY_DIR}/share/shockmap/${folder}
       SYMBOLIC)
endforeach()

# The bash completion, where bash-completion looks under the prefix (loaded on first use of
# `shockmap` in a shell).
set(SHOCKMAP_COMPLETION ${CMAKE_BINARY_DIR}/completion/shockmap)
file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/completion)
add_custom_command(OUTPUT ${SHOCKMAP_COMPLETION}
                   COMMAND shockmap completion bash > ${SHOCKMAP_COMPLETION}
                   DEPENDS shockmap
                   COMMENT "Writing the bash completion")
add_custom_target(shockmap_completion ALL DEPENDS ${SHOCKMAP_COMPLETION})
install(FILES ${SHOCKMAP_COMPLETION}
        DESTINATION ${CMAKE_INSTALL_DATADIR}/bash-completion/completions)

# The man page, from the commands' --help by help2man (Debian package help2man), when present:
# the top-level help, then every command's (cmake/man_commands.cmake), then app/shockmap.h2m.
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(SHOCKMAP_MAN_PAGE ${CMAKE_BINARY_DIR}/man/shockmap.1)
  set(SHOCKMAP_MAN_COMMANDS ${CMAKE_BINARY_DIR}/man/commands.h2m)
  file(MAKE_DIRECTORY ${CMAKE_BINARY_DIR}/man)
  add_custom_command(
    OUTPUT ${SHOCKMAP_MAN_PAGE}
    COMMAND ${CMAKE_COMMAND} -DSHOCKMAP=$<TARGET_FILE:shockmap> -DOUTPUT=${SHOCKMAP_MAN_COMMANDS}
            -P ${CMAKE_SOURCE_DIR}/cmake/man_commands.cmake
    COMMAND ${HELP2MAN} --no-info --version-string=${PROJECT_VERSION}
            "--name=validity maps of modal reduction with explicit integration"
            --include=${SHOCKMAP_MAN_COMMANDS} --include=${CMAKE_SOURCE_DIR}/app/shockmap.h2m
            --output=${SHOCKMAP_MAN_PAGE} $<TARGET_FILE:shockmap>
    DEPENDS shockmap ${CMAKE_SOURCE_DIR}/cmake/man_commands.cmake
            ${CMAKE_SOURCE_DIR}/app/shockmap.h2m
    COMMENT "Writing the man page shockmap.1"
    VERBATIM)
  add_custom_target(shockmap_man_page ALL DEPENDS ${SHOCKMAP_MAN_PAGE})
  install(FILES ${SHOCKMAP_MAN_PAGE} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found (Debian package help2man): the man page shockmap.1 is "
                 "neither built nor installed")
endif()
