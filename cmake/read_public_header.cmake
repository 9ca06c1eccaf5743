# creepwork_read_public_header(<creepwork.h> <out_var>): the text of the
# public header with each `#include "creepwork/creepwork_<part>.h"` of a part
# beside it (creepwork_wear.h, creepwork_wheelrail.h) replaced by that part's
# text, so that the generators and the checks read the whole C API as one
# text, as the compiler does. (creepwork_export.h, generated into the build
# tree, is not beside it and stays an include.)
function(creepwork_read_public_header header out_var)
  file(READ "${header}" text)
  get_filename_component(dir "${header}" DIRECTORY)
  string(REGEX MATCHALL "#include \"creepwork/creepwork_[a-z0-9_]+\\.h\"" includes "${text}")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^#include \"creepwork/(creepwork_[a-z0-9_]+\\.h)\"$" "\\1" part "${line}")
    if(EXISTS "${dir}/${part}")
      file(READ "${dir}/${part}" part_text)
      string(REPLACE "${line}" "${part_text}" text "${text}")
    endif()
  endforeach()
  set(${out_var} "${text}" PARENT_SCOPE)
endfunction()
