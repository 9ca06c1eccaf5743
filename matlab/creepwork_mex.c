/* MEX gateway of creepwork for MATLAB and GNU Octave: one function,
 *
 *   varargout = creepwork_mex(command, ...)
 *
 * called by the m-files of the package folder +creepwork, which document
 * the commands for users (help creepwork.solve, ...). It converts MATLAB
 * structs to the C structs and back by the field tables of
 * creepwork_fields.h, generated from creepwork.h (python/generate_layout.py),
 * so a field appended to the header is an input or output here after the
 * next build; offsets come from the C compiler (offsetof).
 *
 * Arrays: a per-element field is an nx-by-ny matrix, element (i, j) at
 * f(i+1, j+1), i along x: MATLAB's column-major order is the library's
 * [i + j*nx], so the library writes straight into the matrix.
 *
 * Errors: mexErrMsgIdAndTxt with the identifier creepwork:<CW_ERR_ name> and
 * the library's message naming the input (N when the struct names the load
 * N). a, b and N are required, as at every door (creepwork:missingInput).
 * A 2-D gap must be nx-by-ny, x along the first dimension. The library's
 * plausibility checks (cw_params_check: units that look like a mistake)
 * warn with the identifier creepwork:implausibleUnits.
 *
 * The same source builds as an Octave MEX (mkoctfile --mex) and a MATLAB
 * MEX (mex); it uses only the MEX API both provide. */
#include <ctype.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "mex.h"

#include <creepwork/creepwork.h>

#include "creepwork_fields.h"

enum { MESSAGE_LEN = 512, MAX_SOLVERS = 256 };

/* ------------------------------------------------------------ field tables */

enum kind { K_DOUBLE, K_FLOAT, K_INT, K_UNSIGNED, K_SIZE_T, K_INT32, K_UINT32, K_INT64, K_UINT64,
            K_CHAR, K_POINTER };
#define CW_KIND_DOUBLE K_DOUBLE
#define CW_KIND_FLOAT K_FLOAT
#define CW_KIND_INT K_INT
#define CW_KIND_UNSIGNED K_UNSIGNED
#define CW_KIND_SIZE_T K_SIZE_T
#define CW_KIND_INT32 K_INT32
#define CW_KIND_UINT32 K_UINT32
#define CW_KIND_INT64 K_INT64
#define CW_KIND_UINT64 K_UINT64
#define CW_KIND_CHAR K_CHAR
#define CW_KIND_POINTER K_POINTER

typedef struct {
    const char* name;
    size_t offset;
    enum kind kind;
    int count;
} field_info;

typedef struct {
    const char* struct_name;
    const field_info* fields;
    size_t n_fields;
} struct_info;

#define FIELD_ENTRY(s, f, k, n) {#f, offsetof(s, f), k, n},
static const field_info params_fields[] = {CW_FIELDS_cw_params(FIELD_ENTRY)};
static const field_info grid_fields[] = {CW_FIELDS_cw_grid(FIELD_ENTRY)};
static const field_info result_fields[] = {CW_FIELDS_cw_result(FIELD_ENTRY)};
static const field_info patch_fields[] = {CW_FIELDS_cw_patch(FIELD_ENTRY)};
static const field_info tparams_fields[] = {CW_FIELDS_cw_temperature_params(FIELD_ENTRY)};
static const field_info tresult_fields[] = {CW_FIELDS_cw_temperature_result(FIELD_ENTRY)};
static const field_info dparams_fields[] = {CW_FIELDS_cw_damage_params(FIELD_ENTRY)};
static const field_info dresult_fields[] = {CW_FIELDS_cw_damage_result(FIELD_ENTRY)};
static const field_info tinput_fields[] = {CW_FIELDS_cw_transient_input(FIELD_ENTRY)};
static const field_info tstep_fields[] = {CW_FIELDS_cw_transient_result(FIELD_ENTRY)};
static const field_info wparams_fields[] = {CW_FIELDS_cw_wear_params(FIELD_ENTRY)};
#undef FIELD_ENTRY
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))
static const struct_info PARAMS = {"cw_params", params_fields, COUNT(params_fields)};
static const struct_info GRID = {"cw_grid", grid_fields, COUNT(grid_fields)};
static const struct_info RESULT = {"cw_result", result_fields, COUNT(result_fields)};
static const struct_info PATCH = {"cw_patch", patch_fields, COUNT(patch_fields)};
static const struct_info TPARAMS = {"cw_temperature_params", tparams_fields,
                                    COUNT(tparams_fields)};
static const struct_info TRESULT = {"cw_temperature_result", tresult_fields,
                                    COUNT(tresult_fields)};
static const struct_info DPARAMS = {"cw_damage_params", dparams_fields, COUNT(dparams_fields)};
static const struct_info DRESULT = {"cw_damage_result", dresult_fields, COUNT(dresult_fields)};
static const struct_info TINPUT = {"cw_transient_input", tinput_fields, COUNT(tinput_fields)};
static const struct_info TSTEP = {"cw_transient_result", tstep_fields, COUNT(tstep_fields)};
static const struct_info WPARAMS = {"cw_wear_params", wparams_fields, COUNT(wparams_fields)};

typedef struct {
    const char* struct_name;
    const char* field;
    const char* name;
    double value;
} enum_info;
#define ENUM_ENTRY(s, f, n, v) {#s, #f, n, v},
static const enum_info enums[] = {CW_ENUMS(ENUM_ENTRY)};
#undef ENUM_ENTRY

typedef struct {
    const char* name;
    double value;
} constant_info;
#define CONSTANT_ENTRY(c) {#c, (double)(c)},
static const constant_info constants[] = {CW_CONSTANTS(CONSTANT_ENTRY)};
#undef CONSTANT_ENTRY

#define STATUS_ENTRY(name, value, message) {#name, value},
static const struct {
    const char* name;
    int value;
} statuses[] = {CW_STATUS_LIST(STATUS_ENTRY)};
#undef STATUS_ENTRY

/* ----------------------------------------------------------------- errors */

static void fail_status(int status, const char* detail)
{
    char id[80] = "creepwork:unknownStatus";
    for (size_t k = 0; k < COUNT(statuses); ++k)
        if (statuses[k].value == status) snprintf(id, sizeof id, "creepwork:%s", statuses[k].name);
    mexErrMsgIdAndTxt(id, "%s", detail && *detail ? detail : cw_status_string(status));
}

#define FAIL(id, ...) mexErrMsgIdAndTxt("creepwork:" id, __VA_ARGS__)

/* ------------------------------------------------------- MATLAB -> C structs */

static const field_info* find_exact(const struct_info* s, const char* name)
{
    for (size_t k = 0; k < s->n_fields; ++k)
        if (strcmp(s->fields[k].name, name) == 0 && strcmp(name, "struct_size") != 0)
            return &s->fields[k];
    return NULL;
}

/* The field a name gives: its own, or the library's alias (N, spin). */
static const field_info* find_field(const struct_info* s, const char* name)
{
    const field_info* f = find_exact(s, name);
    char canonical[64];
    if (!f && cw_input_name(name, canonical, sizeof canonical) == CW_OK)
        f = find_exact(s, canonical);
    return f;
}

static void unknown_field(const struct_info* s, const char* name)
{
    char list[1024] = "";
    for (size_t k = 1; k < s->n_fields; ++k) {
        strncat(list, s->fields[k].name, sizeof list - strlen(list) - 1);
        if (k + 1 < s->n_fields) strncat(list, ", ", sizeof list - strlen(list) - 1);
    }
    /* A field of the other struct: say where it goes. */
    const char* hint = "";
    if (s == &PARAMS && find_field(&GRID, name))
        hint = "; it is a field of the grid: give it in 'grid', struct(...)";
    else if (s == &GRID && find_field(&PARAMS, name))
        hint = "; it is a contact's parameter, not a field of the grid";
    FAIL("unknownField", "'%s' is not a field of %s (%s%s)%s", name, s->struct_name,
         s == &PARAMS ? "N, " : "", list, hint);
}

/* The number an enumeration name stands for, e.g. model 'exact'. */
static double enum_value(const struct_info* s, const field_info* f, const mxArray* v)
{
    char name[64], canonical[64];
    if (mxGetString(v, name, sizeof name) != 0) name[sizeof name - 1] = '\0';
    /* the library's spelling: strips, fast, Semi-Hertz ... */
    if (cw_input_name(name, canonical, sizeof canonical) != CW_OK) strcpy(canonical, name);
    char known[256] = "";
    for (size_t k = 0; k < COUNT(enums); ++k) {
        if (strcmp(enums[k].struct_name, s->struct_name) || strcmp(enums[k].field, f->name))
            continue;
        if (strcmp(enums[k].name, name) == 0 || strcmp(enums[k].name, canonical) == 0)
            return enums[k].value;
        strncat(known, *known ? ", " : "", sizeof known - strlen(known) - 1);
        strncat(known, enums[k].name, sizeof known - strlen(known) - 1);
    }
    mexErrMsgIdAndTxt("creepwork:CW_ERR_UNKNOWN_OPTION", "%s = '%s' is not one of %s", f->name,
                      name, *known ? known : "(no names: give a number)");
    return 0.0;
}

/* Writes value into the struct at f (element k of an array field). */
static void store(void* base, const field_info* f, double value, int k)
{
    char* at = (char*)base + f->offset;
    if (f->kind != K_DOUBLE && f->kind != K_FLOAT) {
        if (!(value == floor(value)) || fabs(value) > 9e15)
            FAIL("notInteger", "%s must be an integer (got %g)", f->name, value);
        /* The C type's range: a cast out of it would be undefined. */
        const int is_signed = f->kind == K_INT || f->kind == K_INT32 || f->kind == K_INT64 ||
                              f->kind == K_CHAR;
        const double top = f->kind == K_INT || f->kind == K_INT32   ? 2147483647.0
                           : f->kind == K_UNSIGNED || f->kind == K_UINT32 ? 4294967295.0
                           : f->kind == K_CHAR                          ? 127.0
                                                                        : 9e15;
        if (value > top || value < (is_signed ? -top - 1.0 : 0.0))
            mexErrMsgIdAndTxt("creepwork:CW_ERR_INVALID_INPUT",
                              "%s = %.17g is outside the range of its C type", f->name, value);
    }
    switch (f->kind) {
    case K_DOUBLE: ((double*)at)[k] = value; break;
    case K_FLOAT: ((float*)at)[k] = (float)value; break;
    case K_INT: ((int*)at)[k] = (int)value; break;
    case K_UNSIGNED: ((unsigned*)at)[k] = (unsigned)value; break;
    case K_SIZE_T: ((size_t*)at)[k] = (size_t)value; break;
    case K_INT32: ((int32_t*)at)[k] = (int32_t)value; break;
    case K_UINT32: ((uint32_t*)at)[k] = (uint32_t)value; break;
    case K_INT64: ((int64_t*)at)[k] = (int64_t)value; break;
    case K_UINT64: ((uint64_t*)at)[k] = (uint64_t)value; break;
    case K_CHAR: ((char*)at)[k] = (char)value; break;
    case K_POINTER: break;
    }
}

static double load(const void* base, const field_info* f, int k)
{
    const char* at = (const char*)base + f->offset;
    switch (f->kind) {
    case K_DOUBLE: return ((const double*)at)[k];
    case K_FLOAT: return ((const float*)at)[k];
    case K_INT: return ((const int*)at)[k];
    case K_UNSIGNED: return ((const unsigned*)at)[k];
    case K_SIZE_T: return (double)((const size_t*)at)[k];
    case K_INT32: return ((const int32_t*)at)[k];
    case K_UINT32: return ((const uint32_t*)at)[k];
    case K_INT64: return (double)((const int64_t*)at)[k];
    case K_UINT64: return (double)((const uint64_t*)at)[k];
    case K_CHAR: return ((const char*)at)[k];
    case K_POINTER: return 0.0;
    }
    return 0.0;
}

/* Element `index` of a MATLAB value given for field f (a scalar stands for
 * every contact; an array gives one value per contact). */
static double value_at(const struct_info* s, const field_info* f, const mxArray* v, size_t index)
{
    if (mxIsChar(v)) return enum_value(s, f, v);
    if (!(mxIsNumeric(v) || mxIsLogical(v)) || mxIsComplex(v) || mxIsEmpty(v))
        FAIL("badValue", "%s must be a real number%s", f->name,
             mxIsEmpty(v) ? " (got an empty array)" : "");
    if (mxGetNumberOfElements(v) == 1) return mxGetScalar(v);
    if (!mxIsDouble(v)) FAIL("badValue", "%s: an array of values must be double", f->name);
    return mxGetPr(v)[index];
}

/* The number of contacts a struct of inputs describes: 1, or the number of
 * elements of its array fields (all the same); dims of the first. */
static size_t contact_count(const mxArray* in, const mxArray** shape)
{
    size_t n = 1;
    *shape = NULL;
    if (!in || mxIsEmpty(in)) return 1;
    for (int k = 0; k < mxGetNumberOfFields(in); ++k) {
        const mxArray* v = mxGetFieldByNumber(in, 0, k);
        if (!v || mxIsChar(v)) continue;
        const size_t m = mxGetNumberOfElements(v);
        if (m == 1) continue;
        if (n == 1) {
            n = m;
            *shape = v;
        } else if (m != n) {
            FAIL("sizeMismatch", "%s has %zu values, another field %zu: array fields must have "
                 "one value per contact", mxGetFieldNameByNumber(in, k), m, n);
        }
    }
    return n;
}

/* Fills out (count structs of s's type, each initialised) from in, a 1x1
 * struct whose fields are scalars or arrays of count values. */
static void to_structs(const struct_info* s, const mxArray* in, void* out, size_t size,
                       size_t count)
{
    if (!in || mxIsEmpty(in)) return;
    if (!mxIsStruct(in) || mxGetNumberOfElements(in) != 1)
        FAIL("badValue", "the %s inputs must be one struct (fields: the C struct's)",
             s->struct_name);
    for (int k = 0; k < mxGetNumberOfFields(in); ++k) {
        const char* name = mxGetFieldNameByNumber(in, k);
        const field_info* f = find_field(s, name);
        if (!f) unknown_field(s, name);
        const mxArray* v = mxGetFieldByNumber(in, 0, k);
        if (!v) continue;
        if (f->kind == K_POINTER || f->count > 1) {
            if (count != 1) FAIL("badValue", "%s: give one value for all contacts", f->name);
            if (f->kind == K_POINTER) {
                if (!mxIsDouble(v) || mxIsComplex(v))
                    FAIL("badValue", "%s must be a real double array", f->name);
                *(void**)((char*)out + f->offset) = mxGetPr(v);
                /* Its length field (gap -> gap_len) follows the array unless
                   the struct gives it too. */
                char length_name[64];
                snprintf(length_name, sizeof length_name, "%s_len", f->name);
                const field_info* length = find_field(s, length_name);
                if (length && mxGetFieldNumber(in, length_name) < 0)
                    store(out, length, (double)mxGetNumberOfElements(v), 0);
                continue;
            }
            if (mxGetNumberOfElements(v) != (size_t)f->count || !mxIsDouble(v))
                FAIL("badValue", "%s must be %d doubles", f->name, f->count);
            for (int e = 0; e < f->count; ++e) store(out, f, mxGetPr(v)[e], e);
            continue;
        }
        for (size_t c = 0; c < count; ++c) store((char*)out + c * size, f, value_at(s, f, v, c), 0);
    }
}

/* --------------------------------------------------------- C -> MATLAB */

static mxArray* shaped(const mxArray* shape, size_t count)
{
    if (!shape) return mxCreateDoubleMatrix(count == 1 ? 1 : count, 1, mxREAL);
    return mxCreateNumericArray(mxGetNumberOfDimensions(shape), mxGetDimensions(shape),
                                mxDOUBLE_CLASS, mxREAL);
}

/* A struct of every field of count C structs (scalars, or arrays shaped like shape). */
static mxArray* from_structs(const struct_info* s, const void* in, size_t size, size_t count,
                             const mxArray* shape, size_t extra_fields, const char** extra)
{
    const char** names = mxMalloc((s->n_fields + extra_fields) * sizeof *names);
    int n = 0;
    for (size_t k = 1; k < s->n_fields; ++k) names[n++] = s->fields[k].name;
    for (size_t k = 0; k < extra_fields; ++k) names[n++] = extra[k];
    mxArray* out = mxCreateStructMatrix(1, 1, n, names);
    mxFree(names);
    for (size_t k = 1; k < s->n_fields; ++k) {
        const field_info* f = &s->fields[k];
        mxArray* v;
        if (f->count > 1) {
            v = mxCreateDoubleMatrix(1, (size_t)f->count, mxREAL);
            for (int e = 0; e < f->count; ++e) mxGetPr(v)[e] = load(in, f, e);
        } else {
            v = count == 1 ? mxCreateDoubleMatrix(1, 1, mxREAL) : shaped(shape, count);
            for (size_t c = 0; c < count; ++c) mxGetPr(v)[c] = load((const char*)in + c * size, f, 0);
        }
        mxSetField(out, 0, f->name, v);
    }
    return out;
}

/* -------------------------------------------- the library's policy */

/* The name the user gave the load in the struct: "N" or "normal_force". */
static const char* load_name(const mxArray* params_in)
{
    return params_in && mxIsStruct(params_in) && mxGetFieldNumber(params_in, "N") >= 0
               ? "N"
               : "normal_force";
}

/* message with the load named as the user typed it (in place). */
static void as_typed(const mxArray* params_in, char* message, size_t len)
{
    if (strcmp(load_name(params_in), "N") != 0) return;
    char out[MESSAGE_LEN] = "";
    const char* field = "normal_force";
    const size_t n = strlen(field);
    for (const char* at = message; *at;) {
        const char* hit = strstr(at, field);
        const int word = hit && (hit == message || !(isalnum((unsigned char)hit[-1]) || hit[-1] == '_')) &&
                         !(isalnum((unsigned char)hit[n]) || hit[n] == '_');
        const size_t keep = hit ? (size_t)(hit - at) + (word ? 0 : n) : strlen(at);
        strncat(out, at, keep < sizeof out - strlen(out) - 1 ? keep : sizeof out - strlen(out) - 1);
        if (!hit) break;
        if (word) strncat(out, "N", sizeof out - strlen(out) - 1);
        at = hit + n;
    }
    snprintf(message, len, "%s", out);
}

/* a, b and N: required, as at every door (no sensible default); a gap's
 * load: N, or normal_load 'approach'. */
static void require_geometry(const mxArray* params_in)
{
    const int has = params_in && mxIsStruct(params_in);
    const int gap = has && mxGetFieldNumber(params_in, "gap") >= 0;
    const int load = has && (mxGetFieldNumber(params_in, "N") >= 0 ||
                             mxGetFieldNumber(params_in, "normal_force") >= 0);
    if (gap) {
        if (!load && !(has && mxGetFieldNumber(params_in, "normal_load") >= 0))
            FAIL("missingInput", "N: missing: a gap's load, N or 'normal_load', 'approach' with "
                 "'approach'");
        return;
    }
    char missing[32] = "";
    if (!has || mxGetFieldNumber(params_in, "a") < 0) strcat(missing, "a");
    if (!has || mxGetFieldNumber(params_in, "b") < 0) strcat(missing, *missing ? ", b" : "b");
    if (!load) strcat(missing, *missing ? ", N" : "N");
    if (*missing)
        FAIL("missingInput", "%s: missing: the contact's semi-axes and load have no sensible "
             "default (e.g. 'a', 6e-3, 'b', 6e-3, 'N', 80e3: a 6 mm circle under 80 kN; a, b "
             "from the radii: creepwork.hertz)", missing);
}

/* A 2-D gap must be nx-by-ny: x along the first dimension, MATLAB's
 * column-major order being the library's [i + j*nx]. */
static void check_gap_shape(const mxArray* params_in, int nx, int ny)
{
    const mxArray* g = params_in && mxIsStruct(params_in) ? mxGetField(params_in, 0, "gap") : NULL;
    if (!g || mxGetNumberOfDimensions(g) != 2) return;
    const size_t rows = mxGetM(g), cols = mxGetN(g);
    if (rows == 1 || cols == 1 || (rows == (size_t)nx && cols == (size_t)ny)) return;
    mexErrMsgIdAndTxt("creepwork:CW_ERR_INVALID_INPUT",
                      "gap is %zu-by-%zu; the grid's nx = %d cells along x and ny = %d along y "
                      "need an nx-by-ny matrix (%d-by-%d): x along the first dimension, gap(i, j) "
                      "at x0 + (i-1)*dx, y0 + (j-1)*dy%s",
                      rows, cols, nx, ny, nx, ny,
                      rows == (size_t)ny && cols == (size_t)nx ? " (transposed: gap.' has that size)" : "");
}

/* The library's plausibility checks of count contacts on grid, one warning
 * per rule, the load named as typed. */
static void warn_units(const cw_grid* grid, const cw_params* p, size_t count,
                       const mxArray* params_in)
{
    size_t found = 0;
    if (cw_params_check(grid, p, count, NULL, 0, &found) != CW_OK || found == 0) return;
    cw_check* c = mxCalloc(found, sizeof *c);
    for (size_t k = 0; k < found; ++k) cw_check_init(&c[k]);
    if (cw_params_check(grid, p, count, c, found, &found) == CW_OK)
        for (size_t k = 0; k < found; ++k) {
            char text[sizeof c[k].message];
            snprintf(text, sizeof text, "%s", c[k].message);
            as_typed(params_in, text, sizeof text);
            mexWarnMsgIdAndTxt("creepwork:implausibleUnits", "%s", text);
        }
    mxFree(c);
}

/* ------------------------------------------------------------- solvers */

static cw_solver* solvers[MAX_SOLVERS]; /* handles of creepwork.Solver objects */
static cw_grid solver_grids[MAX_SOLVERS]; /* their grids, for the checks */
static int directions[MAX_SOLVERS];     /* rolling_direction of each one's last solve */

static cw_transient* transients[MAX_SOLVERS]; /* handles of creepwork.Transient objects */
static int transient_nx[MAX_SOLVERS], transient_ny[MAX_SOLVERS];

static void destroy_all(void)
{
    for (int k = 0; k < MAX_SOLVERS; ++k) {
        cw_solver_destroy(solvers[k]);
        solvers[k] = NULL;
        cw_transient_destroy(transients[k]);
        transients[k] = NULL;
    }
}

static int solver_id(const mxArray* v)
{
    const double id = (v && mxGetNumberOfElements(v) == 1 && mxIsNumeric(v)) ? mxGetScalar(v) : 0;
    if (!(id >= 1 && id <= MAX_SOLVERS && id == floor(id)) || !solvers[(int)id - 1])
        FAIL("badHandle", "no such creepwork solver (closed, or not made by creepwork.Solver)");
    return (int)id - 1;
}

static cw_grid grid_of(const mxArray* grid_in)
{
    cw_grid grid;
    cw_grid_init(&grid);
    to_structs(&GRID, grid_in, &grid, sizeof grid, 1);
    return grid;
}

static cw_solver* make_solver(const cw_grid* grid)
{
    cw_solver* s = NULL;
    char message[MESSAGE_LEN] = "";
    const int status = cw_solver_create(grid, &s, message, sizeof message);
    if (status != CW_OK) fail_status(status, message);
    return s;
}

static int flag(const mxArray* v)
{
    return v && !mxIsEmpty(v) && mxGetScalar(v) != 0.0;
}

/* One contact's parameters on grid: required inputs, the gap's shape,
 * then the library's checks. */
static cw_params params_of(const mxArray* params_in, const cw_grid* grid)
{
    require_geometry(params_in);
    if (grid->kind == CW_GRID_GAP) check_gap_shape(params_in, grid->nx, grid->ny);
    cw_params p;
    cw_params_init(&p);
    to_structs(&PARAMS, params_in, &p, sizeof p, 1);
    warn_units(grid, &p, 1, params_in);
    return p;
}

/* The separate patches of the last solve (cw_solver_get_patches): one
 * struct of cw_patch's fields, each a column with an entry per patch. */
static mxArray* patches_of(cw_solver* s)
{
    size_t count = 0;
    cw_solver_get_patches(s, NULL, 0, &count);
    cw_patch* p = mxCalloc(count ? count : 1, sizeof *p);
    for (size_t k = 0; k < count; ++k) cw_patch_init(&p[k]);
    if (count) cw_solver_get_patches(s, p, count, &count);
    mxArray* out = from_structs(&PATCH, p, sizeof *p, count, NULL, 0, NULL);
    mxFree(p);
    return out;
}

static mxArray* solved_result(cw_solver* s, int owned, const cw_result* r, int fields,
                              const double* jac);

/* One solve of p on s: totals and patches, and with fields the per-element maps,
 * states and profile; with jacobian the 4 x 4 matrix. On error s is
 * destroyed first when owned (an error does not return). */
static mxArray* solve_one(cw_solver* s, int owned, cw_params p, int fields, int jacobian,
                          const mxArray* params_in)
{
    cw_result r;
    cw_result_init(&r);
    double jac[CW_JACOBIAN_LEN];
    const int mode = fields ? CW_SOLVE_FULL : CW_SOLVE_FORCES;
    int status = jacobian ? cw_solver_solve_jacobian(s, &p, mode, &r, jac, CW_JACOBIAN_LEN)
                          : cw_solver_solve(s, &p, mode, &r);
    if (status != CW_OK) {
        char message[MESSAGE_LEN];
        snprintf(message, sizeof message, "%s", cw_solver_last_error(s));
        as_typed(params_in, message, sizeof message);
        if (owned) cw_solver_destroy(s);
        fail_status(status, message);
    }
    return solved_result(s, owned, &r, fields, jacobian ? jac : NULL);
}

/* The result of s's last solve r: totals and patches, with fields the maps,
 * states and profile, with jac the 4 x 4 matrix. */
static mxArray* solved_result(cw_solver* s, int owned, const cw_result* rp, int fields,
                              const double* jac)
{
    cw_result r = *rp;
    const int jacobian = jac != NULL;
    int status = CW_OK;
    static const char* extra_names[] = {"fields", "state", "profile", "jacobian", "patches"};
    mxArray* out = from_structs(&RESULT, &r, sizeof r, 1, NULL, 5, extra_names);
    mxSetField(out, 0, "patches", patches_of(s));
    if (jacobian) {
        mxArray* j = mxCreateDoubleMatrix(4, 4, mxREAL);
        for (int row = 0; row < 4; ++row) /* C row-major -> MATLAB column-major */
            for (int col = 0; col < 4; ++col) mxGetPr(j)[row + 4 * col] = jac[4 * row + col];
        mxSetField(out, 0, "jacobian", j);
    }
    if (!fields) return out;
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    const size_t n = (size_t)nx * (size_t)ny;
    /* The CW_FIELD_* constants of the header, by their lower-case names. */
    const char* names[64];
    double ids[64];
    int nf = 0;
    char lower[64][48];
    for (size_t k = 0; k < COUNT(constants) && nf < 64; ++k) {
        if (strncmp(constants[k].name, "CW_FIELD_", 9) != 0) continue;
        size_t c = 0;
        for (const char* t = constants[k].name + 9; *t && c + 1 < sizeof lower[0]; ++t)
            lower[nf][c++] = (char)(*t >= 'A' && *t <= 'Z' ? *t - 'A' + 'a' : *t);
        lower[nf][c] = '\0';
        names[nf] = lower[nf];
        ids[nf++] = constants[k].value;
    }
    mxArray* maps = mxCreateStructMatrix(1, 1, nf, names);
    for (int k = 0; k < nf; ++k) {
        mxArray* m = mxCreateDoubleMatrix((size_t)nx, (size_t)ny, mxREAL);
        status = cw_solver_get_field(s, (int)ids[k], mxGetPr(m), n);
        if (status != CW_OK) {
            if (owned) cw_solver_destroy(s);
            fail_status(status, "reading a field");
        }
        mxSetField(maps, 0, names[k], m);
    }
    mxSetField(out, 0, "fields", maps);
    int* state = mxMalloc(n * sizeof *state);
    status = cw_solver_get_state(s, state, n);
    mxArray* st = mxCreateDoubleMatrix((size_t)nx, (size_t)ny, mxREAL);
    for (size_t k = 0; k < n; ++k) mxGetPr(st)[k] = state[k];
    mxFree(state);
    mxSetField(out, 0, "state", st);
    static const char* profile_names[] = {"y", "w", "parabola"};
    mxArray* prof = mxCreateStructMatrix(1, 1, 3, profile_names);
    mxArray* y = mxCreateDoubleMatrix((size_t)ny, 1, mxREAL);
    mxArray* w = mxCreateDoubleMatrix((size_t)ny, 1, mxREAL);
    mxArray* par = mxCreateDoubleMatrix((size_t)ny, 1, mxREAL);
    if (status == CW_OK)
        status = cw_solver_get_profile(s, mxGetPr(y), mxGetPr(w), mxGetPr(par), (size_t)ny);
    if (status != CW_OK) {
        if (owned) cw_solver_destroy(s);
        fail_status(status, "reading the states or the profile");
    }
    mxSetField(prof, 0, "y", y);
    mxSetField(prof, 0, "w", w);
    mxSetField(prof, 0, "parabola", par);
    mxSetField(out, 0, "profile", prof);
    return out;
}

/* ------------------------------------------------- surface post-processors */

/* The library's plausibility checks of a surface post-processor's
 * parameters (tp, else dp), one warning per finding: its inputs are typed
 * by their field names. At most 7 findings (6 thermal properties and the
 * speed; 4 of damage). */
static void warn_surface_units(const cw_temperature_params* tp, const cw_damage_params* dp)
{
    enum { MAX_FINDINGS = 16 };
    cw_check c[MAX_FINDINGS];
    size_t found = 0;
    for (int k = 0; k < MAX_FINDINGS; ++k) cw_check_init(&c[k]);
    const int status = tp ? cw_temperature_params_check(tp, c, MAX_FINDINGS, &found)
                          : cw_damage_params_check(dp, c, MAX_FINDINGS, &found);
    if (status == CW_OK)
        for (size_t k = 0; k < found; ++k)
            mexWarnMsgIdAndTxt("creepwork:implausibleUnits", "%s", c[k].message);
}

/* An nx-by-ny matrix of one field of a temperature or damage handle. */
static mxArray* handle_field(int (*get)(const void*, int, double*, size_t), const void* h, int id,
                             int nx, int ny)
{
    mxArray* m = mxCreateDoubleMatrix((size_t)nx, (size_t)ny, mxREAL);
    if (get(h, id, mxGetPr(m), (size_t)nx * (size_t)ny) != CW_OK)
        FAIL("internal", "reading a field of a surface post-processor");
    return m;
}

static int temperature_field(const void* h, int id, double* out, size_t n)
{
    return cw_temperature_get_field((const cw_temperature*)h, id, out, n);
}

static int damage_field(const void* h, int id, double* out, size_t n)
{
    return cw_damage_get_field((const cw_damage*)h, id, out, n);
}

/* Both bodies' temperatures of s's last solve (the result's fields, and
 * rail, wheel, heat as nx-by-ny matrices); with table (count points, its
 * temperatures then its mu, count >= 0) solved with friction mu(T) first
 * (cw_temperature_solve of params p, the loop's defaults). */
static mxArray* temperature_of(cw_solver* s, const cw_temperature_params* tp,
                               const cw_params* p, const double* table, size_t count)
{
    cw_temperature* t = NULL;
    int status = cw_temperature_create(s, &t);
    if (status != CW_OK) fail_status(status, "making the temperature workspace");
    cw_temperature_result r;
    cw_temperature_result_init(&r);
    if (p) {
        cw_mu_temperature m;
        cw_mu_temperature_init(&m);
        m.count = count;
        m.temperature = count ? table : NULL;
        m.mu = count ? table + count : NULL;
        status = cw_temperature_solve(t, s, p, tp, &m, NULL, &r);
    } else {
        status = cw_temperature_compute(t, s, tp, &r);
    }
    if (status != CW_OK) {
        char message[MESSAGE_LEN];
        snprintf(message, sizeof message, "%s", cw_temperature_last_error(t));
        cw_temperature_destroy(t);
        fail_status(status, message);
    }
    static const char* extra[] = {"rail", "wheel", "heat"};
    mxArray* out = from_structs(&TRESULT, &r, sizeof r, 1, NULL, 3, extra);
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    const int ids[] = {CW_TEMPERATURE_FIELD_RAIL, CW_TEMPERATURE_FIELD_WHEEL,
                       CW_TEMPERATURE_FIELD_HEAT};
    for (int k = 0; k < 3; ++k)
        mxSetField(out, 0, extra[k], handle_field(temperature_field, t, ids[k], nx, ny));
    cw_temperature_destroy(t);
    return out;
}

/* The damage indices of s's last solve (the result's fields, and
 * rcf_index, t_gamma_density as nx-by-ny matrices). */
static mxArray* damage_of(cw_solver* s, const cw_damage_params* p)
{
    cw_damage* d = NULL;
    int status = cw_damage_create(s, &d);
    if (status != CW_OK) fail_status(status, "making the damage workspace");
    cw_damage_result r;
    cw_damage_result_init(&r);
    status = cw_damage_compute(d, s, p, &r);
    if (status != CW_OK) {
        char message[MESSAGE_LEN];
        snprintf(message, sizeof message, "%s", cw_damage_last_error(d));
        cw_damage_destroy(d);
        fail_status(status, message);
    }
    static const char* extra[] = {"rcf_index", "t_gamma_density"};
    mxArray* out = from_structs(&DRESULT, &r, sizeof r, 1, NULL, 2, extra);
    int nx = 0, ny = 0;
    cw_solver_grid_size(s, &nx, &ny);
    const int ids[] = {CW_DAMAGE_FIELD_RCF_INDEX, CW_DAMAGE_FIELD_T_GAMMA_DENSITY};
    for (int k = 0; k < 2; ++k)
        mxSetField(out, 0, extra[k], handle_field(damage_field, d, ids[k], nx, ny));
    cw_damage_destroy(d);
    return out;
}

/* After each part of a solve_many: progress(done, total), a function
 * handle. Its error is raised again once the batch is destroyed. */
static void call_progress(const mxArray* progress, size_t done, size_t count, cw_batch* batch)
{
    mxArray* args[3] = {(mxArray*)progress, mxCreateDoubleScalar((double)done),
                        mxCreateDoubleScalar((double)count)};
    mxArray* error = mexCallMATLABWithTrap(0, NULL, 3, args, "feval");
    mxDestroyArray(args[1]);
    mxDestroyArray(args[2]);
    if (!error) return;
    cw_batch_destroy(batch);
    mexCallMATLAB(0, NULL, 1, &error, "rethrow");
}

/* Many contacts in one cw_batch_solve call; with a progress function handle
 * in about a hundred calls (the same results bitwise), after each of which
 * it is called. */
static mxArray* solve_many(const mxArray* params_in, const mxArray* grid_in, int full, int threads,
                           const mxArray* progress)
{
    if (progress && !mxIsClass(progress, "function_handle"))
        FAIL("badValue", "progress must be a function handle");
    const mxArray* shape = NULL;
    const size_t count = contact_count(params_in, &shape);
    cw_params* p = mxMalloc(count * sizeof *p);
    cw_result* r = mxMalloc(count * sizeof *r);
    int* st = mxMalloc(count * sizeof *st);
    for (size_t c = 0; c < count; ++c) {
        cw_params_init(&p[c]);
        cw_result_init(&r[c]);
    }
    require_geometry(params_in);
    to_structs(&PARAMS, params_in, p, sizeof *p, count);
    const cw_grid grid = grid_of(grid_in);
    warn_units(&grid, p, count, params_in);
    cw_batch* batch = NULL;
    char message[MESSAGE_LEN] = "";
    int status = cw_batch_create(&grid, threads, &batch, message, sizeof message);
    if (status != CW_OK) fail_status(status, message);
    const int mode = full ? CW_SOLVE_FULL : CW_SOLVE_FORCES;
    const size_t step = progress ? (count + 99) / 100 : count;
    for (size_t first = 0; first < count; first += step) {
        const size_t n = count - first < step ? count - first : step;
        status = cw_batch_solve(batch, n, p + first, mode, r + first, st + first);
        if (progress) call_progress(progress, first + n, count, batch);
    }
    cw_batch_destroy(batch);
    static const char* extra_names[] = {"status", "message"};
    mxArray* out = from_structs(&RESULT, r, sizeof *r, count, shape, 2, extra_names);
    mxArray* codes = count == 1 ? mxCreateDoubleMatrix(1, 1, mxREAL) : shaped(shape, count);
    mxArray* messages = mxCreateCellArray(mxGetNumberOfDimensions(codes), mxGetDimensions(codes));
    /* A failed contact: its own message by solving it again alone (the batch
     * keeps the first failure's only), and NaN totals. */
    cw_solver* one = NULL;
    for (size_t c = 0; c < count; ++c) {
        mxGetPr(codes)[c] = st[c];
        const char* text = "";
        char typed[MESSAGE_LEN]; /* text points here until mxCreateString copies it */
        if (st[c] != CW_OK) {
            if (!one && cw_solver_create(&grid, &one, NULL, 0) != CW_OK) one = NULL;
            p[c].warm_start = 0;
            text = one && cw_solver_solve(one, &p[c], mode, NULL) == st[c]
                       ? cw_solver_last_error(one)
                       : cw_status_string(st[c]);
            snprintf(typed, sizeof typed, "%s", text);
            as_typed(params_in, typed, sizeof typed);
            text = typed;
            for (size_t k = 1; k < RESULT.n_fields; ++k)
                if (RESULT.fields[k].kind == K_DOUBLE && RESULT.fields[k].count <= 1)
                    mxGetPr(mxGetField(out, 0, RESULT.fields[k].name))[c] = mxGetNaN();
        }
        mxSetCell(messages, c, mxCreateString(text));
    }
    cw_solver_destroy(one);
    mxSetField(out, 0, "status", codes);
    mxSetField(out, 0, "message", messages);
    mxFree(p);
    mxFree(r);
    mxFree(st);
    (void)status; /* each contact's status is in the output */
    return out;
}

/* ------------------------------------------------------ transient rolling */

static int transient_id(const mxArray* v)
{
    const double id = (v && mxGetNumberOfElements(v) == 1 && mxIsNumeric(v)) ? mxGetScalar(v) : 0;
    if (!(id >= 1 && id <= MAX_SOLVERS && id == floor(id)) || !transients[(int)id - 1])
        FAIL("badHandle", "no such creepwork transient (closed, or not made by creepwork.Transient)");
    return (int)id - 1;
}

/* A creepwork.Transient's handle from grid and params (a gap grid, the
 * exact model): the normal problem is solved here. */
static int transient_create(const mxArray* grid_in, const mxArray* params_in)
{
    int k = 0;
    while (k < MAX_SOLVERS && transients[k]) ++k;
    if (k == MAX_SOLVERS) FAIL("tooManySolvers", "more than %d transients open", MAX_SOLVERS);
    const cw_grid grid = grid_of(grid_in);
    const cw_params p = params_of(params_in, &grid);
    char message[MESSAGE_LEN] = "";
    const int status = cw_transient_create(&grid, &p, &transients[k], message, sizeof message);
    if (status != CW_OK) {
        as_typed(params_in, message, sizeof message);
        fail_status(status, message);
    }
    transient_nx[k] = grid.nx;
    transient_ny[k] = grid.ny;
    return k;
}

/* The handle's status as an error with its message (an error does not return). */
static void transient_check(int k, int status)
{
    if (status != CW_OK) fail_status(status, cw_transient_last_error(transients[k]));
}

/* One step (or, with steady, the steady start) of input_in; with commit the
 * step becomes the state. Returns cw_transient_result's fields. */
static mxArray* transient_step(int k, const mxArray* input_in, int steady, int commit)
{
    cw_transient_input in;
    cw_transient_input_init(&in);
    to_structs(&TINPUT, input_in, &in, sizeof in, 1);
    cw_transient_result r;
    cw_transient_result_init(&r);
    transient_check(k, steady ? cw_transient_start_steady(transients[k], &in, &r)
                              : cw_transient_step(transients[k], &in, &r));
    if (commit) transient_check(k, cw_transient_commit(transients[k]));
    return from_structs(&TSTEP, &r, sizeof r, 1, NULL, 0, NULL);
}

/* The fields of the last step as nx-by-ny matrices, and its element states. */
static mxArray* transient_fields(int k)
{
    static const char* names[] = {"x", "y", "pz", "px", "py", "sx", "sy", "work", "state"};
    static const int ids[] = {CW_FIELD_X,  CW_FIELD_Y,  CW_FIELD_PZ, CW_FIELD_PX,
                              CW_FIELD_PY, CW_FIELD_SX, CW_FIELD_SY, CW_FIELD_WORK_CONSISTENT};
    const size_t nx = (size_t)transient_nx[k], ny = (size_t)transient_ny[k], n = nx * ny;
    mxArray* out = mxCreateStructMatrix(1, 1, 9, names);
    for (int f = 0; f < 8; ++f) {
        mxArray* m = mxCreateDoubleMatrix(nx, ny, mxREAL);
        mxSetField(out, 0, names[f], m);
        transient_check(k, cw_transient_get_field(transients[k], ids[f], mxGetPr(m), n));
    }
    int* state = mxMalloc(n * sizeof *state);
    const int status = cw_transient_get_state(transients[k], state, n);
    mxArray* st = mxCreateDoubleMatrix(nx, ny, mxREAL);
    for (size_t e = 0; status == CW_OK && e < n; ++e) mxGetPr(st)[e] = state[e];
    mxFree(state);
    mxSetField(out, 0, "state", st);
    transient_check(k, status);
    return out;
}

/* The committed state as a column of uint64 words. */
static mxArray* transient_save(int k)
{
    size_t words = 0;
    transient_check(k, cw_transient_state_size(transients[k], &words));
    mxArray* out = mxCreateNumericMatrix(words, 1, mxUINT64_CLASS, mxREAL);
    transient_check(k, cw_transient_save(transients[k], (uint64_t*)mxGetData(out), words));
    return out;
}

static void transient_restore(int k, const mxArray* state)
{
    if (!state || !mxIsUint64(state) || mxIsComplex(state))
        FAIL("badValue", "state must be the uint64 words of Transient.save (got %s)",
             state ? mxGetClassName(state) : "nothing");
    transient_check(k, cw_transient_restore(transients[k], (const uint64_t*)mxGetData(state),
                                            mxGetNumberOfElements(state)));
}

static double scalar(const mxArray* v, const char* name);

/* The coordinates: 'contact', 'world' or a CW_COORDINATES_* value. */
static void transient_set_coordinates(int k, const mxArray* v)
{
    char text[16] = "";
    int c = -1;
    if (v && mxIsChar(v) && mxGetString(v, text, sizeof text) == 0) {
        if (strcmp(text, "contact") == 0) c = CW_COORDINATES_CONTACT;
        if (strcmp(text, "world") == 0) c = CW_COORDINATES_WORLD;
        if (c < 0) FAIL("badValue", "coordinates = '%s' is not 'contact' or 'world'", text);
    } else {
        c = (int)scalar(v, "coordinates");
    }
    transient_check(k, cw_transient_set_coordinates(transients[k], c));
}

/* The last step's Jacobian as a 3-by-3 matrix: J(r, c) = the C API's
 * jacobian[3 (r-1) + c-1]. */
static mxArray* transient_jacobian(int k)
{
    double J[CW_TRANSIENT_JACOBIAN_LEN];
    transient_check(k, cw_transient_jacobian(transients[k], J, CW_TRANSIENT_JACOBIAN_LEN));
    mxArray* out = mxCreateDoubleMatrix(3, 3, mxREAL);
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) mxGetPr(out)[r + 3 * c] = J[3 * r + c];
    return out;
}

/* Adds the last step's wear by the law of params_in (cw_wear_params
 * fields; the defaults otherwise); returns the step's mass [kg]. */
static mxArray* transient_add_wear(int k, const mxArray* params_in)
{
    cw_wear_params w;
    cw_wear_params_init(&w);
    if (params_in) to_structs(&WPARAMS, params_in, &w, sizeof w, 1);
    double mass = 0.0;
    transient_check(k, cw_transient_add_wear(transients[k], &w, &mass));
    return mxCreateDoubleScalar(mass);
}

/* The accumulated wear: mass [kg] and mass_map (nx-by-ny) [kg]. */
static mxArray* transient_wear(int k)
{
    static const char* names[] = {"mass", "mass_map"};
    const size_t nx = (size_t)transient_nx[k], ny = (size_t)transient_ny[k];
    mxArray* out = mxCreateStructMatrix(1, 1, 2, names);
    mxArray* map = mxCreateDoubleMatrix(nx, ny, mxREAL);
    mxSetField(out, 0, "mass_map", map);
    double mass = 0.0;
    transient_check(k, cw_transient_get_wear(transients[k], mxGetPr(map), nx * ny, &mass));
    mxSetField(out, 0, "mass", mxCreateDoubleScalar(mass));
    return out;
}

/* ------------------------------------------------------------- helpers */

static double scalar(const mxArray* v, const char* name)
{
    if (!v || mxGetNumberOfElements(v) != 1 || !(mxIsNumeric(v) || mxIsLogical(v)))
        FAIL("badValue", "%s must be a real number", name);
    return mxGetScalar(v);
}

static mxArray* row(const double* v, int n)
{
    mxArray* out = mxCreateDoubleMatrix(1, (size_t)n, mxREAL);
    memcpy(mxGetPr(out), v, (size_t)n * sizeof *v);
    return out;
}

static mxArray* defaults(const char* which)
{
    if (strcmp(which, "cw_params") == 0) {
        cw_params p;
        cw_params_init(&p);
        return from_structs(&PARAMS, &p, sizeof p, 1, NULL, 0, NULL);
    }
    if (strcmp(which, "cw_grid") == 0) {
        cw_grid g;
        cw_grid_init(&g);
        return from_structs(&GRID, &g, sizeof g, 1, NULL, 0, NULL);
    }
    FAIL("badValue", "defaults of cw_params or cw_grid, not '%s'", which);
    return NULL;
}

static mxArray* constant_struct(void)
{
    const char** names = mxMalloc(COUNT(constants) * sizeof *names);
    for (size_t k = 0; k < COUNT(constants); ++k) names[k] = constants[k].name;
    mxArray* out = mxCreateStructMatrix(1, 1, (int)COUNT(constants), names);
    mxFree(names);
    for (size_t k = 0; k < COUNT(constants); ++k)
        mxSetField(out, 0, constants[k].name, mxCreateDoubleScalar(constants[k].value));
    return out;
}

/* ------------------------------------------------------------ dispatch */

void mexFunction(int nlhs, mxArray* plhs[], int nrhs, const mxArray* prhs[])
{
    static int registered = 0;
    if (!registered) {
        mexAtExit(destroy_all);
        registered = 1;
    }
    (void)nlhs;
    if (nrhs < 1 || !mxIsChar(prhs[0])) FAIL("usage", "creepwork_mex(command, ...)");
    char command[48];
    mxGetString(prhs[0], command, sizeof command);
    const mxArray* a1 = nrhs > 1 ? prhs[1] : NULL;
    const mxArray* a2 = nrhs > 2 ? prhs[2] : NULL;
    const mxArray* a3 = nrhs > 3 ? prhs[3] : NULL;
    const mxArray* a4 = nrhs > 4 ? prhs[4] : NULL;
    char message[MESSAGE_LEN] = "";
    int status = CW_OK;

    if (strcmp(command, "solve") == 0) { /* params, grid, fields, jacobian */
        const cw_grid grid = grid_of(a2);
        const cw_params p = params_of(a1, &grid); /* errors before anything is made */
        cw_solver* s = make_solver(&grid);
        plhs[0] = solve_one(s, 1, p, flag(a3), flag(a4), a1);
        cw_solver_destroy(s);
    } else if (strcmp(command, "solve_many") == 0) { /* params, grid, full, threads, progress */
        plhs[0] = solve_many(a1, a2, flag(a3), a4 ? (int)scalar(a4, "threads") : 0,
                             nrhs > 5 && !mxIsEmpty(prhs[5]) ? prhs[5] : NULL);
    } else if (strcmp(command, "solver_create") == 0) { /* grid -> id */
        int k = 0;
        while (k < MAX_SOLVERS && solvers[k]) ++k;
        if (k == MAX_SOLVERS) FAIL("tooManySolvers", "more than %d solvers open", MAX_SOLVERS);
        solver_grids[k] = grid_of(a1);
        solvers[k] = make_solver(&solver_grids[k]);
        directions[k] = 1;
        int nx = 0, ny = 0;
        cw_solver_grid_size(solvers[k], &nx, &ny);
        plhs[0] = mxCreateDoubleScalar(k + 1);
        if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(nx);
        if (nlhs > 2) plhs[2] = mxCreateDoubleScalar(ny);
    } else if (strcmp(command, "solver_solve") == 0) { /* id, params, fields, jacobian */
        const int k = solver_id(a1);
        const cw_params p = params_of(a2, &solver_grids[k]);
        plhs[0] = solve_one(solvers[k], 0, p, flag(a3), flag(a4), a2);
        directions[k] = p.rolling_direction;
    } else if (strcmp(command, "solver_temperature") == 0) { /* id, params */
        const int k = solver_id(a1);
        cw_temperature_params tp;
        cw_temperature_params_init(&tp);
        tp.rolling_direction = directions[k]; /* the last solve's, unless given */
        to_structs(&TPARAMS, a2, &tp, sizeof tp, 1);
        warn_surface_units(&tp, NULL);
        plhs[0] = temperature_of(solvers[k], &tp, NULL, NULL, 0);
    } else if (strcmp(command, "solver_solve_mu_T") == 0) { /* id, params, tparams, [T mu] */
        const int k = solver_id(a1);
        const cw_params p = params_of(a2, &solver_grids[k]);
        cw_temperature_params tp;
        cw_temperature_params_init(&tp);
        tp.rolling_direction = 0; /* the solve's, unless given */
        to_structs(&TPARAMS, a3, &tp, sizeof tp, 1);
        warn_surface_units(&tp, NULL);
        if (!a4 || !mxIsDouble(a4) || mxIsComplex(a4) || mxGetN(a4) != 2)
            FAIL("badValue", "mu_T: a real matrix of two columns, temperature [deg C] and mu");
        directions[k] = p.rolling_direction;
        plhs[0] = temperature_of(solvers[k], &tp, &p, mxGetPr(a4), mxGetM(a4));
        cw_result r;
        cw_result_init(&r);
        cw_solver_get_result(solvers[k], &r);
        if (nlhs > 1) plhs[1] = solved_result(solvers[k], 0, &r, 1, NULL);
    } else if (strcmp(command, "solver_damage") == 0) { /* id, params */
        const int k = solver_id(a1);
        cw_damage_params dp;
        cw_damage_params_init(&dp);
        to_structs(&DPARAMS, a2, &dp, sizeof dp, 1);
        warn_surface_units(NULL, &dp);
        plhs[0] = damage_of(solvers[k], &dp);
    } else if (strcmp(command, "solver_destroy") == 0) {
        const int k = solver_id(a1);
        cw_solver_destroy(solvers[k]);
        solvers[k] = NULL;
    } else if (strcmp(command, "transient_create") == 0) { /* grid, params -> id, nx, ny */
        const int k = transient_create(a1, a2);
        plhs[0] = mxCreateDoubleScalar(k + 1);
        if (nlhs > 1) plhs[1] = mxCreateDoubleScalar(transient_nx[k]);
        if (nlhs > 2) plhs[2] = mxCreateDoubleScalar(transient_ny[k]);
    } else if (strcmp(command, "transient_step") == 0) { /* id, input, commit */
        plhs[0] = transient_step(transient_id(a1), a2, 0, flag(a3));
    } else if (strcmp(command, "transient_start_steady") == 0) { /* id, input */
        plhs[0] = transient_step(transient_id(a1), a2, 1, 0);
    } else if (strcmp(command, "transient_start_zero") == 0) {
        const int k = transient_id(a1);
        transient_check(k, cw_transient_start_zero(transients[k]));
    } else if (strcmp(command, "transient_commit") == 0) {
        const int k = transient_id(a1);
        transient_check(k, cw_transient_commit(transients[k]));
    } else if (strcmp(command, "transient_rewind") == 0) {
        const int k = transient_id(a1);
        transient_check(k, cw_transient_rewind(transients[k]));
    } else if (strcmp(command, "transient_save") == 0) {
        plhs[0] = transient_save(transient_id(a1));
    } else if (strcmp(command, "transient_restore") == 0) { /* id, words */
        transient_restore(transient_id(a1), a2);
    } else if (strcmp(command, "transient_fields") == 0) {
        plhs[0] = transient_fields(transient_id(a1));
    } else if (strcmp(command, "transient_set_coordinates") == 0) { /* id, coordinates */
        transient_set_coordinates(transient_id(a1), a2);
    } else if (strcmp(command, "transient_jacobian") == 0) {
        plhs[0] = transient_jacobian(transient_id(a1));
    } else if (strcmp(command, "transient_add_wear") == 0) { /* id, law params */
        plhs[0] = transient_add_wear(transient_id(a1), a2);
    } else if (strcmp(command, "transient_wear") == 0) {
        plhs[0] = transient_wear(transient_id(a1));
    } else if (strcmp(command, "transient_reset_wear") == 0) {
        const int k = transient_id(a1);
        transient_check(k, cw_transient_reset_wear(transients[k]));
    } else if (strcmp(command, "transient_destroy") == 0) {
        const int k = transient_id(a1);
        cw_transient_destroy(transients[k]);
        transients[k] = NULL;
    } else if (strcmp(command, "model_grid") == 0) { /* model -> the grid it gets by default */
        cw_grid g;
        const field_info* model = find_field(&PARAMS, "model");
        const int m = a1 && mxIsChar(a1) ? (int)enum_value(&PARAMS, model, a1) : (int)scalar(a1, "model");
        if (cw_grid_init_model(&g, m) != CW_OK) FAIL("badValue", "model %d is not a CW_MODEL_*", m);
        plhs[0] = from_structs(&GRID, &g, sizeof g, 1, NULL, 0, NULL);
    } else if (strcmp(command, "input_name") == 0) { /* the library's spelling of a name */
        char typed[64], name[64];
        if (!a1 || !mxIsChar(a1) || mxGetString(a1, typed, sizeof typed) != 0)
            FAIL("badValue", "input_name takes a name (char)");
        if (cw_input_name(typed, name, sizeof name) != CW_OK) strcpy(name, typed);
        plhs[0] = mxCreateString(name);
    } else if (strcmp(command, "defaults") == 0) {
        char which[32] = "";
        if (a1) mxGetString(a1, which, sizeof which);
        plhs[0] = defaults(which);
    } else if (strcmp(command, "constants") == 0) {
        plhs[0] = constant_struct();
    } else if (strcmp(command, "version") == 0) {
        plhs[0] = mxCreateString(cw_version_string());
    } else if (strcmp(command, "status_string") == 0) {
        plhs[0] = mxCreateString(cw_status_string((int)scalar(a1, "status")));
    } else if (strcmp(command, "kalker_coefficients") == 0) {
        double c[4];
        status = cw_kalker_coefficients(scalar(a1, "a_over_b"), scalar(a2, "nu"), c, message,
                                        sizeof message);
        if (status == CW_OK) plhs[0] = row(c, 4);
    } else if (strcmp(command, "kalker_flexibilities") == 0) {
        double l[3];
        status = cw_kalker_flexibilities(scalar(a1, "a"), scalar(a2, "b"), scalar(a3, "G"),
                                         scalar(a4, "nu"), l, message, sizeof message);
        if (status == CW_OK) plhs[0] = row(l, 3);
    } else if (strcmp(command, "hertz") == 0) { /* A, B, N, E_star, as one row */
        double h[4];
        if (!a1 || mxGetNumberOfElements(a1) != 4 || !mxIsDouble(a1))
            FAIL("badValue", "hertz takes [A, B, N, E_star]");
        const double* v = mxGetPr(a1);
        status = cw_hertz_solve(v[0], v[1], v[2], v[3], h, message, sizeof message);
        if (status == CW_OK) plhs[0] = row(h, 4);
    } else if (strcmp(command, "friction_polach") == 0) { /* [mu0 A B] -> params with the law */
        if (!a1 || mxGetNumberOfElements(a1) != 3 || !mxIsDouble(a1))
            FAIL("badValue", "polach takes [mu0, A, B] (B in s/m)");
        const double* v = mxGetPr(a1);
        cw_params p;
        cw_params_init(&p);
        status = cw_friction_polach(v[0], v[1], v[2], &p, message, sizeof message);
        if (status == CW_OK) plhs[0] = from_structs(&PARAMS, &p, sizeof p, 1, NULL, 0, NULL);
    } else if (strcmp(command, "fastsim_normalised") == 0) { /* [ux uy fx fy mx my tol] */
        if (!a1 || mxGetNumberOfElements(a1) != 7 || !mxIsDouble(a1))
            FAIL("badValue", "fastsim_normalised takes [ux, uy, fx, fy, mx, my, tol]");
        const double* v = mxGetPr(a1);
        double t[2];
        status = cw_fastsim_normalised(v[0], v[1], v[2], v[3], (int)v[4], (int)v[5], v[6], &t[0],
                                       &t[1], message, sizeof message);
        if (status == CW_OK) plhs[0] = row(t, 2);
    } else {
        FAIL("usage", "unknown command '%s'", command);
    }
    if (status != CW_OK) fail_status(status, message);
}
