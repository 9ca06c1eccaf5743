/* Wear through the C ABI: cw_wear_* on a solved contact and
 * cw_wear_profile_* on a host profile grid. What the numbers must be, and
 * every invalid input: a named status, nothing written, the handle usable. */
#include "capi_fixtures.h"

#include <stdlib.h>

enum { NX = 12, NY = 9, N = NX * NY };

static cw_solver* solved(int k, int kind)
{
    cw_solver* s = cw_test_solver(kind, NX, NY, 1.2);
    cw_params p;
    cw_test_case(k, &p);
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    return s;
}

/* The defaults are the published coefficients in SI units (Braghin et al.
 * 2006 for USFD, R8T/900A; Jendel 2002's KTH map boundaries and band
 * middles), as the header lists them. */
static void defaults_are_the_published_values(void** state)
{
    (void)state;
    cw_wear_params p;
    memset(&p, 0, sizeof p);
    assert_int_equal(cw_wear_params_init(&p), CW_OK);
    assert_int_equal(p.struct_size, sizeof p);
    assert_int_equal(p.law, CW_WEAR_USFD);
    assert_int_equal(p.source, CW_WEAR_SOURCE_CONSISTENT);
    assert_true(p.density == 7800.0 && p.pass_length == 1.0 && p.rolling_speed == 0.0);
    /* 5.3 ug/(m mm^2) per N/mm^2 = 5.3e-9 kg/(N m); 55.0 ug/(m mm^2) =
     * 55e-3 kg/m^3; 4778.7 ug/(m mm^2) = 4.7787 kg/m^3. */
    assert_close(p.usfd_k1, 5.3e-9, 1e-15, 0);
    assert_close(p.usfd_t1, 10.4e6, 1e-15, 0);
    assert_close(p.usfd_k2, 55.0e-3, 1e-15, 0);
    assert_close(p.usfd_t2, 77.2e6, 1e-15, 0);
    assert_close(p.usfd_k3, 61.9e-9, 1e-15, 0);
    assert_close(p.usfd_c3, 4.7787, 1e-15, 0);
    assert_true(p.kth_v1 == 0.2 && p.kth_v2 == 0.7 && p.kth_seizure_ratio == 0.8);
    assert_true(p.kth_k_seizure == 350e-4 && p.kth_k_slow == 5.5e-4);
    assert_true(p.kth_k_severe == 35e-4 && p.kth_k_fast == 5.5e-4);
    assert_true(p.hardness == 2.5e9);
    assert_int_equal(cw_wear_params_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_result_init(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_profile_totals_init(NULL), CW_ERR_NULL_POINTER);
}

/* Mass per distance = sum over elements of rate x area (to 1e-12, the
 * rounding of the two summation orders); mass per pass = that x
 * pass_length; depth = rate area / (rho dy); strip depth = sum of the
 * element depths; both laws, all sources, every test contact, both grids;
 * every value finite and >= 0. */
static void mass_is_rate_times_area(void** state)
{
    (void)state;
    double area[N], rate[N], depth[N], mass[N], dens[N], slide[N];
    double y[NY], dy[NY], strip[NY], par[NY];
    int regime[N];
    for (int kind = CW_GRID_KALKER_STRIPS; kind <= CW_GRID_UNIFORM; ++kind)
        for (int k = 0; k < CW_TEST_CASES; ++k) {
            cw_solver* s = solved(k, kind);
            cw_wear* w = NULL;
            assert_int_equal(cw_wear_create(s, &w), CW_OK);
            assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, N), CW_OK);
            for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law)
                for (int src = CW_WEAR_SOURCE_CONSISTENT; src <= CW_WEAR_SOURCE_SLIP; ++src) {
                    cw_wear_params p;
                    cw_wear_params_init(&p);
                    p.law = law;
                    p.source = src;
                    p.rolling_speed = 25.0;
                    p.pass_length = 2.0 * M_PI * 0.46;
                    cw_wear_result r, again;
                    cw_wear_result_init(&r);
                    cw_wear_result_init(&again);
                    assert_int_equal(cw_wear_compute(w, s, &p, &r), CW_OK);
                    assert_int_equal(cw_wear_get_result(w, &again), CW_OK);
                    assert_memory_equal(&r, &again, sizeof r);
                    assert_int_equal(r.law, law);
                    assert_int_equal(r.source, src);
                    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate, N), CW_OK);
                    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_DEPTH, depth, N), CW_OK);
                    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_MASS, mass, N), CW_OK);
                    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_WORK_DENSITY, dens, N),
                                     CW_OK);
                    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_SLIDING, slide, N), CW_OK);
                    assert_int_equal(cw_wear_get_regimes(w, regime, N), CW_OK);
                    assert_int_equal(cw_wear_get_strips(w, y, dy, strip, par, NY), CW_OK);
                    double sum = 0.0, section = 0.0, par_section = 0.0;
                    for (int j = 0; j < NY; ++j) {
                        double sd = 0.0;
                        for (int i = 0; i < NX; ++i) {
                            const int e = i + j * NX;
                            assert_true(isfinite(rate[e]) && rate[e] >= 0.0);
                            assert_true(isfinite(dens[e]) && dens[e] >= 0.0);
                            assert_true(isfinite(slide[e]) && slide[e] >= 0.0);
                            assert_true(regime[e] >= 0 && regime[e] <= 4);
                            if (regime[e] == CW_WEAR_REGIME_NONE) assert_true(rate[e] == 0.0);
                            sum += rate[e] * area[e];
                            assert_close(mass[e], rate[e] * area[e] * p.pass_length, 1e-15, 0);
                            assert_close(depth[e], rate[e] * area[e] / (p.density * dy[j]), 1e-15,
                                         0);
                            sd += depth[e];
                        }
                        assert_close(strip[j], sd, 1e-14, 1e-300);
                        section += strip[j] * dy[j];
                        par_section += par[j] * dy[j];
                    }
                    assert_close(r.mass_per_distance, sum, 1e-12, 0.0);
                    assert_close(r.mass_per_pass, sum * p.pass_length, 1e-12, 0.0);
                    assert_close(r.volume_per_distance, sum / p.density, 1e-12, 0.0);
                    /* The parabola keeps the cross-section inside [-b, b]: on
                     * the uniform box (1.2 b) strips straddle b, and the
                     * parabola is cut there. */
                    assert_close(par_section, section, 1e-12, 1e-300);
                }
            cw_wear_destroy(w);
            cw_solver_destroy(s);
        }
}

/* Every invalid input: its status, a message naming it, no output written,
 * and afterwards the handle holds no wear (CW_ERR_NO_SOLUTION) until a
 * good compute. */
static void compute_errors_are_named(void** state)
{
    (void)state;
    cw_solver* s = solved(2, CW_GRID_KALKER_STRIPS);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    cw_wear_params good;
    cw_wear_params_init(&good);
    double out[N];
    cw_wear_result r;

#define BAD(field, value, status_, needle)                                            \
    do {                                                                              \
        cw_wear_params p = good;                                                      \
        p.field = value;                                                              \
        assert_int_equal(cw_wear_compute(w, s, &good, NULL), CW_OK);                  \
        memset(&r, CW_POISON, sizeof r);                                              \
        r.struct_size = sizeof r;                                                     \
        assert_int_equal(cw_wear_compute(w, s, &p, &r), status_);                     \
        assert_names(cw_wear_last_error(w), needle);                                  \
        unsigned char poison[sizeof r];                                               \
        memset(poison, CW_POISON, sizeof poison);                                     \
        assert_memory_equal((unsigned char*)&r + sizeof(size_t), poison + sizeof(size_t), \
                            sizeof r - sizeof(size_t));                               \
        cw_fill(out, N, CW_SENTINEL);                                                 \
        assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_DEPTH, out, N),           \
                         CW_ERR_NO_SOLUTION);                                         \
        assert_untouched(out, N);                                                     \
    } while (0)

    BAD(law, 7, CW_ERR_UNKNOWN_OPTION, "law");
    BAD(source, -1, CW_ERR_UNKNOWN_OPTION, "source");
    BAD(density, NAN, CW_ERR_INVALID_INPUT, "density");
    BAD(density, 0.5, CW_ERR_INVALID_INPUT, "density");
    BAD(pass_length, 0.0, CW_ERR_INVALID_INPUT, "pass_length");
    BAD(pass_length, INFINITY, CW_ERR_INVALID_INPUT, "pass_length");
    BAD(usfd_k1, -1e-9, CW_ERR_INVALID_INPUT, "usfd_k1");
    BAD(usfd_k2, NAN, CW_ERR_INVALID_INPUT, "usfd_k2");
    BAD(usfd_k3, 1e7, CW_ERR_INVALID_INPUT, "usfd_k3");
    BAD(usfd_c3, -INFINITY, CW_ERR_INVALID_INPUT, "usfd_c3");
    BAD(usfd_t1, 0.0, CW_ERR_INVALID_INPUT, "usfd_t1");
    BAD(usfd_t2, 1e6, CW_ERR_INVALID_INPUT, "usfd_t2"); /* below t1 */
    BAD(rolling_speed, -1.0, CW_ERR_INVALID_INPUT, "rolling_speed");
    good.law = CW_WEAR_ARCHARD_KTH;
    good.rolling_speed = 20.0;
    BAD(rolling_speed, 0.0, CW_ERR_INVALID_INPUT, "rolling_speed"); /* Archard needs V */
    BAD(rolling_speed, 1e4, CW_ERR_INVALID_INPUT, "rolling_speed");
    BAD(hardness, 0.0, CW_ERR_INVALID_INPUT, "hardness");
    BAD(hardness, NAN, CW_ERR_INVALID_INPUT, "hardness");
    BAD(kth_v1, -0.1, CW_ERR_INVALID_INPUT, "kth_v1");
    BAD(kth_v2, 0.1, CW_ERR_INVALID_INPUT, "kth_v2"); /* below v1 */
    BAD(kth_seizure_ratio, 0.0, CW_ERR_INVALID_INPUT, "kth_seizure_ratio");
    BAD(kth_k_seizure, NAN, CW_ERR_INVALID_INPUT, "kth_k_seizure");
    BAD(kth_k_slow, -1.0, CW_ERR_INVALID_INPUT, "kth_k_slow");
    BAD(kth_k_severe, INFINITY, CW_ERR_INVALID_INPUT, "kth_k_severe");
    BAD(kth_k_fast, 2e6, CW_ERR_INVALID_INPUT, "kth_k_fast");
#undef BAD

    /* struct_size */
    cw_wear_params p = good;
    p.struct_size = 0;
    assert_int_equal(cw_wear_compute(w, s, &p, NULL), CW_ERR_STRUCT_SIZE);
    assert_names(cw_wear_last_error(w), "struct_size");
    cw_wear_result_init(&r);
    r.struct_size = 1;
    assert_int_equal(cw_wear_compute(w, s, &good, &r), CW_ERR_STRUCT_SIZE);
    /* NULLs */
    assert_int_equal(cw_wear_compute(NULL, s, &good, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_compute(w, NULL, &good, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_wear_last_error(w), "solver");
    assert_int_equal(cw_wear_compute(w, s, NULL, NULL), CW_ERR_NULL_POINTER);
    assert_names(cw_wear_last_error(w), "params");
    cw_wear_destroy(w);
    assert_int_equal(cw_wear_create(NULL, &w), CW_ERR_NULL_POINTER); /* w now NULL */
    assert_null(w);
    assert_int_equal(cw_wear_create(s, NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    /* getters before any compute, bad field, short buffers */
    cw_fill(out, N, CW_SENTINEL);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, out, N), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_wear_get_strips(w, out, NULL, NULL, NULL, NY), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_wear_get_result(w, &r), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_wear_compute(w, s, &good, NULL), CW_OK);
    assert_int_equal(cw_wear_get_field(w, 5, out, N), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_wear_last_error(w), "field");
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, out, N - 1),
                     CW_ERR_BUFFER_TOO_SMALL);
    assert_names(cw_wear_last_error(w), "out");
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, NULL, N), CW_ERR_NULL_POINTER);
    int regimes[N];
    cw_fill_int(regimes, N, CW_INT_SENTINEL);
    assert_int_equal(cw_wear_get_regimes(w, regimes, N - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_untouched_int(regimes, N);
    assert_int_equal(cw_wear_get_strips(w, out, out, out, out, NY - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_untouched(out, N);
    assert_int_equal(cw_wear_get_strips(w, NULL, NULL, NULL, NULL, 0), CW_OK);
    assert_string_equal(cw_wear_last_error(w), "");
    assert_non_null(cw_wear_last_error(NULL));
    /* a FORCES solve has no work map; a failed solve none at all; another grid */
    cw_params cp;
    cw_test_case(0, &cp);
    assert_int_equal(cw_solver_solve(s, &cp, CW_SOLVE_FORCES, NULL), CW_OK);
    assert_int_equal(cw_wear_compute(w, s, &good, NULL), CW_ERR_NO_WORK);
    cp.a = -1.0;
    assert_int_equal(cw_solver_solve(s, &cp, CW_SOLVE_FULL, NULL), CW_ERR_INVALID_INPUT);
    assert_int_equal(cw_wear_compute(w, s, &good, NULL), CW_ERR_NO_SOLUTION);
    cw_solver* other = solved(0, CW_GRID_UNIFORM);
    assert_int_equal(cw_wear_compute(w, other, &good, NULL), CW_ERR_GRID_MISMATCH);
    assert_names(cw_wear_last_error(w), "grid");
    cw_solver_destroy(other);
    assert_int_equal(cw_wear_destroy(NULL), CW_OK);
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

/* A profile grid: nodes from -30 to +30 mm, spacing 0.5 mm. */
enum { NS = 121 };
static void nodes(double* s)
{
    for (int k = 0; k < NS; ++k) s[k] = -0.03 + 0.0005 * k;
}

static void profile_errors_are_named(void** state)
{
    (void)state;
    double s[NS];
    nodes(s);
    char msg[256];
    cw_wear_profile* pr = (cw_wear_profile*)&msg; /* must be reset to NULL on error */
    assert_int_equal(cw_wear_profile_create(s, 1, &pr, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_null(pr);
    assert_names(msg, "nodes");
    double bad[NS];
    memcpy(bad, s, sizeof bad);
    bad[40] = bad[39];
    assert_int_equal(cw_wear_profile_create(bad, NS, &pr, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_names(msg, "s[40]");
    bad[40] = NAN;
    assert_int_equal(cw_wear_profile_create(bad, NS, &pr, msg, sizeof msg), CW_ERR_INVALID_INPUT);
    assert_names(msg, "s[40]");
    assert_int_equal(cw_wear_profile_create(NULL, NS, &pr, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_names(msg, "s");
    assert_int_equal(cw_wear_profile_create(s, NS, NULL, msg, sizeof msg), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_profile_create(s, NS, &pr, msg, sizeof msg), CW_OK);
    assert_string_equal(msg, "");

    /* Some wear first, so "unchanged" is not trivially zero. */
    const double y[3] = {-1e-3, 0.0, 1e-3}, w[3] = {1e-3, 1e-3, 1e-3}, d[3] = {1e-9, 2e-9, 1e-9};
    assert_int_equal(cw_wear_profile_add_strips(pr, y, w, d, 3, 0.001, 1, 0.2, 10.0), CW_OK);
    double before[NS], after[NS];
    assert_int_equal(cw_wear_profile_get_depth(pr, CW_WEAR_DEPTH_HEIGHT, before, NS), CW_OK);
#define BAD_ADD(call, status_, needle)                                                  \
    do {                                                                                \
        assert_int_equal(call, status_);                                                \
        assert_names(cw_wear_profile_last_error(pr), needle);                           \
        assert_int_equal(cw_wear_profile_get_depth(pr, CW_WEAR_DEPTH_HEIGHT, after, NS), \
                         CW_OK);                                                        \
        assert_memory_equal(before, after, sizeof before);                              \
    } while (0)
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, NAN, 1, 0.0, 1.0), CW_ERR_INVALID_INPUT,
            "s0");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, 2e6, 1, 0.0, 1.0), CW_ERR_INVALID_INPUT,
            "s0");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, 0.0, 0, 0.0, 1.0), CW_ERR_INVALID_INPUT,
            "orientation");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, 0.0, 1, 1.5, 1.0), CW_ERR_INVALID_INPUT,
            "contact_angle");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, 0.0, 1, 0.0, -1.0), CW_ERR_INVALID_INPUT,
            "passes");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 3, 0.0, 1, 0.0, 2e15), CW_ERR_INVALID_INPUT,
            "passes");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, d, 0, 0.0, 1, 0.0, 1.0), CW_ERR_INVALID_INPUT,
            "count");
    BAD_ADD(cw_wear_profile_add_strips(pr, NULL, w, d, 3, 0.0, 1, 0.0, 1.0), CW_ERR_NULL_POINTER,
            "y");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, NULL, 3, 0.0, 1, 0.0, 1.0), CW_ERR_NULL_POINTER,
            "depth");
    const double negw[3] = {1e-3, -1e-3, 1e-3}, nand[3] = {1e-9, NAN, 1e-9};
    BAD_ADD(cw_wear_profile_add_strips(pr, y, negw, d, 3, 0.0, 1, 0.0, 1.0),
            CW_ERR_INVALID_INPUT, "width[1]");
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, nand, 3, 0.0, 1, 0.0, 1.0),
            CW_ERR_INVALID_INPUT, "depth[1]");
    const double huge[3] = {1e100, 1e100, 1e100};
    BAD_ADD(cw_wear_profile_add_strips(pr, y, w, huge, 3, 0.0, 1, 0.0, 1e15), CW_ERR_NUMERIC,
            "range");
    /* add from a wear handle that has no compute */
    cw_solver* sv = solved(0, CW_GRID_KALKER_STRIPS);
    cw_wear* wr = NULL;
    assert_int_equal(cw_wear_create(sv, &wr), CW_OK);
    BAD_ADD(cw_wear_profile_add(pr, wr, 0.0, 1, 0.0, 1.0), CW_ERR_NO_SOLUTION, "cw_wear_compute");
    BAD_ADD(cw_wear_profile_add(pr, NULL, 0.0, 1, 0.0, 1.0), CW_ERR_NULL_POINTER, "wear");
#undef BAD_ADD
    /* getters */
    cw_fill(after, NS, CW_SENTINEL);
    assert_int_equal(cw_wear_profile_get_depth(pr, 2, after, NS), CW_ERR_UNKNOWN_OPTION);
    assert_names(cw_wear_profile_last_error(pr), "kind");
    assert_int_equal(cw_wear_profile_get_depth(pr, CW_WEAR_DEPTH_NORMAL, after, NS - 1),
                     CW_ERR_BUFFER_TOO_SMALL);
    assert_untouched(after, NS);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    t.struct_size = 3;
    assert_int_equal(cw_wear_profile_get_totals(pr, &t), CW_ERR_STRUCT_SIZE);
    assert_int_equal(cw_wear_profile_get_totals(pr, NULL), CW_ERR_NULL_POINTER);
    /* merge and states across different nodes */
    double s2[NS];
    nodes(s2);
    s2[0] -= 1e-4;
    cw_wear_profile* q = NULL;
    assert_int_equal(cw_wear_profile_create(s2, NS, &q, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_merge(pr, q), CW_ERR_GRID_MISMATCH);
    assert_int_equal(cw_wear_profile_merge(pr, NULL), CW_ERR_NULL_POINTER);
    size_t words = 0;
    assert_int_equal(cw_wear_profile_state_size(q, &words), CW_OK);
    assert_int_equal(words, 5 + 30 + 20 * NS);
    uint64_t* st = malloc(words * sizeof *st);
    assert_int_equal(cw_wear_profile_get_state(q, st, words - 1), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_wear_profile_get_state(q, st, words), CW_OK);
    assert_int_equal(cw_wear_profile_add_state(pr, st, words), CW_ERR_GRID_MISMATCH);
    assert_names(cw_wear_profile_last_error(pr), "state");
    assert_int_equal(cw_wear_profile_add_state(q, st, words - 1), CW_ERR_GRID_MISMATCH);
    assert_int_equal(cw_wear_profile_add_state(q, NULL, words), CW_ERR_NULL_POINTER);
    free(st);
    /* the update helper */
    double old[NS], depth[NS], nw[NS];
    for (int k = 0; k < NS; ++k) {
        old[k] = 1e-3 * k;
        depth[k] = 1e-6;
    }
    cw_fill(nw, NS, CW_SENTINEL);
    assert_int_equal(cw_wear_profile_update(s, old, depth, NS, 1e-3, nw, NS - 1, msg, sizeof msg),
                     CW_ERR_BUFFER_TOO_SMALL);
    assert_names(msg, "new_profile");
    assert_int_equal(cw_wear_profile_update(s, old, depth, NS, -1.0, nw, NS, msg, sizeof msg),
                     CW_ERR_INVALID_INPUT);
    assert_names(msg, "smoothing");
    old[3] = INFINITY;
    assert_int_equal(cw_wear_profile_update(s, old, depth, NS, 0.0, nw, NS, msg, sizeof msg),
                     CW_ERR_INVALID_INPUT);
    assert_names(msg, "old_profile[3]");
    old[3] = 1e308;
    depth[3] = -1e308;
    assert_int_equal(cw_wear_profile_update(s, old, depth, NS, 0.0, nw, NS, msg, sizeof msg),
                     CW_ERR_NUMERIC);
    assert_names(msg, "new_profile[3]");
    assert_int_equal(cw_wear_profile_update(s, old, NULL, NS, 0.0, nw, NS, msg, sizeof msg),
                     CW_ERR_NULL_POINTER);
    assert_names(msg, "depth");
    assert_untouched(nw, NS);
    assert_int_equal(cw_wear_profile_reset(NULL), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wear_profile_destroy(NULL), CW_OK);
    assert_non_null(cw_wear_profile_last_error(NULL));
    cw_wear_profile_destroy(q);
    cw_wear_profile_destroy(pr);
    cw_wear_destroy(wr);
    cw_solver_destroy(sv);
}

/* Twenty contacts at twenty positions: the depth accumulated is the same
 * to the bit (a) added once with passes = 1000 each, (b) added 1000 = 1 +
 * 999 times in reverse order, (c) split over two profiles merged, (d) one
 * of them moved through its saved state. Rail (pass = axle passage) and
 * wheel (passes = rolled distance / (2 pi R)) use the same call. */
static void accumulation_is_bitwise_split_invariant(void** state)
{
    (void)state;
    double s[NS];
    nodes(s);
    cw_solver* sv = cw_test_solver(CW_GRID_KALKER_STRIPS, 16, 12, 1.0);
    cw_wear* w[20];
    cw_wear_params wp;
    cw_wear_params_init(&wp);
    for (int i = 0; i < 20; ++i) {
        cw_params p;
        cw_test_case(i % CW_TEST_CASES, &p);
        p.a *= 1.0 + 0.03 * i;
        p.b *= 1.0 - 0.02 * i;
        assert_int_equal(cw_solver_solve(sv, &p, CW_SOLVE_FULL, NULL), CW_OK);
        assert_int_equal(cw_wear_create(sv, &w[i]), CW_OK);
        assert_int_equal(cw_wear_compute(w[i], sv, &wp, NULL), CW_OK);
    }
    cw_wear_profile *a, *b, *c1, *c2, *d;
    assert_int_equal(cw_wear_profile_create(s, NS, &a, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s, NS, &b, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s, NS, &c1, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s, NS, &c2, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s, NS, &d, NULL, 0), CW_OK);
    for (int i = 0; i < 20; ++i) {
        const double s0 = -0.02 + 0.002 * i, angle = 0.05 * (i - 10);
        assert_int_equal(cw_wear_profile_add(a, w[i], s0, 1, angle, 1000.0), CW_OK);
        assert_int_equal(cw_wear_profile_add(i % 2 ? c1 : c2, w[i], s0, 1, angle, 1000.0), CW_OK);
        if (i % 2) assert_int_equal(cw_wear_profile_add(d, w[i], s0, 1, angle, 1000.0), CW_OK);
    }
    for (int i = 19; i >= 0; --i) {
        const double s0 = -0.02 + 0.002 * i, angle = 0.05 * (i - 10);
        assert_int_equal(cw_wear_profile_add(b, w[i], s0, 1, angle, 999.0), CW_OK);
        assert_int_equal(cw_wear_profile_add(b, w[i], s0, 1, angle, 1.0), CW_OK);
    }
    assert_int_equal(cw_wear_profile_merge(c1, c2), CW_OK);
    size_t words = 0;
    cw_wear_profile_state_size(c2, &words);
    uint64_t* st = malloc(words * sizeof *st);
    assert_int_equal(cw_wear_profile_get_state(c2, st, words), CW_OK);
    assert_int_equal(cw_wear_profile_add_state(d, st, words), CW_OK);
    free(st);
    for (int kind = CW_WEAR_DEPTH_NORMAL; kind <= CW_WEAR_DEPTH_HEIGHT; ++kind) {
        double da[NS], db[NS], dc[NS], dd[NS];
        cw_wear_profile_get_depth(a, kind, da, NS);
        cw_wear_profile_get_depth(b, kind, db, NS);
        cw_wear_profile_get_depth(c1, kind, dc, NS);
        cw_wear_profile_get_depth(d, kind, dd, NS);
        assert_memory_equal(da, db, sizeof da);
        assert_memory_equal(da, dc, sizeof da);
        assert_memory_equal(da, dd, sizeof da);
        double peak = 0.0;
        for (int k = 0; k < NS; ++k) peak = fmax(peak, da[k]);
        assert_true(peak > 0.0);
    }
    cw_wear_profile_totals ta, tb;
    cw_wear_profile_totals_init(&ta);
    cw_wear_profile_totals_init(&tb);
    cw_wear_profile_get_totals(a, &ta);
    cw_wear_profile_get_totals(b, &tb);
    assert_true(ta.passes == 20000.0 && tb.passes == 20000.0);
    assert_true(ta.volume == tb.volume && ta.volume > 0.0);
    assert_int_equal(ta.adds, 20);
    assert_int_equal(tb.adds, 40);
    /* The volume: sum over the contacts of passes x sum_j d_j dy_j. */
    double expect = 0.0;
    for (int i = 0; i < 20; ++i) {
        double y[12], dy[12], dep[12];
        assert_int_equal(cw_wear_get_strips(w[i], y, dy, dep, NULL, 12), CW_OK);
        for (int j = 0; j < 12; ++j) expect += 1000.0 * dep[j] * dy[j];
    }
    assert_close(ta.volume, expect, 1e-13, 0.0);
    assert_int_equal(cw_wear_profile_reset(a), CW_OK);
    cw_wear_profile_get_totals(a, &ta);
    assert_true(ta.passes == 0.0 && ta.volume == 0.0 && ta.adds == 0);
    cw_wear_profile_destroy(a);
    cw_wear_profile_destroy(b);
    cw_wear_profile_destroy(c1);
    cw_wear_profile_destroy(c2);
    cw_wear_profile_destroy(d);
    for (int i = 0; i < 20; ++i) cw_wear_destroy(w[i]);
    cw_solver_destroy(sv);
}

/* A wheel and a rail see the same contact: the same depth per pass. The
 * wheel of radius R rolling D makes D / (2 pi R) passes; its mass per
 * revolution is the mass per rolled distance x 2 pi R (pass_length). */
static void wheel_and_rail_passes(void** state)
{
    (void)state;
    cw_solver* sv = solved(0, CW_GRID_KALKER_STRIPS);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(sv, &w), CW_OK);
    cw_wear_params p;
    cw_wear_params_init(&p);
    const double R = 0.46, D = 1000.0;
    p.pass_length = 2.0 * M_PI * R;
    cw_wear_result r;
    cw_wear_result_init(&r);
    assert_int_equal(cw_wear_compute(w, sv, &p, &r), CW_OK);
    assert_close(r.mass_per_pass, r.mass_per_distance * 2.0 * M_PI * R, 1e-15, 0);
    double s[NS];
    nodes(s);
    cw_wear_profile *wheel, *rail;
    assert_int_equal(cw_wear_profile_create(s, NS, &wheel, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_create(s, NS, &rail, NULL, 0), CW_OK);
    assert_int_equal(cw_wear_profile_add(wheel, w, 0.0, -1, 0.0, D / (2.0 * M_PI * R)), CW_OK);
    assert_int_equal(cw_wear_profile_add(rail, w, 0.0, 1, 0.0, 1.0), CW_OK);
    cw_wear_profile_totals tw, tr;
    cw_wear_profile_totals_init(&tw);
    cw_wear_profile_totals_init(&tr);
    cw_wear_profile_get_totals(wheel, &tw);
    cw_wear_profile_get_totals(rail, &tr);
    /* The wheel's worn cross-section x its circumference is the mass worn
     * over D divided by the density. */
    assert_close(tw.volume * 2.0 * M_PI * R, r.mass_per_distance * D / p.density, 1e-12, 0);
    /* One axle passage wears the rail by the depth per pass: volume per
     * metre of rail = mass per rolled distance / density. */
    assert_close(tr.volume, r.mass_per_distance / p.density, 1e-12, 0);
    cw_wear_profile_destroy(wheel);
    cw_wear_profile_destroy(rail);
    cw_wear_destroy(w);
    cw_solver_destroy(sv);
}

/* Element by element through the C ABI, from the exported fields alone:
 * T/A = work / area (the energy-consistent map), sliding = (T/A) / |p|,
 * and Archard's rate = rho k pz s / H with k the KTH map's value for the
 * element's regime (Jendel 2002 as in the header), to 1e-13. And the USFD
 * plateau includes both of its ends, as published ("10.4-77.2"): with t1
 * or t2 set to an element's own T/A, that element is in regime 2. */
static void elements_follow_the_laws(void** state)
{
    (void)state;
    cw_solver* s = solved(2, CW_GRID_KALKER_STRIPS);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    double area[N], px[N], py[N], pz[N], work[N], dens[N], slide[N], rate[N];
    int regime[N];
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, N), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PX, px, N), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PY, py, N), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, N), CW_OK);
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, work, N), CW_OK);
    cw_wear_params p;
    cw_wear_params_init(&p);
    p.law = CW_WEAR_ARCHARD_KTH;
    p.rolling_speed = 60.0;
    p.kth_v1 = 0.05; /* boundaries inside this contact's sliding velocities */
    p.kth_v2 = 0.12;
    assert_int_equal(cw_wear_compute(w, s, &p, NULL), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_WORK_DENSITY, dens, N), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_SLIDING, slide, N), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate, N), CW_OK);
    assert_int_equal(cw_wear_get_regimes(w, regime, N), CW_OK);
    const double k[5] = {0.0, p.kth_k_slow, p.kth_k_severe, p.kth_k_fast, p.kth_k_seizure};
    int seen[5] = {0, 0, 0, 0, 0}, max_e = -1;
    for (int e = 0; e < N; ++e) {
        if (area[e] <= 0.0) continue;
        const double tga = work[e] > 0 ? work[e] / area[e] : 0.0;
        assert_close(dens[e], tga, 1e-15, 0.0);
        const double sl = tga > 0 ? tga / hypot(px[e], py[e]) : 0.0;
        assert_close(slide[e], sl, 1e-14, 0.0);
        ++seen[regime[e]];
        assert_close(rate[e], p.density * k[regime[e]] * pz[e] * sl / p.hardness, 1e-13, 0.0);
        if (regime[e] && (max_e < 0 || dens[e] > dens[max_e])) max_e = e;
    }
    assert_true(seen[1] > 0 && seen[2] > 0 && seen[3] > 0); /* all three velocity regimes */
    /* USFD with the plateau's ends on an element's own T/A. */
    cw_wear_params u;
    cw_wear_params_init(&u);
    u.usfd_t1 = 0.5 * dens[max_e];
    u.usfd_t2 = dens[max_e];
    assert_int_equal(cw_wear_compute(w, s, &u, NULL), CW_OK);
    assert_int_equal(cw_wear_get_regimes(w, regime, N), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate, N), CW_OK);
    assert_int_equal(regime[max_e], 2);
    assert_close(rate[max_e], u.usfd_k2, 0.0, 0.0);
    u.usfd_t1 = dens[max_e];
    u.usfd_t2 = 2.0 * dens[max_e];
    assert_int_equal(cw_wear_compute(w, s, &u, NULL), CW_OK);
    assert_int_equal(cw_wear_get_regimes(w, regime, N), CW_OK);
    assert_int_equal(regime[max_e], 2);
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

/* The KTH map's regime boundaries approached from both sides through the C
 * ABI: with a boundary set to one element's own sliding velocity
 * v = sliding * rolling_speed (the product the library forms) or pressure,
 * the element is on the boundary's closed side, and one ulp further on the
 * other: v1 <= v <= v2 is regime 2, v < v1 regime 1, v > v2 regime 3,
 * pressure > ratio * hardness regime 4 (header, Jendel 2002). */
static void kth_boundaries_from_both_sides(void** state)
{
    (void)state;
    cw_solver* s = solved(2, CW_GRID_KALKER_STRIPS);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    double pz[N], slide[N];
    int regime[N];
    assert_int_equal(cw_solver_get_field(s, CW_FIELD_PZ, pz, N), CW_OK);
    cw_wear_params p;
    cw_wear_params_init(&p);
    p.law = CW_WEAR_ARCHARD_KTH;
    p.rolling_speed = 60.0;
    assert_int_equal(cw_wear_compute(w, s, &p, NULL), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_SLIDING, slide, N), CW_OK);
    int e = -1; /* the element sliding fastest */
    for (int k = 0; k < N; ++k)
        if (slide[k] > 0.0 && (e < 0 || slide[k] > slide[e])) e = k;
    assert_true(e >= 0);
    const double v = slide[e] * p.rolling_speed;
    const struct {
        double v1, v2, ratio, hardness;
        int regime;
    } cases[] = {
        {v, 2.0 * v, 0.8, 2.5e9, 2},                    /* v = v1: severe */
        {nextafter(v, INFINITY), 2.0 * v, 0.8, 2.5e9, 1}, /* just below v1: slow */
        {0.5 * v, v, 0.8, 2.5e9, 2},                    /* v = v2: severe */
        {0.5 * v, nextafter(v, 0.0), 0.8, 2.5e9, 3},    /* just above v2: fast */
        {0.5 * v, 2.0 * v, 1.0, pz[e], 2},              /* p = ratio H: not seizure */
        {0.5 * v, 2.0 * v, 1.0, nextafter(pz[e], 0.0), 4}, /* just above: seizure */
    };
    for (size_t c = 0; c < sizeof cases / sizeof cases[0]; ++c) {
        p.kth_v1 = cases[c].v1;
        p.kth_v2 = cases[c].v2;
        p.kth_seizure_ratio = cases[c].ratio;
        p.hardness = cases[c].hardness;
        assert_int_equal(cw_wear_compute(w, s, &p, NULL), CW_OK);
        assert_int_equal(cw_wear_get_regimes(w, regime, N), CW_OK);
        if (regime[e] != cases[c].regime) print_error("case %zu\n", c);
        assert_int_equal(regime[e], cases[c].regime);
    }
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

/* The update helper on uneven nodes: the worn cross-section is kept,
 * sum (old - new) w = sum depth w with the cells' own widths (1e-12). */
static void update_keeps_volume_on_uneven_nodes(void** state)
{
    (void)state;
    enum { M = 90 };
    double s[M], w[M], old[M], depth[M], nw[M];
    for (int k = 0; k < M; ++k) s[k] = -0.02 + 0.04 * pow(k / (M - 1.0), 1.7);
    for (int k = 0; k < M; ++k) {
        const double lo = k ? 0.5 * (s[k - 1] + s[k]) : s[0] - 0.5 * (s[1] - s[0]);
        const double hi = k < M - 1 ? 0.5 * (s[k] + s[k + 1]) : s[M - 1] + 0.5 * (s[M - 1] - s[M - 2]);
        w[k] = hi - lo;
        old[k] = 0.0;
        depth[k] = 1e-6 * exp(-pow((s[k] - 0.001) / 0.004, 2)) + (k == 70 ? 5e-6 : 0.0);
    }
    for (double smoothing = 0.0; smoothing < 4e-3; smoothing += 1.3e-3) {
        assert_int_equal(cw_wear_profile_update(s, old, depth, M, smoothing, nw, M, NULL, 0), CW_OK);
        double removed = 0.0, worn = 0.0;
        for (int k = 0; k < M; ++k) {
            removed += (old[k] - nw[k]) * w[k];
            worn += depth[k] * w[k];
        }
        assert_close(removed, worn, 1e-12, 0.0);
    }
}

/* Wear of the exact model (Kalker's theory on the uniform 12 x 12 grid,
 * box 1.2; the wear of every model), partial and full slip, both
 * laws: mass per distance = sum of rate x area (1e-12); the energy-
 * consistent source feeds the law the model's own W_macro (1e-12: the
 * exact model's consistent map sums to its W_macro, test_capi_exact); each
 * element's USFD rate is the law of its T/A = W_e/A_e (1e-15, Braghin et
 * al. 2006 as printed), so that in the mild regime the mass is k1 x
 * W_macro (1e-12); and the wear is the same whether the exact model
 * is solved cold or warm from another contact (to the solver's tolerance). */
static void exact_model_wear(void** state)
{
    (void)state;
    enum { EN = 12 * 12 };
    cw_solver* s = cw_test_solver(CW_GRID_UNIFORM, 12, 12, 1.2);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    double area[EN], work[EN], rate[EN], dens[EN];
    int regime[EN];
    const double xis[2] = {1e-3, 8e-3}; /* partial slip; full slip */
    for (int c = 0; c < 2; ++c) {
        cw_params p;
        cw_params_init(&p);
        p.model = CW_MODEL_EXACT;
        p.warm_start = 0;
        p.a = 0.006;
        p.b = 0.005;
        p.normal_force = 80e3;
        p.mu = 0.3;
        p.G = 82e9;
        p.nu = 0.28;
        p.xi_x = xis[c];
        p.xi_y = 5e-4;
        p.phi = 0.4;
        cw_result r;
        cw_result_init(&r);
        assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, &r), CW_OK);
        assert_true(r.W_macro > 0.0);
        if (c == 1) assert_true(r.n_adhesion == 0); /* full slip indeed */
        if (c == 0) assert_true(r.n_adhesion > 0 && r.n_slip > 0);
        assert_int_equal(cw_solver_get_field(s, CW_FIELD_AREA, area, EN), CW_OK);
        assert_int_equal(cw_solver_get_field(s, CW_FIELD_WORK_CONSISTENT, work, EN), CW_OK);
        for (int law = CW_WEAR_USFD; law <= CW_WEAR_ARCHARD_KTH; ++law) {
            cw_wear_params wp;
            cw_wear_params_init(&wp);
            wp.law = law;
            wp.rolling_speed = 20.0;
            cw_wear_result wr;
            cw_wear_result_init(&wr);
            assert_int_equal(cw_wear_compute(w, s, &wp, &wr), CW_OK);
            assert_close(wr.work, r.W_macro, 1e-12, 0.0);
            assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate, EN), CW_OK);
            assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_WORK_DENSITY, dens, EN), CW_OK);
            assert_int_equal(cw_wear_get_regimes(w, regime, EN), CW_OK);
            double mass = 0.0, worn_area = 0.0;
            for (int e = 0; e < EN; ++e) {
                assert_true(isfinite(rate[e]) && rate[e] >= 0.0);
                mass += rate[e] * area[e];
                if (regime[e] != CW_WEAR_REGIME_NONE) worn_area += area[e];
                if (law != CW_WEAR_USFD || area[e] <= 0.0) continue;
                const double tga = work[e] > 0.0 ? work[e] / area[e] : 0.0;
                assert_close(dens[e], tga, 1e-15, 0.0);
                const double expect = tga < wp.usfd_t1   ? wp.usfd_k1 * tga
                                      : tga <= wp.usfd_t2 ? wp.usfd_k2
                                                          : fmax(0.0, wp.usfd_k3 * tga - wp.usfd_c3);
                assert_close(rate[e], expect, 1e-15, 0.0);
            }
            assert_true(mass > 0.0);
            assert_close(wr.mass_per_distance, mass, 1e-12, 0.0);
            if (law == CW_WEAR_USFD) {
                /* T/A stays below 10.4 N/mm^2 here (mild everywhere), where
                 * the rate is k1 T/A: the mass per rolled metre is then
                 * k1 x (sum of the consistent work) = k1 x W_macro. */
                assert_true(wr.regime_area[0] > 0.0 && wr.regime_area[1] == 0.0 &&
                            wr.regime_area[2] == 0.0);
                assert_close(wr.mass_per_distance, wp.usfd_k1 * r.W_macro, 1e-12, 0.0);
            }
            assert_close(wr.regime_area[0] + wr.regime_area[1] + wr.regime_area[2] +
                             wr.regime_area[3],
                         worn_area, 1e-12, 0.0);
            if (law == CW_WEAR_USFD) {
                /* Warm from the other contact: the same wear to the solver's
                 * tolerance (1e-8, relative; 1e-4 leaves room for
                 * an element near a regime boundary). */
                cw_params q = p;
                q.xi_x = xis[1 - c];
                assert_int_equal(cw_solver_solve(s, &q, CW_SOLVE_FULL, NULL), CW_OK);
                p.warm_start = 1;
                assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
                p.warm_start = 0;
                cw_wear_result warm;
                cw_wear_result_init(&warm);
                assert_int_equal(cw_wear_compute(w, s, &wp, &warm), CW_OK);
                assert_close(warm.mass_per_distance, wr.mass_per_distance, 1e-4, 0.0);
                /* And back to the cold solve for the next law. */
                assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
            }
        }
    }
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

/* Archard's rolling speed 0 takes the solve's cw_params.V, with the bits of
 * the same speed given; both given must agree and the error names both;
 * USFD, which does not use the speed, needs neither. */
static void archard_speed_from_the_solve(void** state)
{
    (void)state;
    cw_solver* s = cw_test_solver(CW_GRID_KALKER_STRIPS, NX, NY, 1.2);
    cw_params p;
    cw_test_case(1, &p);
    p.V = 25.0;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    cw_wear* w = NULL;
    assert_int_equal(cw_wear_create(s, &w), CW_OK);
    cw_wear_params wp;
    cw_wear_params_init(&wp);
    wp.law = CW_WEAR_ARCHARD_KTH;
    cw_wear_result from_V, given;
    cw_wear_result_init(&from_V);
    cw_wear_result_init(&given);
    double rate_from_V[N], rate_given[N];
    assert_int_equal(cw_wear_compute(w, s, &wp, &from_V), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate_from_V, N), CW_OK);
    wp.rolling_speed = 25.0;
    assert_int_equal(cw_wear_compute(w, s, &wp, &given), CW_OK);
    assert_int_equal(cw_wear_get_field(w, CW_WEAR_FIELD_RATE, rate_given, N), CW_OK);
    assert_memory_equal(&from_V, &given, sizeof given);
    assert_memory_equal(rate_from_V, rate_given, sizeof rate_given);
    assert_true(given.mass_per_distance > 0.0);
    wp.rolling_speed = 20.0;
    assert_int_equal(cw_wear_compute(w, s, &wp, &given), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_wear_last_error(w), "rolling_speed"));
    assert_non_null(strstr(cw_wear_last_error(w), "cw_params.V"));
    p.V = 0.0;
    assert_int_equal(cw_solver_solve(s, &p, CW_SOLVE_FULL, NULL), CW_OK);
    wp.rolling_speed = 0.0;
    assert_int_equal(cw_wear_compute(w, s, &wp, &given), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_wear_last_error(w), "cw_params.V"));
    wp.law = CW_WEAR_USFD;
    assert_int_equal(cw_wear_compute(w, s, &wp, &given), CW_OK);
    cw_wear_destroy(w);
    cw_solver_destroy(s);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(defaults_are_the_published_values),
        cmocka_unit_test(mass_is_rate_times_area),
        cmocka_unit_test(compute_errors_are_named),
        cmocka_unit_test(profile_errors_are_named),
        cmocka_unit_test(accumulation_is_bitwise_split_invariant),
        cmocka_unit_test(wheel_and_rail_passes),
        cmocka_unit_test(elements_follow_the_laws),
        cmocka_unit_test(kth_boundaries_from_both_sides),
        cmocka_unit_test(update_keeps_volume_on_uneven_nodes),
        cmocka_unit_test(exact_model_wear),
        cmocka_unit_test(archard_speed_from_the_solve),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
