// What a campaign carries from its input to a worker and back: one contact
// (the grid and parameters of one row, or why the row could not be read)
// and the outcome of its solve. Plain data, so the same structs travel in
// MPI messages and in the checkpoint journal (wire.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

namespace cwcampaign {

// Statuses of rows the input reader rejected (never sent to the library).
// Library statuses are the CW_STATUS_LIST codes, all >= 0; the reader also
// gives a row the library's CW_ERR_INVALID_INPUT or CW_ERR_GRID_OUT_OF_RANGE
// when a value is out of its range (the checks of `creepwork solve`).
constexpr int kStatusRowUnreadable = -1;  // a cell or a combination cannot be read
constexpr int kStatusRowImplausible = -2; // --strict: a plausibility warning

// The bodies whose profiles a wear campaign accumulates (--wear).
constexpr int kRail = 0, kWheel = 1, kWearBodies = 2;

// Where a row's patch sits on its body's profile and how many passes it
// stands for (the arguments of cw_wear_profile_add), resolved by the
// reader from the row's wear columns. Unused without --wear.
struct RowWear {
    int32_t body = kRail;
    int32_t unused = 0;  // explicit padding: the struct travels as its bytes
    double s0 = 0.0;     // profile coordinate of the patch centre [m]
    double angle = 0.0;  // contact angle [rad]
    double passes = 0.0; // axle passages (rail) or wheel revolutions (wheel)
    double speed = 0.0;  // rolling speed [m/s]; 0: --speed's (or none)
};

// One contact, in SI, as cw_batch_solve takes it. A row the reader rejected
// keeps its status and reason and is passed through untouched.
struct ContactCase {
    cw_grid grid;
    cw_params params; // a gap row's params.gap: set by the solver from gap_values
    RowWear wear;
    // A row with a gap_file (grid.kind CW_GRID_GAP): the file's values at
    // [i + j*nx], as rank 0 read and checked them (gap_rows.hpp), shared by
    // the rows of one file; they travel with the chunk, so no other rank
    // reads the file. nullptr for an elliptic row.
    std::shared_ptr<const std::vector<double>> gap_values;
    std::string rejected; // non-empty: why the reader rejected the row
    int32_t rejected_status = kStatusRowUnreadable; // its status, when rejected
};

// A row's wear results (Outcome::wear), in this order; results.csv's wear
// columns carry the same names.
enum WearValue {
    kWearPasses,
    kWearWork,            // cw_wear_result.work [J/m]
    kWearMassPerDistance, // [kg/m]
    kWearMassPerPass,     // [kg]
    kWearMaxDepth,        // deepest strip per pass [m]
    kWearMass,            // passes x mass per pass [kg]
    kWearArea1, kWearArea2, kWearArea3, kWearArea4, // contact area per regime [m^2]
    kWearValues
};

// A row's temperature and damage results (Outcome::surface, with
// --temperature or --k-yield), in this order; results.csv's columns carry
// the names of `creepwork solve`'s JSON keys.
enum SurfaceValue {
    kSurfaceTMax1, kSurfaceTMax2, // hottest contact element of body 1 (rail), 2 (wheel) [deg C]
    kSurfaceTMaxX, kSurfaceTMaxY, // the hotter body's hottest element [m]
    kSurfaceIterations,           // passes of solve and temperature (--mu-T)
    kSurfaceRcfIndexMax, kSurfaceFISurf, // [-]
    kSurfaceTGamma,               // [N]
    kSurfaceWlrmDamage,           // per pass [-]
    kSurfaceValues
};

// The optional column groups of results.csv.
struct ResultColumns {
    bool wear = false;        // --wear: body, passes, wear_*
    bool temperature = false; // --temperature: T_max_1, T_max_2, T_max_x, T_max_y
    bool iterations = false;  // --mu-T: temperature_iterations
    bool damage = false;      // --k-yield: rcf_index_max, FI_surf, T_gamma, wlrm_damage
};

// The result of one row: the library's status and totals, or a message.
struct Outcome {
    int status = CW_OK; // CW_OK, a CW_ERR_* code, or a kStatusRow* code
    cw_result result;   // valid when status == CW_OK
    std::string message; // why the row failed ("" when it succeeded)
    // With --wear: the row's kWearValues wear results (empty otherwise, and
    // for a failed row). Its wear-depth profile went into its chunk's
    // accumulator (ChunkResult::wear_states).
    std::vector<double> wear;
    // With --temperature or --k-yield: the row's kSurfaceValues (empty
    // otherwise, and for a failed row).
    std::vector<double> surface;
};

// A run of consecutive input rows: the unit of scheduling and checkpoints.
struct Chunk {
    uint64_t id = 0;        // assignment number (diagnostics only)
    uint64_t first_row = 0; // input row index (0-based) of cases[0]
    int mode = CW_SOLVE_FULL;
    std::vector<ContactCase> cases;
};

struct ChunkResult {
    uint64_t id = 0;
    uint64_t first_row = 0;
    double seconds = 0.0; // the worker's wall time for the chunk (load balancing)
    std::vector<Outcome> outcomes;
    // With --wear: per body, the exact state (cw_wear_profile_get_state) of
    // the chunk's rows' wear-depth profiles added together; empty when no
    // row of the chunk wore that body. Being exact sums, they reduce to the
    // same bits in any order, and the checkpoint keeps them with their
    // rows, so a resumed campaign counts every row once.
    std::array<std::vector<uint64_t>, kWearBodies> wear_states;
};

// Whether the library builds the same grid for a and b: kind, nx, ny, and
// the bits of a uniform grid's box scale or a gap grid's origin and spacing.
bool same_grid_shape(const cw_grid& a, const cw_grid& b);
// A strict order of grid shapes under the same comparison.
bool grid_shape_less(const cw_grid& a, const cw_grid& b);

// Human name of a status for results.csv: "ok", "CW_ERR_INVALID_INPUT", ...,
// "ROW_UNREADABLE" or "ROW_IMPLAUSIBLE".
const char* status_name(int status);

// "rail", "wheel".
const char* body_name(int body);

} // namespace cwcampaign
