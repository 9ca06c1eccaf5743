/* A rail profile worn by a hunting wheelset over 10^4 axle passages, from the
 * profiles (doc/wheelrail.md, "Rail wear from a hunting wheelset").
 *
 * One wheel (the right one) of a wheelset that hunts kinematically along
 * the track: lateral shift y = A sin(theta), yaw psi = dy/dx = A k cos(theta)
 * with k = 2 pi / wavelength, rolling at speed V with the pitch rate of the
 * nominal radius, vertical force Fz. A given section of rail meets the
 * passing wheelsets at every phase theta alike, so one axle passage wears
 * it by the mean over theta of the wear at each phase: the phases
 * theta_m = 2 pi m / M, each with passes / M.
 *
 * The 10^4 passages run in steps. Per step: the wheel/rail handle is made
 * from the current rail profile (written as a table of y z lines in mm,
 * OUT_DIR/rail_profile_step.txt) and the wheel's file, every phase
 * is solved with the vertical force prescribed (CW_MODEL_EXACT by default,
 * "fast" for CW_MODEL_FASTSIM with the semi-Hertzian normal problem), its
 * wear (USFD law on the energy-consistent work map) is added to the rail's
 * profile grid (cw_wheelrail_add_wear), and the rail's top is lowered by the
 * step's vertical depth (cw_wear_profile_update, volume-conserving
 * smoothing). The rail's head is resampled on the grid nodes; the gauge face
 * beyond the grid keeps its points.
 *
 * Usage: rail_wear_hunting DATA_DIR [OUT_DIR] [fast]
 *   DATA_DIR holds MBench_UIC60_v3.prr and MBench_S1002_v3.prw (the
 *   Manchester benchmark's profiles, tests/wheelrail/data; the rail's points
 *   are read here, the wheel's by the library); OUT_DIR gets
 *   rail_wear_hunting.csv (y, initial z, worn z in mm, worn depth in um) and
 *   rail_wear_contacts.csv (every step's contact points).
 * Prints the worn cross-section against the wear laws' volume (they must
 * agree: the update conserves volume) and the deepest wear, and fails
 * (exit 1) if they disagree by more than 1e-6 or the wear lies outside the
 * band the contact points swept. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <creepwork/creepwork.h>

static const double kPi = 3.14159265358979323846;
static const double kAmplitude = 5e-3;   /* [m] hunting amplitude */
static const double kWavelength = 15.0;  /* [m] */
static const double kSpeed = 30.0;       /* [m/s] */
static const double kRadius = 0.46;      /* [m] nominal rolling radius (the benchmark's) */
static const double kLoad = 60e3;        /* [N] vertical wheel force (12 t axle) */
static const double kPasses = 1e4;       /* axle passages */
enum { kSteps = 10, kPhases = 16 };
static const double kNodeLo = -40e-3, kNodeHi = 27e-3, kNodeStep = 0.25e-3; /* [m] rail head grid */
static const double kSmoothing = 0.5e-3; /* [m] of the profile update */
static const double kElement = 0.5e-3;   /* [m] patch elements: about 500 in a 60 kN patch */

/* Points of a SIMPACK profile (two numbers per line between point.begin
 * and point.end), in its file units (mm here). */
static int read_points(const char* path, double** y, double** z, int* n)
{
    FILE* f = fopen(path, "r");
    if (!f) {
        fprintf(stderr, "rail_wear_hunting: cannot open %s\n", path);
        return 1;
    }
    char line[512];
    int inside = 0, cap = 0;
    *n = 0;
    *y = *z = NULL;
    while (fgets(line, sizeof line, f)) {
        if (strstr(line, "point.begin")) inside = 1;
        else if (strstr(line, "point.end")) inside = 0;
        double a, b;
        if (!inside || sscanf(line, "%lf %lf", &a, &b) != 2) continue;
        if (*n == cap) {
            cap = cap ? 2 * cap : 256;
            *y = realloc(*y, cap * sizeof **y);
            *z = realloc(*z, cap * sizeof **z);
        }
        (*y)[*n] = a;
        (*z)[*n] = b;
        ++*n;
    }
    fclose(f);
    return *n < 4;
}

/* z at y on the polyline (y increasing where it is asked). */
static double z_at(const double* y, const double* z, int n, double at)
{
    for (int k = 1; k < n; ++k)
        if (y[k - 1] <= at && at <= y[k] && y[k] > y[k - 1])
            return z[k - 1] + (z[k] - z[k - 1]) * (at - y[k - 1]) / (y[k] - y[k - 1]);
    return NAN;
}

static int fail(const char* what, const char* message)
{
    fprintf(stderr, "rail_wear_hunting: %s: %s\n", what, message);
    return 1;
}

int main(int argc, char** argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: rail_wear_hunting DATA_DIR [OUT_DIR] [fast]\n");
        return 2;
    }
    const char* out_dir = argc > 2 ? argv[2] : ".";
    const int fast = argc > 3 && strcmp(argv[3], "fast") == 0;
    char path[1024];
    char wheel_file[1024], rail_table[1024];
    double *ry, *rz;
    int rn;
    snprintf(path, sizeof path, "%s/MBench_UIC60_v3.prr", argv[1]);
    if (read_points(path, &ry, &rz, &rn)) return fail(path, "no profile points");
    for (int k = 0; k < rn; ++k) ry[k] *= 1e-3, rz[k] *= 1e-3; /* mm -> m */
    snprintf(wheel_file, sizeof wheel_file, "%s/MBench_S1002_v3.prw", argv[1]);
    snprintf(rail_table, sizeof rail_table, "%s/rail_profile_step.txt", out_dir);

    /* The rail head on the grid nodes; the points outside it as they are. */
    const int nodes = (int)lround((kNodeHi - kNodeLo) / kNodeStep) + 1;
    double* s = malloc(nodes * sizeof *s);
    double* z0 = malloc(nodes * sizeof *z0);
    double* z = malloc(nodes * sizeof *z);
    double* depth = malloc(nodes * sizeof *depth);
    double* py = malloc((rn + nodes) * sizeof *py);
    double* pz = malloc((rn + nodes) * sizeof *pz);
    for (int k = 0; k < nodes; ++k) {
        s[k] = kNodeLo + k * kNodeStep;
        z0[k] = z[k] = z_at(ry, rz, rn, s[k]);
        if (isnan(z[k])) return fail("rail profile", "not a function of y over the head grid");
    }

    char msg[512];
    cw_wear_profile* rail_wear = NULL;
    if (cw_wear_profile_create(s, (size_t)nodes, &rail_wear, msg, sizeof msg)) return fail("grid", msg);
    cw_wear_params law;
    cw_wear_params_init(&law); /* USFD on the energy-consistent work map */
    law.rolling_speed = kSpeed;
    cw_wheelrail_params p;
    cw_wheelrail_params_init(&p); /* the benchmark's track and wheelset, steel */
    p.nominal_radius = kRadius;
    p.mu = 0.3;
    p.dx = p.ds = kElement;
    if (fast) {
        p.model = CW_MODEL_FASTSIM;
        p.normal_method = CW_NORMAL_SEMI_HERTZ;
    }
    snprintf(path, sizeof path, "%s/rail_wear_contacts.csv", out_dir);
    FILE* contacts = fopen(path, "w");
    if (!contacts) return fail(path, "cannot write");
    fprintf(contacts, "step,theta,y_ws_mm,yaw_mrad,patch,y_rail_mm,z_rail_mm,Fn_N,Fx_N,Fs_N,contact_angle_deg\n");

    double volume = 0.0, band_lo = 1.0, band_hi = -1.0, z_ws = 0.0;
    long solves = 0;
    const double k_wave = 2.0 * kPi / kWavelength, passes = kPasses / kSteps / kPhases;
    for (int step = 0; step < kSteps; ++step) {
        /* the profile: the gauge face below the grid, the head, the field side */
        int n = 0;
        for (int k = 0; k < rn && ry[k] < kNodeLo - 0.5 * kNodeStep; ++k) py[n] = ry[k], pz[n++] = rz[k];
        for (int k = 0; k < nodes; ++k) py[n] = s[k], pz[n++] = z[k];
        for (int k = 0; k < rn; ++k)
            if (ry[k] > kNodeHi + 0.5 * kNodeStep) py[n] = ry[k], pz[n++] = rz[k];
        FILE* table = fopen(rail_table, "w");
        if (!table) return fail(rail_table, "cannot write");
        for (int k = 0; k < n; ++k) fprintf(table, "%.9f %.9f\n", py[k] * 1e3, pz[k] * 1e3);
        fclose(table);
        cw_wheelrail* w = NULL;
        if (cw_wheelrail_create(&p, rail_table, wheel_file, &w, msg, sizeof msg)) return fail("wheel/rail", msg);
        cw_wear_profile_reset(rail_wear);
        for (int m = 0; m < kPhases; ++m) {
            const double theta = 2.0 * kPi * m / kPhases;
            cw_wheelrail_motion mo;
            cw_wheelrail_motion_init(&mo);
            mo.y = kAmplitude * sin(theta);
            mo.yaw = kAmplitude * k_wave * cos(theta);
            mo.z = z_ws;
            mo.vs = kSpeed;
            mo.vy = kSpeed * mo.yaw;                                  /* dy/dt = V dy/dx */
            mo.vyaw = -kSpeed * kAmplitude * k_wave * k_wave * sin(theta); /* d psi/dt */
            mo.vpitch = -kSpeed / kRadius;
            cw_wheelrail_totals t;
            cw_wheelrail_totals_init(&t);
            if (cw_wheelrail_solve(w, &mo, CW_WHEELRAIL_FORCE, kLoad, &t)) return fail("solve", cw_wheelrail_last_error(w));
            z_ws = t.z;
            ++solves;
            cw_wear_result r;
            cw_wear_result_init(&r);
            if (cw_wheelrail_add_wear(w, &law, passes, rail_wear, NULL, &r)) return fail("wear", cw_wheelrail_last_error(w));
            for (int k = 0; k < t.n_patches; ++k) {
                cw_wheelrail_patch q;
                cw_wheelrail_patch_init(&q);
                cw_wheelrail_get_patch(w, (size_t)k, &q);
                const double half = 0.5 * q.field_ny * q.field_ds;
                band_lo = fmin(band_lo, q.rail_profile_y - half);
                band_hi = fmax(band_hi, q.rail_profile_y + half);
                fprintf(contacts, "%d,%.6f,%.4f,%.4f,%d,%.4f,%.4f,%.1f,%.1f,%.1f,%.3f\n", step, theta,
                        mo.y * 1e3, mo.yaw * 1e3, k, q.rail_profile_y * 1e3, q.z_contact_rail * 1e3, q.Fn, q.Fx,
                        q.Fs, q.contact_angle * 180.0 / kPi);
            }
        }
        cw_wheelrail_destroy(w);
        cw_wear_profile_totals tot;
        cw_wear_profile_totals_init(&tot);
        cw_wear_profile_get_totals(rail_wear, &tot);
        if (tot.volume_lost > 1e-6 * tot.volume) return fail("wear", "worn volume fell outside the head grid");
        volume += tot.volume;
        /* z grows downwards: the worn top moves down by the vertical depth */
        cw_wear_profile_get_depth(rail_wear, CW_WEAR_DEPTH_HEIGHT, depth, (size_t)nodes);
        for (int k = 0; k < nodes; ++k) z[k] = -z[k];
        if (cw_wear_profile_update(s, z, depth, (size_t)nodes, kSmoothing, z, (size_t)nodes, msg, sizeof msg))
            return fail("update", msg);
        for (int k = 0; k < nodes; ++k) z[k] = -z[k];
    }
    fclose(contacts);

    /* The worn cross-section between the profiles (vertical depth x cell
     * width; every node's cell is kNodeStep wide) against the laws' volume
     * (depth x strip width in the contact plane, summed over the passes):
     * equal, as the vertical depth spreads a strip's worn area over its
     * width along y. */
    double area = 0.0, deepest = 0.0, at = 0.0;
    for (int k = 0; k < nodes; ++k) {
        const double d = z[k] - z0[k];
        area += d * kNodeStep;
        if (d > deepest) deepest = d, at = s[k];
    }
    snprintf(path, sizeof path, "%s/rail_wear_hunting.csv", out_dir);
    FILE* out = fopen(path, "w");
    if (!out) return fail(path, "cannot write");
    fprintf(out, "y_mm,z_initial_mm,z_worn_mm,depth_um\n");
    for (int k = 0; k < nodes; ++k)
        fprintf(out, "%.3f,%.6f,%.6f,%.4f\n", s[k] * 1e3, z0[k] * 1e3, z[k] * 1e3, (z[k] - z0[k]) * 1e6);
    fclose(out);

    printf("rail worn by a hunting wheelset (%s model): A = %g mm, wavelength %g m, V = %g m/s, Fz = %g kN\n",
           fast ? "fast" : "exact", kAmplitude * 1e3, kWavelength, kSpeed, kLoad * 1e-3);
    printf("%g axle passages in %d steps of %d phases: %ld contact solves\n", kPasses, kSteps, kPhases, solves);
    printf("worn cross-section %.4g mm^2 (wear laws: %.4g mm^2)\n", area * 1e6, volume * 1e6);
    printf("deepest wear %.2f um at y = %.2f mm; contacts swept y = %.2f .. %.2f mm\n", deepest * 1e6, at * 1e3,
           band_lo * 1e3, band_hi * 1e3);
    const int conserved = fabs(area - volume) <= 1e-6 * volume;
    const int located = deepest > 0.0 && at >= band_lo && at <= band_hi;
    printf("%s\n", conserved && located ? "volume conserved, wear where the wheel ran"
                                        : "FAILED: volume not conserved or wear outside the contact band");
    free(ry), free(rz), free(s), free(z0), free(z), free(depth), free(py), free(pz);
    cw_wear_profile_destroy(rail_wear);
    return conserved && located ? 0 : 1;
}
