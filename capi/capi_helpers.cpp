// Free functions: Kalker's coefficients and flexibilities, Hertz, Kalker's 1982 normalised
// FASTSIM, Polach's friction law as the exponential law.
#include "capi_internal.hpp"

#include <cmath>
#include <cstddef>

#include "contact/hertz.hpp"
#include "contact/kalker_coefficients.hpp"
#include "march/march_setup.hpp"
#include "fastsim/kalker_normalised.hpp"
#include "friction/slip_speed_law.hpp"

extern "C" {

int cw_kalker_coefficients(double a_over_b, double nu, double coefficients[4], char* message,
                           size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(coefficients, "coefficients");
        require_finite("a_over_b", a_over_b);
        require_finite("nu", nu);
        if (!(a_over_b >= CW_MIN_ASPECT && a_over_b <= CW_MAX_ASPECT))
            fail(CW_ERR_INVALID_INPUT, "a_over_b = " + std::to_string(a_over_b) +
                                           " must lie in [1e-3, 1e3]");
        if (!(nu >= 0.0 && nu <= 0.5))
            fail(CW_ERR_INVALID_INPUT, "nu = " + std::to_string(nu) + " must lie in [0, 0.5]");
        const cw::CreepCoefficients c = cw::kalker_coefficients(a_over_b, nu);
        coefficients[0] = c.C11;
        coefficients[1] = c.C22;
        coefficients[2] = c.C23;
        coefficients[3] = c.C33;
        return CW_OK;
    });
}

int cw_friction_polach(double mu0, double A, double B, cw_params* params, char* message,
                       size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(params, "params");
        if (params->struct_size < offsetof(cw_params, s_h2) + sizeof params->s_h2)
            fail(CW_ERR_STRUCT_SIZE, "params->struct_size = " +
                                         std::to_string(params->struct_size) +
                                         " ends before the friction law's fields (cw_params_init "
                                         "sets it)");
        const cw::SlipSpeedLaw law = cw::polach_law(mu0, A, B); // names mu, polach_A, polach_B
        params->friction_law = CW_FRICTION_EXPONENTIAL;
        params->mu = law.mu_kin;
        params->mu_e1 = law.mu_e1;
        params->s_h1 = law.s_h1;
        params->mu_e2 = 0.0;
        params->s_h2 = 0.0;
        return CW_OK;
    });
}

int cw_kalker_flexibilities(double a, double b, double G, double nu, double flexibilities[3],
                            char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(flexibilities, "flexibilities");
        cw::ContactInput in;
        in.a = a;
        in.b = b;
        in.G = G;
        in.nu = nu;
        const cw::ModelSetup s = cw::make_model_setup(in); // validates a, b, G, nu
        flexibilities[0] = s.L1;
        flexibilities[1] = s.L2;
        flexibilities[2] = s.L3;
        return CW_OK;
    });
}

int cw_hertz_solve(double A, double B, double normal_force, double E_star, double hertz[4],
                   char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(hertz, "hertz");
        const double values[4] = {A, B, normal_force, E_star};
        const char* names[4] = {"A", "B", "normal_force", "E_star"};
        for (int k = 0; k < 4; ++k) {
            require_finite(names[k], values[k]);
            const bool ok = k == 2 ? values[k] >= 0.0 : values[k] > 0.0;
            if (!ok)
                fail(CW_ERR_INVALID_INPUT, std::string(names[k]) + " = " +
                                               std::to_string(values[k]) +
                                               (k == 2 ? " must be >= 0" : " must be > 0"));
        }
        const double ratio = std::max(A, B) / std::min(A, B);
        if (!std::isfinite(ratio) || ratio > 1e12)
            fail(CW_ERR_INVALID_INPUT, "A/B = " + std::to_string(A / B) +
                                           " is too extreme (ratio of curvatures above 1e12)");
        const cw::HertzContact h = cw::hertz_from_curvatures(A, B, normal_force, E_star);
        const double out[4] = {h.a, h.b, h.p0, h.approach};
        for (double v : out)
            if (!std::isfinite(v))
                fail(CW_ERR_NUMERIC, "the Hertz solution overflowed for these inputs");
        std::copy(out, out + 4, hertz);
        return CW_OK;
    });
}

int cw_fastsim_normalised(double ux, double uy, double fx, double fy, int mx, int my, double tol,
                          double* tx, double* ty, char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(tx, "tx");
        require(ty, "ty");
        // Named here: the core's grid speaks of nx, ny.
        if (mx < 1 || mx > CW_MAX_GRID_CELLS)
            fail(CW_ERR_GRID_OUT_OF_RANGE, "mx = " + std::to_string(mx) + " is outside 1..1000");
        if (my < 1 || my > CW_MAX_GRID_CELLS)
            fail(CW_ERR_GRID_OUT_OF_RANGE, "my = " + std::to_string(my) + " is outside 1..1000");
        const cw::NormalisedForces f = cw::kalker_fastsim_normalised(ux, uy, fx, fy, mx, my, tol);
        if (!std::isfinite(f.tx) || !std::isfinite(f.ty))
            fail(CW_ERR_NUMERIC, "the normalised forces overflowed for these inputs");
        *tx = f.tx;
        *ty = f.ty;
        return CW_OK;
    });
}

} // extern "C"
