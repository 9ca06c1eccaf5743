// libFuzzer target for the whole C ABI. Arbitrary bytes are
// decoded into grids, parameters (NaN, Inf, negative, huge, denormal, odd
// struct sizes and enumerations), buffer lengths (short, exact, long, NULL)
// and a sequence of calls: create, solve, get result/fields/state/profile,
// accumulator create/add/get/reset/destroy, batch create/solve/destroy,
// the free functions, destroy and reuse after errors, and the wear calls
// (cw_wear_* on the session's solver, cw_wear_profile_* with decoded nodes,
// strips and placements, state round trips, the update helper). It checks the
// contract of creepwork.h after every call:
//  - every status is one of the listed codes, and it is CW_OK exactly when
//    no documented error applies;
//  - on error nothing is written (sentinels), the handle keeps a message
//    and holds no solution after a failed solve;
//  - on success everything is finite, |p| <= mu pz on every element,
//    |F| <= sum mu pz area, counts match the state map, and with
//    work_flags == 0 the energy-consistent map is >= 0 and sums to W_macro
//    (1e-9 relative); batch results equal single solves bit for bit.
// A violation prints what failed and aborts, which libFuzzer reports.
// Grids stay small (<= 24 x 24) except occasional limit checks (one side
// up to 1001, the other tiny), so that an execution takes well under 1 ms;
// the exact model runs on at most 400 elements (a few ms); one
// solve in ten is the calibrated model's.
//
// Built two ways: with libFuzzer (CREEPWORK_BUILD_FUZZ, clang) and, with any
// compiler, as fuzz_capi_replay (replay_main.cpp), which runs the committed
// corpus in every CTest build.
#include <cfloat>
#include <climits>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "creepwork/creepwork.h"

namespace {

#define FUZZ_CHECK(cond)                                                                 \
    do {                                                                                 \
        if (!(cond)) {                                                                   \
            std::fprintf(stderr, "fuzz_capi: invariant failed at line %d: %s\n", __LINE__, \
                         #cond);                                                         \
            std::abort();                                                                \
        }                                                                                \
    } while (0)

constexpr unsigned char kSentinel = 0xA5;
constexpr int kMaxOps = 16;
constexpr size_t kGuard = 4; // sentinel elements after every buffer

// ------------------------------------------------------------ input decoding

class Bytes {
public:
    Bytes(const uint8_t* data, size_t size) : p_(data), n_(size) {}
    bool empty() const { return n_ == 0; }
    uint8_t u8()
    {
        if (n_ == 0) return 0;
        --n_;
        return *p_++;
    }
    uint16_t u16() { return static_cast<uint16_t>(u8() | (u8() << 8)); }
    uint32_t u32() { return static_cast<uint32_t>(u16()) | (static_cast<uint32_t>(u16()) << 16); }
    uint64_t u64() { return static_cast<uint64_t>(u32()) | (static_cast<uint64_t>(u32()) << 32); }

    // Any double, biased towards values that matter: physical magnitudes of
    // either sign, specials, limits, and raw bit patterns.
    double number()
    {
        static const double special[] = {
            0.0,     -0.0,     1.0,      -1.0,    0.5,      NAN,      INFINITY, -INFINITY,
            DBL_MAX, -DBL_MAX, DBL_MIN,  -DBL_MIN, 4.9e-324, 1e-300,  1e300,    1e-12,
            1e100,   1e155,    1e-155,   1e3,     1e-3,     100.0,    0.28,     82e9,
            6e-3,    80e3,     0.3,      1e200,   1.0000001e3, 9.999999e-4, 0.5000001, -1e-300};
        const uint8_t how = u8();
        if (how < 128) {
            const double mantissa = 1.0 + u16() / 65536.0;
            const int exponent = static_cast<int>(u8() % 64) - 32;
            const double v = mantissa * std::pow(10.0, exponent);
            return how & 1 ? -v : v;
        }
        if (how < 224) return special[how % (sizeof special / sizeof special[0])];
        double v;
        const uint64_t bits = u64();
        std::memcpy(&v, &bits, sizeof v);
        return v;
    }

    int small_int()
    {
        const uint8_t how = u8();
        if (how < 240) return static_cast<int8_t>(how) % 4; // -3 .. 3, mostly valid
        static const int special[] = {INT_MIN, INT_MAX, -1, 2, 100, 1 << 20};
        if (how < 246) return special[how - 240];
        return static_cast<int>(u32());
    }

    template <class T>
    size_t struct_size()
    {
        const uint8_t how = u8();
        if (how < 232) return sizeof(T);
        static const size_t special[] = {0, 1, 7, 8, 16, sizeof(T) - 8, sizeof(T) + 8,
                                         (size_t)1 << 16, ((size_t)1 << 16) + 1, SIZE_MAX,
                                         sizeof(T) / 2, 24};
        return special[how % (sizeof special / sizeof special[0])];
    }

private:
    const uint8_t* p_;
    size_t n_;
};

// v * k wrapped to int (no signed overflow in the fuzzer itself).
int scaled(int v, unsigned k)
{
    const uint32_t u = static_cast<uint32_t>(v) * k;
    int out;
    std::memcpy(&out, &u, sizeof out);
    return out;
}

// FUZZ_CAPI_VERBOSE=1 prints every call's inputs, to read a crash file.
bool verbose()
{
    static const bool on = std::getenv("FUZZ_CAPI_VERBOSE") != nullptr;
    return on;
}

void print_params(const char* what, const cw_params& p, int mode)
{
    if (!verbose()) return;
    std::fprintf(stderr,
                 "%s: size=%zu a=%.17g b=%.17g N=%.17g mu=%.17g flex=%d pressure=%d G=%.17g "
                 "nu=%.17g L=(%.17g, %.17g, %.17g) xi=(%.17g, %.17g) phi=%.17g dir=%d mode=%d\n",
                 what, p.struct_size, p.a, p.b, p.normal_force, p.mu, p.flexibility, p.pressure,
                 p.G, p.nu, p.L1, p.L2, p.L3, p.xi_x, p.xi_y, p.phi, p.rolling_direction, mode);
}

bool known_status(int st) { return st >= CW_OK && st < CW_STATUS_END_; }

bool untouched(const void* p, size_t bytes)
{
    const auto* c = static_cast<const unsigned char*>(p);
    for (size_t k = 0; k < bytes; ++k)
        if (c[k] != kSentinel) return false;
    return true;
}

bool all_finite(const double* v, size_t n)
{
    for (size_t k = 0; k < n; ++k)
        if (!std::isfinite(v[k])) return false;
    return true;
}

bool result_finite(const cw_result& r)
{
    const double v[] = {r.Fx,  r.Fy,  r.Mz,  r.W_macro, r.W_micro_paper, r.K, r.W_consistent,
                        r.balance_factor, r.adhesion_fraction, r.a, r.b, r.L1, r.L2, r.L3,
                        r.C11, r.C22, r.C23, r.C33, r.profile_max_diff, r.profile_rms_diff};
    return all_finite(v, sizeof v / sizeof v[0]);
}

// A message owned by a handle: non-NULL and NUL-terminated within reason.
void check_message(const char* m, bool must_have_text)
{
    FUZZ_CHECK(m != nullptr);
    const size_t len = strnlen(m, 4096);
    FUZZ_CHECK(len < 4096);
    if (must_have_text) FUZZ_CHECK(len > 0);
}

// A caller message buffer of random length inside a larger sentinel block.
struct MessageBuffer {
    char block[320];
    size_t len;
    char* ptr;
    explicit MessageBuffer(Bytes& in)
    {
        std::memset(block, kSentinel, sizeof block);
        const uint8_t how = in.u8();
        len = how < 200 ? how : (how < 230 ? 0 : 300);
        ptr = how >= 250 ? nullptr : block;
    }
    void check(int status) const
    {
        if (!ptr || len == 0) {
            FUZZ_CHECK(untouched(block, sizeof block));
            return;
        }
        const size_t n = strnlen(block, len);
        FUZZ_CHECK(n < len);                                    // NUL within len
        FUZZ_CHECK(untouched(block + n + 1, sizeof block - n - 1)); // nothing else written
        if (status == CW_OK) FUZZ_CHECK(n == 0);
        else if (len > 1) FUZZ_CHECK(n > 0);
    }
};

cw_grid decode_grid(Bytes& in)
{
    cw_grid g;
    cw_grid_init(&g);
    g.struct_size = in.struct_size<cw_grid>();
    const uint8_t kind = in.u8();
    g.kind = kind < 248 ? kind % 2 : in.small_int();
    auto cells = [&]() {
        const uint8_t how = in.u8();
        if (how < 244) return 1 + how % 24;
        static const int special[] = {0, -1, 1000, 1001, INT_MIN, INT_MAX, 999, 64, 2, 500, 3, 1};
        return special[how - 244];
    };
    g.nx = cells();
    g.ny = cells();
    // Limit checks stay cheap: a long side goes with a short one.
    if (g.nx > 64 && g.ny > 4) g.ny = 1 + g.ny % 4;
    if (g.ny > 64 && g.nx > 4) g.nx = 1 + g.nx % 4;
    const uint8_t scale = in.u8();
    g.box_scale = scale < 200 ? 1.0 + scale / 64.0 : in.number();
    return g;
}

bool grid_valid(const cw_grid& g)
{
    if (g.struct_size < sizeof(size_t) || g.struct_size > ((size_t)1 << 16)) return false;
    // Fields beyond a short struct_size take their defaults (20 x 20 strips).
    cw_grid d;
    cw_grid_init(&d);
    std::memcpy(&d, &g, std::min(g.struct_size, sizeof d));
    if (d.kind != CW_GRID_KALKER_STRIPS && d.kind != CW_GRID_UNIFORM) return false;
    if (d.nx < 1 || d.nx > CW_MAX_GRID_CELLS || d.ny < 1 || d.ny > CW_MAX_GRID_CELLS) return false;
    if (d.kind == CW_GRID_UNIFORM && !(d.box_scale >= 1.0 && d.box_scale <= CW_MAX_BOX_SCALE))
        return false;
    return true;
}

cw_params decode_params(Bytes& in, size_t struct_size)
{
    cw_params p;
    cw_params_init(&p);
    p.struct_size = struct_size;
    const uint16_t mask = in.u16();
    double* doubles[] = {&p.a,  &p.b,  &p.normal_force, &p.mu,   &p.G,   &p.nu,
                         &p.L1, &p.L2, &p.L3,           &p.xi_x, &p.xi_y, &p.phi};
    // Creepages are usually set, the rest usually keeps the valid default.
    for (int k = 0; k < 12; ++k)
        if (mask & (1u << k)) *doubles[k] = in.number();
    if (mask & (1u << 12)) p.flexibility = in.small_int();
    if (mask & (1u << 13)) p.pressure = in.small_int();
    if (mask & (1u << 14)) p.rolling_direction = in.small_int();
    if (mask & (1u << 15)) p.flexibility = CW_FLEX_GIVEN, p.L1 = p.L2 = p.L3 = 1e-11;
    return p;
}

// ------------------------------------------------------------- the session

struct Session {
    cw_solver* solver = nullptr;
    cw_grid grid{};      // of the solver
    size_t cells = 0;    // nx * ny
    int ny = 0;
    bool solved = false; // shadow of has_solution()
    bool full = false;   // shadow of has_work()
    cw_result last{};    // result of the last successful solve
    cw_accumulator* acc = nullptr;
    cw_grid acc_grid{};
    cw_batch* batch = nullptr;
    cw_grid batch_grid{};
    std::vector<double> buf, pz, area, px, py;
    std::vector<int> ibuf;

    ~Session()
    {
        cw_solver_destroy(solver);
        cw_accumulator_destroy(acc);
        cw_batch_destroy(batch);
    }
};

bool same_grid(const cw_grid& a, const cw_grid& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny &&
           (a.kind == CW_GRID_KALKER_STRIPS || a.box_scale == b.box_scale);
}

// Effective grid (defaults beyond a short struct_size).
cw_grid effective_grid(const cw_grid& g)
{
    cw_grid d;
    cw_grid_init(&d);
    std::memcpy(&d, &g, std::min(g.struct_size, sizeof d));
    d.struct_size = sizeof d;
    return d;
}

void fetch(const cw_solver* s, int field, std::vector<double>& out, size_t n)
{
    out.assign(n, 0.0);
    FUZZ_CHECK(cw_solver_get_field(s, field, out.data(), n) == CW_OK);
}

// The physical invariants of a successful solve.
void check_solution(Session& z, const cw_params& p_in, int mode, const cw_result& r)
{
    FUZZ_CHECK(result_finite(r));
    cw_params p;
    cw_params_init(&p);
    std::memcpy(&p, &p_in, std::min(p_in.struct_size, sizeof p));
    const size_t n = z.cells;
    fetch(z.solver, CW_FIELD_PZ, z.pz, n);
    fetch(z.solver, CW_FIELD_AREA, z.area, n);
    fetch(z.solver, CW_FIELD_PX, z.px, n);
    fetch(z.solver, CW_FIELD_PY, z.py, n);
    // Rounding slack: relative, plus absolute for subnormal pressures (a
    // subnormal load gives pz with an absolute error of a few 1e-324, which
    // mu multiplies: mu pz and the traction mu p0 shape then differ).
    // A subnormal input reads as 0 inside the library (denormals-are-zero,
    // capi/capi_fp_mode.hpp): a mu of -4.6e-311 is the mu = 0 it solves.
    const double mu = std::fpclassify(p.mu) == FP_SUBNORMAL ? 0.0 : p.mu;
    const double slack = mu * 1e-321 + 1e-300;
    double bound = 0.0, total_area = 0.0;
    for (size_t k = 0; k < n; ++k) {
        FUZZ_CHECK(std::isfinite(z.pz[k]) && z.pz[k] >= 0.0);
        FUZZ_CHECK(std::isfinite(z.area[k]) && z.area[k] >= 0.0);
        const double local = mu * z.pz[k];
        if (!(std::hypot(z.px[k], z.py[k]) <= local * (1.0 + 1e-12) + slack) && verbose())
            std::fprintf(stderr, "element %zu: p = (%.17g, %.17g), mu pz = %.17g\n", k, z.px[k],
                         z.py[k], local);
        FUZZ_CHECK(std::hypot(z.px[k], z.py[k]) <= local * (1.0 + 1e-12) + slack);
        bound += local * z.area[k];
        total_area += z.area[k];
    }
    // bound may overflow to Inf (mu N beyond DBL_MAX with finite forces):
    // then the check holds trivially.
    FUZZ_CHECK(std::hypot(r.Fx, r.Fy) <= bound * (1.0 + 1e-12) + slack * (1.0 + total_area));
    for (int f : {CW_FIELD_X, CW_FIELD_Y, CW_FIELD_MZ}) {
        fetch(z.solver, f, z.buf, n);
        FUZZ_CHECK(all_finite(z.buf.data(), n));
    }
    z.ibuf.assign(n, -1);
    FUZZ_CHECK(cw_solver_get_state(z.solver, z.ibuf.data(), n) == CW_OK);
    int contact = 0, slip = 0;
    for (size_t k = 0; k < n; ++k) {
        const int st = z.ibuf[k];
        FUZZ_CHECK(st == CW_STATE_EXTERIOR || st == CW_STATE_ADHESION || st == CW_STATE_SLIP);
        contact += st != CW_STATE_EXTERIOR;
        slip += st == CW_STATE_SLIP;
    }
    FUZZ_CHECK(contact == r.n_contact && slip == r.n_slip);
    FUZZ_CHECK(r.n_adhesion + r.n_slip == r.n_contact);
    FUZZ_CHECK(r.adhesion_fraction >= 0.0 && r.adhesion_fraction <= 1.0);
    if (p.struct_size >= offsetof(cw_params, model) + sizeof p.model && p.model == CW_MODEL_EXACT) {
        // Never an unconverged answer: the residual is within the tolerance.
        // The ABI reads subnormal inputs as 0 (DAZ, doc/reference/guarantees.md), so a
        // subnormal tolerance selects the default 1e-8, as 0 does.
        const double tol = p.tolerance >= DBL_MIN ? p.tolerance : 1e-8;
        FUZZ_CHECK(r.model == CW_MODEL_EXACT && r.iterations >= 0 && r.residual <= tol);
        FUZZ_CHECK(r.p_max >= 0.0 && r.approach >= 0.0);
    }
    if (mode != CW_SOLVE_FULL) return;
    for (int f : {CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_PAPER}) {
        fetch(z.solver, f, z.buf, n);
        FUZZ_CHECK(all_finite(z.buf.data(), n));
    }
    fetch(z.solver, CW_FIELD_WORK_CONSISTENT, z.buf, n);
    double sum = 0.0;
    for (size_t k = 0; k < n; ++k) {
        FUZZ_CHECK(std::isfinite(z.buf[k]) && z.buf[k] >= 0.0);
        sum += z.buf[k];
    }
    FUZZ_CHECK(std::fabs(sum - r.W_consistent) <= 1e-12 * std::fabs(sum) + 1e-300);
    // Also when balance = W_macro / total underflows (W_macro tiny next to the
    // model's dissipation, e.g. xi_x = -1e31, phi = 1e300 on a 1x1 grid:
    // input regress-balance-underflow): the core then divides first.
    if (r.work_flags == 0)
        FUZZ_CHECK(std::fabs(sum - r.W_macro) <= 1e-9 * std::fabs(r.W_macro) + 1e-300);
    FUZZ_CHECK((r.work_flags & ~(CW_WORK_UNRESOLVED | CW_WORK_NON_POSITIVE)) == 0);
}

// ------------------------------------------------------------------- calls

void op_create(Session& z, Bytes& in)
{
    cw_solver_destroy(z.solver);
    z.solver = nullptr;
    z.solved = z.full = false;
    cw_grid g = decode_grid(in);
    MessageBuffer msg(in);
    const bool null_grid = in.u8() > 250;
    cw_solver* s = reinterpret_cast<cw_solver*>(&g); // must become NULL on error
    if (verbose())
        std::fprintf(stderr, "create: size=%zu kind=%d nx=%d ny=%d box=%.17g null=%d\n",
                     g.struct_size, g.kind, g.nx, g.ny, g.box_scale, null_grid);
    const int st = cw_solver_create(null_grid ? nullptr : &g, &s, msg.ptr, msg.len);
    FUZZ_CHECK(known_status(st));
    msg.check(st);
    FUZZ_CHECK((st == CW_OK) == (!null_grid && grid_valid(g)));
    if (st != CW_OK) {
        FUZZ_CHECK(s == nullptr);
        return;
    }
    FUZZ_CHECK(s != nullptr);
    z.solver = s;
    z.grid = effective_grid(g);
    int nx = 0, ny = 0;
    FUZZ_CHECK(cw_solver_grid_size(s, &nx, &ny) == CW_OK);
    FUZZ_CHECK(nx == z.grid.nx && ny == z.grid.ny);
    z.cells = static_cast<size_t>(nx) * ny;
    z.ny = ny;
    check_message(cw_solver_last_error(s), false);
}

// The Jacobian of a FASTSIM or calibrated solve just made (doc/theory/jacobians.md), read from
// no further input bytes so the corpus decodes as before: the same totals
// bitwise, 16 finite numbers and nothing past them; on an error (no load,
// overflow) nothing is written, and the solve is redone so the session's
// state holds.
void check_jacobian(Session& z, const cw_params& p, int mode, const cw_result& full)
{
    double J[CW_JACOBIAN_LEN + 1];
    std::memset(J, kSentinel, sizeof J);
    cw_result r;
    cw_result_init(&r);
    const int st = cw_solver_solve_jacobian(z.solver, &p, mode, &r, J, CW_JACOBIAN_LEN);
    FUZZ_CHECK(known_status(st));
    FUZZ_CHECK(untouched(&J[CW_JACOBIAN_LEN], sizeof(double)));
    if (st == CW_OK) {
        for (int k = 0; k < CW_JACOBIAN_LEN; ++k) FUZZ_CHECK(std::isfinite(J[k]));
        FUZZ_CHECK(std::memcmp(&r.Fx, &full.Fx, sizeof r.Fx) == 0);
        FUZZ_CHECK(std::memcmp(&r.Fy, &full.Fy, sizeof r.Fy) == 0);
        FUZZ_CHECK(std::memcmp(&r.Mz, &full.Mz, sizeof r.Mz) == 0);
        FUZZ_CHECK(std::memcmp(&r.W_macro, &full.W_macro, sizeof r.W_macro) == 0);
        return;
    }
    FUZZ_CHECK(st == CW_ERR_INVALID_INPUT || st == CW_ERR_NUMERIC);
    FUZZ_CHECK(untouched(J, sizeof J));
    check_message(cw_solver_last_error(z.solver), true);
    FUZZ_CHECK(cw_solver_solve(z.solver, &p, mode, nullptr) == CW_OK);
}

void op_solve(Session& z, Bytes& in)
{
    const size_t size = in.struct_size<cw_params>();
    // Room for a struct_size larger than the struct (read up to sizeof).
    const cw_params p_decoded = decode_params(in, size);
    const uint8_t how = in.u8();
    const int mode = how < 250 ? how % 2 : in.small_int();
    const bool with_result = how % 7 != 3;
    // The exact model on small grids only, so an execution stays
    // short: its own options fuzzed too.
    cw_params p = p_decoded;
    if (how < 250 && how % 10 == 5 && z.solver && z.cells <= 400) {
        p.model = CW_MODEL_EXACT;
        const uint8_t e = in.u8();
        if (e & 1) p.tolerance = in.number();
        if (e & 2) p.max_iterations = in.small_int();
        if (e & 4) p.warm_start = in.small_int();
        if (e & 8) p.spin_offset = in.number();
        if (e & 16) p.flexibility = CW_FLEX_FROM_MATERIAL;
        if (e & 32) p.model = in.small_int();
    } else if (how < 250 && how % 10 == 7) {
        // The calibrated model on any grid: FASTSIM's march with
        // its table's blended bound, from the fuzzed creepages and load.
        p.model = CW_MODEL_CALIBRATED;
        p.flexibility = CW_FLEX_FROM_MATERIAL;
    }
    // The exact-load pressure scale on every model, one solve in six, with an
    // invalid flag now and then.
    if (how < 250 && how % 6 == 1) p.exact_load = how % 12 == 1 ? 1 : in.small_int();
    cw_result r;
    std::memset(&r, kSentinel, sizeof r);
    r.struct_size = in.u8() < 245 ? sizeof r : in.struct_size<cw_result>();
    const size_t result_size = r.struct_size;
    print_params("solve", p, mode);
    const int st = cw_solver_solve(z.solver, &p, mode, with_result ? &r : nullptr);
    if (verbose()) std::fprintf(stderr, "  -> %d %s\n", st, cw_solver_last_error(z.solver));
    FUZZ_CHECK(known_status(st));
    if (!z.solver) {
        FUZZ_CHECK(st == CW_ERR_NULL_POINTER);
        return;
    }
    check_message(cw_solver_last_error(z.solver), st != CW_OK);
    if (st != CW_OK) {
        FUZZ_CHECK(r.struct_size == result_size);
        FUZZ_CHECK(untouched(reinterpret_cast<unsigned char*>(&r) + sizeof(size_t),
                             sizeof r - sizeof(size_t)));
        z.solved = z.full = false;
        cw_result probe;
        cw_result_init(&probe);
        FUZZ_CHECK(cw_solver_get_result(z.solver, &probe) == CW_ERR_NO_SOLUTION);
        return;
    }
    FUZZ_CHECK(mode == CW_SOLVE_FORCES || mode == CW_SOLVE_FULL);
    cw_result full;
    cw_result_init(&full);
    FUZZ_CHECK(cw_solver_get_result(z.solver, &full) == CW_OK);
    if (with_result) {
        // The caller's struct got min(struct_size, sizeof) bytes of the same values.
        FUZZ_CHECK(r.struct_size == result_size);
        const size_t copied = std::min(result_size, sizeof r);
        FUZZ_CHECK(std::memcmp(reinterpret_cast<unsigned char*>(&r) + sizeof(size_t),
                               reinterpret_cast<unsigned char*>(&full) + sizeof(size_t),
                               copied - sizeof(size_t)) == 0);
        FUZZ_CHECK(untouched(reinterpret_cast<unsigned char*>(&r) + copied, sizeof r - copied));
    }
    if (p.model != CW_MODEL_EXACT && how % 3 == 0) check_jacobian(z, p, mode, full);
    z.solved = true;
    z.full = mode == CW_SOLVE_FULL;
    z.last = full;
    check_solution(z, p, mode, full);
}

void op_get_result(Session& z, Bytes& in)
{
    cw_result r;
    std::memset(&r, kSentinel, sizeof r);
    r.struct_size = in.struct_size<cw_result>();
    const bool null_out = in.u8() > 240;
    const int st = cw_solver_get_result(z.solver, null_out ? nullptr : &r);
    FUZZ_CHECK(known_status(st));
    const bool size_ok = r.struct_size >= sizeof(size_t) && r.struct_size <= ((size_t)1 << 16);
    const bool ok = z.solver && !null_out && z.solved && size_ok;
    FUZZ_CHECK((st == CW_OK) == ok);
    if (st == CW_OK) {
        const size_t copied = std::min(r.struct_size, sizeof r);
        FUZZ_CHECK(std::memcmp(reinterpret_cast<unsigned char*>(&r) + sizeof(size_t),
                               reinterpret_cast<unsigned char*>(&z.last) + sizeof(size_t),
                               copied - sizeof(size_t)) == 0);
    } else {
        FUZZ_CHECK(untouched(reinterpret_cast<unsigned char*>(&r) + sizeof(size_t),
                             sizeof r - sizeof(size_t)));
    }
}

size_t decode_length(Bytes& in, size_t need)
{
    const uint8_t how = in.u8();
    if (how < 200) return need;
    switch (how % 6) {
    case 0: return need > 0 ? need - 1 : 0;
    case 1: return 0;
    case 2: return need + 3;
    case 3: return need / 2;
    case 4: return 1;
    default: return SIZE_MAX; // claims a huge buffer: only need is written
    }
}

void op_get_field(Session& z, Bytes& in)
{
    const uint8_t f = in.u8();
    const int field = f < 240 ? f % 11 : scaled(in.small_int(), 7);
    const size_t need = z.cells;
    const size_t len = decode_length(in, need);
    const bool null_out = in.u8() > 245;
    const size_t room = std::min(len, need + kGuard) + kGuard;
    z.buf.assign(room, 0.0);
    std::memset(z.buf.data(), kSentinel, room * sizeof(double));
    const int st = cw_solver_get_field(z.solver, field, null_out ? nullptr : z.buf.data(), len);
    FUZZ_CHECK(known_status(st));
    const bool field_ok = field >= CW_FIELD_X && field <= CW_FIELD_WORK_CONSISTENT;
    const bool needs_work = field == CW_FIELD_SX || field == CW_FIELD_SY ||
                            field == CW_FIELD_WORK_PAPER || field == CW_FIELD_WORK_CONSISTENT;
    const bool ok = z.solver && field_ok && !null_out && z.solved && (!needs_work || z.full) &&
                    len >= need;
    FUZZ_CHECK((st == CW_OK) == ok);
    if (z.solver) check_message(cw_solver_last_error(z.solver), st != CW_OK);
    if (st == CW_OK) {
        FUZZ_CHECK(all_finite(z.buf.data(), need));
        FUZZ_CHECK(untouched(z.buf.data() + need, (room - need) * sizeof(double)));
    } else {
        FUZZ_CHECK(untouched(z.buf.data(), room * sizeof(double)));
    }
}

void op_get_state(Session& z, Bytes& in)
{
    const size_t need = z.cells;
    const size_t len = decode_length(in, need);
    const bool null_out = in.u8() > 245;
    const size_t room = std::min(len, need + kGuard) + kGuard;
    z.ibuf.assign(room, 0);
    std::memset(z.ibuf.data(), kSentinel, room * sizeof(int));
    const int st = cw_solver_get_state(z.solver, null_out ? nullptr : z.ibuf.data(), len);
    FUZZ_CHECK(known_status(st));
    const bool ok = z.solver && !null_out && z.solved && len >= need;
    FUZZ_CHECK((st == CW_OK) == ok);
    if (st == CW_OK) {
        for (size_t k = 0; k < need; ++k) FUZZ_CHECK(z.ibuf[k] >= 0 && z.ibuf[k] <= 2);
        FUZZ_CHECK(untouched(z.ibuf.data() + need, (room - need) * sizeof(int)));
    } else {
        FUZZ_CHECK(untouched(z.ibuf.data(), room * sizeof(int)));
    }
}

void op_get_profile(Session& z, Bytes& in)
{
    const size_t need = static_cast<size_t>(z.ny);
    const size_t len = decode_length(in, need);
    const uint8_t which = in.u8(); // bit k: buffer k is NULL
    const size_t room = std::min(len, need + kGuard) + kGuard;
    std::vector<double> b(3 * room);
    std::memset(b.data(), kSentinel, b.size() * sizeof(double));
    double* ptr[3];
    for (int k = 0; k < 3; ++k) ptr[k] = which & (1 << k) ? nullptr : b.data() + k * room;
    const int st = cw_solver_get_profile(z.solver, ptr[0], ptr[1], ptr[2], len);
    FUZZ_CHECK(known_status(st));
    const bool ok = z.solver && z.solved && z.full && len >= need;
    FUZZ_CHECK((st == CW_OK) == ok);
    for (int k = 0; k < 3; ++k) {
        const double* v = b.data() + k * room;
        if (st == CW_OK && ptr[k]) {
            FUZZ_CHECK(all_finite(v, need));
            FUZZ_CHECK(untouched(v + need, (room - need) * sizeof(double)));
        } else {
            FUZZ_CHECK(untouched(v, room * sizeof(double)));
        }
    }
}

void op_accumulator(Session& z, Bytes& in)
{
    const uint8_t what = in.u8() % 6;
    if (what == 0) { // (re)create
        cw_accumulator_destroy(z.acc);
        z.acc = reinterpret_cast<cw_accumulator*>(&z); // must become NULL on error
        const int st = cw_accumulator_create(z.solver, &z.acc);
        FUZZ_CHECK(known_status(st));
        FUZZ_CHECK((st == CW_OK) == (z.solver != nullptr));
        if (st != CW_OK) FUZZ_CHECK(z.acc == nullptr);
        else z.acc_grid = z.grid;
        return;
    }
    if (what == 5) {
        FUZZ_CHECK(cw_accumulator_destroy(z.acc) == CW_OK);
        z.acc = nullptr;
        return;
    }
    cw_accumulation before, after;
    std::memset(&before, 0, sizeof before);
    before.struct_size = sizeof before;
    after = before;
    const int got = cw_accumulator_get_totals(z.acc, &before);
    FUZZ_CHECK(got == (z.acc ? CW_OK : CW_ERR_NULL_POINTER));
    if (what == 1) { // add
        const double distance = in.u8() < 128 ? (in.u8() + 1) * 1e-3 : in.number();
        const int st = cw_accumulator_add(z.acc, z.solver, distance);
        FUZZ_CHECK(known_status(st));
        if (!z.acc) {
            FUZZ_CHECK(st == CW_ERR_NULL_POINTER);
            return;
        }
        check_message(cw_accumulator_last_error(z.acc), st != CW_OK);
        const bool could = z.solver && same_grid(z.grid, z.acc_grid) && z.solved && z.full &&
                           std::isfinite(distance) && distance >= 0.0;
        if (!could) FUZZ_CHECK(st != CW_OK);
        if (could) FUZZ_CHECK(st == CW_OK || st == CW_ERR_NUMERIC); // overflow is refused
        cw_accumulator_get_totals(z.acc, &after);
        if (st != CW_OK) FUZZ_CHECK(std::memcmp(&before, &after, sizeof before) == 0);
        else FUZZ_CHECK(after.steps == before.steps + 1);
        const double t[] = {after.distance, after.W_macro, after.W_micro_paper, after.K,
                            after.W_consistent};
        FUZZ_CHECK(all_finite(t, 5));
        return;
    }
    if (what == 2) { // fields
        if (!z.acc) return;
        const size_t need = static_cast<size_t>(z.acc_grid.nx) * z.acc_grid.ny;
        const int field = in.u8() % 2 ? CW_FIELD_WORK_PAPER : CW_FIELD_WORK_CONSISTENT;
        const size_t len = decode_length(in, need);
        const size_t room = std::min(len, need + kGuard) + kGuard;
        z.buf.assign(room, 0.0);
        std::memset(z.buf.data(), kSentinel, room * sizeof(double));
        const int st = cw_accumulator_get_field(z.acc, field, z.buf.data(), len);
        FUZZ_CHECK((st == CW_OK) == (len >= need));
        if (st == CW_OK) FUZZ_CHECK(all_finite(z.buf.data(), need));
        else FUZZ_CHECK(untouched(z.buf.data(), room * sizeof(double)));
        const size_t strips = static_cast<size_t>(z.acc_grid.ny);
        z.buf.assign(strips + kGuard, 0.0);
        FUZZ_CHECK(cw_accumulator_get_strip_work(z.acc, z.buf.data(), strips) == CW_OK);
        FUZZ_CHECK(all_finite(z.buf.data(), strips));
        return;
    }
    if (what == 3) { // reset
        FUZZ_CHECK(cw_accumulator_reset(z.acc) == (z.acc ? CW_OK : CW_ERR_NULL_POINTER));
        if (z.acc) {
            cw_accumulator_get_totals(z.acc, &after);
            FUZZ_CHECK(after.steps == 0 && after.W_macro == 0.0 && after.distance == 0.0);
        }
        return;
    }
    // what == 4: totals into an odd struct
    cw_accumulation odd;
    std::memset(&odd, kSentinel, sizeof odd);
    odd.struct_size = in.struct_size<cw_accumulation>();
    const int st = cw_accumulator_get_totals(z.acc, &odd);
    FUZZ_CHECK(known_status(st));
    if (st != CW_OK)
        FUZZ_CHECK(untouched(reinterpret_cast<unsigned char*>(&odd) + sizeof(size_t),
                             sizeof odd - sizeof(size_t)));
}

void op_batch(Session& z, Bytes& in)
{
    const uint8_t what = in.u8() % 4;
    if (what == 0) { // (re)create
        cw_batch_destroy(z.batch);
        z.batch = nullptr;
        cw_grid g = decode_grid(in);
        const int threads = static_cast<int>(in.u8() % 10) - 1; // -1 .. 8
        MessageBuffer msg(in);
        cw_batch* b = reinterpret_cast<cw_batch*>(&g);
        const int st = cw_batch_create(&g, threads, &b, msg.ptr, msg.len);
        FUZZ_CHECK(known_status(st));
        msg.check(st);
        FUZZ_CHECK((st == CW_OK) == grid_valid(g));
        if (st != CW_OK) {
            FUZZ_CHECK(b == nullptr);
            return;
        }
        z.batch = b;
        z.batch_grid = effective_grid(g);
        return;
    }
    if (what == 3) {
        FUZZ_CHECK(cw_batch_destroy(z.batch) == CW_OK);
        z.batch = nullptr;
        return;
    }
    // Solve count contacts; compare with single solves on a twin solver.
    const size_t count = in.u8() % 7;
    const uint8_t sizes = in.u8();
    size_t pstride = sizeof(cw_params), rstride = sizeof(cw_result);
    if (sizes > 230) pstride = sizes % 2 ? sizeof(cw_params) - 8 : sizeof(cw_params) + 24;
    if (sizes > 243) rstride = sizes % 3 ? sizeof(cw_result) - 16 : sizeof(cw_result) + 8;
    const size_t pbytes = std::max<size_t>(count, 1) * std::max(pstride, sizeof(cw_params));
    const size_t rbytes = std::max<size_t>(count, 1) * std::max(rstride, sizeof(cw_result));
    std::vector<unsigned char> pmem(pbytes, 0), rmem(rbytes, kSentinel);
    std::vector<cw_params> ps(count);
    for (size_t k = 0; k < count; ++k) {
        ps[k] = decode_params(in, pstride);
        std::memcpy(pmem.data() + k * pstride, &ps[k], std::min(pstride, sizeof(cw_params)));
        std::memcpy(rmem.data() + k * rstride, &rstride, sizeof rstride);
    }
    // Exact contacts on small batch grids (always started cold by the batch:
    // the twin below solves them with warm_start = 0).
    const bool exact = sizes % 9 == 4 && pstride == sizeof(cw_params) &&
                       static_cast<size_t>(z.batch_grid.nx) * z.batch_grid.ny <= 256;
    if (exact)
        for (size_t k = 0; k < count; ++k) {
            ps[k].model = CW_MODEL_EXACT;
            std::memcpy(pmem.data() + k * pstride, &ps[k], sizeof(cw_params));
        }
    const uint8_t how = in.u8();
    const int mode = how < 250 ? how % 2 : in.small_int();
    std::vector<int> statuses(count + 1, -12345);
    const bool with_statuses = how % 5 != 1;
    const int st = cw_batch_solve(z.batch, count, reinterpret_cast<const cw_params*>(pmem.data()),
                                  mode, reinterpret_cast<cw_result*>(rmem.data()),
                                  with_statuses ? statuses.data() : nullptr);
    FUZZ_CHECK(known_status(st));
    if (!z.batch) {
        FUZZ_CHECK(st == CW_ERR_NULL_POINTER);
        return;
    }
    check_message(cw_batch_last_error(z.batch), st != CW_OK);
    FUZZ_CHECK(statuses[count] == -12345);
    if (count == 0) {
        FUZZ_CHECK(st == CW_OK);
        return;
    }
    const bool mode_ok = mode == CW_SOLVE_FORCES || mode == CW_SOLVE_FULL;
    if (!mode_ok) FUZZ_CHECK(st == CW_ERR_UNKNOWN_OPTION);
    if (!mode_ok || st == CW_ERR_STRUCT_SIZE) {
        for (size_t k = 0; k < count; ++k)
            FUZZ_CHECK(untouched(rmem.data() + k * rstride + sizeof(size_t),
                                 std::min(rstride, sizeof(cw_result)) - sizeof(size_t)));
        return;
    }
    // Every contact as a single solve on a twin of the batch's grid.
    cw_solver* twin = nullptr;
    FUZZ_CHECK(cw_solver_create(&z.batch_grid, &twin, nullptr, 0) == CW_OK);
    int first_error = CW_OK;
    for (size_t k = 0; k < count; ++k) {
        cw_result single;
        cw_result_init(&single);
        cw_params one = ps[k];
        if (exact && one.warm_start == 1) one.warm_start = 0;
        const int s1 = cw_solver_solve(twin, &one, mode, &single);
        if (with_statuses) FUZZ_CHECK(statuses[k] == s1);
        if (first_error == CW_OK) first_error = s1;
        const unsigned char* got = rmem.data() + k * rstride;
        const size_t copied = std::min(rstride, sizeof(cw_result));
        if (s1 == CW_OK)
            FUZZ_CHECK(std::memcmp(got + sizeof(size_t),
                                   reinterpret_cast<unsigned char*>(&single) + sizeof(size_t),
                                   copied - sizeof(size_t)) == 0);
        else
            FUZZ_CHECK(untouched(got + sizeof(size_t), copied - sizeof(size_t)));
    }
    FUZZ_CHECK(st == first_error);
    cw_solver_destroy(twin);
}

void op_free_functions(Bytes& in)
{
    MessageBuffer msg(in);
    double out[5];
    std::memset(out, kSentinel, sizeof out);
    int st = CW_OK;
    switch (in.u8() % 4) {
    case 0:
        st = cw_kalker_coefficients(in.number(), in.number(), out, msg.ptr, msg.len);
        break;
    case 1: {
        const double a = in.number(), b = in.number(), G = in.number(), nu = in.number();
        st = cw_kalker_flexibilities(a, b, G, nu, out, msg.ptr, msg.len);
        break;
    }
    case 2: {
        const double A = in.number(), B = in.number(), N = in.number(), E = in.number();
        st = cw_hertz_solve(A, B, N, E, out, msg.ptr, msg.len);
        break;
    }
    default: {
        const double ux = in.number(), uy = in.number(), fx = in.number(), fy = in.number();
        const uint8_t m = in.u8(), n = in.u8();
        const int mx = m < 250 ? 1 + m % 20 : scaled(in.small_int(), 333);
        const int my = n < 250 ? 1 + n % 20 : scaled(in.small_int(), 333);
        const double tol = in.number();
        st = cw_fastsim_normalised(ux, uy, fx, fy, mx, my > 64 && mx > 4 ? 4 : my, tol, &out[0],
                                   &out[1], msg.ptr, msg.len);
        // |F|/(mu N) is bounded by the discrete sum of the bound times the
        // element areas over pi/2, at most 4/(pi/2) (one element, 1x1 grid).
        if (st == CW_OK) FUZZ_CHECK(std::hypot(out[0], out[1]) <= 8.0 / M_PI * (1.0 + 1e-12));
        break;
    }
    }
    FUZZ_CHECK(known_status(st));
    msg.check(st);
    if (st == CW_OK) {
        size_t k = 0;
        while (k < 5 && !untouched(&out[k], sizeof out[k])) {
            FUZZ_CHECK(std::isfinite(out[k]));
            ++k;
        }
        FUZZ_CHECK(k >= 2);
    } else {
        FUZZ_CHECK(untouched(out, sizeof out));
    }
}

void op_destroy_solver(Session& z)
{
    FUZZ_CHECK(cw_solver_destroy(z.solver) == CW_OK);
    z.solver = nullptr;
    z.solved = z.full = false;
    z.cells = 0;
    z.ny = 0;
}

// ------------------------------------------------------------------- wear

// Wear handles and profiles of a session (the solver's grid when made).
struct WearSession {
    cw_wear* wear = nullptr;
    cw_grid wear_grid{};
    bool computed = false; // shadow of the handle's "holds a wear"
    cw_wear_profile* profile = nullptr;
    std::vector<double> nodes;
    ~WearSession()
    {
        cw_wear_destroy(wear);
        cw_wear_profile_destroy(profile);
    }
};

// x as the library sees it: every call flushes subnormal inputs to zero
// (header, "Floating point").
double as_seen(double x) { return std::fabs(x) < DBL_MIN ? 0.0 * x : x; }

// Nodes valid for cw_wear_profile_create (header: n >= 2, finite, within
// +-1e6 m, strictly increasing).
bool nodes_valid(const std::vector<double>& s)
{
    if (s.size() < 2) return false;
    for (size_t k = 0; k < s.size(); ++k) {
        if (!std::isfinite(s[k]) || std::fabs(s[k]) > 1e6) return false;
        if (k && !(as_seen(s[k]) > as_seen(s[k - 1]))) return false;
    }
    return true;
}

std::vector<double> decode_nodes(Bytes& in)
{
    const uint8_t how = in.u8();
    const size_t n = how % 40;
    std::vector<double> s(n);
    if (how < 200) { // a plausible profile: spacing 0.1 .. 2 mm around 0
        const double step = (1 + in.u8() % 20) * 1e-4;
        for (size_t k = 0; k < n; ++k) s[k] = -0.01 + step * static_cast<double>(k);
    } else {
        for (double& v : s) v = in.number();
    }
    return s;
}

// Depths of the profile, bitwise, or empty without one.
std::vector<double> depths(const WearSession& w)
{
    if (!w.profile) return {};
    std::vector<double> d(2 * w.nodes.size());
    FUZZ_CHECK(cw_wear_profile_get_depth(w.profile, CW_WEAR_DEPTH_NORMAL, d.data(),
                                         w.nodes.size()) == CW_OK);
    FUZZ_CHECK(cw_wear_profile_get_depth(w.profile, CW_WEAR_DEPTH_HEIGHT,
                                         d.data() + w.nodes.size(), w.nodes.size()) == CW_OK);
    return d;
}

void check_wear_values(Session& z, WearSession& w, const cw_wear_result& r)
{
    const size_t n = static_cast<size_t>(w.wear_grid.nx) * w.wear_grid.ny;
    const double t[] = {r.mass_per_distance, r.mass_per_pass, r.volume_per_distance,
                        r.max_depth, r.work, r.regime_area[0], r.regime_area[1],
                        r.regime_area[2], r.regime_area[3]};
    FUZZ_CHECK(all_finite(t, 9));
    for (double v : t) FUZZ_CHECK(v >= 0.0);
    std::vector<double> rate(n), area(n);
    FUZZ_CHECK(cw_wear_get_field(w.wear, CW_WEAR_FIELD_RATE, rate.data(), n) == CW_OK);
    FUZZ_CHECK(cw_solver_get_field(z.solver, CW_FIELD_AREA, area.data(), n) == CW_OK);
    double mass = 0.0;
    for (size_t k = 0; k < n; ++k) {
        FUZZ_CHECK(std::isfinite(rate[k]) && rate[k] >= 0.0);
        mass += rate[k] * area[k];
    }
    FUZZ_CHECK(std::fabs(mass - r.mass_per_distance) <= 1e-9 * mass + 1e-300);
    for (int f = CW_WEAR_FIELD_DEPTH; f <= CW_WEAR_FIELD_SLIDING; ++f) {
        FUZZ_CHECK(cw_wear_get_field(w.wear, f, rate.data(), n) == CW_OK);
        for (size_t k = 0; k < n; ++k) FUZZ_CHECK(std::isfinite(rate[k]) && rate[k] >= 0.0);
    }
    z.ibuf.assign(n, -1);
    FUZZ_CHECK(cw_wear_get_regimes(w.wear, z.ibuf.data(), n) == CW_OK);
    for (size_t k = 0; k < n; ++k) FUZZ_CHECK(z.ibuf[k] >= 0 && z.ibuf[k] <= 4);
}

void op_wear(Session& z, WearSession& w, Bytes& in)
{
    const uint8_t what = in.u8() % 8;
    if (what == 0) { // (re)create on the session's solver
        cw_wear_destroy(w.wear);
        w.wear = reinterpret_cast<cw_wear*>(&w); // must become NULL on error
        const int st = cw_wear_create(z.solver, &w.wear);
        FUZZ_CHECK((st == CW_OK) == (z.solver != nullptr));
        if (st != CW_OK) FUZZ_CHECK(w.wear == nullptr);
        else w.wear_grid = z.grid;
        w.computed = false;
        return;
    }
    if (what == 1) { // compute
        cw_wear_params p;
        cw_wear_params_init(&p);
        p.struct_size = in.struct_size<cw_wear_params>();
        p.law = in.u8() < 200 ? in.u8() % 2 : in.small_int();
        p.source = in.u8() < 200 ? in.u8() % 3 : in.small_int();
        p.rolling_speed = in.u8() < 128 ? 1.0 + in.u8() : in.number();
        double* fields[] = {&p.density,  &p.pass_length, &p.usfd_k1, &p.usfd_t1, &p.usfd_k2,
                            &p.usfd_t2,  &p.usfd_k3,     &p.usfd_c3, &p.hardness, &p.kth_v1,
                            &p.kth_v2,   &p.kth_seizure_ratio, &p.kth_k_seizure, &p.kth_k_slow,
                            &p.kth_k_severe, &p.kth_k_fast};
        const uint8_t touch = in.u8();
        if (touch < 100) *fields[touch % 16] = in.number();
        cw_wear_result r;
        std::memset(&r, kSentinel, sizeof r);
        r.struct_size = in.struct_size<cw_wear_result>();
        const bool null_result = in.u8() > 240;
        const int st = cw_wear_compute(w.wear, z.solver, &p, null_result ? nullptr : &r);
        FUZZ_CHECK(known_status(st));
        if (!w.wear) {
            FUZZ_CHECK(st == CW_ERR_NULL_POINTER);
            return;
        }
        check_message(cw_wear_last_error(w.wear), st != CW_OK);
        const bool could = z.solver && same_grid(z.grid, w.wear_grid) && z.solved && z.full;
        if (!could) FUZZ_CHECK(st != CW_OK);
        w.computed = st == CW_OK;
        if (st == CW_OK) {
            cw_wear_result full;
            cw_wear_result_init(&full);
            FUZZ_CHECK(cw_wear_get_result(w.wear, &full) == CW_OK);
            check_wear_values(z, w, full);
        } else {
            if (!null_result && r.struct_size >= sizeof(size_t) && r.struct_size <= (1u << 16))
                FUZZ_CHECK(untouched(reinterpret_cast<unsigned char*>(&r) + sizeof(size_t),
                                     sizeof r - sizeof(size_t)));
            double one = 0;
            FUZZ_CHECK(cw_wear_get_field(w.wear, CW_WEAR_FIELD_RATE, &one, SIZE_MAX) ==
                       CW_ERR_NO_SOLUTION);
        }
        return;
    }
    if (what == 2) { // a field into an odd buffer
        const uint8_t f = in.u8();
        const int field = f < 240 ? f % 6 : scaled(in.small_int(), 5);
        const size_t need = w.wear ? static_cast<size_t>(w.wear_grid.nx) * w.wear_grid.ny : 0;
        const size_t len = decode_length(in, need);
        const size_t room = std::min(len, need + kGuard) + kGuard;
        z.buf.assign(room, 0.0);
        std::memset(z.buf.data(), kSentinel, room * sizeof(double));
        const int st = cw_wear_get_field(w.wear, field, z.buf.data(), len);
        FUZZ_CHECK(known_status(st));
        const bool ok = w.wear && w.computed && field >= 0 && field <= 4 && len >= need;
        FUZZ_CHECK((st == CW_OK) == ok);
        if (st == CW_OK) {
            FUZZ_CHECK(all_finite(z.buf.data(), need));
            FUZZ_CHECK(untouched(z.buf.data() + need, (room - need) * sizeof(double)));
        } else {
            FUZZ_CHECK(untouched(z.buf.data(), room * sizeof(double)));
        }
        return;
    }
    if (what == 3) { // strips, some NULL
        const size_t need = w.wear ? static_cast<size_t>(w.wear_grid.ny) : 0;
        const size_t len = decode_length(in, need);
        const uint8_t which = in.u8();
        const size_t room = std::min(len, need + kGuard) + kGuard;
        std::vector<double> b(4 * room);
        std::memset(b.data(), kSentinel, b.size() * sizeof(double));
        double* ptr[4];
        for (int k = 0; k < 4; ++k) ptr[k] = which & (1 << k) ? nullptr : b.data() + k * room;
        const int st = cw_wear_get_strips(w.wear, ptr[0], ptr[1], ptr[2], ptr[3], len);
        FUZZ_CHECK(known_status(st));
        const bool any = ptr[0] || ptr[1] || ptr[2] || ptr[3];
        FUZZ_CHECK((st == CW_OK) == (w.wear && w.computed && (!any || len >= need)));
        for (int k = 0; k < 4; ++k) {
            const double* v = b.data() + k * room;
            if (st == CW_OK && ptr[k]) FUZZ_CHECK(all_finite(v, need));
            if (st != CW_OK || !ptr[k]) FUZZ_CHECK(untouched(v, room * sizeof(double)));
        }
        return;
    }
    if (what == 4) { // (re)create the profile
        cw_wear_profile_destroy(w.profile);
        w.profile = nullptr;
        const std::vector<double> s = decode_nodes(in);
        MessageBuffer msg(in);
        cw_wear_profile* p = reinterpret_cast<cw_wear_profile*>(&w);
        const int st = cw_wear_profile_create(s.empty() ? nullptr : s.data(), s.size(), &p,
                                              msg.ptr, msg.len);
        FUZZ_CHECK(known_status(st));
        msg.check(st);
        FUZZ_CHECK((st == CW_OK) == (!s.empty() && nodes_valid(s)));
        if (st != CW_OK) {
            FUZZ_CHECK(p == nullptr);
            return;
        }
        w.profile = p;
        w.nodes = s;
        return;
    }
    if (what == 5 || what == 6) { // add from the wear, or from decoded strips
        const std::vector<double> before = depths(w);
        cw_wear_profile_totals t0, t1;
        cw_wear_profile_totals_init(&t0);
        cw_wear_profile_totals_init(&t1);
        if (w.profile) cw_wear_profile_get_totals(w.profile, &t0);
        const double s0 = in.u8() < 200 ? (in.u8() - 128) * 1e-4 : in.number();
        const int orientation = in.u8() < 200 ? (in.u8() % 2 ? 1 : -1) : in.small_int();
        const double angle = in.u8() < 200 ? (in.u8() - 128) * 0.01 : in.number();
        const double passes = in.u8() < 200 ? in.u8() : in.number();
        int st;
        bool could;
        const bool placement_ok = std::isfinite(s0) && std::fabs(s0) <= 1e6 &&
                                  (orientation == 1 || orientation == -1) &&
                                  std::isfinite(angle) &&
                                  std::fabs(angle) <= CW_WEAR_MAX_CONTACT_ANGLE &&
                                  std::isfinite(passes) && as_seen(passes) >= 0.0 &&
                                  passes <= CW_WEAR_MAX_PASSES;
        if (what == 5) {
            st = cw_wear_profile_add(w.profile, w.wear, s0, orientation, angle, passes);
            could = w.profile && w.wear && w.computed && placement_ok;
        } else {
            const size_t count = in.u8() % 6;
            std::vector<double> y(count), width(count), depth(count);
            bool strips_ok = count >= 1;
            for (size_t k = 0; k < count; ++k) {
                y[k] = in.u8() < 200 ? (in.u8() - 128) * 1e-4 : in.number();
                width[k] = in.u8() < 200 ? (1 + in.u8()) * 1e-5 : in.number();
                depth[k] = in.u8() < 200 ? in.u8() * 1e-9 : in.number();
                strips_ok = strips_ok && std::isfinite(y[k]) && std::fabs(y[k]) <= 1e6 &&
                            std::isfinite(width[k]) && as_seen(width[k]) > 0.0 &&
                            width[k] <= 1e6 &&
                            std::isfinite(depth[k]) && as_seen(depth[k]) >= 0.0;
            }
            st = cw_wear_profile_add_strips(w.profile, y.data(), width.data(), depth.data(), count,
                                            s0, orientation, angle, passes);
            could = w.profile && strips_ok && placement_ok;
        }
        FUZZ_CHECK(known_status(st));
        if (!could) FUZZ_CHECK(st != CW_OK);
        if (could) FUZZ_CHECK(st == CW_OK || st == CW_ERR_NUMERIC); // exact range refused
        if (!w.profile) return;
        check_message(cw_wear_profile_last_error(w.profile), st != CW_OK);
        const std::vector<double> after = depths(w);
        cw_wear_profile_get_totals(w.profile, &t1);
        if (st != CW_OK) {
            FUZZ_CHECK(std::memcmp(before.data(), after.data(), before.size() * sizeof(double)) ==
                       0);
            FUZZ_CHECK(t1.adds == t0.adds);
        } else {
            FUZZ_CHECK(all_finite(after.data(), after.size()));
            for (size_t k = 0; k < after.size(); ++k) FUZZ_CHECK(after[k] >= before[k]);
            FUZZ_CHECK(t1.adds == t0.adds + 1);
            const double v[] = {t1.passes, t1.volume, t1.volume_lost};
            FUZZ_CHECK(all_finite(v, 3));
            FUZZ_CHECK(t1.volume_lost <= t1.volume * (1 + 1e-12));
        }
        return;
    }
    // what == 7: state round trip and merge, then the update helper
    if (w.profile) {
        size_t words = 0;
        FUZZ_CHECK(cw_wear_profile_state_size(w.profile, &words) == CW_OK);
        std::vector<uint64_t> state(words);
        FUZZ_CHECK(cw_wear_profile_get_state(w.profile, state.data(), words) == CW_OK);
        cw_wear_profile* copy = nullptr;
        FUZZ_CHECK(cw_wear_profile_create(w.nodes.data(), w.nodes.size(), &copy, nullptr, 0) ==
                   CW_OK);
        const size_t len = decode_length(in, words);
        if (len < words && !state.empty()) state[0] ^= in.u8(); // sometimes a damaged state
        const int st = cw_wear_profile_add_state(copy, state.data(), std::min(len, words));
        FUZZ_CHECK(known_status(st));
        if (st == CW_OK) {
            cw_wear_profile* twice = nullptr;
            FUZZ_CHECK(cw_wear_profile_create(w.nodes.data(), w.nodes.size(), &twice, nullptr,
                                              0) == CW_OK);
            FUZZ_CHECK(cw_wear_profile_merge(twice, w.profile) == CW_OK);
            const size_t n = w.nodes.size();
            std::vector<double> a(n), b(n);
            cw_wear_profile_get_depth(copy, CW_WEAR_DEPTH_HEIGHT, a.data(), n);
            cw_wear_profile_get_depth(twice, CW_WEAR_DEPTH_HEIGHT, b.data(), n);
            FUZZ_CHECK(std::memcmp(a.data(), b.data(), n * sizeof(double)) == 0);
            cw_wear_profile_destroy(twice);
        }
        cw_wear_profile_destroy(copy);
    }
    const std::vector<double> s = decode_nodes(in);
    const size_t n = s.size();
    std::vector<double> old(n), dep(n), out(n + kGuard);
    for (size_t k = 0; k < n; ++k) {
        old[k] = in.u8() < 220 ? in.u8() * 1e-3 : in.number();
        dep[k] = in.u8() < 220 ? in.u8() * 1e-6 : in.number();
    }
    const double smoothing = in.u8() < 200 ? in.u8() * 1e-4 : in.number();
    const size_t len = decode_length(in, n);
    std::memset(out.data(), kSentinel, out.size() * sizeof(double));
    MessageBuffer msg(in);
    const int st = cw_wear_profile_update(n ? s.data() : nullptr, old.data(), dep.data(), n,
                                          smoothing, out.data(), std::min(len, n + kGuard),
                                          msg.ptr, msg.len);
    FUZZ_CHECK(known_status(st));
    msg.check(st);
    bool inputs_ok = n >= 1 && nodes_valid(s) && std::isfinite(smoothing) && as_seen(smoothing) >= 0.0 &&
                     smoothing <= 1e6 && std::min(len, n + kGuard) >= n;
    for (size_t k = 0; k < n; ++k)
        inputs_ok = inputs_ok && std::isfinite(old[k]) && std::isfinite(dep[k]);
    if (!inputs_ok) FUZZ_CHECK(st != CW_OK);
    if (st == CW_OK) {
        FUZZ_CHECK(all_finite(out.data(), n));
        FUZZ_CHECK(untouched(out.data() + n, kGuard * sizeof(double)));
    } else {
        FUZZ_CHECK(untouched(out.data(), out.size() * sizeof(double)));
    }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
    Bytes in(data, size);
    Session z;
    WearSession w; // destroyed before z: wear handles never outlive the solver's grid use
    for (int op = 0; op < kMaxOps && !in.empty(); ++op) {
        const uint8_t code = in.u8();
        if (code >= 232) { // the wear calls (appended: older corpus bytes mostly decode as before)
            op_wear(z, w, in);
            continue;
        }
        switch (code % 12) {
        case 0:
        case 1: op_create(z, in); break;
        case 2:
        case 3:
        case 4: op_solve(z, in); break;
        case 5: op_get_result(z, in); break;
        case 6: op_get_field(z, in); break;
        case 7: op_get_state(z, in); break;
        case 8: op_get_profile(z, in); break;
        case 9: op_accumulator(z, in); break;
        case 10: op_batch(z, in); break;
        default:
            if (in.u8() % 8 == 0) op_destroy_solver(z);
            else op_free_functions(in);
            break;
        }
    }
    // Handles that were never created answer with statuses, never crash.
    FUZZ_CHECK(std::strlen(cw_status_string(static_cast<int>(size) - 3)) > 0);
    return 0;
}
