# What `cmake --install` puts under the prefix: the programs polarform and polarform-studio, the
# four layer libraries with their public headers (repository paths kept under include/polarform,
# so `#include "src/nurbs/bspline.h"` works as in the tree) and the generated version header, and
# the CMake package: find_package(polarform) gives polarform::core, ::designers, ::export and
# ::jobs. tests/install checks it by building examples/consumer against an installed tree.
include_guard(GLOBAL)
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(polarform_package_dir ${CMAKE_INSTALL_LIBDIR}/cmake/polarform)
set(polarform_header_dir ${CMAKE_INSTALL_INCLUDEDIR}/polarform)

install(TARGETS polarform RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(TARGET polarform-studio)
  install(TARGETS polarform-studio RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
endif()

install(TARGETS polarform_core polarform_designers polarform_export polarform_jobs
        EXPORT polarformTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# Each library's folder, headers only (the globbing happens at install time, so a new header is
# installed without touching this file).
foreach(folder src designers export jobs)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${folder} DESTINATION ${polarform_header_dir}
          FILES_MATCHING PATTERN "*.h")
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/polarform_version.h
        DESTINATION ${polarform_header_dir})

install(EXPORT polarformTargets NAMESPACE polarform:: DESTINATION ${polarform_package_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/polarformConfig.cmake.in
  ${PROJECT_BINARY_DIR}/package/polarformConfig.cmake
  INSTALL_DESTINATION ${polarform_package_dir})
# Before 1.0 a minor release may change the API: then only the same major.minor is compatible.
if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(compatibility SameMinorVersion)
else()
  set(compatibility SameMajorVersion)
endif()
write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/polarformConfigVersion.cmake
  COMPATIBILITY ${compatibility})
install(FILES ${PROJECT_BINARY_DIR}/package/polarformConfig.cmake
              ${PROJECT_BINARY_DIR}/package/polarformConfigVersion.cmake
        DESTINATION ${polarform_package_dir})
