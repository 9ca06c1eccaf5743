/* A friction law of the slip speed in the wheel/rail patches, through the
 * public header: a law without falling terms is Coulomb's law by another
 * path (the exact model's law iteration against its Coulomb solve; the
 * fast model's law march, bitwise), a patch in full sliding carries mu(s)
 * Fn at its rigid slip speed s = |(cksi, ceta)| veloc (the closed form of
 * sliding friction) with either model, and every refusal names its input.
 * Manchester benchmark profiles. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "creepwork/creepwork.h"
#include "test_support.h"

static const char* rail_file = CW_WHEELRAIL_DATA "/MBench_UIC60_v3.prr";
static const char* wheel_file = CW_WHEELRAIL_DATA "/MBench_S1002_v3.prw";

/* CONTACT's tractcurv law (FKIN 0.14, FEXP1 0.19, SABSH1 1.25 m/s). */
static void tractcurv_law(cw_wheelrail_params* p)
{
    p->friction_law = CW_FRICTION_EXPONENTIAL;
    p->mu = 0.14;
    p->mu_e1 = 0.19;
    p->s_h1 = 1.25;
}

/* The wheelset at y = 3 mm (case A-2.2's roll) and yaw, forward at vs with
 * the pitch rate vpitch, under 10 kN: totals and patch 0. */
static int solve(const cw_wheelrail_params* p, double yaw, double vs, double vpitch, cw_wheelrail_totals* t,
                 cw_wheelrail_patch* patch, char* error, size_t error_len)
{
    cw_wheelrail* w = NULL;
    char msg[512];
    int rc = cw_wheelrail_create(p, rail_file, wheel_file, &w, msg, sizeof msg);
    if (rc != CW_OK) {
        snprintf(error, error_len, "%s", msg);
        return rc;
    }
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = 3.0e-3;
    m.yaw = yaw;
    m.roll = -0.00018030;
    m.vs = vs;
    m.vpitch = vpitch;
    cw_wheelrail_totals_init(t);
    rc = cw_wheelrail_solve(w, &m, CW_WHEELRAIL_FORCE, 1e4, t);
    snprintf(error, error_len, "%s", cw_wheelrail_last_error(w));
    if (rc == CW_OK) {
        cw_wheelrail_patch_init(patch);
        assert_int_equal(cw_wheelrail_get_patch(w, 0, patch), CW_OK);
    }
    cw_wheelrail_destroy(w);
    return rc;
}

/* The fast model: FASTSIM with the semi-Hertzian normal problem. */
static void fast_model(cw_wheelrail_params* p)
{
    p->model = CW_MODEL_FASTSIM;
    p->normal_method = CW_NORMAL_SEMI_HERTZ;
}

/* Case A-2.2's position in partial slip under Coulomb's law (p as given)
 * and under the exponential law without a falling term: totals and patch 0
 * of each. */
static void coulomb_and_flat_law(cw_wheelrail_params* p, cw_wheelrail_totals* tc, cw_wheelrail_patch* pc,
                                 cw_wheelrail_totals* tl, cw_wheelrail_patch* pl)
{
    char error[512];
    assert_int_equal(solve(p, 0.0003, 10.0, -10.0 / 0.46, tc, pc, error, sizeof error), CW_OK);
    p->friction_law = CW_FRICTION_EXPONENTIAL;
    assert_int_equal(solve(p, 0.0003, 10.0, -10.0 / 0.46, tl, pl, error, sizeof error), CW_OK);
    printf("Coulomb: %d adhesion, %d slip elements\n", pc->n_adhesion, pc->n_slip);
    assert_true(pc->n_slip > 0 && pc->n_adhesion > 0); /* partial slip: the law's path matters */
}

/* The exponential law with no falling term is mu at every slip speed:
 * the law's Newton iteration lands on Coulomb's solution within the exact
 * solver's tolerance (1e-8 relative; asserted to 1e-7 of mu Fn). */
static void law_without_falling_terms_is_coulomb(void** state)
{
    (void)state;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    cw_wheelrail_totals tc, tl;
    cw_wheelrail_patch pc, pl;
    coulomb_and_flat_law(&p, &tc, &pc, &tl, &pl);
    const double scale = p.mu * pc.Fn;
    assert_close(tl.Fz, tc.Fz, 0.0, 1e-7 * tc.Fz);
    assert_close(pl.Fx, pc.Fx, 0.0, 1e-7 * scale);
    assert_close(pl.Fs, pc.Fs, 0.0, 1e-7 * scale);
    assert_close(pl.Mn, pc.Mn, 0.0, 1e-7 * scale * 1e-2);
}

/* The same with the fast model: the law's march, whose roots land on
 * Coulomb's t = mu pn at the first evaluation, gives Coulomb's bits. */
static void fast_model_law_without_falling_terms_is_coulomb(void** state)
{
    (void)state;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    fast_model(&p);
    cw_wheelrail_totals tc, tl;
    cw_wheelrail_patch pc, pl;
    coulomb_and_flat_law(&p, &tc, &pc, &tl, &pl);
    assert_true(tl.Fz == tc.Fz && pl.Fx == pc.Fx && pl.Fs == pc.Fs && pl.Mn == pc.Mn);
    assert_int_equal(pl.n_slip, pc.n_slip);
}

/* Full sliding at 20 % longitudinal creepage and 10 m/s: every element
 * slips at about the rigid slip speed s = |(cksi, ceta)| veloc, so the
 * tangential force is mu(s) Fn, mu(s) = 0.14 + 0.19 exp(-ln2 s/1.25). The
 * elastic part of the slip (about mu p0 / (G cksi), 2 % of it) and the spin
 * move the elements' speeds around s, symmetrically to first order: they
 * move the force by 7.3e-5 of mu(s) Fn here with the exact model, 1.2e-4
 * with the fast model (FASTSIM's elastic slip (L1, L2) (1 - f) q / dx);
 * 3e-4 is asserted. */
static void full_sliding_with(int fast)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    tractcurv_law(&p);
    if (fast) fast_model(&p);
    cw_wheelrail_totals t;
    cw_wheelrail_patch patch;
    char error[512];
    const double vs = 10.0, vpitch = -0.8 * vs / 0.46;
    assert_int_equal(solve(&p, 0.0072, vs, vpitch, &t, &patch, error, sizeof error), CW_OK);
    assert_int_equal(patch.n_adhesion, 0);
    const double s = hypot(patch.cksi, patch.ceta) * patch.veloc;
    assert_true(s > 1.0 && s < 4.0);
    const double mu_s = 0.14 + 0.19 * exp(-log(2.0) * s / 1.25);
    const double ft = hypot(patch.Fx, patch.Fs);
    printf("%s model: s = %.4f m/s, mu(s) = %.6f, Ft/Fn = %.6f, relative %.2e\n",
           fast ? "fast" : "exact", s, mu_s, ft / patch.Fn, ft / patch.Fn / mu_s - 1.0);
    assert_close(ft / patch.Fn, mu_s, 0.0, 3e-4 * mu_s);
    /* and not Coulomb's static coefficient */
    assert_true(ft / patch.Fn < 0.9 * (0.14 + 0.19));
}

static void full_sliding_follows_the_law(void** state)
{
    (void)state;
    full_sliding_with(0);
}

static void fast_model_full_sliding_follows_the_law(void** state)
{
    (void)state;
    full_sliding_with(1);
}

static void refusal(cw_wheelrail_params* p, double vs, int code, const char* needle)
{
    cw_wheelrail_totals t;
    cw_wheelrail_patch patch;
    char error[512] = "";
    assert_int_equal(solve(p, 0.0072, vs, -vs / 0.46, &t, &patch, error, sizeof error), code);
    if (!strstr(error, needle)) fail_msg("'%s' does not name %s", error, needle);
}

static void errors_name_their_input(void** state)
{
    (void)state;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.friction_law = 1; /* no law 1 */
    refusal(&p, 10.0, CW_ERR_UNKNOWN_OPTION, "friction_law = 1");
    cw_wheelrail_params_init(&p);
    tractcurv_law(&p);
    fast_model(&p);
    p.mu_e1 = -0.1; /* the fast model checks the law as the exact model */
    refusal(&p, 10.0, CW_ERR_INVALID_INPUT, "mu_e1");
    cw_wheelrail_params_init(&p);
    tractcurv_law(&p);
    p.mu_e1 = NAN;
    refusal(&p, 10.0, CW_ERR_INVALID_INPUT, "mu_e1");
    cw_wheelrail_params_init(&p);
    tractcurv_law(&p);
    p.s_h1 = 0.0; /* a falling term needs its half speed */
    refusal(&p, 10.0, CW_ERR_INVALID_INPUT, "s_h1");
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(law_without_falling_terms_is_coulomb),
        cmocka_unit_test(full_sliding_follows_the_law),
        cmocka_unit_test(fast_model_law_without_falling_terms_is_coulomb),
        cmocka_unit_test(fast_model_full_sliding_follows_the_law),
        cmocka_unit_test(errors_name_their_input),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
