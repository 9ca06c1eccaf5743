# The legacy layer's documentation cannot drift from its code: every CW*
# subroutine of the legacy sources (SOURCE: fortran/creepwork_legacy*.f90)
# must appear with the same argument list in the installed include files
# (creepwork_legacy.inc, as a "! CALL NAME(...)" comment and an EXTERNAL line;
# creepwork_legacy.fi, as an interface body) and in the user documentation
# (DOCS, the manual's pages: a "`CALL NAME(...)`" line followed by a table
# row for every argument, in any one of them; pages that do not exist are
# skipped), and nothing else may be documented there.
# usage: cmake -DSOURCE="a.f90;b.f90" -DINC=... -DFI=... -DDOCS="x.md;y.md"
#              -P check_legacy_docs.cmake
cmake_minimum_required(VERSION 3.25)

# Joins Fortran continuation lines ('&' at the end, optional '&' or '!' at the
# start of the next) into one line each.
function(joined_text path out)
  file(READ ${path} text)
  string(REGEX REPLACE "&[ \t]*\n[ \t]*!?[ \t]*&?" " " text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# NAME;args... of every "<prefix>NAME(args)" in text, NAME matching CW[A-Z]+.
function(signatures text regex out)
  string(REGEX MATCHALL "${regex}" hits "${text}")
  set(result "")
  foreach(hit IN LISTS hits)
    string(REGEX REPLACE ".*(CW[A-Z]+)[ \t]*\\(([^)]*)\\).*" "\\1|\\2" sig "${hit}")
    string(REGEX REPLACE "[ \t\n]+" "" sig "${sig}")
    list(APPEND result "${sig}")
  endforeach()
  set(${out} "${result}" PARENT_SCOPE)
endfunction()

set(source_sigs "")
foreach(source IN LISTS SOURCE)
  joined_text(${source} source_text)
  string(TOUPPER "${source_text}" source_upper)
  signatures("${source_upper}" "\nSUBROUTINE CW[A-Z]+[ \t]*\\([^)]*\\)" sigs)
  list(APPEND source_sigs ${sigs})
endforeach()
list(LENGTH source_sigs count)
if(count EQUAL 0)
  message(FATAL_ERROR "no CW* subroutine found in ${SOURCE}")
endif()

joined_text(${FI} fi_text)
string(TOUPPER "${fi_text}" fi_upper)
signatures("${fi_upper}" "SUBROUTINE CW[A-Z]+[ \t]*\\([^)]*\\)" fi_sigs)

file(READ ${INC} inc_text)
# "! CALL NAME(a, b," / "!             c, d)" comment blocks: join them.
string(REGEX REPLACE ",[ \t]*\n![ \t]*" ", " inc_joined "${inc_text}")
signatures("${inc_joined}" "! CALL CW[A-Z]+\\([^)]*\\)" inc_sigs)
string(REGEX MATCHALL "\n      EXTERNAL CW[A-Z]+" inc_externals "${inc_text}")

# The documentation: every existing file of DOCS, as one text.
set(docs_text "")
set(doc_files "")
foreach(doc IN LISTS DOCS)
  if(EXISTS ${doc})
    file(READ ${doc} text)
    string(APPEND docs_text "${text}\n")
    list(APPEND doc_files ${doc})
  endif()
endforeach()
if(NOT doc_files)
  message(FATAL_ERROR "none of the documentation files exists: ${DOCS}")
endif()
signatures("${docs_text}" "`CALL CW[A-Z]+\\([^)]*\\)`" docs_sigs)

set(problems "")
foreach(where fi inc docs)
  foreach(sig IN LISTS ${where}_sigs)
    if(NOT sig IN_LIST source_sigs)
      string(APPEND problems "\n  ${where}: ${sig} matches no subroutine of the source")
    endif()
  endforeach()
endforeach()
foreach(sig IN LISTS source_sigs)
  string(REGEX REPLACE "\\|.*" "" name "${sig}")
  foreach(where fi inc docs)
    if(NOT sig IN_LIST ${where}_sigs)
      string(APPEND problems "\n  ${where}: ${name} missing or with other arguments than ${sig}")
    endif()
  endforeach()
  if(NOT "\n      EXTERNAL ${name}" IN_LIST inc_externals)
    string(APPEND problems "\n  inc: no EXTERNAL ${name}")
  endif()
  # docs: each argument in a table row of this routine's section.
  string(FIND "${docs_text}" "`CALL ${name}(" start)
  if(start GREATER -1)
    string(SUBSTRING "${docs_text}" ${start} -1 section)
    string(SUBSTRING "${section}" 1 -1 rest)
    string(FIND "${rest}" "`CALL CW" next)
    if(next GREATER -1)
      string(SUBSTRING "${section}" 0 ${next} section)
    endif()
    string(REGEX REPLACE "^[^|]*\\|" "" args "${sig}")
    string(REPLACE "," ";" args "${args}")
    foreach(arg IN LISTS args)
      if(NOT section MATCHES "\n\\|[^\n]*`${arg}`")
        string(APPEND problems "\n  docs: no table row for ${name} argument ${arg}")
      endif()
    endforeach()
  endif()
endforeach()
if(problems)
  message(FATAL_ERROR "legacy layer documentation drifted:${problems}")
endif()
message(STATUS "${count} legacy routines documented alike in source, .inc, .fi and ${doc_files}")
