# The layers of polarform (ui -> jobs -> {designers, export} -> src), enforced by the compiler:
# each library gets an include root of its own, a folder of the build tree that holds nothing but a
# link to the library's source folder. `#include "designers/cam/plate_cam.h"` therefore resolves
# only in targets that link polarform_designers, and a lower layer that includes a higher one does
# not compile. tests/layers adds the include-direction ctest and the link-alone checks.
include_guard(GLOBAL)
include(GNUInstallDirs)

# polarform_include_root(TARGET FOLDER [PRIVATE|INTERFACE]): FOLDER (relative to the source tree,
# e.g. "src" or "ui/cli") becomes includable as "FOLDER/..." by TARGET and, unless PRIVATE, by
# whatever links it (INTERFACE: only by what links it, for header-only libraries).
function(polarform_include_root target folder)
  set(root ${PROJECT_BINARY_DIR}/include-roots/${target})
  get_filename_component(parent ${root}/${folder} DIRECTORY)
  file(MAKE_DIRECTORY ${parent})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/${folder} ${root}/${folder} SYMBOLIC)
  if(ARGV2 STREQUAL "PRIVATE")
    target_include_directories(${target} PRIVATE ${root})
  elseif(ARGV2 STREQUAL "INTERFACE")
    target_include_directories(${target} INTERFACE ${root})
  else()
    target_include_directories(${target} PUBLIC
      $<BUILD_INTERFACE:${root}> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/polarform>)
  endif()
endfunction()

# polarform_library(NAME FOLDER SOURCES... LINKS...): a static library of one layer, its sources
# listed explicitly (relative to FOLDER), its include root FOLDER and the libraries it links.
function(polarform_library name folder)
  cmake_parse_arguments(arg "" "" "SOURCES;LINKS" ${ARGN})
  list(TRANSFORM arg_SOURCES PREPEND ${PROJECT_SOURCE_DIR}/${folder}/)
  add_library(${name} STATIC ${arg_SOURCES})
  string(REPLACE "polarform_" "" export_name ${name})
  set_target_properties(${name} PROPERTIES EXPORT_NAME ${export_name})
  add_library(polarform::${export_name} ALIAS ${name})
  polarform_include_root(${name} ${folder})
  target_link_libraries(${name} PUBLIC ${arg_LINKS})
endfunction()
