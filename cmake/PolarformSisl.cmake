# SINTEF's SISL, where Debian's libsisl-dev is installed (sisl.h and the static libsisl.a): the
# conversion study's second peer (designers/convert/sisl_peer.cpp, s1961).
find_path(POLARFORM_SISL_INCLUDE_DIR sisl.h)
find_library(POLARFORM_SISL_LIBRARY NAMES sisl)
if(POLARFORM_SISL_INCLUDE_DIR AND POLARFORM_SISL_LIBRARY)
  set(POLARFORM_SISL_FOUND TRUE)
else()
  set(POLARFORM_SISL_FOUND FALSE)
endif()

# polarform_link_sisl(<target> <link scope> <definition scope>): the target sees sisl.h, links
# libsisl (and libm, which it needs) and POLARFORM_HAVE_SISL=1 is defined with the given scope;
# returns without a word when SISL is not found (the caller says what it loses).
function(polarform_link_sisl target link_scope definition_scope)
  if(NOT POLARFORM_SISL_FOUND)
    return()
  endif()
  target_include_directories(${target} SYSTEM ${link_scope} ${POLARFORM_SISL_INCLUDE_DIR})
  target_link_libraries(${target} ${link_scope} ${POLARFORM_SISL_LIBRARY} m)
  target_compile_definitions(${target} ${definition_scope} POLARFORM_HAVE_SISL=1)
endfunction()
