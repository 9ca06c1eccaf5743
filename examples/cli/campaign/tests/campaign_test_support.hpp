// Helpers of the campaign tests: running programs (under mpirun or not),
// reading CSV independently of the runner's own reader, and a set of input
// rows known both as CSV text and as the structs the library sees.
#pragma once

#include <map>
#include <string>
#include <vector>

#include <sys/types.h>

#include <creepwork/creepwork.h>

namespace cwctest {

struct Run {
    int status = -1; // exit status; -1 when killed or not started
    std::string out, err;
};

// Set by main from the test's arguments.
struct Tools {
    std::string creepwork; // the creepwork program
    std::string mpirun;    // mpirun (Open MPI)
    std::string scratch;   // this test's directory
};
extern Tools g_tools;

// Runs argv[0] with argv, extra environment entries ("NAME=value") added,
// capturing stdout and stderr; waits for it.
Run run(const std::vector<std::string>& argv, const std::vector<std::string>& env = {});

// `creepwork campaign args...` on np ranks (mpirun --oversubscribe), or
// without mpirun when np == 0 (MPI's singleton start).
Run campaign(int np, const std::vector<std::string>& args,
             const std::vector<std::string>& env = {});
std::vector<std::string> campaign_argv(int np, const std::vector<std::string>& args);

// Starts argv in a process group of its own, output to files; returns the
// pid (= the group id).
pid_t start_group(const std::vector<std::string>& argv, const std::vector<std::string>& env,
                  const std::string& out_file, const std::string& err_file);

// The live (not zombie) descendants of pid, from /proc.
std::vector<pid_t> live_descendants(pid_t pid);
// Whether pid exists and is not a zombie.
bool process_alive(pid_t pid);
// Whether another process holds an exclusive flock on path.
bool file_locked(const std::string& path);

std::string slurp(const std::string& path);
void write_text(const std::string& path, const std::string& text);
bool exists(const std::string& path);

// RFC 4180 records of a whole file (quotes, "" escapes; no trimming).
std::vector<std::vector<std::string>> read_csv(const std::string& path);

// One input row, as the text of its CSV cells; "" = empty cell.
using Row = std::map<std::string, std::string>;

// The columns written by write_input: required, then the optional ones.
const std::vector<std::string>& input_columns();
void write_input(const std::string& path, const std::vector<Row>& rows);

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

// Index of each name in a header record.
std::map<std::string, size_t> header_index(const std::vector<std::string>& header);

} // namespace cwctest
