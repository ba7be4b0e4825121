# covmap_embed_assets(): files of their own (a page, its stylesheet and script, an API document)
# compiled in as C++ raw strings, so a program carries them and they stay readable and testable
# as what they are.
#
#   covmap_embed_assets(TEMPLATE assets.cpp.in OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/assets.cpp
#                       ASSETS VAR_A file_a VAR_B file_b ...)
#
# Each file's text is set as VAR for configure_file(@ONLY), where the template writes it inside
# R"covmap_asset(@VAR@)covmap_asset". Editing a file re-runs the configure step; a file holding
# the raw string's closing delimiter stops it, as it would end the string early.
include_guard(GLOBAL)

function(covmap_embed_assets)
  cmake_parse_arguments(E "" "TEMPLATE;OUTPUT" "ASSETS" ${ARGN})
  list(LENGTH E_ASSETS count)
  math(EXPR odd "${count} % 2")
  if(count EQUAL 0 OR NOT odd EQUAL 0)
    message(FATAL_ERROR "covmap_embed_assets: ASSETS takes pairs of a variable and a file")
  endif()
  math(EXPR last "${count} - 1")
  foreach(k RANGE 0 ${last} 2)
    math(EXPR f "${k} + 1")
    list(GET E_ASSETS ${k} var)
    list(GET E_ASSETS ${f} file)
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
    file(READ "${file}" text)
    string(FIND "${text}" ")covmap_asset\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "${var} contains the raw-string delimiter )covmap_asset\"")
    endif()
    set(${var} "${text}")
  endforeach()
  configure_file("${E_TEMPLATE}" "${E_OUTPUT}" @ONLY)
endfunction()
