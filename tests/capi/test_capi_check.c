/* The policy every door shares (header, "plausibility"): cw_params_check's
 * rules, each tried just beyond and just inside its threshold (the
 * thresholds of the CW_CHECK_* comments in the header), with the input it
 * names, its value and unit; a contact left at cw_params_init's size and
 * load; a gap grid's spacing and heights; many contacts counted once per
 * rule; the caller's buffer as cw_solver_get_patches'. Then the exact
 * model's default grid (cw_grid_init_model) and the canonical names of
 * inputs and enumeration values (cw_input_name). Last, the surface
 * post-processors' rules (cw_temperature_params_check,
 * cw_damage_params_check) the same way. */
#include "capi_fixtures.h"

#include <stdio.h>

enum { MAX_CHECKS = 16 };

/* The checks of count contacts on grid into out (cw_check_init'ed). */
static size_t run_checks(const cw_grid* grid, const cw_params* p, size_t count, cw_check* out)
{
    for (int k = 0; k < MAX_CHECKS; ++k) cw_check_init(&out[k]);
    size_t found = 999;
    assert_int_equal(cw_params_check(grid, p, count, out, MAX_CHECKS, &found), CW_OK);
    assert_true(found < MAX_CHECKS);
    return found;
}

/* A contact the rules find plausible: 7 x 5 mm, 100 kN (README's example). */
static cw_params plausible(void)
{
    cw_params p;
    cw_params_init(&p);
    p.a = 7e-3;
    p.b = 5e-3;
    p.normal_force = 100e3;
    p.xi_x = 1e-3;
    return p;
}

static void set(cw_params* p, const char* field, double v)
{
    if (!strcmp(field, "a")) p->a = v;
    else if (!strcmp(field, "b")) p->b = v;
    else if (!strcmp(field, "normal_force")) p->normal_force = v;
    else if (!strcmp(field, "mu")) p->mu = v;
    else if (!strcmp(field, "G")) p->G = v;
    else if (!strcmp(field, "L1")) p->L1 = v;
    else if (!strcmp(field, "L2")) p->L2 = v;
    else if (!strcmp(field, "L3")) p->L3 = v;
    else if (!strcmp(field, "xi_x")) p->xi_x = v;
    else if (!strcmp(field, "xi_y")) p->xi_y = v;
    else if (!strcmp(field, "phi")) p->phi = v;
    else if (!strcmp(field, "V")) p->V = v;
    else fail_msg("no field %s", field);
}

/* c is one contact's finding of rule on field = value [unit], its reason
 * naming the mistake and its message "<field> = <value> <unit> is
 * implausible for a wheel-rail contact: <reason>". */
static void expect_finding(const cw_check* c, int rule, const char* field, const char* unit,
                           double value, const char* mistake)
{
    assert_int_equal(c->rule, rule);
    assert_string_equal(c->input, field);
    assert_string_equal(c->unit, unit);
    assert_true(c->value == value);
    assert_int_equal(c->contacts, 1);
    assert_int_equal(c->first, 0);
    assert_non_null(strstr(c->reason, mistake));
    char head[96];
    snprintf(head, sizeof head, "%s = %.10g%s%s is implausible for a wheel-rail contact: ", field,
             value, *unit ? " " : "", unit);
    assert_true(strncmp(c->message, head, strlen(head)) == 0);
    assert_string_equal(c->message + strlen(head), c->reason);
}

/* Every rule of an elliptic contact at its threshold (header, CW_CHECK_*). */
static void each_rule_fires_beyond_its_threshold_only(void** state)
{
    (void)state;
    static const struct {
        const char* field;
        int rule;
        const char* unit;
        double beyond, inside;
        int given; /* CW_FLEX_GIVEN with L = 5e-14 */
        const char* mistake; /* in the reason */
    } rules[] = {
        {"a", CW_CHECK_SEMI_AXIS, "m", 0.11, 0.09, 0, "millimetres typed as metres"},
        {"a", CW_CHECK_SEMI_AXIS, "m", 0.9e-4, 1.1e-4, 0, "not below 0.1 mm"},
        {"b", CW_CHECK_SEMI_AXIS, "m", 0.11, 0.09, 0, "millimetres typed as metres"},
        {"b", CW_CHECK_SEMI_AXIS, "m", 0.9e-4, 1.1e-4, 0, "not below 0.1 mm"},
        {"normal_force", CW_CHECK_NORMAL_FORCE, "N", 1.1e7, 0.9e7, 0, "kN typed as N"},
        {"normal_force", CW_CHECK_NORMAL_FORCE, "N", 999.0, 1001.0, 0, "kN typed where N"},
        {"mu", CW_CHECK_FRICTION, "", 1.6, 1.4, 0, "0.1-0.6"},
        {"G", CW_CHECK_MODULUS, "Pa", 0.9e6, 1.1e6, 0, "MPa or N/mm^2 typed as Pa"},
        {"G", CW_CHECK_MODULUS, "Pa", 1.1e12, 0.9e12, 0, "no solid exceeds 1e12 Pa"},
        {"L1", CW_CHECK_FLEXIBILITY, "m/Pa", 2e-10, 0.9e-10, 1, "mm^3/N"},
        {"L2", CW_CHECK_FLEXIBILITY, "m/Pa", 0.9e-18, 1.1e-18, 1, "mm^3/N"},
        {"L3", CW_CHECK_FLEXIBILITY, "m/Pa", 2e-10, 0.9e-10, 1, "mm^3/N"},
        {"xi_x", CW_CHECK_CREEPAGE, "", -0.6, -0.4, 0, "a per cent typed as a ratio"},
        {"xi_y", CW_CHECK_CREEPAGE, "", 0.6, 0.4, 0, "a per cent typed as a ratio"},
        {"phi", CW_CHECK_SPIN, "1/m", 51.0, 49.0, 0, "1/mm typed as 1/m"},
        {"V", CW_CHECK_SPEED, "m/s", 151.0, 149.0, 0, "km/h typed as m/s"},
    };
    cw_grid g;
    cw_grid_init(&g);
    cw_check c[MAX_CHECKS];
    for (size_t k = 0; k < sizeof rules / sizeof rules[0]; ++k) {
        cw_params p = plausible();
        if (rules[k].given) {
            p.flexibility = CW_FLEX_GIVEN;
            p.L1 = p.L2 = p.L3 = 5e-14;
        }
        /* a/b within Kalker's range either side */
        if (rules[k].beyond > 0.05 && !strcmp(rules[k].field, "a")) p.b = 0.08;
        if (rules[k].beyond > 0.05 && !strcmp(rules[k].field, "b")) p.a = 0.08;
        set(&p, rules[k].field, rules[k].inside);
        if (run_checks(&g, &p, 1, c) != 0) fail_msg("%s = %g: %s", rules[k].field, rules[k].inside, c[0].message);
        set(&p, rules[k].field, rules[k].beyond);
        if (run_checks(&g, &p, 1, c) != 1) fail_msg("%s = %g: no finding", rules[k].field, rules[k].beyond);
        expect_finding(&c[0], rules[k].rule, rules[k].field, rules[k].unit, rules[k].beyond,
                       rules[k].mistake);
        /* the other flexibility source is not read */
        if (!strcmp(rules[k].field, "G")) {
            p.flexibility = CW_FLEX_GIVEN;
            p.L1 = p.L2 = p.L3 = 5e-14;
            assert_int_equal(run_checks(&g, &p, 1, c), 0);
        }
    }
}

/* A contact whose size and load were never set: cw_params_init's
 * placeholders, all three. Any one of them set is no longer the signature. */
static void default_geometry_is_reported(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    cw_params p;
    cw_params_init(&p);
    p.xi_x = 1e-3;
    cw_check c[MAX_CHECKS];
    assert_int_equal(run_checks(&g, &p, 1, c), 1);
    assert_int_equal(c[0].rule, CW_CHECK_DEFAULT_GEOMETRY);
    assert_non_null(strstr(c[0].reason, "left out"));
    assert_non_null(strstr(c[0].reason, "6 mm, 6 mm, 80 kN"));
    p.normal_force = 90e3;
    assert_int_equal(run_checks(&g, &p, 1, c), 0);
    /* on a gap grid a and b are not used */
    cw_params_init(&p);
    g.kind = CW_GRID_GAP;
    g.nx = g.ny = 10;
    g.dx = g.dy = 0.4e-3;
    assert_int_equal(run_checks(&g, &p, 1, c), 0);
}

/* A gap grid typed in millimetres: its spacing, its heights' spread (to
 * 1 um) and an approach; a and b are not read there. */
static void gap_in_millimetres_is_reported(void** state)
{
    (void)state;
    enum { NX = 12, NY = 10 };
    double h[NX * NY];
    double lo = 1e9, hi = -1e9;
    for (int j = 0; j < NY; ++j)
        for (int i = 0; i < NX; ++i) {
            const double x = (i - 5.5) * 0.4e-3, y = (j - 4.5) * 0.4e-3;
            h[i + NX * j] = x * x / 0.9 + y * y / 0.5; /* Hertzian, metres */
            if (h[i + NX * j] < lo) lo = h[i + NX * j];
            if (h[i + NX * j] > hi) hi = h[i + NX * j];
        }
    cw_grid g;
    cw_grid_init(&g);
    g.kind = CW_GRID_GAP;
    g.nx = NX;
    g.ny = NY;
    g.dx = g.dy = 0.4e-3;
    g.x0 = -5.5 * g.dx;
    g.y0 = -4.5 * g.dy;
    cw_params p = plausible();
    p.a = 7.2; /* not read on a gap grid */
    p.gap = h;
    p.gap_len = NX * NY;
    cw_check c[MAX_CHECKS];
    assert_int_equal(run_checks(&g, &p, 1, c), 0);
    /* heights in mm: spread 1000 times larger, above 10 mm */
    for (int k = 0; k < NX * NY; ++k) h[k] *= 1e3;
    assert_true((hi - lo) * 1e3 > 1e-2);
    assert_int_equal(run_checks(&g, &p, 1, c), 1);
    assert_int_equal(c[0].rule, CW_CHECK_GAP_HEIGHTS);
    assert_string_equal(c[0].input, "gap");
    assert_close(c[0].value, (hi - lo) * 1e3, 0, 0.5e-6);
    assert_non_null(strstr(c[0].reason, "millimetres typed as metres"));
    /* ... and the spacing: dx, dy, then the heights */
    g.dx = g.dy = 0.4;
    assert_int_equal(run_checks(&g, &p, 1, c), 3);
    assert_string_equal(c[0].input, "dx");
    assert_string_equal(c[1].input, "dy");
    assert_string_equal(c[2].input, "gap");
    assert_int_equal(c[0].rule, CW_CHECK_GAP_SPACING);
    assert_true(c[0].value == 0.4);
    /* a gap shorter than the grid is left to the solve's error */
    g.dx = g.dy = 0.4e-3;
    p.gap_len = NX * NY - 1;
    assert_int_equal(run_checks(&g, &p, 1, c), 0);
    /* an approach in mm */
    for (int k = 0; k < NX * NY; ++k) h[k] *= 1e-3;
    p.gap_len = NX * NY;
    p.normal_load = CW_NORMAL_APPROACH;
    p.approach = 0.05;
    assert_int_equal(run_checks(&g, &p, 1, c), 1);
    assert_int_equal(c[0].rule, CW_CHECK_APPROACH);
    assert_true(c[0].value == 0.05);
    p.approach = 50e-6;
    assert_int_equal(run_checks(&g, &p, 1, c), 0);
}

/* Many contacts: each rule once, with how many break it and the first. */
static void many_contacts_count_once_per_rule(void** state)
{
    (void)state;
    enum { N = 1000 };
    cw_params* p = malloc(N * sizeof *p);
    for (int k = 0; k < N; ++k) p[k] = plausible();
    p[3].a = 7.2;
    p[500].a = 7.3;
    p[500].mu = 5.0;
    cw_grid g;
    cw_grid_init(&g);
    cw_check c[MAX_CHECKS];
    assert_int_equal(run_checks(&g, p, N, c), 2);
    assert_string_equal(c[0].input, "a");
    assert_int_equal(c[0].contacts, 2);
    assert_int_equal(c[0].first, 3);
    assert_true(c[0].value == 7.2);
    assert_non_null(strstr(c[0].message, "a = 7.2 m (2 of 1000 contacts) is implausible"));
    assert_string_equal(c[1].input, "mu");
    assert_int_equal(c[1].contacts, 1);
    assert_int_equal(c[1].first, 500);
    free(p);
}

/* The caller's array, as cw_solver_get_patches: a count query, too short,
 * a struct_size not set; nothing written on error. */
static void buffer_rules(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init(&g);
    cw_params p = plausible();
    p.a = 7.2;
    p.mu = 5;
    size_t found = 0;
    assert_int_equal(cw_params_check(&g, &p, 1, NULL, 0, &found), CW_OK);
    assert_int_equal(found, 2);
    cw_check one;
    cw_check_init(&one);
    found = 0;
    assert_int_equal(cw_params_check(&g, &p, 1, &one, 1, &found), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(found, 2);
    assert_int_equal(one.rule, 0);
    cw_check two[2];
    memset(two, 0, sizeof two);
    assert_int_equal(cw_params_check(&g, &p, 1, two, 2, &found), CW_ERR_STRUCT_SIZE);
    assert_int_equal(cw_params_check(NULL, &p, 1, two, 2, &found), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_params_check(&g, NULL, 1, two, 2, &found), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_params_check(&g, &p, 1, two, 2, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_params_check(&g, NULL, 0, NULL, 0, &found), CW_OK);
    assert_int_equal(found, 0);
    /* an array of older, smaller cw_check structs: the fields they have */
    const size_t small = offsetof(cw_check, contacts);
    unsigned char* bytes = calloc(3, small);
    for (int k = 0; k < 3; ++k) ((cw_check*)(bytes + k * small))->struct_size = small;
    memset(bytes + 2 * small, 0x5A, small);
    assert_int_equal(cw_params_check(&g, &p, 1, (cw_check*)bytes, 2, &found), CW_OK);
    const cw_check* first = (const cw_check*)bytes;
    const cw_check* second = (const cw_check*)(bytes + small);
    assert_int_equal(first->rule, CW_CHECK_SEMI_AXIS);
    assert_true(first->value == 7.2);
    assert_int_equal(second->rule, CW_CHECK_FRICTION);
    assert_string_equal(second->input, "mu");
    for (size_t k = 2 * small; k < 3 * small; ++k) assert_int_equal(bytes[k], 0x5A); /* untouched */
    free(bytes);
    assert_int_equal(cw_check_init(NULL), CW_ERR_NULL_POINTER);
}

/* The exact model's default grid (header: CONTACT's layout, 24 x 24 over
 * 1.2 times the semi-axes); the others' is cw_grid_init's. */
static void model_default_grids(void** state)
{
    (void)state;
    cw_grid g, d;
    cw_grid_init(&d);
    memset(&g, 0xA5, sizeof g);
    assert_int_equal(cw_grid_init_model(&g, CW_MODEL_EXACT), CW_OK);
    assert_int_equal(g.struct_size, sizeof g);
    assert_int_equal(g.kind, CW_GRID_UNIFORM);
    assert_int_equal(g.nx, 24);
    assert_int_equal(g.ny, 24);
    assert_true(g.box_scale == 1.2);
    /* 20 elements across the ellipse: 24 over 1.2 times its width */
    assert_close(g.nx / g.box_scale, 20.0, 1e-12, 0);
    for (int model = CW_MODEL_FASTSIM; model <= CW_MODEL_CALIBRATED; model += 2) {
        assert_int_equal(cw_grid_init_model(&g, model), CW_OK);
        assert_memory_equal(&g, &d, sizeof g);
    }
    assert_int_equal(cw_grid_init_model(&g, 7), CW_ERR_UNKNOWN_OPTION);
    assert_int_equal(cw_grid_init_model(NULL, CW_MODEL_EXACT), CW_ERR_NULL_POINTER);
    /* the exact model solves on it */
    cw_grid_init_model(&g, CW_MODEL_EXACT);
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p = plausible();
    p.model = CW_MODEL_EXACT;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, NULL), CW_OK);
    cw_solver_destroy(s);
}

/* One spelling per input and enumeration value (header, cw_input_name). */
static void input_names(void** state)
{
    (void)state;
    static const char* pairs[][2] = {
        {"N", "normal_force"},    {"spin", "phi"},          {"strips", "kalker_strips"},
        {"Strips", "kalker_strips"}, {"fast", "fastsim"},   {"FASTSIM", "fastsim"},
        {"semi-hertz", "semi_hertz"}, {"Semi-Hertz", "semi_hertz"}, {"semi_hertz", "semi_hertz"},
        {"Uniform", "uniform"},   {"from-material", "from_material"},
        {"a", "a"},               {"G", "G"},               {"normal_force", "normal_force"},
        {"n", "n"},               {"xi-x", "xi-x"},         {"", ""}};
    char name[32];
    for (size_t k = 0; k < sizeof pairs / sizeof pairs[0]; ++k) {
        assert_int_equal(cw_input_name(pairs[k][0], name, sizeof name), CW_OK);
        if (strcmp(name, pairs[k][1])) fail_msg("%s -> %s, expected %s", pairs[k][0], name, pairs[k][1]);
    }
    assert_int_equal(cw_input_name("N", name, 12), CW_ERR_BUFFER_TOO_SMALL);
    assert_string_equal(name, "");
    assert_int_equal(cw_input_name("N", name, 13), CW_OK);
    assert_int_equal(cw_input_name(NULL, name, sizeof name), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_input_name("a", NULL, 0), CW_ERR_NULL_POINTER);
}

/* The exact model's defaults where params give 0 (header, CW_DEFAULT_*):
 * the same bits as the values given. */
static void exact_defaults_are_the_macros(void** state)
{
    (void)state;
    cw_grid g;
    cw_grid_init_model(&g, CW_MODEL_EXACT);
    cw_solver* s = NULL;
    assert_int_equal(cw_solver_create(&g, &s, NULL, 0), CW_OK);
    cw_params p = plausible();
    p.model = CW_MODEL_EXACT;
    p.warm_start = 0;
    p.xi_y = 2e-3;
    p.phi = 0.5;
    cw_result zero, given;
    cw_result_init(&zero);
    cw_result_init(&given);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &zero), CW_OK);
    p.tolerance = CW_DEFAULT_TOLERANCE;
    p.max_iterations = CW_DEFAULT_MAX_ITERATIONS;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FORCES, &given), CW_OK);
    assert_memory_equal(&zero, &given, sizeof zero);
    assert_true(zero.residual <= CW_DEFAULT_TOLERANCE);
    cw_solver_destroy(s);
}

/* The surface post-processors' parameters at each rule's threshold (header,
 * CW_CHECK_* and cw_temperature_params_check / cw_damage_params_check):
 * cw_*_params_init's steel and Burstow's thresholds find nothing; one value
 * just beyond a threshold is one finding naming it, just inside none. */
static size_t run_surface_checks(const cw_temperature_params* t, const cw_damage_params* d,
                                 cw_check* out)
{
    for (int k = 0; k < MAX_CHECKS; ++k) cw_check_init(&out[k]);
    size_t found = 999;
    if (t) assert_int_equal(cw_temperature_params_check(t, out, MAX_CHECKS, &found), CW_OK);
    else assert_int_equal(cw_damage_params_check(d, out, MAX_CHECKS, &found), CW_OK);
    assert_true(found < MAX_CHECKS);
    return found;
}

static double* surface_field(cw_temperature_params* t, cw_damage_params* d, const char* field)
{
    if (!strcmp(field, "conductivity_1")) return &t->conductivity_1;
    if (!strcmp(field, "conductivity_2")) return &t->conductivity_2;
    if (!strcmp(field, "heat_capacity_1")) return &t->heat_capacity_1;
    if (!strcmp(field, "heat_capacity_2")) return &t->heat_capacity_2;
    if (!strcmp(field, "density_1")) return &t->density_1;
    if (!strcmp(field, "density_2")) return &t->density_2;
    if (!strcmp(field, "rolling_speed")) return &t->rolling_speed;
    if (!strcmp(field, "k_yield")) return &d->k_yield;
    if (!strcmp(field, "wlrm_onset")) return &d->wlrm_onset;
    if (!strcmp(field, "wlrm_peak")) return &d->wlrm_peak;
    if (!strcmp(field, "wlrm_zero")) return &d->wlrm_zero;
    fail_msg("no field %s", field);
    return NULL;
}

static void surface_rules_fire_beyond_their_threshold_only(void** state)
{
    (void)state;
    static const struct {
        const char* field;
        int rule;
        const char* unit;
        double beyond, inside;
        const char* mistake; /* in the reason */
    } rules[] = {
        {"conductivity_1", CW_CHECK_CONDUCTIVITY, "W/(m K)", 0.99, 1.01, "W/(mm K) typed"},
        {"conductivity_2", CW_CHECK_CONDUCTIVITY, "W/(m K)", 0.05, 1.01, "W/(mm K) typed"},
        {"conductivity_1", CW_CHECK_CONDUCTIVITY, "W/(m K)", 1001.0, 999.0, "mW/(m K) typed"},
        {"conductivity_2", CW_CHECK_CONDUCTIVITY, "W/(m K)", 1001.0, 999.0, "mW/(m K) typed"},
        {"heat_capacity_1", CW_CHECK_HEAT_CAPACITY, "J/kg/K", 99.0, 101.0, "kJ/kg/K"},
        {"heat_capacity_2", CW_CHECK_HEAT_CAPACITY, "J/kg/K", 0.45, 101.0, "kJ/kg/K"},
        {"heat_capacity_1", CW_CHECK_HEAT_CAPACITY, "J/kg/K", 5001.0, 4999.0, "mJ/kg/K"},
        {"heat_capacity_2", CW_CHECK_HEAT_CAPACITY, "J/kg/K", 5001.0, 4999.0, "mJ/kg/K"},
        {"density_1", CW_CHECK_DENSITY, "kg/m^3", 7.85, 1001.0, "g/cm^3"},
        {"density_2", CW_CHECK_DENSITY, "kg/m^3", 999.0, 1001.0, "g/cm^3"},
        {"density_1", CW_CHECK_DENSITY, "kg/m^3", 25001.0, 24999.0, "g/m^3 typed"},
        {"density_2", CW_CHECK_DENSITY, "kg/m^3", 25001.0, 24999.0, "g/m^3 typed"},
        {"rolling_speed", CW_CHECK_SPEED, "m/s", 150.5, 149.5, "km/h typed as m/s"},
        {"k_yield", CW_CHECK_YIELD_STRESS, "Pa", 0.99e6, 1.01e6, "MPa or N/mm^2 typed as Pa"},
        {"k_yield", CW_CHECK_YIELD_STRESS, "Pa", 300.0, 3e8, "MPa or N/mm^2 typed as Pa"},
        {"wlrm_onset", CW_CHECK_WLRM_THRESHOLD, "N", 0.99, 1.01, "kN or J/mm typed as N"},
        {"wlrm_peak", CW_CHECK_WLRM_THRESHOLD, "N", 0.065, 1.01, "kN or J/mm typed as N"},
        {"wlrm_zero", CW_CHECK_WLRM_THRESHOLD, "N", 0.99, 1.01, "kN or J/mm typed as N"},
    };
    cw_check c[MAX_CHECKS];
    for (size_t k = 0; k < sizeof rules / sizeof rules[0]; ++k) {
        cw_temperature_params t;
        cw_damage_params d;
        cw_temperature_params_init(&t);
        cw_damage_params_init(&d);
        t.rolling_speed = 30.0;
        d.k_yield = 3e8;
        const int thermal = rules[k].rule <= CW_CHECK_DENSITY || rules[k].rule == CW_CHECK_SPEED;
        /* the other thresholds of the WLRM below the one tried, none in (0, 1) N */
        if (!strcmp(rules[k].field, "wlrm_peak") || !strcmp(rules[k].field, "wlrm_zero")) d.wlrm_onset = 0.0;
        if (!strcmp(rules[k].field, "wlrm_zero")) d.wlrm_peak = 1.005;
        double* v = surface_field(&t, &d, rules[k].field);
        *v = rules[k].inside;
        if (run_surface_checks(thermal ? &t : NULL, &d, c) != 0)
            fail_msg("%s = %g: %s", rules[k].field, rules[k].inside, c[0].message);
        *v = rules[k].beyond;
        if (run_surface_checks(thermal ? &t : NULL, &d, c) != 1)
            fail_msg("%s = %g: no finding", rules[k].field, rules[k].beyond);
        expect_finding(&c[0], rules[k].rule, rules[k].field, rules[k].unit, rules[k].beyond,
                       rules[k].mistake);
    }
    /* k_yield = 0 (not set) is cw_damage_compute's error, a threshold of 0 N valid */
    cw_damage_params d;
    cw_damage_params_init(&d);
    d.wlrm_onset = 0.0;
    assert_int_equal(run_surface_checks(NULL, &d, c), 0);
}

/* Several findings in the fixed order (body 1 before body 2, then the
 * speed), the count query and the caller's buffer as cw_params_check's. */
static void surface_checks_buffer_rules(void** state)
{
    (void)state;
    cw_temperature_params t;
    cw_temperature_params_init(&t);
    t.rolling_speed = 300.0; /* 300 km/h typed as m/s */
    t.density_2 = 7.85;
    t.conductivity_1 = 0.05;
    size_t found = 0;
    assert_int_equal(cw_temperature_params_check(&t, NULL, 0, &found), CW_OK);
    assert_int_equal(found, 3);
    cw_check c[3];
    for (int k = 0; k < 3; ++k) cw_check_init(&c[k]);
    assert_int_equal(cw_temperature_params_check(&t, c, 2, &found), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(found, 3);
    assert_int_equal(c[0].rule, 0);
    assert_int_equal(cw_temperature_params_check(&t, c, 3, &found), CW_OK);
    assert_string_equal(c[0].input, "conductivity_1");
    assert_string_equal(c[1].input, "density_2");
    assert_string_equal(c[2].input, "rolling_speed");
    cw_damage_params d;
    cw_damage_params_init(&d);
    d.k_yield = 300.0;
    d.wlrm_onset = 0.02;
    d.wlrm_peak = 0.065;
    d.wlrm_zero = 0.175;
    assert_int_equal(cw_damage_params_check(&d, NULL, 0, &found), CW_OK);
    assert_int_equal(found, 4);
    cw_check two[2];
    memset(two, 0, sizeof two);
    assert_int_equal(cw_damage_params_check(&d, two, 2, &found), CW_ERR_STRUCT_SIZE);
    assert_int_equal(cw_damage_params_check(NULL, c, 3, &found), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_damage_params_check(&d, c, 3, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_temperature_params_check(NULL, c, 3, &found), CW_ERR_NULL_POINTER);
    cw_temperature_params bad = t;
    bad.struct_size = 3;
    assert_int_equal(cw_temperature_params_check(&bad, c, 3, &found), CW_ERR_STRUCT_SIZE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(each_rule_fires_beyond_its_threshold_only),
        cmocka_unit_test(default_geometry_is_reported),
        cmocka_unit_test(gap_in_millimetres_is_reported),
        cmocka_unit_test(many_contacts_count_once_per_rule),
        cmocka_unit_test(buffer_rules),
        cmocka_unit_test(model_default_grids),
        cmocka_unit_test(input_names),
        cmocka_unit_test(exact_defaults_are_the_macros),
        cmocka_unit_test(surface_rules_fire_beyond_their_threshold_only),
        cmocka_unit_test(surface_checks_buffer_rules),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
