// Translation between the C structs and the core, and the small helpers of
// every area (capi_internal.hpp).
#include "capi_internal.hpp"

#include <cmath>

#include "contact/number_text.hpp"

#ifdef _OPENMP
#include <omp.h>
#endif

namespace creepwork::capi {

int map_kind(cw::ErrorKind kind)
{
    switch (kind) {
    case cw::ErrorKind::invalid_input: return CW_ERR_INVALID_INPUT;
    case cw::ErrorKind::grid_out_of_range: return CW_ERR_GRID_OUT_OF_RANGE;
    case cw::ErrorKind::numeric_failure: return CW_ERR_NUMERIC;
    case cw::ErrorKind::not_converged: return CW_ERR_NOT_CONVERGED;
    }
    return CW_ERR_INTERNAL;
}

// Free functions report through a caller buffer instead of a handle.
void copy_message(const std::string& text, char* out, size_t len) noexcept
{
    if (!out || len == 0) return;
    const size_t n = std::min(text.size(), len - 1);
    std::memcpy(out, text.data(), n);
    out[n] = '\0';
}

[[noreturn]] void fail(int status, const std::string& message)
{
    throw Failure{status, message};
}

void require(const void* p, const char* name)
{
    if (!p) fail(CW_ERR_NULL_POINTER, std::string(name) + " is NULL");
}

cw_grid default_grid()
{
    cw_grid g;
    std::memset(&g, 0, sizeof g);
    g.struct_size = sizeof g;
    g.kind = CW_GRID_KALKER_STRIPS;
    g.nx = 20;
    g.ny = 20;
    g.box_scale = 1.0;
    return g;
}

cw_params default_params()
{
    cw_params p;
    std::memset(&p, 0, sizeof p);
    p.struct_size = sizeof p;
    p.a = 6e-3;
    p.b = 6e-3;
    p.normal_force = 80e3;
    p.mu = 0.3;
    p.flexibility = CW_FLEX_FROM_MATERIAL;
    p.pressure = CW_PRESSURE_PARABOLIC;
    p.G = 82e9;
    p.nu = 0.28;
    p.rolling_direction = 1;
    p.model = CW_MODEL_FASTSIM;
    p.warm_start = 1;
    p.spin_offset = CW_SPIN_OFFSET_DEFAULT;
    p.gap = nullptr;
    p.normal_load = CW_NORMAL_FORCE;
    p.normal_method = CW_NORMAL_EXACT;
    p.friction_law = CW_FRICTION_COULOMB;
    p.friction_speed = CW_FRICTION_SPEED_LOCAL;
    p.k0 = 1.0;
    p.alpha_inf = 1.0;
    return p;
}

cw::GridSpec to_grid(const cw_grid* grid)
{
    require(grid, "grid");
    const cw_grid g = read_struct(grid, default_grid(), "grid");
    cw::GridSpec spec;
    if (g.kind == CW_GRID_KALKER_STRIPS)
        spec.kind = cw::GridKind::kalker_strips;
    else if (g.kind == CW_GRID_UNIFORM)
        spec.kind = cw::GridKind::uniform;
    else if (g.kind == CW_GRID_GAP)
        spec.kind = cw::GridKind::gap;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "grid->kind = " + std::to_string(g.kind) +
                                        " is not CW_GRID_KALKER_STRIPS (0), CW_GRID_UNIFORM (1) "
                                        "or CW_GRID_GAP (2)");
    spec.nx = g.nx;
    spec.ny = g.ny;
    // The strip and gap grids have no box: whatever the caller left there
    // (even NaN) must not make two equal grids compare unequal.
    spec.box_scale = spec.kind == cw::GridKind::uniform ? g.box_scale : 1.0;
    if (spec.kind == cw::GridKind::gap) {
        spec.x0 = g.x0;
        spec.y0 = g.y0;
        spec.dx = g.dx;
        spec.dy = g.dy;
    }
    return spec;
}

cw::ContactInput to_input(const cw_params* params)
{
    const cw_params p = read_struct(params, default_params(), "params");
    cw::ContactInput in;
    in.a = p.a;
    in.b = p.b;
    in.normal_force = p.normal_force;
    in.mu = p.mu;
    in.V = p.V;
    if (p.flexibility == CW_FLEX_FROM_MATERIAL)
        in.flexibility = cw::FlexibilitySource::kalker_from_material;
    else if (p.flexibility == CW_FLEX_GIVEN)
        in.flexibility = cw::FlexibilitySource::given;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "params->flexibility = " +
                                        std::to_string(p.flexibility) +
                                        " is not CW_FLEX_FROM_MATERIAL (0) or CW_FLEX_GIVEN (1)");
    if (p.pressure == CW_PRESSURE_PARABOLIC)
        in.pressure = cw::PressureKind::parabolic;
    else if (p.pressure == CW_PRESSURE_ELLIPTIC)
        in.pressure = cw::PressureKind::elliptic;
    else
        fail(CW_ERR_UNKNOWN_OPTION,
             "params->pressure = " + std::to_string(p.pressure) +
                 " is not CW_PRESSURE_PARABOLIC (0) or CW_PRESSURE_ELLIPTIC (1)");
    in.G = p.G;
    in.nu = p.nu;
    in.L1 = p.L1;
    in.L2 = p.L2;
    in.L3 = p.L3;
    in.xi_x = p.xi_x;
    in.xi_y = p.xi_y;
    in.phi = p.phi;
    in.rolling_direction = p.rolling_direction;
    in.model = to_model(p.model, "params->model");
    in.tolerance = p.tolerance;
    in.max_iterations = p.max_iterations;
    if (p.warm_start != 0 && p.warm_start != 1)
        fail(CW_ERR_INVALID_INPUT,
             "params->warm_start = " + std::to_string(p.warm_start) + " must be 0 or 1");
    in.warm_start = p.warm_start == 1;
    in.spin_offset = p.spin_offset;
    if (p.flexibility_blending != 0 && p.flexibility_blending != 1)
        fail(CW_ERR_INVALID_INPUT, "params->flexibility_blending = " +
                                       std::to_string(p.flexibility_blending) +
                                       " must be 0 or 1");
    in.flexibility_blending = p.flexibility_blending == 1;
    if (p.exact_load != 0 && p.exact_load != 1)
        fail(CW_ERR_INVALID_INPUT,
             "params->exact_load = " + std::to_string(p.exact_load) + " must be 0 or 1");
    in.exact_load = p.exact_load == 1;
    in.gap = p.gap;
    in.gap_len = p.gap_len;
    if (p.normal_load == CW_NORMAL_FORCE)
        in.normal_load = cw::NormalLoad::force;
    else if (p.normal_load == CW_NORMAL_APPROACH)
        in.normal_load = cw::NormalLoad::approach;
    else
        fail(CW_ERR_UNKNOWN_OPTION, "params->normal_load = " + std::to_string(p.normal_load) +
                                        " is not CW_NORMAL_FORCE (0) or CW_NORMAL_APPROACH (1)");
    in.approach = p.approach;
    if (p.normal_method == CW_NORMAL_EXACT)
        in.normal_method = cw::NormalMethod::exact;
    else if (p.normal_method == CW_NORMAL_SEMI_HERTZ)
        in.normal_method = cw::NormalMethod::semi_hertz;
    else
        fail(CW_ERR_UNKNOWN_OPTION,
             "params->normal_method = " + std::to_string(p.normal_method) +
                 " is not CW_NORMAL_EXACT (0) or CW_NORMAL_SEMI_HERTZ (1)");
    if (p.friction_law != CW_FRICTION_COULOMB && p.friction_law != CW_FRICTION_LINEAR &&
        p.friction_law != CW_FRICTION_RATIONAL && p.friction_law != CW_FRICTION_EXPONENTIAL)
        fail(CW_ERR_UNKNOWN_OPTION, "params->friction_law = " + std::to_string(p.friction_law) +
                                        " is not CW_FRICTION_COULOMB (0), _LINEAR (2), "
                                        "_RATIONAL (3) or _EXPONENTIAL (4)");
    in.friction_law = static_cast<cw::FrictionLaw>(p.friction_law);
    in.mu_e1 = p.mu_e1;
    in.s_h1 = p.s_h1;
    in.mu_e2 = p.mu_e2;
    in.s_h2 = p.s_h2;
    if (p.friction_speed == CW_FRICTION_SPEED_LOCAL)
        in.friction_speed = cw::FrictionSpeed::local;
    else if (p.friction_speed == CW_FRICTION_SPEED_GLOBAL)
        in.friction_speed = cw::FrictionSpeed::global;
    else
        fail(CW_ERR_UNKNOWN_OPTION,
             "params->friction_speed = " + std::to_string(p.friction_speed) +
                 " is not CW_FRICTION_SPEED_LOCAL (0) or CW_FRICTION_SPEED_GLOBAL (1)");
    in.k0 = p.k0;
    in.alpha_inf = p.alpha_inf;
    in.beta = p.beta;
    in.memory_distance = p.memory_distance;
    in.memory_s0 = p.memory_s0;
    in.layer_h = p.layer_h;
    in.layer_G = p.layer_G;
    in.tau_c0 = p.tau_c0;
    in.k_tau = p.k_tau;
    return in;
}

cw::ModelKind to_model(int model, const char* name)
{
    switch (model) {
    case CW_MODEL_FASTSIM: return cw::ModelKind::fastsim;
    case CW_MODEL_EXACT: return cw::ModelKind::exact;
    case CW_MODEL_CALIBRATED: return cw::ModelKind::calibrated;
    default:
        fail(CW_ERR_UNKNOWN_OPTION, std::string(name) + " = " + std::to_string(model) +
                                        " is not CW_MODEL_FASTSIM (0), CW_MODEL_EXACT (1) or "
                                        "CW_MODEL_CALIBRATED (2)");
    }
}

cw::SolveMode to_mode(int mode)
{
    if (mode == CW_SOLVE_FORCES) return cw::SolveMode::forces_only;
    if (mode == CW_SOLVE_FULL) return cw::SolveMode::full;
    fail(CW_ERR_UNKNOWN_OPTION, "mode = " + std::to_string(mode) +
                                    " is not CW_SOLVE_FORCES (0) or CW_SOLVE_FULL (1)");
}

cw_result to_result(const cw::SolveTotals& t)
{
    cw_result r;
    std::memset(&r, 0, sizeof r);
    r.struct_size = sizeof r;
    r.Fx = t.Fx;
    r.Fy = t.Fy;
    r.Mz = t.Mz;
    r.W_macro = t.W_macro;
    r.W_micro_paper = t.W_micro_paper;
    r.K = t.K;
    r.W_consistent = t.W_consistent;
    r.balance_factor = t.balance_factor;
    r.adhesion_fraction = t.adhesion_fraction;
    r.n_contact = t.n_contact;
    r.n_adhesion = t.n_adhesion;
    r.n_slip = t.n_slip;
    r.work_flags = t.work_flags;
    r.a = t.a;
    r.b = t.b;
    r.L1 = t.L1;
    r.L2 = t.L2;
    r.L3 = t.L3;
    r.C11 = t.C11;
    r.C22 = t.C22;
    r.C23 = t.C23;
    r.C33 = t.C33;
    r.profile_max_diff = t.profile_max_diff;
    r.profile_rms_diff = t.profile_rms_diff;
    r.model = static_cast<int>(t.model);
    r.p_max = t.p_max;
    r.approach = t.approach;
    r.iterations = t.iterations;
    r.residual = t.residual;
    r.normal_force = t.normal_force;
    r.n_patches = t.n_patches;
    r.mu_static = t.mu_static;
    r.mu_min = t.mu_min;
    r.mu_max = t.mu_max;
    return r;
}

cw::Field to_field(int field)
{
    if (field < CW_FIELD_X || field > CW_FIELD_WORK_CONSISTENT)
        fail(CW_ERR_UNKNOWN_OPTION, "field = " + std::to_string(field) +
                                        " is not one of CW_FIELD_X (0) .. "
                                        "CW_FIELD_WORK_CONSISTENT (10)");
    return static_cast<cw::Field>(field);
}

void require_length(size_t have, size_t need, const char* name)
{
    if (have < need)
        fail(CW_ERR_BUFFER_TOO_SMALL, std::string(name) + " holds " + std::to_string(have) +
                                          " values but " + std::to_string(need) +
                                          " are needed");
}

size_t element_count(const cw::Solver& s)
{
    return static_cast<size_t>(s.grid().nx()) * static_cast<size_t>(s.grid().ny());
}

void require_solution(const cw::Solver& s, bool needs_work)
{
    if (!s.has_solution())
        fail(CW_ERR_NO_SOLUTION, "no successful solve on this solver yet (or the last failed)");
    if (needs_work && !s.has_work())
        fail(CW_ERR_NO_WORK, "this output needs the last solve to use CW_SOLVE_FULL");
}

void require_finite(const char* name, double v)
{
    if (!std::isfinite(v)) fail(CW_ERR_INVALID_INPUT, std::string(name) + " must be finite");
}

// A post-processor's rolling speed [m/s]: its own (own_name) when > 0, else
// the V its solve was given (cw_params.V). Both given must agree.
double rolling_speed_of(double own, const char* own_name, double solve_V)
{
    const std::string name = own_name;
    require_finite(own_name, own);
    if (!(own >= 0.0))
        fail(CW_ERR_INVALID_INPUT, name + " = " + cw::number_text(own) +
                                       " is invalid: must be >= 0 (0: the solve's cw_params.V)");
    if (own == 0.0) {
        if (solve_V > 0.0) return solve_V;
        fail(CW_ERR_INVALID_INPUT,
             name + " = 0 and the solve's cw_params.V = 0: the rolling speed is needed, "
                    "in one of them");
    }
    if (solve_V > 0.0 && std::fabs(own - solve_V) > 1e-9 * solve_V)
        fail(CW_ERR_INVALID_INPUT, name + " = " + cw::number_text(own) +
                                       " differs from the solve's cw_params.V = " +
                                       cw::number_text(solve_V) +
                                       ": give the rolling speed once (" + name +
                                       " = 0 takes cw_params.V), or the same in both");
    return own;
}

int hardware_threads()
{
#ifdef _OPENMP
    return std::max(1, omp_get_num_procs());
#else
    return 1;
#endif
}

} // namespace creepwork::capi
