# Open CASCADE, where Debian's libocct-*-dev is installed: the conversion study's peer
# (designers/convert/occt_peer.cpp) and the exchange tests' read-back (occt_readback.h).
find_package(OpenCASCADE QUIET)

# polarform_link_occt(<target> <link scope> <definition scope> <toolkit>...): the target sees Open
# CASCADE's headers and links the toolkits, and POLARFORM_HAVE_OCCT=1 is defined with the given
# scope; returns without a word when Open CASCADE is not found (the caller says what it loses).
# The toolkits are linked by file: Debian's imported targets also name libtbb.so, which only
# libtbb-dev provides.
function(polarform_link_occt target link_scope definition_scope)
  if(NOT OpenCASCADE_FOUND)
    return()
  endif()
  target_include_directories(${target} SYSTEM ${link_scope} ${OpenCASCADE_INCLUDE_DIR})
  foreach(toolkit ${ARGN})
    find_library(POLARFORM_OCCT_${toolkit} ${toolkit} HINTS ${OpenCASCADE_LIBRARY_DIR})
    target_link_libraries(${target} ${link_scope} ${POLARFORM_OCCT_${toolkit}})
  endforeach()
  target_compile_definitions(${target} ${definition_scope} POLARFORM_HAVE_OCCT=1)
endfunction()
