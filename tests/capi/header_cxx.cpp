// The public header as strict C++11 (-Wall -Wextra -Werror -pedantic): a C++
// host includes it as is. (That the functions have C linkage is shown by the
// C tests linking and by test_capi_exports: no mangled names.)
#include "creepwork/creepwork.h"

#include <type_traits>

static_assert(std::is_standard_layout<cw_params>::value, "cw_params must be a plain C struct");
static_assert(std::is_standard_layout<cw_result>::value, "cw_result must be a plain C struct");
static_assert(std::is_trivially_copyable<cw_grid>::value, "cw_grid must be a plain C struct");
static_assert(offsetof(cw_params, struct_size) == 0, "struct_size comes first");

typedef int cw_solve_fn(cw_solver*, const cw_params*, int, cw_result*);

int cw_header_cxx_check();
int cw_header_cxx_check()
{
    cw_solve_fn* solve = &cw_solver_solve;
    const int status = CW_ERR_INTERNAL;
    return (solve != nullptr) + status + CW_VERSION_NUMBER;
}
