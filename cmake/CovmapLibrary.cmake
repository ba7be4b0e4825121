# covmap_library(): one folder, one library, and what its users may see.
#
# Sources include covmap headers by their path from the repository root ("voronoi/engine.h").
# A target does not get the whole tree on its include path: each library publishes only the
# headers it lists as PUBLIC_HEADERS, through a folder of links in the build tree
# (build/visible/<target>/<folder>/<header>), and sees all of its own folder through a second one
# (build/visible/internal/<folder>). Including another library's internal header, or a header of a
# library one does not link, is then a compile error rather than a silent arrow upwards.
#
#   covmap_library(NAME covmap_voronoi FOLDER voronoi
#                  SOURCES ... PUBLIC_HEADERS engine.h faces.h ...
#                  PUBLIC_DEPS covmap_core PRIVATE_DEPS CGAL::CGAL)
#
# covmap_sees_internals(TARGET FOLDER...) gives a test or benchmark the internal headers of FOLDER
# (white-box tests of a library's parts).
include_guard(GLOBAL)

function(covmap_visible_root out)
  set(${out} "${PROJECT_BINARY_DIR}/visible" PARENT_SCOPE)
endfunction()

# A symbolic link at `link` to `target`, made at configure time (kept when already right).
function(covmap_link target link)
  get_filename_component(dir "${link}" DIRECTORY)
  file(MAKE_DIRECTORY "${dir}")
  if(IS_SYMLINK "${link}")
    file(READ_SYMLINK "${link}" current)
    if(current STREQUAL target)
      return()
    endif()
    file(REMOVE "${link}")
  endif()
  file(CREATE_LINK "${target}" "${link}" SYMBOLIC)
endfunction()

function(covmap_internal_dir folder out)
  covmap_visible_root(root)
  string(REPLACE "/" "_" key "${folder}")
  set(dir "${root}/internal/${key}")
  covmap_link("${PROJECT_SOURCE_DIR}/${folder}" "${dir}/${folder}")
  set(${out} "${dir}" PARENT_SCOPE)
endfunction()

function(covmap_library)
  cmake_parse_arguments(L "INTERFACE" "NAME;FOLDER" "SOURCES;PUBLIC_HEADERS;PUBLIC_DEPS;PRIVATE_DEPS" ${ARGN})
  covmap_visible_root(root)
  set(public_dir "${root}/${L_NAME}")
  file(REMOVE_RECURSE "${public_dir}")
  foreach(h IN LISTS L_PUBLIC_HEADERS)
    if(NOT EXISTS "${PROJECT_SOURCE_DIR}/${L_FOLDER}/${h}")
      message(FATAL_ERROR "${L_NAME}: public header ${L_FOLDER}/${h} does not exist")
    endif()
    covmap_link("${PROJECT_SOURCE_DIR}/${L_FOLDER}/${h}" "${public_dir}/${L_FOLDER}/${h}")
  endforeach()
  file(MAKE_DIRECTORY "${public_dir}")
  if(L_INTERFACE)
    add_library(${L_NAME} INTERFACE)
    target_include_directories(${L_NAME} INTERFACE "${public_dir}")
    target_link_libraries(${L_NAME} INTERFACE ${L_PUBLIC_DEPS})
    return()
  endif()
  add_library(${L_NAME} STATIC ${L_SOURCES})
  covmap_internal_dir("${L_FOLDER}" internal_dir)
  target_include_directories(${L_NAME} PUBLIC "$<BUILD_INTERFACE:${public_dir}>" PRIVATE "${internal_dir}")
  target_link_libraries(${L_NAME} PUBLIC ${L_PUBLIC_DEPS} PRIVATE ${L_PRIVATE_DEPS})
endfunction()

function(covmap_sees_internals target)
  foreach(folder IN LISTS ARGN)
    covmap_internal_dir("${folder}" dir)
    target_include_directories(${target} PRIVATE "${dir}")
  endforeach()
endfunction()
