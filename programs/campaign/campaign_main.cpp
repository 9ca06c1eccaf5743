// creepwork-campaign: the MPI program behind `creepwork campaign` (which
// execs it, so the creepwork program itself never links MPI). Every rank
// parses the options; rank 0 reads the input, owns the output directory and
// its checkpoint, schedules chunks and solves on a thread of its own; the
// other ranks solve the chunks they are sent. Only rank 0 touches files.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <memory>
#include <string>

#include <creepwork/creepwork.h>

#include "../cli/cli_error.hpp"
#include "../cli/json.hpp"
#include "atomic_file.hpp"
#include "campaign_dir.hpp"
#include "campaign_options.hpp"
#include "coordinator.hpp"
#include "creep_table.hpp"
#include "input_csv.hpp"
#include "mpi_link.hpp"
#include "rank_threads.hpp"
#include "results_writer.hpp"
#include "surface_setup.hpp"
#include "wear_output.hpp"
#include "wear_setup.hpp"
#include "wire.hpp"
#include "worker.hpp"

namespace cwcampaign {

namespace {

using cwcli::CliError;
using cwcli::kExitFailure;
using cwcli::kExitOk;
using cwcli::kExitUsage;

constexpr int kNothingToDo = -1; // setup status: DIR holds the finished campaign

// One line on stderr, as the creepwork program prints.
void say(const std::string& message)
{
    std::string line = message;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "creepwork: %s\n", line.c_str());
}

// Ranks must run one build: contacts and results travel as the library's
// structs (wire.hpp), and every rank must solve with the same library.
long long build_signature()
{
    return (static_cast<long long>(cw_version_number()) << 32) ^
           (static_cast<long long>(sizeof(cw_params)) << 20) ^
           (static_cast<long long>(sizeof(cw_result)) << 8) ^ sizeof(cw_grid) ^
           (static_cast<long long>(CW_ABI_VERSION) << 48);
}

int test_delay_ms()
{
    const char* v = std::getenv("CREEPWORK_CAMPAIGN_TEST_CHUNK_DELAY_MS");
    return v ? std::max(0, std::atoi(v)) : 0;
}

// What rank 0 holds between setup and the end.
struct Setup {
    CampaignInput input;    // the CSV's rows (campaign)
    std::vector<ContactCase> table_rows; // the table's points (--table)
    JournalIdentity identity;
    PreparedOutput output;
    std::vector<double> wear_nodes; // --wear's profile grid
    double setup_seconds = 0.0; // reading the input, opening the checkpoint

    const std::vector<ContactCase>& cases() const
    {
        return identity.kind == 1 ? table_rows : input.cases;
    }
};

void prepare(const CampaignOptions& opt, Setup& s)
{
    const auto start = std::chrono::steady_clock::now();
    if (opt.table) {
        s.table_rows = table_cases(opt.spec);
        s.identity = {1, table_hash(opt.spec), s.table_rows.size()};
    } else {
        WearRules rules;
        if (opt.wear) {
            rules.default_body = opt.wear_setup.default_body;
            rules.wheel_radius = opt.wear_setup.wheel_radius;
            rules.speed_given = opt.wear_setup.params.rolling_speed > 0.0;
            rules.archard = opt.wear_setup.params.law == CW_WEAR_ARCHARD_KTH;
        }
        try {
            s.input = read_campaign_csv(opt.in, opt.wear ? &rules : nullptr, opt.strict);
        } catch (const InputError& e) {
            throw cwcli::usage_error("--in", e.what());
        }
        s.identity = {0, s.input.hash, s.input.cases.size()};
        // --strict rejects rows another run solves: part of what the
        // checkpoint holds, so --resume with the other choice is refused.
        if (opt.strict) s.identity.input_hash = fnv1a("--strict", 8, s.identity.input_hash);
        // The gap files are inputs too: a changed one is another campaign.
        if (s.input.gap_hash)
            s.identity.input_hash =
                fnv1a(&s.input.gap_hash, sizeof s.input.gap_hash, s.identity.input_hash);
        if (opt.wear) {
            // The grid and the wear options are part of what the checkpoint
            // holds: --resume with others is refused as another input.
            WearSetup w = opt.wear_setup;
            w.nodes = profile_nodes(w, s.input.cases);
            s.identity.input_hash = wear_identity(w, s.identity.input_hash);
            s.wear_nodes = std::move(w.nodes);
        }
        if (opt.surface.any()) {
            // Likewise the temperature and damage options; a row that gives
            // the temperature no rolling speed fails alone.
            s.identity.input_hash = surface_identity(opt.surface, s.identity.input_hash);
            for (size_t k = 0; k < s.input.cases.size(); ++k) {
                ContactCase& c = s.input.cases[k];
                const std::string problem = surface_row_problem(opt.surface, c, s.input.lines[k]);
                if (problem.empty()) continue;
                c.rejected = problem;
                c.rejected_status = kStatusRowUnreadable;
            }
        }
    }
    s.output = prepare_output(opt.out, opt.resume, opt.force, s.identity);
    s.setup_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string campaign_json(const CampaignOptions& opt, const Setup& s, const RunStats& run,
                          uint64_t ok, uint64_t failed, double write_seconds, int ranks,
                          int threads_total, int threads_rank0,
                          const cw_wear_profile_totals* wear)
{
    cwcli::JsonObject j;
    const double rate = run.seconds > 0.0 ? static_cast<double>(run.rows) / run.seconds : 0.0;
    j.text("kind", opt.table ? "table" : "campaign")
        .text("input", opt.table ? std::string("--table") : opt.in)
        .text("input_hash", std::to_string(s.identity.input_hash))
        .integer("rows", static_cast<long>(s.identity.rows))
        .integer("ok", static_cast<long>(ok))
        .integer("failed", static_cast<long>(failed))
        .integer("resumed_rows", static_cast<long>(s.output.done_rows))
        .integer("solved_this_run", static_cast<long>(run.rows))
        .integer("chunks_this_run", static_cast<long>(run.chunks))
        .number("seconds_setup", s.setup_seconds)
        .number("seconds_this_run", run.seconds)
        .number("rows_per_second_this_run", rate)
        .number("seconds_writing", write_seconds)
        .integer("ranks", ranks)
        .integer("threads_total", threads_total)
        .integer("threads_rank0", threads_rank0)
        .text("creepwork", cw_version_string());
    if (opt.wear) {
        const cw_wear_params& p = opt.wear_setup.params;
        j.text("wear_law", p.law == CW_WEAR_ARCHARD_KTH ? "archard" : "usfd")
            .text("wear_source", p.source == CW_WEAR_SOURCE_PAPER  ? "paper"
                                 : p.source == CW_WEAR_SOURCE_SLIP ? "slip"
                                                                   : "consistent")
            .integer("wear_profile_nodes", static_cast<long>(opt.wear_setup.nodes.size()));
        for (int body = 0; body < kWearBodies; ++body) {
            const std::string b = std::string("wear_") + body_name(body);
            j.integer(b + "_rows", static_cast<long>(wear[body].adds))
                .number(b + "_passes", wear[body].passes)
                .number(b + "_volume_m2", wear[body].volume)
                .number(b + "_volume_lost_m2", wear[body].volume_lost);
        }
    }
    return j.str(true) + "\n";
}

// Rank 0 after the solves: the results in input order, the summary.
int finish(const CampaignOptions& opt, Setup& s, const RunStats& run, int ranks,
           int threads_total, int threads_rank0)
{
    const auto start = std::chrono::steady_clock::now();
    uint64_t ok = 0, failed = 0, warned = 0;
    std::string first_failure, first_warning, written;
    cw_wear_profile_totals wear_totals[kWearBodies];
    for (cw_wear_profile_totals& t : wear_totals) cw_wear_profile_totals_init(&t);
    if (opt.table) {
        const TableSummary t = write_table(*s.output.journal, opt.spec, opt.out);
        ok = t.points - t.failed;
        failed = t.failed;
        first_failure = t.first_failure;
        written = opt.out + "/table.csv and table.json";
    } else {
        std::unique_ptr<WearProfiles> wear;
        if (opt.wear) wear = std::make_unique<WearProfiles>(opt.wear_setup);
        ResultColumns extra;
        extra.temperature = opt.surface.temperature;
        extra.iterations = opt.surface.mu_T();
        extra.damage = opt.surface.damage;
        const MergeSummary m = write_results_csv(*s.output.journal, s.input,
                                                 opt.out + "/results.csv", wear.get(), extra);
        ok = m.ok;
        failed = m.failed;
        for (const std::string& f : m.first_failures)
            first_failure += (first_failure.empty() ? "" : "; ") + f;
        warned = m.warned;
        for (const std::string& w : m.first_warnings)
            first_warning += (first_warning.empty() ? "" : "; ") + w;
        written = opt.out + "/results.csv";
        if (wear) {
            for (const std::string& name : wear->write(opt.out)) written += ", " + name;
            for (int body = 0; body < kWearBodies; ++body)
                wear_totals[body] = wear->totals(body);
        }
    }
    const double write_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_file_atomically(opt.out + "/campaign.json",
                          campaign_json(opt, s, run, ok, failed, write_seconds, ranks,
                                        threads_total, threads_rank0, wear_totals));
    s.output.journal.reset();
    remove_checkpoint(opt.out);

    const double rate = run.seconds > 0.0 ? static_cast<double>(run.rows) / run.seconds : 0.0;
    char line[256];
    std::snprintf(line, sizeof line,
                  "campaign: this run solved %llu rows in %.3g s on %d rank(s), %d thread(s): "
                  "%.4g rows/s",
                  static_cast<unsigned long long>(run.rows), run.seconds, ranks, threads_total,
                  rate);
    if (!opt.quiet) say(line);
    say("campaign: " + std::to_string(ok + failed) + " rows: " + std::to_string(ok) +
        " solved, " + std::to_string(failed) + " failed" +
        (failed ? " (" + first_failure + ")" : std::string()) + "; wrote " + written);
    if (warned > 0)
        say("campaign: " + std::to_string(warned) +
            (warned == 1 ? " row was solved with warnings in its message ("
                         : " rows were solved with warnings in their messages (") +
            first_warning + "); --strict rejects such rows");
    if (opt.table && failed > 0) {
        say("campaign: a table with failed points cannot be interpolated; table.csv marks them");
        return kExitFailure;
    }
    return kExitOk;
}

int run(int argc, char** argv)
{
    const int rank = mpi::rank(), ranks = mpi::size();
    CampaignOptions opt;
    try {
        opt = read_campaign_options(argc, argv, 1);
    } catch (const CliError& e) {
        if (rank == 0) say(e.what());
        return e.status();
    }
    if (opt.help) {
        if (rank == 0) std::fputs(usage_campaign(), stdout);
        return kExitOk;
    }
    if (!mpi::same_on_all_ranks(build_signature())) {
        if (rank == 0) say("campaign: the ranks run different builds of creepwork");
        return kExitFailure;
    }

    // Rank 0 reads the input and claims the output directory; every rank
    // learns the outcome, so all stop together on a bad input.
    Setup setup;
    int status = kExitOk;
    std::string message;
    if (rank == 0) {
        try {
            prepare(opt, setup);
            if (setup.output.state == PreparedOutput::State::complete) status = kNothingToDo;
        } catch (const CliError& e) {
            status = e.status();
            message = e.what();
        } catch (const std::exception& e) {
            status = kExitFailure;
            message = e.what();
        }
    }
    status = mpi::broadcast_int(status);
    if (status == kNothingToDo) {
        if (rank == 0) say("campaign: nothing to do: '" + opt.out + "' holds this campaign, finished");
        return kExitOk;
    }
    if (status != kExitOk) {
        if (rank == 0) say(message);
        return status;
    }
    if (rank == 0) {
        for (const std::string& note : opt.notes) say(note);
        for (const std::string& note : setup.input.notes) say(note);
    }

    if (opt.wear) {
        // Only rank 0 read the input; every rank needs the same grid.
        opt.wear_setup.nodes =
            nodes_from_bytes(mpi::broadcast_string(rank == 0 ? nodes_to_bytes(setup.wear_nodes)
                                                             : std::string()));
    }

    WorkerConfig worker;
    worker.wear = opt.wear ? &opt.wear_setup : nullptr;
    worker.surface = opt.surface.any() ? &opt.surface : nullptr;
    worker.threads = opt.threads > 0 ? opt.threads : default_threads(mpi::ranks_on_node());
    worker.max_batches = static_cast<size_t>(opt.max_grids);
    worker.test_delay_ms = test_delay_ms();
    const int threads_total = mpi::sum_over_ranks(worker.threads);

    if (rank != 0) {
        try {
            run_remote_worker(worker);
        } catch (const std::exception& e) {
            say("campaign: rank " + std::to_string(rank) + ": " + e.what());
            mpi::abort_all(kExitFailure);
        }
        return kExitOk;
    }

    const auto& cases = setup.cases();
    std::vector<bool> done(cases.size(), false);
    for (const Journal::Record& r : setup.output.journal->records())
        for (uint64_t k = 0; k < r.count; ++k) done[r.first_row + k] = true;
    if (setup.output.state == PreparedOutput::State::resumed && !opt.quiet)
        say("campaign: resuming '" + opt.out + "': " + std::to_string(setup.output.done_rows) +
            " of " + std::to_string(cases.size()) + " rows were done" +
            (setup.output.dropped_torn_tail ? " (a torn last chunk was dropped)" : ""));

    CoordinatorConfig config;
    config.mode = opt.table ? CW_SOLVE_FORCES : CW_SOLVE_FULL;
    config.fixed_chunk = opt.chunk;
    // Bigger chunks for bigger jobs keep rank 0's message and file traffic
    // modest: about one chunk per worker per 0.25 s up to 25 ranks.
    config.target_seconds = std::max(0.25, 0.01 * ranks);
    config.local = worker;
    config.progress = !opt.quiet;
    if (opt.progress > 0) config.first_report = config.report_every = opt.progress;
    RunStats stats;
    try {
        stats = coordinate(cases, done, *setup.output.journal, config);
    } catch (const std::exception& e) {
        say(std::string("campaign: ") + e.what() + " (the checkpoint in '" + opt.out +
            "' keeps the finished chunks: rerun with --resume)");
        mpi::abort_all(kExitFailure);
    }
    try {
        return finish(opt, setup, stats, ranks, threads_total, worker.threads);
    } catch (const std::exception& e) {
        say(std::string("campaign: ") + e.what());
        return kExitFailure;
    }
}

} // namespace

} // namespace cwcampaign

int main(int argc, char** argv)
{
    try {
        cwcampaign::mpi::init(&argc, &argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "creepwork: campaign: %s\n", e.what());
        return cwcli::kExitFailure;
    }
    const int code = cwcampaign::run(argc, argv);
    cwcampaign::mpi::finalize();
    return code;
}
