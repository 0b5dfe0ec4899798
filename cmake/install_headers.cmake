# Run by `cmake --install` (cmake/install.cmake): copies each library folder's headers to
# <prefix>/<HEADER_DIR>/shockmap/<folder>, with their includes of one another written as
# "shockmap/<folder>/x.h", so that a consumer with only <prefix>/<HEADER_DIR> on its include
# path writes #include <shockmap/core/scene.h>. Set: SOURCE_DIR, FOLDERS, HEADER_DIR.
string(REPLACE ";" "|" folder_alternatives "${FOLDERS}")
foreach(folder IN LISTS FOLDERS)
  file(GLOB headers ${SOURCE_DIR}/${folder}/*.h)
  foreach(header IN LISTS headers)
    get_filename_component(name ${header} NAME)
    set(installed "$ENV{DESTDIR}${CMAKE_INSTALL_PREFIX}/${HEADER_DIR}/shockmap/${folder}/${name}")
    file(READ ${header} text)
    string(REGEX REPLACE "#include \"(${folder_alternatives})/" "#include \"shockmap/\\1/" text
                         "${text}")
    set(current "")
    if(EXISTS ${installed})
      file(READ ${installed} current)
    endif()
    if(current STREQUAL text)
      message(STATUS "Up-to-date: ${installed}")
    else()
      message(STATUS "Installing: ${installed}")
      file(WRITE ${installed} "${text}")
    endif()
    list(APPEND CMAKE_INSTALL_MANIFEST_FILES ${installed})
  endforeach()
endforeach()
