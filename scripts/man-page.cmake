# creepwork(1) from the program's own help texts, so the manual page cannot
# drift from the options the program takes: `creepwork --help`, the help of
# every command, and `creepwork-campaign --help` when the campaign runner
# was built. Each help text goes in verbatim (no-fill), escaped for roff.
# usage: cmake -DCLI=<creepwork> [-DCAMPAIGN=<creepwork-campaign>]
#              -DVERSION=<x.y.z> -DOUT=<creepwork.1> -P man-page.cmake
cmake_minimum_required(VERSION 3.25)
foreach(var CLI VERSION OUT)
  if(NOT ${var})
    message(FATAL_ERROR "${var} is not set")
  endif()
endforeach()

# help_text(<out var> <program> [args...]): the program's standard output.
function(help_text out)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE text ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR text STREQUAL "")
    string(REPLACE ";" " " line "${ARGN}")
    message(FATAL_ERROR "man page: '${line}' failed (${rc}): ${err}")
  endif()
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# roff(<out var> <text>): text safe inside .nf/.fi: backslashes as \e, every
# hyphen a minus (so options copy and paste), lines that would start a
# request protected by \&.
function(roff out text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REPLACE "-" "\\-" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

help_text(main ${CLI} --help)
roff(main_roff "${main}")
# The exit status paragraph of the main help, for its own section.
string(REGEX MATCH "exit status:[^\n]*(\n[ ]+[^\n]+)*" exit_status "${main}")
roff(exit_roff "${exit_status}")

set(page ".\\\" Generated from the help texts of creepwork ${VERSION} by scripts/man-page.cmake.
.TH CREEPWORK 1 \"\" \"creepwork ${VERSION}\" \"User Commands\"
.SH NAME
creepwork \\- creep forces, creep moment, frictional work and wear of wheel\\-rail rolling contact
.SH SYNOPSIS
.B creepwork
.I command
.RI [ options ]
.br
.B creepwork
.I command
.B \\-\\-help
.br
.B mpirun \\-np
.I R
.B creepwork campaign
.RI [ options ]
.SH DESCRIPTION
.nf
${main_roff}.fi
.SH COMMANDS
")
foreach(command solve sweep fit-fig6 compare wear wheelrail)
  help_text(text ${CLI} ${command} --help)
  roff(text "${text}")
  string(APPEND page ".SS creepwork ${command}\n.nf\n${text}.fi\n")
endforeach()
string(APPEND page ".SS creepwork campaign\n")
if(CAMPAIGN AND EXISTS "${CAMPAIGN}")
  help_text(text ${CAMPAIGN} --help)
  roff(text "${text}")
  string(APPEND page ".nf\n${text}.fi\n")
else()
  string(APPEND page "This build has no campaign runner (it needs MPI): \\fBcreepwork campaign\\fR says so and exits 1.\n")
endif()
string(APPEND page ".SH EXIT STATUS
.nf
${exit_roff}
.fi
.SH FILES
.TP
.I PREFIX/share/doc/creepwork/
README.md, CHANGELOG.md, LICENSE and the manual:
.I doc/index.md
says what to read first,
.I doc/cli.md
covers this program,
.I doc/campaigns.md
the campaigns.
.SH SEE ALSO
The C header
.IR creepwork/creepwork.h ,
the whole contract of libcreepwork.
")
file(WRITE "${OUT}.tmp" "${page}")
file(COPY_FILE "${OUT}.tmp" "${OUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUT}.tmp")
