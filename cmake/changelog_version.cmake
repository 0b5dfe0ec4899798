# shockmap_check_changelog_version(CHANGELOG VERSION): fails the configuration unless the top
# release entry of CHANGELOG ("## [X.Y.Z] - date", Keep a Changelog; an "Unreleased" entry above
# it is skipped) is VERSION, so that `shockmap --version` and the changelog name one release.
function(shockmap_check_changelog_version changelog version)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${changelog})
  file(STRINGS ${changelog} entries REGEX "^## \\[[0-9]+\\.[0-9]+\\.[0-9]+\\]")
  list(LENGTH entries count)
  if(count EQUAL 0)
    message(FATAL_ERROR "${changelog}: no release entry \"## [X.Y.Z] - YYYY-MM-DD\"")
  endif()
  list(GET entries 0 top)
  string(REGEX MATCH "[0-9]+\\.[0-9]+\\.[0-9]+" top_version "${top}")
  if(NOT top_version STREQUAL version)
    message(FATAL_ERROR "${changelog}: the top release is ${top_version}, but project(VERSION) "
                        "in CMakeLists.txt is ${version}; give both the same number")
  endif()
endfunction()
