# The installed documentation, as a user meets it (the CTest test
# doc_installed): install the build into a fresh prefix, then
#   1. PREFIX/share/doc/creepwork holds README.md, CHANGELOG.md, LICENSE and
#      doc/index.md;
#   2. PREFIX/share/man/man1/creepwork.1 exists, renders without a warning
#      (groff, when installed) and equals the page made now from the
#      installed program's help texts (it cannot drift from them);
#   3. every doc/....md path that `creepwork --help`, a command's help or
#      the campaign runner's help names exists under share/doc/creepwork;
#   4. every example input the manual's commands read ($E/NAME, E being
#      PREFIX/share/creepwork/examples) is installed there (the recipe
#      test runs those commands).
# usage: cmake -DBUILD_DIR=... -DWORK_DIR=... -DSOURCE_DIR=... [-DCONFIG=Release]
#              -P doc-installed.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var BUILD_DIR WORK_DIR SOURCE_DIR)
  if(NOT ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()
if(NOT CONFIG)
  set(CONFIG Release)
endif()
set(prefix ${WORK_DIR}/prefix)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix} --config ${CONFIG}
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "install failed: ${err}")
endif()
set(docdir ${prefix}/share/doc/creepwork)
set(problems "")

# expect_files(<dir> <least> <what> <count-var> <names>...): each name (once)
# is a file under dir, and there are at least `least` of them; else a line
# of problems saying `what` named it. count-var gets the number of names.
function(expect_files dir least what count_var)
  set(names ${ARGN})
  list(REMOVE_DUPLICATES names)
  list(LENGTH names count)
  if(count LESS least)
    string(APPEND problems "\n  ${what} name fewer than ${least} files (${names})")
  endif()
  foreach(name IN LISTS names)
    if(NOT EXISTS ${dir}/${name})
      string(APPEND problems "\n  ${what} name ${name}, which is not in ${dir}")
    endif()
  endforeach()
  set(problems "${problems}" PARENT_SCOPE)
  set(${count_var} ${count} PARENT_SCOPE)
endfunction()

# 1.
foreach(file README.md CHANGELOG.md LICENSE doc/index.md)
  if(NOT EXISTS ${docdir}/${file})
    string(APPEND problems "\n  ${docdir}/${file} was not installed")
  endif()
endforeach()

# 2.
set(man ${prefix}/share/man/man1/creepwork.1)
set(cli ${prefix}/bin/creepwork)
set(campaign ${prefix}/bin/creepwork-campaign)
if(NOT EXISTS ${man})
  string(APPEND problems "\n  ${man} was not installed")
else()
  find_program(GROFF groff)
  if(GROFF)
    execute_process(COMMAND ${GROFF} -man -Tutf8 -ww -z ${man}
                    RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE warnings)
    if(NOT rc EQUAL 0 OR NOT warnings STREQUAL "")
      string(APPEND problems "\n  creepwork.1 does not render cleanly: ${warnings}")
    endif()
  else()
    message(STATUS "groff not found: the man page's rendering is not checked")
  endif()
  file(READ ${SOURCE_DIR}/CMakeLists.txt top)
  string(REGEX MATCH "project\\(creepwork VERSION ([0-9.]+)" _ "${top}")
  execute_process(COMMAND ${CMAKE_COMMAND} -DCLI=${cli} -DCAMPAIGN=${campaign}
                          -DVERSION=${CMAKE_MATCH_1} -DOUT=${WORK_DIR}/creepwork.1
                          -P ${SOURCE_DIR}/scripts/man-page.cmake
                  RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    string(APPEND problems "\n  cannot make the man page from the installed program: ${err}")
  else()
    file(READ ${man} installed)
    file(READ ${WORK_DIR}/creepwork.1 fresh)
    if(NOT installed STREQUAL fresh)
      string(APPEND problems "\n  the installed creepwork.1 differs from the installed program's help texts")
    endif()
  endif()
endif()

# 3.
set(helps "")
foreach(args "--help" "solve;--help" "sweep;--help" "fit-fig6;--help" "compare;--help" "wear;--help")
  execute_process(COMMAND ${cli} ${args} OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  string(APPEND helps "${text}")
endforeach()
if(EXISTS ${campaign})
  execute_process(COMMAND ${campaign} --help OUTPUT_VARIABLE text RESULT_VARIABLE rc)
  string(APPEND helps "${text}")
endif()
string(REGEX MATCHALL "doc/[A-Za-z0-9_./-]*\\.md" paths "${helps}")
expect_files(${docdir} 1 "the help texts" count ${paths})

# 4.
set(inputs README.md)
foreach(page doc/cli.md doc/input-schema.md)
  file(READ ${SOURCE_DIR}/${page} text)
  string(REGEX MATCHALL "\\$E/[A-Za-z0-9_.-]+" named "${text}")
  list(TRANSFORM named REPLACE "^\\$E/" "")
  list(APPEND inputs ${named})
endforeach()
expect_files(${prefix}/share/creepwork/examples 5 "the manual's commands ($E/NAME)" inputs_count
             ${inputs})

if(problems)
  message(FATAL_ERROR "installed documentation:${problems}")
endif()
message(STATUS "installed documentation: man page, doc/index.md, the ${count} doc paths the help "
               "texts name and the ${inputs_count} example files the manual names")
