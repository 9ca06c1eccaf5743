// Versions, status strings, struct initialisers and the solver handle.
#include "capi_internal.hpp"

extern "C" {

int cw_version_number(void) { return CW_VERSION_NUMBER; }
int cw_abi_version(void) { return CW_ABI_VERSION; }
#define CW_STRING_(x) #x
#define CW_STRING(x) CW_STRING_(x)
const char* cw_version_string(void)
{
    return CW_STRING(CW_VERSION_MAJOR) "." CW_STRING(CW_VERSION_MINOR) "." CW_STRING(
        CW_VERSION_PATCH);
}
#undef CW_STRING
#undef CW_STRING_

const char* cw_status_string(int status)
{
    switch (status) {
#define CW_STATUS_MESSAGE_(name, value, message) \
    case value: return message;
        CW_STATUS_LIST(CW_STATUS_MESSAGE_)
#undef CW_STATUS_MESSAGE_
    default: return "unknown status code";
    }
}

int cw_grid_init(cw_grid* grid)
{
    if (!grid) return CW_ERR_NULL_POINTER;
    *grid = default_grid();
    return CW_OK;
}

int cw_params_init(cw_params* params)
{
    if (!params) return CW_ERR_NULL_POINTER;
    *params = default_params();
    return CW_OK;
}

int cw_result_init(cw_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_solver_create(const cw_grid* grid, cw_solver** solver, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(solver, "solver");
        *solver = nullptr;
        const cw::GridSpec spec = to_grid(grid);
        *solver = new cw_solver(spec);
        return CW_OK;
    });
}

int cw_solver_destroy(cw_solver* solver)
{
    delete solver;
    return CW_OK;
}

int cw_solver_grid_size(const cw_solver* solver, int* nx, int* ny)
{
    if (!solver || !nx || !ny) return CW_ERR_NULL_POINTER;
    *nx = solver->solver.grid().nx();
    *ny = solver->solver.grid().ny();
    return CW_OK;
}

int cw_solver_solve(cw_solver* solver, const cw_params* params, int mode, cw_result* result)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    const int status = guarded(&solver->last_error, [&] {
        require(params, "params");
        require_result_size(result, "cw_result_init");
        const cw::ContactInput in = to_input(params);
        const cw::SolveMode m = to_mode(mode);
        solver->V = 0.0;
        solver->rolling_direction = 0;
        const cw::SolveTotals& t = solver->solver.solve(in, m);
        solver->V = in.V;
        solver->rolling_direction = in.rolling_direction;
        if (result) write_struct(result, to_result(t));
        return CW_OK;
    });
    // The header's promise: after any failed solve the handle holds no solution.
    if (status != CW_OK) solver->solver.discard();
    return status;
}

int cw_solver_solve_jacobian(cw_solver* solver, const cw_params* params, int mode,
                             cw_result* result, double* jacobian, size_t jacobian_len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    const int status = guarded(&solver->last_error, [&] {
        require(params, "params");
        require(jacobian, "jacobian");
        require_length(jacobian_len, CW_JACOBIAN_LEN, "jacobian");
        require_result_size(result, "cw_result_init");
        const cw::ContactInput in = to_input(params);
        const cw::SolveMode m = to_mode(mode);
        cw::Jacobian J;
        solver->V = 0.0;
        solver->rolling_direction = 0;
        const cw::SolveTotals& t = solver->solver.solve_jacobian(in, m, J);
        solver->V = in.V;
        solver->rolling_direction = in.rolling_direction;
        if (result) write_struct(result, to_result(t));
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 4; ++c) jacobian[4 * r + c] = J.d[r][c];
        return CW_OK;
    });
    if (status != CW_OK) solver->solver.discard();
    return status;
}

int cw_solver_prepare(cw_solver* solver, int model)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(&solver->last_error, [&] {
        solver->solver.prepare(to_model(model));
        return CW_OK;
    });
}

int cw_solver_get_result(const cw_solver* solver, cw_result* result)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(&solver->last_error, [&] {
        require(result, "result");
        require_solution(solver->solver, false);
        write_struct(result, to_result(solver->solver.totals()));
        return CW_OK;
    });
}

int cw_solver_get_field(const cw_solver* solver, int field, double* out, size_t out_len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(&solver->last_error, [&] {
        const cw::Field f = to_field(field);
        require(out, "out");
        require_solution(solver->solver, cw::Solver::needs_work(f));
        require_length(out_len, element_count(solver->solver), "out");
        solver->solver.copy_field(f, out);
        return CW_OK;
    });
}

int cw_solver_get_state(const cw_solver* solver, int* out, size_t out_len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(&solver->last_error, [&] {
        require(out, "out");
        require_solution(solver->solver, false);
        require_length(out_len, element_count(solver->solver), "out");
        solver->solver.copy_state(out);
        return CW_OK;
    });
}

int cw_solver_get_profile(const cw_solver* solver, double* y, double* w, double* parabola,
                          size_t len)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    return guarded(&solver->last_error, [&] {
        require_solution(solver->solver, true);
        require_length(len, static_cast<size_t>(solver->solver.grid().ny()), "profile buffers");
        solver->solver.copy_profile(y, w, parabola);
        return CW_OK;
    });
}

const char* cw_solver_last_error(const cw_solver* solver)
{
    return solver ? solver->last_error.c_str() : "solver is NULL";
}

} // extern "C"
