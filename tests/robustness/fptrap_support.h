/* Floating-point traps for the FP-trap tests (C and C++): turn on the traps
 * a legacy host turns on (gfortran -ffpe-trap=invalid,zero,overflow,denormal),
 * name the case being solved when one fires, and the sweep of contacts and
 * grids both tests solve. doc/reference/guarantees.md: hosts that trap
 * floating-point exceptions are safe. */
#ifndef CREEPWORK_FPTRAP_SUPPORT_H
#define CREEPWORK_FPTRAP_SUPPORT_H

#ifndef _GNU_SOURCE
#define _GNU_SOURCE /* feenableexcept */
#endif
#include <fenv.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>
#if defined(__x86_64__)
#include <xmmintrin.h>
#define FPTRAP_HAVE_MXCSR 1
#else
#define FPTRAP_HAVE_MXCSR 0
#endif

/* CTest's SKIP_RETURN_CODE (tests/robustness/CMakeLists.txt). */
#define FPTRAP_SKIP 77

/* What is being solved, printed if a trap fires. */
static char fptrap_case[512];

static void fptrap_handler(int sig, siginfo_t* info, void* context)
{
    (void)sig;
    (void)context;
    /* Async-signal-safe: write(2) only. si_code: FPE_FLTINV 7, FPE_FLTDIV 3,
     * FPE_FLTOVF 4; Linux reports a denormal operand as FPE_FLTUND 5. */
    static const char head[] = "SIGFPE (si_code ";
    char code[4] = {(char)('0' + info->si_code % 10), ')', ' ', 0};
    if (write(2, head, sizeof head - 1) < 0 || write(2, code, 3) < 0 ||
        write(2, fptrap_case, strlen(fptrap_case)) < 0 || write(2, "\n", 1) < 0) {
    }
    _exit(1);
}

/* Traps on: invalid, divide-by-zero, overflow, and on x86 denormal operand
 * (MXCSR DM, which glibc's feenableexcept does not offer); flags cleared.
 * Returns 0 if this platform cannot trap them (the test then skips). */
static int fptrap_on(void)
{
    feclearexcept(FE_ALL_EXCEPT);
#if defined(__GLIBC__)
    if (feenableexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW) < 0) return 0;
#else
    return 0;
#endif
#if FPTRAP_HAVE_MXCSR
    _mm_setcsr(_mm_getcsr() & ~((1u << 8) | 0x3fu)); /* unmask DM, clear flags */
    return 1;
#else
    return 0;
#endif
}

/* fptrap_on() with the handler that names the case installed first. */
static int fptrap_enable(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_sigaction = fptrap_handler;
    sa.sa_flags = SA_SIGINFO;
    sigaction(SIGFPE, &sa, NULL);
    return fptrap_on();
}

/* Traps off, flags cleared. The tests turn traps on only around library
 * calls where their own code would consume a subnormal (printf of 1e-310). */
static void fptrap_disable(void)
{
#if defined(__GLIBC__)
    fedisableexcept(FE_ALL_EXCEPT);
#endif
#if FPTRAP_HAVE_MXCSR
    _mm_setcsr(_mm_getcsr() | (1u << 8));
#endif
    feclearexcept(FE_ALL_EXCEPT);
}

/* Exception flags other than inexact raised since the last clear. */
static int fptrap_flags(void)
{
    int flags = fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW | FE_UNDERFLOW);
#if FPTRAP_HAVE_MXCSR
    if (_mm_getcsr() & (1u << 1)) flags |= 1 << 30; /* DE: a denormal operand */
#endif
    return flags;
}

/* ------------------------------------------------------------- the sweep */

/* Grids: both kinds, from one element to 40 x 40 and CONTACT's 44 x 44 box,
 * odd and even counts (padding strips in every kernel), strip counts that
 * leave 1..7 lanes of the widest vector empty. */
typedef struct {
    int kind, nx, ny;
    double box_scale;
} fptrap_grid;

static const fptrap_grid fptrap_grids[] = {
    {0, 1, 1, 1.0},  {0, 2, 3, 1.0},  {0, 5, 5, 1.0},   {0, 7, 7, 1.0},   {0, 20, 20, 1.0},
    {0, 33, 9, 1.0}, {0, 40, 40, 1.0}, {1, 1, 1, 1.0},  {1, 3, 2, 1.0},   {1, 14, 16, 1.0},
    {1, 20, 20, 1.0}, {1, 33, 9, 1.5}, {1, 44, 44, 1.1},
};
#define FPTRAP_GRIDS ((int)(sizeof fptrap_grids / sizeof fptrap_grids[0]))

/* Creepage magnitudes from zero to far beyond saturation (the practical
 * range: the core itself makes no subnormal number there), then absurd ones
 * that only the C ABI's floating-point mode makes safe (flushed to zero);
 * spins phi*a from zero to 100. Each contact is built by fptrap_contact(k)
 * from an index k < FPTRAP_CONTACTS (practical) or FPTRAP_ALL_CONTACTS. */
static const double fptrap_creepages[] = {0.0,  1e-100, 1e-9, 1e-6, 1e-4, 1e-3,  3e-3,
                                          1e-2, 0.1,    1.0,  1e6,  /* absurd: */ 1e100, 1e-300};
#define FPTRAP_N_PRACTICAL 11
static const double fptrap_spins_a[] = {0.0, 1e-12, 0.01, 1.0, -10.0, 100.0};
#define FPTRAP_N_CREEPAGES ((int)(sizeof fptrap_creepages / sizeof fptrap_creepages[0]))
#define FPTRAP_N_SPINS ((int)(sizeof fptrap_spins_a / sizeof fptrap_spins_a[0]))
/* creepage x spin x (xi, eta, both on a 2:1 patch, both on a 1:3 patch) x
 * pressure x rolling direction x (plain FASTSIM, CONTACT's options) */
#define FPTRAP_VARIANTS (FPTRAP_N_SPINS * 4 * 2 * 2 * 2)
#define FPTRAP_CONTACTS (FPTRAP_N_PRACTICAL * FPTRAP_VARIANTS)
#define FPTRAP_ALL_CONTACTS (FPTRAP_N_CREEPAGES * FPTRAP_VARIANTS)

typedef struct {
    double a, b, xi_x, xi_y, phi;
    int pressure, rolling_direction, contact_options;
} fptrap_contact_t;

/* Steel, mu = 0.3, N = 80 kN, a = 6 mm unless the shape varies it. */
static fptrap_contact_t fptrap_contact(int k)
{
    fptrap_contact_t c;
    const double xi = fptrap_creepages[k / FPTRAP_VARIANTS];
    k %= FPTRAP_VARIANTS;
    const double phi_a = fptrap_spins_a[k % FPTRAP_N_SPINS];
    k /= FPTRAP_N_SPINS;
    const int shape = k % 4;
    k /= 4;
    c.a = 6e-3;
    c.b = shape == 2 ? 3e-3 : shape == 3 ? 18e-3 : 6e-3;
    c.xi_x = shape == 1 ? 0.0 : xi;
    c.xi_y = shape == 0 ? 0.0 : -0.5 * xi;
    c.phi = phi_a / c.a;
    c.pressure = k % 2;
    k /= 2;
    c.rolling_direction = k % 2 ? -1 : 1;
    k /= 2;
    c.contact_options = k % 2;
    return c;
}

/* Physical magnitudes from micro-contacts to the absurdly large (the
 * practical range: every combination, in SI units). */
static const double fptrap_sizes[] = {1e-9, 1e-6, 6e-3, 1.0, 1e3};
static const double fptrap_loads[] = {0.0, 1e-12, 1e-3, 80e3, 1e9, 1e15};
static const double fptrap_moduli[] = {1e3, 1e6, 82e9, 1e15};
static const double fptrap_frictions[] = {0.0, 1e-6, 0.3, 10.0};

#endif
