// What the campaign tests share beyond the CLI tests' support
// (cli_checks.hpp): running a campaign (under mpirun or not), and input
// rows known both as CSV text and as the structs the library sees.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "cli_checks.hpp"

namespace cwtest {

// `creepwork campaign args...` on np ranks (mpirun --oversubscribe), or
// without mpirun when np == 0 (MPI's singleton start).
Run campaign(int np, const std::vector<std::string>& args,
             const std::vector<std::string>& env = {});
std::vector<std::string> campaign_argv(int np, const std::vector<std::string>& args);

// Starts `creepwork campaign args...` on np ranks, each chunk slowed by
// delay_ms, and kills it with SIGKILL -- mpirun and every rank -- once its
// checkpoint has grown past min_bytes (at most 120 s). Fails the test
// unless it got that far and no process survives. Returns the number of
// processes killed under mpirun (0 without it).
size_t kill_midway(int np, const std::vector<std::string>& args, int delay_ms,
                   const std::string& checkpoint, uintmax_t min_bytes);

// dir/campaign.json of a run resumed after a kill: at least 3 of the rows
// (not all) came from the checkpoint, and those plus the rows solved in
// this run are the input's `rows` (finished chunks were not redone).
void expect_resumed_part(const std::string& dir, size_t rows);

// One input row, as the text of its CSV cells; "" = empty cell.
using Row = std::map<std::string, std::string>;

// The columns write_input writes by default: every column of the schema
// but the wear columns.
const std::vector<std::string>& input_columns();
// A header of columns, then one line per row (a row's missing cells empty).
void write_input(const std::string& path, const std::vector<Row>& rows,
                 const std::vector<std::string>& columns = input_columns());

// The grid and parameters of a row, as the campaign must read it (cells
// parsed with strtod, defaults from cw_*_init).
void row_to_structs(const Row& row, cw_grid& grid, cw_params& params);
// `creepwork solve` options for the same contact (fastsim rows).
std::vector<std::string> row_to_solve_args(const Row& row);

// A mix of 48 rows over four grid shapes, both pressures, both rolling
// directions, given flexibilities, CONTACT's options, partial and full
// slip; all valid for FASTSIM.
std::vector<Row> mixed_rows();

// The text the library's result gives for a results.csv column, or for a
// failing solve its status name and message, from a one-by-one
// cw_solver_solve of the row (CW_SOLVE_FULL).
struct Expected {
    int status = CW_OK;
    std::string message;
    std::map<std::string, std::string> cells;
};
Expected solve_directly(const Row& row);
// "CW_ERR_INVALID_INPUT" for a library status.
const char* status_name(int status);

} // namespace cwtest
