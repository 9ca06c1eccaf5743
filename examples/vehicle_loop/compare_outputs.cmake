# Runs the three vehicle loops (C, FORTRAN 77 legacy layer, Fortran 2003
# module) and requires the same printed results: totals and the lateral work
# profile, to the 10 significant digits printed (blanks and the case of the
# exponent letter aside).
# Usage: cmake -DPROGRAMS="c;f77;f2003" -P compare_outputs.cmake
cmake_minimum_required(VERSION 3.25)
set(reference "")
foreach(program IN LISTS PROGRAMS)
  execute_process(COMMAND ${program} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${program} failed (${rc}):\n${out}\n${err}")
  endif()
  string(TOLOWER "${out}" out)
  string(REGEX REPLACE "[ \t]+" " " out "${out}")
  string(REGEX REPLACE " ?\n ?" "\n" out "${out}")
  string(STRIP "${out}" out)
  if(reference STREQUAL "")
    set(reference "${out}")
    set(reference_program ${program})
  elseif(NOT out STREQUAL reference)
    message(FATAL_ERROR "${program} and ${reference_program} print different results:\n"
                        "--- ${reference_program}\n${reference}\n--- ${program}\n${out}")
  endif()
endforeach()
message(STATUS "identical results:\n${reference}")
