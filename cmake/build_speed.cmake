# What keeps the build short on two cores, measured choice by choice in
# doc/dev/decisions.md ("Build time"). None of it changes a result bit:
# precompiled headers only pre-parse headers, and the lighter optimisation
# is for programs whose time is spent in the library (IEEE arithmetic
# without contraction gives the same bits at every -O level).

# ccache when it is installed (and no launcher was chosen): a rebuild of an
# unchanged source costs a look-up. A precompiled header is only cached
# when ccache ignores its macros and time stamps, so the launcher says so.
# Paths are hashed relative to the top of the source tree, so that another
# copy of the tree (the documentation's recipes build one) finds the
# objects of this one.
option(CREEPWORK_USE_CCACHE "Compile through ccache when it is installed" ON)
if(CREEPWORK_USE_CCACHE)
  find_program(CREEPWORK_CCACHE ccache)
  mark_as_advanced(CREEPWORK_CCACHE)
  foreach(_cw_lang C CXX)
    if(CREEPWORK_CCACHE AND NOT CMAKE_${_cw_lang}_COMPILER_LAUNCHER)
      set(CMAKE_${_cw_lang}_COMPILER_LAUNCHER ${CREEPWORK_CCACHE})
    endif()
    list(GET CMAKE_${_cw_lang}_COMPILER_LAUNCHER 0 _cw_launcher)
    get_filename_component(_cw_launcher "${_cw_launcher}" NAME)
    if(_cw_launcher STREQUAL "ccache")
      set(CMAKE_${_cw_lang}_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env
          CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime
          CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}
          ${CMAKE_${_cw_lang}_COMPILER_LAUNCHER})
    endif()
  endforeach()
endif()

# creepwork_optimise_lightly(<target>...): -O1 instead of Release's -O3
# for the programs that parse options, format text and call the library,
# where their time goes: their Release compile takes half as long, and
# they run as fast (the creepwork program's own instructions are 0.2 % of
# a 200 x 200 `creepwork solve --out`). The library itself keeps -O3.
function(creepwork_optimise_lightly)
  foreach(_cw_target IN LISTS ARGN)
    target_compile_options(${_cw_target} PRIVATE
      $<$<AND:$<CONFIG:Release>,$<COMPILE_LANGUAGE:C,CXX>>:-O1>)
  endforeach()
endfunction()

# creepwork_unity_folders(<target> BATCH <n> FOLDERS <folder>...): the
# target's sources in each folder compiled as translation units of at most
# <n> sources, as few units as that allows, of equal size (a unity build:
# the headers, Eigen's templates and the inline functions they share are
# compiled once per unit). Sources of other folders, and sources with
# options of their own, stay units of their own. A folder is listed once its
# sources share a namespace without a clash (two private constants of one
# name do not compile).
function(creepwork_unity_folders target)
  cmake_parse_arguments(U "" "BATCH" "FOLDERS" ${ARGN})
  get_target_property(_cw_sources ${target} SOURCES)
  get_target_property(_cw_dir ${target} SOURCE_DIR)
  foreach(_cw_folder IN LISTS U_FOLDERS)
    set(_cw_members "")
    foreach(_cw_source IN LISTS _cw_sources)
      if(IS_ABSOLUTE "${_cw_source}")
        file(RELATIVE_PATH _cw_relative ${_cw_dir} ${_cw_source})
      else()
        set(_cw_relative ${_cw_source})
      endif()
      if(_cw_relative MATCHES "^${_cw_folder}/")
        list(APPEND _cw_members ${_cw_source})
      endif()
    endforeach()
    list(LENGTH _cw_members _cw_count)
    math(EXPR _cw_units "(${_cw_count} + ${U_BATCH} - 1) / ${U_BATCH}")
    set(_cw_index 0)
    foreach(_cw_source IN LISTS _cw_members)
      math(EXPR _cw_unit "${_cw_index} * ${_cw_units} / ${_cw_count}")
      set_source_files_properties(${_cw_source} TARGET_DIRECTORY ${target}
                                  PROPERTIES UNITY_GROUP ${_cw_folder}_${_cw_unit})
      math(EXPR _cw_index "${_cw_index} + 1")
    endforeach()
  endforeach()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_MODE GROUP)
endfunction()

# creepwork_share_test_headers(): the standard headers and Eigen, parsed
# once for all test and tool programs and their support libraries (every
# executable or static library of C++ sources only, without a unity build
# or a precompiled header of its own) instead of once per source: a
# precompiled header of a target of its own, reused; one for executables
# (-fPIE) and one for libraries (-fPIC). Called once, after every directory
# is added. GCC only: GCC parses as before where it cannot use the header
# (other flags), where Clang stops.
function(creepwork_share_test_headers)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "GNU" OR CMAKE_DISABLE_PRECOMPILE_HEADERS)
    return()
  endif()
  set(_cw_dirs ${PROJECT_SOURCE_DIR})
  while(_cw_dirs)
    list(POP_FRONT _cw_dirs _cw_dir)
    get_property(_cw_subdirs DIRECTORY ${_cw_dir} PROPERTY SUBDIRECTORIES)
    list(APPEND _cw_dirs ${_cw_subdirs})
    get_property(_cw_targets DIRECTORY ${_cw_dir} PROPERTY BUILDSYSTEM_TARGETS)
    foreach(_cw_target IN LISTS _cw_targets)
      get_target_property(_cw_type ${_cw_target} TYPE)
      get_target_property(_cw_unity ${_cw_target} UNITY_BUILD)
      get_target_property(_cw_pch ${_cw_target} PRECOMPILE_HEADERS)
      get_target_property(_cw_sources ${_cw_target} SOURCES)
      list(FILTER _cw_sources EXCLUDE REGEX "\\.cpp$")
      if(_cw_type MATCHES "^(EXECUTABLE|STATIC_LIBRARY)$" AND NOT _cw_unity AND NOT _cw_pch
         AND NOT _cw_sources)
        _creepwork_test_pch(${_cw_type} _cw_donor)
        target_precompile_headers(${_cw_target} REUSE_FROM ${_cw_donor})
        # Eigen's headers, should the precompiled header ever be parsed instead.
        target_link_libraries(${_cw_target} PRIVATE Eigen3::Eigen)
      endif()
    endforeach()
  endwhile()
endfunction()

# _creepwork_test_pch(<type> <out>): the target whose precompiled header
# targets of <type> reuse, made on first use.
function(_creepwork_test_pch type out)
  if(type STREQUAL "EXECUTABLE")
    set(_cw_donor creepwork_test_pch)
    set(_cw_pic ${CMAKE_CXX_COMPILE_OPTIONS_PIE})
  else()
    set(_cw_donor creepwork_test_pch_pic)
    set(_cw_pic ${CMAKE_CXX_COMPILE_OPTIONS_PIC})
  endif()
  if(NOT TARGET ${_cw_donor})
    set(_cw_anchor ${PROJECT_BINARY_DIR}/generated/${_cw_donor}.cpp)
    file(CONFIGURE OUTPUT ${_cw_anchor}
         CONTENT "// The source a shared precompiled header is compiled with.\n")
    add_library(${_cw_donor} OBJECT ${_cw_anchor})
    # The flags of the targets that reuse it: an object library's own
    # position-independent flag would be -fPIC for executables too.
    set_target_properties(${_cw_donor} PROPERTIES POSITION_INDEPENDENT_CODE OFF)
    target_compile_options(${_cw_donor} PRIVATE ${_cw_pic})
    target_link_libraries(${_cw_donor} PRIVATE Eigen3::Eigen)
    target_precompile_headers(${_cw_donor} PRIVATE
      <algorithm> <cmath> <cstdio> <cstdlib> <cstring> <fstream> <functional> <map>
      <memory> <sstream> <string> <vector> <Eigen/Core>)
  endif()
  set(${out} ${_cw_donor} PARENT_SCOPE)
endfunction()
