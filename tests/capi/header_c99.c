/* The public header as strict C99 (-Wall -Wextra -Werror -pedantic): a host
 * written in C must be able to include it and use every declaration. */
#include "creepwork/creepwork.h"

/* struct_size first, so old and new layouts agree on where to find it. */
typedef char cw_check_params_size_first[offsetof(cw_params, struct_size) == 0 ? 1 : -1];
typedef char cw_check_result_size_first[offsetof(cw_result, struct_size) == 0 ? 1 : -1];

/* Prototypes are usable as C function pointers (no C++ types leak). */
int cw_header_c99_check(void);
int cw_header_c99_check(void)
{
    int (*solve)(cw_solver*, const cw_params*, int, cw_result*) = cw_solver_solve;
    const char* (*message)(int) = cw_status_string;
    enum cw_status status = CW_OK;
    cw_accumulation totals;
    totals.steps = (int64_t)0;
    return (solve != 0) + (message != 0) + (int)status + (int)totals.steps;
}
