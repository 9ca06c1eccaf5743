/* A solved wheel/rail patch through the public header: its fields in the
 * wheel/rail conventions add up to the patch's forces and moment, its
 * solver view carries the same solution in creepwork's conventions, its
 * wear lands on the profiles where the documented placement puts it (and
 * mirrors between the sides), two patches' wear adds up as documented, a
 * rail offset mirrors between the sides and translates the contact, the
 * fast model follows the exact one, and every documented error names its
 * input. */
#include <stdlib.h>

#include "creepwork/creepwork.h"
#include "test_support.h"

static const char* rail_file = CW_WHEELRAIL_DATA "/MBench_UIC60_v3.prr";
static const char* wheel_file = CW_WHEELRAIL_DATA "/MBench_S1002_v3.prw";


/* The wheelset at (y, yaw, roll), rolling at 2 m/s, under 10 kN on
 * params->side: the handle, solved, with n_patches patches. */
static cw_wheelrail* solved_at(const cw_wheelrail_params* p, double y, double yaw, double roll,
                               double vpitch, int n_patches)
{
    cw_wheelrail* w = NULL;
    char msg[256];
    assert_int_equal(cw_wheelrail_create(p, rail_file, wheel_file, &w, msg, sizeof msg), CW_OK);
    cw_wheelrail_motion m;
    cw_wheelrail_motion_init(&m);
    m.y = y;
    m.yaw = yaw;
    m.roll = roll;
    m.vs = 2.0;
    m.vpitch = vpitch;
    cw_wheelrail_totals t;
    cw_wheelrail_totals_init(&t);
    assert_int_equal(cw_wheelrail_solve(w, &m, CW_WHEELRAIL_FORCE, 1e4, &t), CW_OK);
    assert_int_equal(t.n_patches, n_patches);
    return w;
}

/* Case, y_ws = 3 mm (mbench_a22.csv) plus y_extra, on params->side;
 * the wheelset position is mirrored for the left wheel (y, yaw, roll
 * negated). */
static cw_wheelrail* solved_with(const cw_wheelrail_params* p, double y_extra)
{
    const double sign = p->side == CW_WHEELRAIL_RIGHT ? 1.0 : -1.0;
    return solved_at(p, sign * 3.0e-3 + y_extra, sign * 0.0072, -sign * 0.00018030,
                     -4.34515030, 1);
}

static cw_wheelrail* solved(int side, int model, int normal_method, int solve_mode)
{
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.side = side;
    p.model = model;
    p.normal_method = normal_method;
    p.solve_mode = solve_mode;
    return solved_with(&p, 0.0);
}

static cw_wheelrail_patch patch0(const cw_wheelrail* w)
{
    cw_wheelrail_patch p;
    cw_wheelrail_patch_init(&p);
    assert_int_equal(cw_wheelrail_get_patch(w, 0, &p), CW_OK);
    return p;
}

static double* field(const cw_wheelrail* w, const cw_wheelrail_patch* p, int f)
{
    const size_t n = (size_t)p->field_nx * (size_t)p->field_ny;
    double* v = malloc(n * sizeof *v);
    assert_non_null(v);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 0, f, v, n), CW_OK);
    return v;
}

/* The patch's totals are sums over its elements (the definitions of Fn,
 * Fx, Fs and Mn in the wheel/rail conventions): to rounding. The grid is
 * the documented one, and the states count the patch's elements. */
static void fields_add_up_to_the_patch(void** state)
{
    (void)state;
    cw_wheelrail* w = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    const cw_wheelrail_patch p = patch0(w);
    const size_t n = (size_t)p.field_nx * (size_t)p.field_ny;
    assert_int_equal(p.field_nx, p.nx); /* 0.2 mm elements: no coarsening */
    double *area = field(w, &p, CW_FIELD_AREA), *pz = field(w, &p, CW_FIELD_PZ),
           *px = field(w, &p, CW_FIELD_PX), *ps = field(w, &p, CW_FIELD_PY),
           *mz = field(w, &p, CW_FIELD_MZ), *x = field(w, &p, CW_FIELD_X), *s = field(w, &p, CW_FIELD_Y),
           *work = field(w, &p, CW_FIELD_WORK_CONSISTENT);
    double fn = 0, fx = 0, fs = 0, mn = 0, mn_xs = 0;
    for (size_t e = 0; e < n; ++e) {
        fn += pz[e] * area[e];
        fx += px[e] * area[e];
        fs += ps[e] * area[e];
        mn += mz[e];
        mn_xs += (x[e] * ps[e] - s[e] * px[e]) * area[e];
        assert_true(work[e] >= 0.0);
    }
    assert_close(fn, p.Fn, 1e-12, 0);
    assert_close(fx, p.Fx, 1e-10, 1e-9 * p.Fn);
    assert_close(fs, p.Fs, 1e-10, 1e-9 * p.Fn);
    assert_close(mn, p.Mn, 1e-9, 1e-12 * p.Fn);
    assert_close(mn_xs, p.Mn, 1e-9, 1e-12 * p.Fn);
    const size_t last = n - 1;
    assert_close(x[0], p.field_x0, 0, 1e-15);
    assert_close(s[0], p.field_s0, 0, 1e-15);
    assert_close(x[last], p.field_x0 + (p.field_nx - 1) * p.field_dx, 0, 1e-12);
    assert_close(s[last], p.field_s0 + (p.field_ny - 1) * p.field_ds, 0, 1e-12);

    int* st = malloc(n * sizeof *st);
    assert_int_equal(cw_wheelrail_get_patch_state(w, 0, st, n), CW_OK);
    int contact = 0, slip = 0;
    for (size_t e = 0; e < n; ++e) {
        contact += st[e] != CW_STATE_EXTERIOR;
        slip += st[e] == CW_STATE_SLIP;
        assert_true((st[e] != CW_STATE_EXTERIOR) == (area[e] > 0.0));
    }
    assert_int_equal(contact, p.n_contact);
    assert_int_equal(slip, p.n_slip);

    /* the solver view: creepwork's conventions (forces on the wheel, y = -s) */
    const cw_solver* view = cw_wheelrail_patch_solver(w, 0);
    assert_non_null(view);
    assert_ptr_equal(cw_wheelrail_patch_solver(w, 0), view);
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_get_result(view, &r), CW_OK);
    assert_close(r.Fx, -p.Fx, 1e-14, 0);
    assert_close(r.Fy, p.Fs, 1e-14, 0);
    assert_close(r.normal_force, p.Fn, 1e-14, 0);
    assert_null(cw_wheelrail_patch_solver(w, 1));
    assert_non_null(strstr(cw_wheelrail_last_error(w), "k = 1"));
    free(st);
    free(area), free(pz), free(px), free(ps), free(mz), free(x), free(s), free(work);
    cw_wheelrail_destroy(w);
}

/* Nodes every 0.02 mm over a profile's width. */
enum { kNodes = 4001 };
static double nodes[kNodes];

static cw_wear_profile* profile_grid(void)
{
    for (int k = 0; k < kNodes; ++k) nodes[k] = -0.04 + 2e-5 * k;
    cw_wear_profile* g = NULL;
    char msg[128];
    assert_int_equal(cw_wear_profile_create(nodes, kNodes, &g, msg, sizeof msg), CW_OK);
    return g;
}

static void depth_of(const cw_wear_profile* g, double* d)
{
    assert_int_equal(cw_wear_profile_get_depth(g, CW_WEAR_DEPTH_HEIGHT, d, kNodes), CW_OK);
}

/* The wear of the patch on both profiles equals the documented placement
 * done by hand through the public wear API: the patch solver's strips
 * (creepwork's y) at s = -(y + y0) from the reference point, y0 the grid's
 * first row, placed at rail_profile_y with orientation sign(rail_s_cos)
 * and contact angle acos|rail_s_cos| (the wheel's likewise). The worn
 * volume is passes x the wear's volume per distance. */
static void wear_lands_where_documented(void** state)
{
    (void)state;
    cw_wheelrail* w = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    const cw_wheelrail_patch p = patch0(w);
    cw_wear_params law;
    cw_wear_params_init(&law);
    const double passes = 5e3;
    cw_wear_profile *rail = profile_grid(), *wheel = profile_grid();
    cw_wear_result sum;
    cw_wear_result_init(&sum);
    assert_int_equal(cw_wheelrail_add_wear(w, &law, passes, rail, wheel, &sum), CW_OK);

    const cw_solver* view = cw_wheelrail_patch_solver(w, 0);
    cw_wear* wear = NULL;
    assert_int_equal(cw_wear_create(view, &wear), CW_OK);
    cw_wear_result one;
    cw_wear_result_init(&one);
    assert_int_equal(cw_wear_compute(wear, view, &law, &one), CW_OK);
    assert_close(sum.volume_per_distance, one.volume_per_distance, 1e-15, 0);
    const int ny = p.field_ny;
    double *y = malloc(ny * sizeof *y), *width = malloc(ny * sizeof *y), *depth = malloc(ny * sizeof *y);
    assert_int_equal(cw_wear_get_strips(wear, y, width, depth, NULL, (size_t)ny), CW_OK);
    const double y0 = -(p.field_s0 + (ny - 1) * p.field_ds);
    for (int j = 0; j < ny; ++j) y[j] = -(y[j] + y0);
    cw_wear_profile *rail_hand = profile_grid(), *wheel_hand = profile_grid();
    assert_int_equal(cw_wear_profile_add_strips(rail_hand, y, width, depth, (size_t)ny, p.rail_profile_y,
                                                p.rail_s_cos < 0 ? -1 : 1, acos(fabs(p.rail_s_cos)), passes),
                     CW_OK);
    assert_int_equal(cw_wear_profile_add_strips(wheel_hand, y, width, depth, (size_t)ny, p.wheel_profile_y,
                                                p.wheel_s_cos < 0 ? -1 : 1, acos(fabs(p.wheel_s_cos)), passes),
                     CW_OK);
    static double a[kNodes], b[kNodes];
    double peak = 0;
    depth_of(rail, a);
    depth_of(rail_hand, b);
    for (int k = 0; k < kNodes; ++k) peak = fmax(peak, b[k]);
    assert_true(peak > 0.0);
    for (int k = 0; k < kNodes; ++k) assert_close(a[k], b[k], 0, 1e-14 * peak);
    depth_of(wheel, a);
    depth_of(wheel_hand, b);
    for (int k = 0; k < kNodes; ++k) assert_close(a[k], b[k], 0, 1e-14 * peak);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    assert_int_equal(cw_wear_profile_get_totals(rail, &t), CW_OK);
    assert_close(t.volume, passes * one.volume_per_distance, 1e-12, 0);
    assert_close(t.passes, passes, 0, 0);
    /* the rail's contact angle is the patch's (a rail without cant) */
    assert_close(acos(fabs(p.rail_s_cos)), fabs(p.contact_angle), 0, 1e-9);
    free(y), free(width), free(depth);
    cw_wear_destroy(wear);
    cw_wear_profile_destroy(rail), cw_wear_profile_destroy(wheel);
    cw_wear_profile_destroy(rail_hand), cw_wear_profile_destroy(wheel_hand);
    cw_wheelrail_destroy(w);
}

/* Two patches (case b11 of tools/contact_reference/wheelrail: the
 * right wheel at y = 5 mm, yaw 0.012, roll -0.00035, 10 kN, with D_SEP =
 * 2 mm and D_COMB = 1 mm keeping the two interpenetration regions apart):
 * the wear result of cw_wheelrail_add_wear sums the patches' mass, volume
 * and work per pass and takes the deeper patch's max_depth (header), each
 * patch's own wear computed through its solver view with cw_wear_compute. */
static void wear_of_two_patches(void** state)
{
    (void)state;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    p.d_sep = 2e-3;
    p.d_comb = 1e-3;
    cw_wheelrail* w = solved_at(&p, 5.0e-3, 0.012, -0.00035, -4.335, 2);
    cw_wear_params law;
    cw_wear_params_init(&law);
    cw_wear_result sum;
    cw_wear_result_init(&sum);
    cw_wear_profile* rail = profile_grid();
    assert_int_equal(cw_wheelrail_add_wear(w, &law, 1e3, rail, NULL, &sum), CW_OK);
    cw_wear_result one[2];
    for (int k = 0; k < 2; ++k) {
        const cw_solver* view = cw_wheelrail_patch_solver(w, (size_t)k);
        assert_non_null(view);
        cw_wear* wear = NULL;
        assert_int_equal(cw_wear_create(view, &wear), CW_OK);
        cw_wear_result_init(&one[k]);
        assert_int_equal(cw_wear_compute(wear, view, &law, &one[k]), CW_OK);
        assert_true(one[k].max_depth > 0.0);
        cw_wear_destroy(wear);
    }
    print_message("max_depth per pass: patches %.4g and %.4g m, together %.4g m\n",
                  one[0].max_depth, one[1].max_depth, sum.max_depth);
    assert_true(sum.max_depth == fmax(one[0].max_depth, one[1].max_depth));
    assert_true(sum.max_depth < one[0].max_depth + one[1].max_depth);
    assert_close(sum.mass_per_distance, one[0].mass_per_distance + one[1].mass_per_distance,
                 1e-15, 0);
    assert_close(sum.volume_per_distance,
                 one[0].volume_per_distance + one[1].volume_per_distance, 1e-15, 0);
    assert_close(sum.work, one[0].work + one[1].work, 1e-15, 0);
    cw_wear_profile_destroy(rail);
    cw_wheelrail_destroy(w);
}

/* Two force balances each meet the vertical force to its tolerance (1e-6,
 * the default): the heights they accept lie up to that apart, and the
 * forces with them (the left and the right wheel's take different paths to
 * rounding: the trial heights solve to looser tolerances and start from the
 * fast model's height; measured 1.8e-8 of the forces at y = 3 mm). */
static const double kBalances = 2e-6;

/* What the exact solve's tolerance (1e-8) guarantees of a moment: the
 * tractions to 1e-8 of the largest, so Mn to 1e-8 |F| times a length of
 * the patch (here an element's, less than the patch's size). Mn of the
 * benchmark's patch is small (0.024 N m against |F| dx = 0.59 N m), so 1e-8 of
 * Mn itself holds only while both sides' solves follow mirror paths, which
 * the warm steps' coarse correction (its blocks on the patch's grid) need
 * not. */
static double mn_tolerance(const cw_wheelrail_patch* p)
{
    return 1e-8 * hypot(p->Fx, p->Fs) * p->field_dx;
}

/* Mirror symmetry: the left wheel at the mirrored position wears the same
 * profiles (as their points are given) as the right wheel, and its forces
 * mirror (Fs and Mn change sign), to kBalances. */
static void sides_mirror(void** state)
{
    (void)state;
    cw_wheelrail* r = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    cw_wheelrail* l = solved(CW_WHEELRAIL_LEFT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    const cw_wheelrail_patch pr = patch0(r), pl = patch0(l);
    assert_close(pl.Fx, pr.Fx, kBalances, 0);
    assert_close(pl.Fs, -pr.Fs, kBalances, 0);
    assert_close(pl.Mn, -pr.Mn, kBalances, mn_tolerance(&pr));
    assert_close(pl.rail_profile_y, pr.rail_profile_y, 0, 1e-12);
    assert_close(pl.rail_s_cos, -pr.rail_s_cos, 0, 1e-12);
    cw_wear_params law;
    cw_wear_params_init(&law);
    cw_wear_profile *rail_r = profile_grid(), *rail_l = profile_grid();
    cw_wear_profile *wheel_r = profile_grid(), *wheel_l = profile_grid();
    assert_int_equal(cw_wheelrail_add_wear(r, &law, 1e3, rail_r, wheel_r, NULL), CW_OK);
    assert_int_equal(cw_wheelrail_add_wear(l, &law, 1e3, rail_l, wheel_l, NULL), CW_OK);
    static double a[kNodes], b[kNodes];
    double peak = 0;
    depth_of(rail_r, a);
    depth_of(rail_l, b);
    for (int k = 0; k < kNodes; ++k) peak = fmax(peak, a[k]);
    for (int k = 0; k < kNodes; ++k) assert_close(b[k], a[k], 0, kBalances * peak);
    depth_of(wheel_r, a);
    depth_of(wheel_l, b);
    for (int k = 0; k < kNodes; ++k) assert_close(b[k], a[k], 0, kBalances * peak);
    cw_wear_profile_destroy(rail_r), cw_wear_profile_destroy(rail_l);
    cw_wear_profile_destroy(wheel_r), cw_wear_profile_destroy(wheel_l);
    cw_wheelrail_destroy(r);
    cw_wheelrail_destroy(l);
}

/* A rail deviation rail_dy is a lateral shift in track coordinates on
 * either side (header, cw_wheelrail_params), also with the rail placed by
 * its gauge point (the default gauge_height, 14 mm): the left rail moved by
 * -0.6 mm (outwards) under the left wheel at the mirrored position carries
 * the right wheel's forces over the right rail moved by +0.6 mm, mirrored;
 * and a rail moved by dy under a wheelset moved by dy is the undisturbed
 * contact moved by dy (the same forces, the reference point dy along y);
 * forces to kBalances (as sides_mirror). */
static void rail_offset_mirrors_with_the_gauge(void** state)
{
    (void)state;
    const double dy = 0.6e-3;
    cw_wheelrail* moved[2];
    cw_wheelrail_patch p[2], p0[2];
    for (int side = CW_WHEELRAIL_RIGHT; side <= CW_WHEELRAIL_LEFT; ++side) {
        const double sign = side == CW_WHEELRAIL_RIGHT ? 1.0 : -1.0;
        cw_wheelrail_params params;
        cw_wheelrail_params_init(&params);
        assert_true(params.gauge_height > 0.0);
        params.side = side;
        params.rail_dy = sign * dy;
        /* At the benchmark's position over the moved rail, and moved with it. */
        moved[side] = solved_with(&params, 0.0);
        p[side] = patch0(moved[side]);
        cw_wheelrail* with_rail = solved_with(&params, sign * dy);
        const cw_wheelrail_patch shifted = patch0(with_rail);
        cw_wheelrail* fixed = solved(side, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
        p0[side] = patch0(fixed);
        assert_close(shifted.y_contact, p0[side].y_contact + sign * dy, 0, 1e-12);
        assert_close(shifted.Fn, p0[side].Fn, kBalances, 0);
        assert_close(shifted.Fx, p0[side].Fx, kBalances, 0);
        assert_close(shifted.Fs, p0[side].Fs, kBalances, 0);
        assert_close(shifted.Mn, p0[side].Mn, kBalances, 1e-12);
        cw_wheelrail_destroy(with_rail);
        cw_wheelrail_destroy(fixed);
    }
    const cw_wheelrail_patch r = p[CW_WHEELRAIL_RIGHT], l = p[CW_WHEELRAIL_LEFT];
    /* The offset matters: the right patch moved by more than 1 % of its Fs. */
    /* The offset matters: the right contact moved outwards with the rail
     * (by 1.17 mm: 0.6 mm and a new point on the wheel's tread). */
    assert_true(r.y_contact - p0[CW_WHEELRAIL_RIGHT].y_contact > 0.5 * dy);
    assert_close(l.y_contact, -r.y_contact, 0, 1e-12);
    assert_close(l.contact_angle, -r.contact_angle, 0, 1e-12);
    assert_close(l.Fn, r.Fn, kBalances, 0);
    assert_close(l.Fx, r.Fx, kBalances, 0);
    assert_close(l.Fs, -r.Fs, kBalances, 0);
    assert_close(l.Mn, -r.Mn, kBalances, mn_tolerance(&r));
    assert_close(l.cksi, r.cksi, 1e-12, 0);
    assert_close(l.ceta, -r.ceta, 1e-12, 0);
    cw_wheelrail_destroy(moved[0]);
    cw_wheelrail_destroy(moved[1]);
}

/* The fast model (FASTSIM with the semi-Hertzian normal problem) against
 * the exact model on the same position: forces within 3 % of mu Fn, the
 * fast method's accuracy target; the vertical force is met by both. */
static void fast_model_follows_exact(void** state)
{
    (void)state;
    cw_wheelrail* e = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    cw_wheelrail* f = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_FASTSIM, CW_NORMAL_SEMI_HERTZ, CW_SOLVE_FORCES);
    const cw_wheelrail_patch pe = patch0(e), pf = patch0(f);
    const double mu_n = 0.3 * pe.Fn;
    assert_close(pf.Fn, pe.Fn, 0, 0.03 * mu_n);
    assert_close(pf.Fx, pe.Fx, 0, 0.03 * mu_n);
    assert_close(pf.Fs, pe.Fs, 0, 0.03 * mu_n);
    assert_close(pf.Fz_track, 1e4, 1e-6, 0);
    cw_result r;
    cw_result_init(&r);
    assert_int_equal(cw_solver_get_result(cw_wheelrail_patch_solver(f, 0), &r), CW_OK);
    assert_int_equal(r.model, CW_MODEL_FASTSIM);
    assert_int_equal(cw_solver_get_result(cw_wheelrail_patch_solver(e, 0), &r), CW_OK);
    assert_int_equal(r.model, CW_MODEL_EXACT);
    /* CW_SOLVE_FORCES: no work map, and no wear */
    const size_t n = (size_t)pf.field_nx * (size_t)pf.field_ny;
    double* v = malloc(n * sizeof *v);
    assert_int_equal(cw_wheelrail_get_patch_field(f, 0, CW_FIELD_PZ, v, n), CW_OK);
    assert_int_equal(cw_wheelrail_get_patch_field(f, 0, CW_FIELD_WORK_CONSISTENT, v, n), CW_ERR_NO_WORK);
    cw_wear_params law;
    cw_wear_params_init(&law);
    cw_wear_profile* rail = profile_grid();
    assert_int_equal(cw_wheelrail_add_wear(f, &law, 1.0, rail, NULL, NULL), CW_ERR_NO_WORK);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    assert_int_equal(cw_wear_profile_get_totals(rail, &t), CW_OK);
    assert_int_equal((int)t.adds, 0);
    free(v);
    cw_wear_profile_destroy(rail);
    cw_wheelrail_destroy(e);
    cw_wheelrail_destroy(f);
}

/* Least distance from (y, z) to the polyline through the points. */
static double distance_to(const double* py, const double* pz, size_t n, double y, double z)
{
    double best = INFINITY;
    for (size_t k = 0; k + 1 < n; ++k) {
        const double ey = py[k + 1] - py[k], ez = pz[k + 1] - pz[k], len2 = ey * ey + ez * ez;
        double t = len2 > 0 ? ((y - py[k]) * ey + (z - pz[k]) * ez) / len2 : 0.0;
        t = t < 0 ? 0 : t > 1 ? 1 : t;
        const double dy = py[k] + t * ey - y, dz = pz[k] + t * ez - z;
        best = fmin(best, sqrt(dy * dy + dz * dz));
    }
    return best;
}

/* The profiles where the position puts them: the contact reference point
 * (track coordinates) lies on the rail's surface, and the wheel's profile
 * passes it within the patch's approach (the rigid overlap at the height
 * found), on both sides. */
static void profiles_meet_at_the_contact(void** state)
{
    (void)state;
    for (int side = CW_WHEELRAIL_RIGHT; side <= CW_WHEELRAIL_LEFT; ++side) {
        cw_wheelrail* w = solved(side, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FORCES);
        const cw_wheelrail_patch p = patch0(w);
        size_t n = 0;
        assert_int_equal(cw_wheelrail_get_profile(w, CW_WHEELRAIL_RAIL, NULL, NULL, 0, &n), CW_ERR_BUFFER_TOO_SMALL);
        assert_true(n > 100);
        double* y = malloc(n * sizeof *y);
        double* z = malloc(n * sizeof *z);
        size_t got = 0;
        assert_int_equal(cw_wheelrail_get_profile(w, CW_WHEELRAIL_RAIL, y, z, n, &got), CW_OK);
        assert_int_equal((int)got, (int)n);
        assert_true(distance_to(y, z, n, p.y_contact, p.z_contact) < 1e-6);
        free(y), free(z);
        assert_int_equal(cw_wheelrail_get_profile(w, CW_WHEELRAIL_WHEEL, NULL, NULL, 0, &n), CW_ERR_BUFFER_TOO_SMALL);
        y = malloc(n * sizeof *y);
        z = malloc(n * sizeof *z);
        assert_int_equal(cw_wheelrail_get_profile(w, CW_WHEELRAIL_WHEEL, y, z, n, &got), CW_OK);
        const double d = distance_to(y, z, n, p.y_contact, p.z_contact);
        assert_true(d <= p.approach + 2e-6);
        free(y), free(z);
        assert_int_equal(cw_wheelrail_get_profile(w, 7, NULL, NULL, 0, &n), CW_ERR_UNKNOWN_OPTION);
        assert_non_null(strstr(cw_wheelrail_last_error(w), "which = 7"));
        assert_int_equal(cw_wheelrail_get_profile(w, CW_WHEELRAIL_RAIL, NULL, NULL, 0, NULL), CW_ERR_NULL_POINTER);
        cw_wheelrail_destroy(w);
    }
}

static void errors_name_their_input(void** state)
{
    (void)state;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p);
    cw_wheelrail* w = NULL;
    char msg[256];
    p.model = CW_MODEL_CALIBRATED;
    assert_int_equal(cw_wheelrail_create(&p, rail_file, wheel_file, &w, msg, sizeof msg), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(msg, "params->model = 2"));
    cw_wheelrail_params_init(&p);
    p.normal_method = 5;
    assert_int_equal(cw_wheelrail_create(&p, rail_file, wheel_file, &w, msg, sizeof msg), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(msg, "params->normal_method = 5"));
    cw_wheelrail_params_init(&p);
    p.solve_mode = -1;
    assert_int_equal(cw_wheelrail_create(&p, rail_file, wheel_file, &w, msg, sizeof msg), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(msg, "params->solve_mode = -1"));
    assert_null(w);

    cw_wheelrail_params_init(&p);
    assert_int_equal(cw_wheelrail_create(&p, rail_file, wheel_file, &w, msg, sizeof msg), CW_OK);
    double v[4];
    int s[4];
    cw_wear_params law;
    cw_wear_params_init(&law);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_PZ, v, 4), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_wheelrail_get_patch_state(w, 0, s, 4), CW_ERR_NO_SOLUTION);
    assert_int_equal(cw_wheelrail_add_wear(w, &law, 1.0, NULL, NULL, NULL), CW_ERR_NO_SOLUTION);
    assert_null(cw_wheelrail_patch_solver(w, 0));
    assert_null(cw_wheelrail_patch_solver(NULL, 0));
    assert_int_equal(cw_wheelrail_get_patch_field(NULL, 0, CW_FIELD_PZ, v, 4), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wheelrail_add_wear(NULL, &law, 1.0, NULL, NULL, NULL), CW_ERR_NULL_POINTER);
    cw_wheelrail_destroy(w);

    w = solved(CW_WHEELRAIL_RIGHT, CW_MODEL_EXACT, CW_NORMAL_EXACT, CW_SOLVE_FULL);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_PZ, NULL, 4), CW_ERR_NULL_POINTER);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 0, CW_FIELD_PZ, v, 4), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 0, 99, v, 4), CW_ERR_UNKNOWN_OPTION);
    assert_int_equal(cw_wheelrail_get_patch_field(w, 3, CW_FIELD_PZ, v, 4), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_wheelrail_last_error(w), "k = 3"));
    assert_int_equal(cw_wheelrail_get_patch_state(w, 0, s, 4), CW_ERR_BUFFER_TOO_SMALL);
    assert_int_equal(cw_wheelrail_add_wear(w, NULL, 1.0, NULL, NULL, NULL), CW_ERR_NULL_POINTER);
    cw_wear_profile* g = profile_grid();
    assert_int_equal(cw_wheelrail_add_wear(w, &law, 1.0, g, g, NULL), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_wheelrail_last_error(w), "same profile accumulator"));
    assert_int_equal(cw_wheelrail_add_wear(w, &law, -1.0, g, NULL, NULL), CW_ERR_INVALID_INPUT);
    assert_non_null(strstr(cw_wheelrail_last_error(w), "passes"));
    law.law = 9;
    assert_int_equal(cw_wheelrail_add_wear(w, &law, 1.0, g, NULL, NULL), CW_ERR_UNKNOWN_OPTION);
    assert_non_null(strstr(cw_wheelrail_last_error(w), "law = 9"));
    cw_wear_result bad;
    bad.struct_size = 0;
    cw_wear_params_init(&law);
    assert_int_equal(cw_wheelrail_add_wear(w, &law, 1.0, g, NULL, &bad), CW_ERR_STRUCT_SIZE);
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    assert_int_equal(cw_wear_profile_get_totals(g, &t), CW_OK);
    assert_int_equal((int)t.adds, 0); /* no failed call added anything */
    cw_wear_profile_destroy(g);
    cw_wheelrail_destroy(w);
}

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(fields_add_up_to_the_patch),
        cmocka_unit_test(wear_lands_where_documented),
        cmocka_unit_test(wear_of_two_patches),
        cmocka_unit_test(sides_mirror),
        cmocka_unit_test(rail_offset_mirrors_with_the_gauge),
        cmocka_unit_test(fast_model_follows_exact),
        cmocka_unit_test(profiles_meet_at_the_contact),
        cmocka_unit_test(errors_name_their_input),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : NULL);
}
