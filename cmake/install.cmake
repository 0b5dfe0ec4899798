# `cmake --install`: the executable, the libraries with their headers (include/shockmap/<folder>),
# and a CMake package: find_package(shockmap) gives the targets shockmap::core ...
# shockmap::views, their dependencies found again by shockmapConfig.cmake.
include(CMakePackageConfigHelpers)

set(SHOCKMAP_LIBRARIES core records reference validation statistics compare formats db engine views)
set(SHOCKMAP_LIBRARY_TARGETS)
foreach(folder IN LISTS SHOCKMAP_LIBRARIES)
  set_target_properties(shockmap_${folder} PROPERTIES EXPORT_NAME ${folder})
  list(APPEND SHOCKMAP_LIBRARY_TARGETS shockmap_${folder})
  install(DIRECTORY ${CMAKE_SOURCE_DIR}/${folder}/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shockmap/${folder}
          FILES_MATCHING PATTERN "*.h")
endforeach()

install(TARGETS shockmap RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(TARGETS ${SHOCKMAP_LIBRARY_TARGETS} EXPORT shockmapTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/shockmap)
set(SHOCKMAP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/shockmap)
install(EXPORT shockmapTargets NAMESPACE shockmap:: DESTINATION ${SHOCKMAP_CMAKE_DIR})

configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/shockmapConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/shockmapConfig.cmake
                              INSTALL_DESTINATION ${SHOCKMAP_CMAKE_DIR})
# Before 1.0 a minor release may change the interfaces: only the same minor version matches.
write_basic_package_version_file(${CMAKE_BINARY_DIR}/shockmapConfigVersion.cmake
                                 VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/shockmapConfig.cmake
              ${CMAKE_BINARY_DIR}/shockmapConfigVersion.cmake
        DESTINATION ${SHOCKMAP_CMAKE_DIR})
install(FILES ${CMAKE_SOURCE_DIR}/LICENSE ${CMAKE_SOURCE_DIR}/CHANGELOG.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
