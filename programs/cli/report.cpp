#include "report.hpp"

#include <cstdio>

#include "contact_options.hpp"

namespace cwcli {

std::string fmt(double v, int digits)
{
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    return buf;
}

namespace {

struct Entry {
    const char* key;
    double si_value;
    Quantity q;
};

std::vector<Entry> totals(const cw_result& r)
{
    using Q = Quantity;
    return {{"Fx", r.Fx, Q::force},
            {"Fy", r.Fy, Q::force},
            {"Mz", r.Mz, Q::moment},
            {"W_macro", r.W_macro, Q::work},
            {"W_micro_paper", r.W_micro_paper, Q::work},
            {"K", r.K, Q::dimensionless},
            {"W_consistent", r.W_consistent, Q::work},
            {"balance_factor", r.balance_factor, Q::dimensionless}};
}

std::vector<Entry> geometry(const cw_result& r)
{
    using Q = Quantity;
    return {{"a", r.a, Q::length},
            {"b", r.b, Q::length},
            {"L1", r.L1, Q::flexibility},
            {"L2", r.L2, Q::flexibility},
            {"L3", r.L3, Q::flexibility},
            {"C11", r.C11, Q::dimensionless},
            {"C22", r.C22, Q::dimensionless},
            {"C23", r.C23, Q::dimensionless},
            {"C33", r.C33, Q::dimensionless}};
}

const char* friction_law_name(int law)
{
    return law == CW_FRICTION_LINEAR        ? "linear"
           : law == CW_FRICTION_RATIONAL    ? "rational"
           : law == CW_FRICTION_EXPONENTIAL ? "exponential"
                                            : "coulomb";
}

// The law as solved (SI; Polach's input appears as its exponential law).
JsonObject friction_json(const cw_params& p, const Units& u)
{
    JsonObject f;
    f.text("law", friction_law_name(p.friction_law))
        .number("mu_kin", p.mu)
        .number("mu_e1", p.mu_e1)
        .number("s_h1", p.s_h1)
        .number("mu_e2", p.mu_e2)
        .number("s_h2", p.s_h2)
        .number("V", p.V)
        .text("speed", p.friction_speed == CW_FRICTION_SPEED_GLOBAL ? "global" : "local");
    if (p.friction_speed == CW_FRICTION_SPEED_GLOBAL)
        f.number("k0", p.k0).number("alpha_inf", p.alpha_inf).number("beta", p.beta);
    else
        f.number("memory_distance", u.from_si(Quantity::length, p.memory_distance))
            .number("memory_s0", p.memory_s0);
    return f;
}

JsonObject input_json(const cw_params& p, const cw_grid& g, const Units& u)
{
    JsonObject in;
    in.number("N", u.from_si(Quantity::force, p.normal_force))
        .number("mu", p.mu)
        .number("xi_x", p.xi_x)
        .number("xi_y", p.xi_y)
        .number("spin", u.from_si(Quantity::spin, p.phi))
        .text("flexibility", p.flexibility == CW_FLEX_GIVEN ? "given" : "from_material");
    if (p.flexibility != CW_FLEX_GIVEN)
        in.number("G", u.from_si(Quantity::stress, p.G)).number("nu", p.nu);
    if (p.friction_law != CW_FRICTION_COULOMB || p.friction_speed != CW_FRICTION_SPEED_LOCAL)
        in.object("friction", friction_json(p, u));
    if (p.layer_h > 0.0 || p.tau_c0 > 0.0) {
        JsonObject layer;
        layer.number("layer_h", u.from_si(Quantity::length, p.layer_h))
            .number("layer_G", u.from_si(Quantity::stress, p.layer_G))
            .number("tau_c0", u.from_si(Quantity::stress, p.tau_c0))
            .number("k_tau", p.k_tau);
        in.object("layer", layer);
    }
    in.text("model", model_name(p.model));
    if (p.model == CW_MODEL_EXACT)
        in.number("tolerance", effective_tolerance(p))
            .integer("max_iterations", effective_max_iterations(p));
    // The exact model ignores params.pressure: it solves its own normal
    // problem; the calibrated model uses its own law (doc/theory/calibrated.md:
    // parabolic blended towards Hertz's as the slip grows).
    in.text("pressure", p.model == CW_MODEL_EXACT        ? "discrete_normal_problem"
                        : p.model == CW_MODEL_CALIBRATED ? "calibrated_blend"
                                                         : pressure_name(p.pressure))
        .integer("rolling_direction", p.rolling_direction)
        .integer("exact_load", p.exact_load)
        .text("grid", grid_kind_name(g.kind))
        .integer("nx", g.nx)
        .integer("ny", g.ny)
        .number("box_scale", g.box_scale);
    return in;
}

} // namespace

JsonObject result_json(const cw_result& r, const cw_params& p, const cw_grid& g, const Units& u)
{
    JsonObject j, unit_of;
    for (const Entry& e : totals(r)) {
        j.number(e.key, u.from_si(e.q, e.si_value));
        unit_of.text(e.key, u.label(e.q));
    }
    j.integer("work_flags", r.work_flags)
        .number("adhesion_fraction", r.adhesion_fraction)
        .integer("n_contact", r.n_contact)
        .integer("n_adhesion", r.n_adhesion)
        .integer("n_slip", r.n_slip);
    for (const Entry& e : geometry(r)) {
        j.number(e.key, u.from_si(e.q, e.si_value));
        unit_of.text(e.key, u.label(e.q));
    }
    j.number("profile_max_diff", r.profile_max_diff)
        .number("profile_rms_diff", r.profile_rms_diff)
        .text("model", model_name(r.model))
        .number("p_max", u.from_si(Quantity::stress, r.p_max))
        .number("approach", u.from_si(Quantity::length, r.approach))
        .integer("iterations", r.iterations)
        .number("residual", r.residual)
        .number("mu_static", r.mu_static)
        .number("mu_min", r.mu_min)
        .number("mu_max", r.mu_max)
        .text("units", u.name())
        .text("sign_convention",
              "Fx, Fy, Mz act on the wheel (Kalker, CONTACT): opposite to the creepages; "
              "the paper prints the force on the rail")
        .object("input", input_json(p, g, u))
        .object("unit_of", unit_of.text("p_max", u.label(Quantity::stress))
                               .text("approach", u.label(Quantity::length))
                               .text("N", u.label(Quantity::force))
                               .text("spin", u.label(Quantity::spin))
                               .text("G", u.label(Quantity::stress)));
    return j;
}

void print_result_text(std::ostream& os, const cw_result& r, const cw_params& p, const cw_grid& g,
                       const Units& u)
{
    const auto val = [&u](double si, Quantity q) {
        return fmt(u.from_si(q, si)) + (q == Quantity::dimensionless ? "" : " " + u.label(q));
    };
    os << "contact    a = " << val(r.a, Quantity::length) << ", b = " << val(r.b, Quantity::length)
       << ", N = " << val(p.normal_force, Quantity::force) << ", mu = " << fmt(p.mu) << "\n";
    if (p.flexibility == CW_FLEX_GIVEN)
        os << "material   flexibilities given\n";
    else
        os << "material   G = " << val(p.G, Quantity::stress) << ", nu = " << fmt(p.nu) << "\n";
    os << "creepage   xi_x = " << fmt(p.xi_x) << ", xi_y = " << fmt(p.xi_y)
       << ", spin = " << val(p.phi, Quantity::spin) << ", rolling towards "
       << (p.rolling_direction > 0 ? "+x" : "-x") << "\n";
    os << "grid       " << grid_kind_name(g.kind) << " " << g.nx << " x " << g.ny;
    if (g.kind == CW_GRID_UNIFORM) os << ", box " << fmt(g.box_scale) << " a x " << fmt(g.box_scale) << " b";
    if (r.model == CW_MODEL_EXACT)
        os << ", pressure of the discrete normal problem\n"
           << "model      exact (Kalker's half-space theory): p_max = "
           << val(r.p_max, Quantity::stress) << ", approach = " << val(r.approach, Quantity::length)
           << ", " << r.iterations << " iterations, residual " << fmt(r.residual, 3) << "\n";
    else
        os << ", " << pressure_name(p.pressure) << " pressure\n"
           << "model      " << model_name(r.model)
           << (r.model == CW_MODEL_FASTSIM ? " (Kalker's simplified theory)" : "") << "\n";
    if (p.friction_law != CW_FRICTION_COULOMB || p.friction_speed != CW_FRICTION_SPEED_LOCAL)
        os << "friction   " << friction_law_name(p.friction_law) << " law, V = " << fmt(p.V)
           << " m/s, mu_static = " << fmt(r.mu_static) << "; mu "
           << (p.friction_speed == CW_FRICTION_SPEED_GLOBAL
                   ? "at the contact's slip speed = " + fmt(r.mu_min)
                   : "over the slip area " + fmt(r.mu_min) + " .. " + fmt(r.mu_max))
           << "\n";
    os << "results    (forces and moment on the wheel; the rail gets the opposite sign)\n";
    for (const Entry& e : totals(r))
        os << "  " << e.key << std::string(16 - std::string(e.key).size(), ' ') << "= "
           << val(e.si_value, e.q) << "\n";
    os << "  adhesion_fraction = " << fmt(r.adhesion_fraction, 4) << "  (" << r.n_adhesion
       << " adhesion, " << r.n_slip << " slip of " << r.n_contact << " elements)\n";
    if (r.work_flags)
        os << "  work_flags      = " << r.work_flags << " (see creepwork.h CW_WORK_*)\n";
    for (const Entry& e : geometry(r))
        if (e.key[0] != 'a' && e.key[0] != 'b')
            os << "  " << e.key << std::string(16 - std::string(e.key).size(), ' ') << "= "
               << val(e.si_value, e.q) << "\n";
    os << "  profile vs equal-area parabola: max diff " << fmt(100 * r.profile_max_diff, 3)
       << " %, RMS " << fmt(100 * r.profile_rms_diff, 3) << " % of the peak\n";
}

JsonObject jacobian_json(const double J[CW_JACOBIAN_LEN])
{
    const char* rows[4] = {"Fx", "Fy", "Mz", "W_macro"};
    const char* cols[4] = {"xi_x", "xi_y", "phi", "N"};
    JsonObject j;
    for (int r = 0; r < 4; ++r) {
        JsonObject row;
        for (int c = 0; c < 4; ++c) row.number(cols[c], J[4 * r + c]);
        j.object(rows[r], row);
    }
    return j;
}

void print_jacobian_text(std::ostream& os, const double J[CW_JACOBIAN_LEN])
{
    os << "jacobian   (SI)        d/dxi_x        d/dxi_y        d/dphi         d/dN\n";
    const char* rows[4] = {"Fx", "Fy", "Mz", "W_macro"};
    for (int r = 0; r < 4; ++r) {
        char line[160];
        std::snprintf(line, sizeof line, "  %-19s %14.6g %14.6g %14.6g %14.6g\n", rows[r],
                      J[4 * r], J[4 * r + 1], J[4 * r + 2], J[4 * r + 3]);
        os << line;
    }
}


} // namespace cwcli
