/* Unit tests of the campaign runner's parts that need no MPI: the number
 * text (the same digits as `creepwork solve`), the CSV record reader, the
 * chunk planner (every pending row exactly once, in order, a single
 * pending row included), the wire encoding (round trip; a malformed buffer
 * is an error, never a read past its end), the checkpoint journal (reopen,
 * torn tail, wrong input) and the results writer (input order from chunks
 * out of order, what a failed row and a warned row show, gaps and repeats
 * refused).
 *
 * usage: test_campaign_units <scratch dir> [test name] */
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "../../cli/json.hpp"
#include "../chunk_planner.hpp"
#include "../../cli/csv_text.hpp"
#include "../journal.hpp"
#include "../number_text.hpp"
#include "../results_writer.hpp"
#include "../wire.hpp"
#include "cli_checks.hpp"
// Last: cmocka defines macros (fail, skip) that clash with the C++ library.
#include "test_support.h"

namespace fs = std::filesystem;
using namespace cwcampaign;
using cwcli::csv_quote;
using cwcli::CsvRecordReader;
using cwtest::g_tools;

namespace {

void number_text_equals_shortest_exact(void** state)
{
    (void)state;
    // The CLI's JSON digits (cwcli::shortest_exact, printf-based) are the
    // reference: random bit patterns, decimal fractions, and powers of two
    // times integers (where the 15/16/17-digit choice is decided).
    std::mt19937_64 g(12345);
    long checked = 0;
    for (long i = 0; i < 200000; ++i) {
        double v = 0.0;
        const uint64_t bits = g();
        switch (i % 3) {
        case 0: std::memcpy(&v, &bits, sizeof v); break;
        case 1: v = static_cast<double>(bits % 1000000) / 1000.0; break;
        default: v = std::ldexp(static_cast<double>(bits >> 11), static_cast<int>(g() % 120) - 80);
        }
        if (!std::isfinite(v)) continue;
        const std::string want = cwcli::shortest_exact(v), got = number_text(v);
        if (want != got) print_error("%.17g: %s, expected %s\n", v, got.c_str(), want.c_str());
        assert_string_equal(got.c_str(), want.c_str());
        ++checked;
    }
    assert_true(checked > 190000);
    assert_string_equal(number_text(0.1).c_str(), "0.1");
    assert_string_equal(number_text(-0.0).c_str(), "-0");
    assert_string_equal(number_text(1e-300).c_str(), "1e-300");
}

std::vector<std::vector<std::string>> records(const std::string& text,
                                              std::vector<std::string>* errors = nullptr)
{
    std::istringstream in(text);
    CsvRecordReader r(in);
    std::vector<std::vector<std::string>> out;
    std::vector<std::string> fields;
    std::string error;
    while (r.next(fields, error)) {
        out.push_back(fields);
        if (errors) errors->push_back(error);
    }
    return out;
}

void csv_reader_follows_rfc4180(void** state)
{
    (void)state;
    std::vector<std::string> errors;
    const auto r = records("a, b ,c\r\n\"x,1\",\"say \"\"hi\"\"\",\"two\nlines\"\n\n last", &errors);
    assert_int_equal(r.size(), 4);
    assert_true((r[0] == std::vector<std::string>{"a", "b", "c"})); // trimmed, CRLF
    assert_true((r[1] == std::vector<std::string>{"x,1", "say \"hi\"", "two\nlines"}));
    assert_true((r[2] == std::vector<std::string>{""})); // a blank line: one empty field
    assert_true((r[3] == std::vector<std::string>{"last"}));
    for (const std::string& e : errors) assert_string_equal(e.c_str(), "");

    errors.clear();
    const auto bad = records("\"a\"b,c\nnext\n\"open", &errors);
    assert_int_equal(bad.size(), 3);
    assert_string_equal(errors[0].c_str(), "text after the closing quote of a field");
    assert_true((bad[1] == std::vector<std::string>{"next"})); // reading goes on
    assert_string_equal(errors[2].c_str(),
                        "a quoted field is not closed before the end of the file");

    // Line numbers count lines, not records (a quoted newline is a line).
    std::istringstream in("h\n\"a\nb\"\nc\n");
    CsvRecordReader reader(in);
    std::vector<std::string> f;
    std::string e;
    reader.next(f, e);
    assert_int_equal(reader.line(), 1);
    reader.next(f, e);
    assert_int_equal(reader.line(), 2);
    reader.next(f, e);
    assert_int_equal(reader.line(), 4);

    assert_string_equal(csv_quote("plain").c_str(), "plain");
    assert_string_equal(csv_quote("a,b").c_str(), "\"a,b\"");
    assert_string_equal(csv_quote("say \"x\"").c_str(), "\"say \"\"x\"\"\"");
}

void chunk_planner_covers_each_row_once(void** state)
{
    (void)state;
    std::vector<bool> done(1000, false);
    for (int k = 100; k < 180; ++k) done[k] = true;
    for (int k = 500; k < 501; ++k) done[k] = true;
    done[999] = true;
    const auto ranges = pending_ranges(done);
    assert_int_equal(ranges.size(), 3);
    assert_int_equal(ranges[1].first, 180);
    assert_int_equal(ranges[1].second, 500);
    for (uint64_t fixed : {uint64_t(0), uint64_t(7)}) {
        ChunkPlanner p(ranges, fixed, 3, 0.25);
        std::vector<int> seen(1000, 0);
        uint64_t last_end = 0, chunks = 0, last_count = 0;
        double rate = 0.0;
        while (!p.empty()) {
            const auto [first, count] = p.next(rate);
            assert_true(count >= 1);
            assert_true(first >= last_end); // input order
            assert_true(first + count <= 1000);
            for (uint64_t k = first; k < first + count; ++k) ++seen[k];
            last_end = first + count;
            last_count = count;
            ++chunks;
            rate = 4000.0; // 1000 rows per 0.25 s
        }
        for (int k = 0; k < 1000; ++k) assert_int_equal(seen[k], done[k] ? 0 : 1);
        assert_int_equal(p.remaining(), 0);
        if (fixed) {
            assert_true(last_count <= fixed);
        } else {
            // The tail shrinks: no chunk at the end holds more than
            // remaining / (2 x workers).
            assert_int_equal(last_count, 1);
            assert_true(chunks > 10);
        }
    }
    // A resume whose pending work is a single row (first, last, or amid
    // done rows): one chunk of that row.
    for (uint64_t row : {uint64_t(0), uint64_t(500), uint64_t(999)}) {
        std::vector<bool> one(1000, true);
        one[row] = false;
        const auto pending = pending_ranges(one);
        assert_int_equal(pending.size(), 1);
        for (uint64_t fixed : {uint64_t(0), uint64_t(7)}) {
            ChunkPlanner p(pending, fixed, 3, 0.25);
            assert_int_equal(p.remaining(), 1);
            assert_false(p.empty());
            const auto [first, count] = p.next(0.0);
            assert_int_equal(first, row);
            assert_int_equal(count, 1);
            assert_true(p.empty());
        }
    }
}

Chunk sample_chunk()
{
    Chunk c;
    c.id = 7;
    c.first_row = 40;
    c.mode = CW_SOLVE_FORCES;
    c.cases.resize(2);
    cw_grid_init(&c.cases[0].grid);
    cw_params_init(&c.cases[0].params);
    c.cases[0].params.xi_x = 1e-3;
    c.cases[0].wear.body = kWheel;
    c.cases[0].wear.s0 = -0.003;
    c.cases[0].wear.passes = 1234.5;
    c.cases[1].rejected = "line 9, column nu: must lie in [0, 0.5] (got 0.7)";
    c.cases[1].rejected_status = CW_ERR_INVALID_INPUT;
    return c;
}

ChunkResult sample_result(uint64_t first_row, size_t n)
{
    ChunkResult r;
    r.id = 3;
    r.first_row = first_row;
    r.seconds = 0.5;
    r.outcomes.resize(n);
    for (size_t k = 0; k < n; ++k) {
        cw_result_init(&r.outcomes[k].result);
        r.outcomes[k].result.Fx = -100.0 * static_cast<double>(first_row + k);
        if (k % 3 == 2) {
            r.outcomes[k].status = CW_ERR_INVALID_INPUT;
            r.outcomes[k].message = "nu = 0.7 is invalid";
        }
    }
    r.outcomes[0].wear = {1.0, 2.0};
    // A wear profile's state: runs of zero words between literal ones, a
    // zero first and last word, and an empty state for the other body.
    r.wear_states[kRail] = {0, 0, 7, 0, 0, 0, 9, 10, 0, 0xffffffffffffffffull, 0, 0};
    return r;
}

void wire_round_trips_and_rejects_damage(void** state)
{
    (void)state;
    const Chunk c = sample_chunk();
    const Chunk back = decode_chunk(encode_chunk(c));
    assert_int_equal(back.first_row, 40);
    assert_int_equal(back.mode, CW_SOLVE_FORCES);
    assert_true(back.cases[0].params.xi_x == 1e-3);
    assert_string_equal(back.cases[1].rejected.c_str(), c.cases[1].rejected.c_str());
    assert_int_equal(back.cases[1].rejected_status, CW_ERR_INVALID_INPUT);
    const ChunkResult r = sample_result(10, 5);
    const Bytes bytes = encode_result(r);
    const ChunkResult rb = decode_result(bytes);
    assert_int_equal(rb.outcomes.size(), 5);
    assert_true(rb.outcomes[4].result.Fx == -1400.0);
    assert_string_equal(rb.outcomes[2].message.c_str(), "nu = 0.7 is invalid");
    assert_true((rb.outcomes[0].wear == std::vector<double>{1.0, 2.0}));
    assert_true(rb.wear_states[kRail] == r.wear_states[kRail]);
    assert_true(rb.wear_states[kWheel].empty());
    assert_true(back.cases[0].wear.body == kWheel && back.cases[0].wear.s0 == -0.003 &&
                back.cases[0].wear.passes == 1234.5);
    // Gap rows carry their file's values, once per chunk for the rows that
    // share them; the sender's pointer does not travel (the solver sets it).
    Chunk gap = c;
    gap.cases.push_back(c.cases[0]);
    const Chunk plain = gap;
    const auto h = std::make_shared<const std::vector<double>>(
        std::vector<double>{1e-5, 2e-5, 3e-5, 0.0, 1e-6, 2e-6, 3e-6, 4e-6, 5e-6});
    for (ContactCase* g : {&gap.cases[0], &gap.cases[2]}) {
        g->grid.kind = CW_GRID_GAP;
        g->params.gap = h->data();
        g->params.gap_len = h->size();
        g->gap_values = h;
    }
    const Bytes gap_bytes = encode_chunk(gap);
    assert_int_equal(gap_bytes.size(), encode_chunk(plain).size() + 4 + 9 * sizeof(double));
    const Chunk gap_back = decode_chunk(gap_bytes);
    assert_true(gap_back.cases[0].gap_values && *gap_back.cases[0].gap_values == *h);
    assert_true(gap_back.cases[2].gap_values == gap_back.cases[0].gap_values);
    assert_true(gap_back.cases[0].params.gap == nullptr && gap_back.cases[0].params.gap_len == 9);
    assert_true(!back.cases[0].gap_values && !gap_back.cases[1].gap_values);
    for (size_t n = 0; n < gap_bytes.size(); ++n) {
        bool threw = false;
        try {
            decode_chunk(Bytes(gap_bytes.begin(), gap_bytes.begin() + static_cast<std::ptrdiff_t>(n)));
        } catch (const WireError&) {
            threw = true;
        }
        assert_true(threw);
    }
    // Zero runs are stored as counts: a long, mostly zero state is small.
    ChunkResult big = r;
    big.wear_states[kWheel].assign(100000, 0);
    big.wear_states[kWheel][50000] = 3;
    const Bytes big_bytes = encode_result(big);
    assert_true(big_bytes.size() < bytes.size() + 100);
    assert_true(decode_result(big_bytes).wear_states[kWheel] == big.wear_states[kWheel]);
    assert_true(is_stop(encode_stop()) && !is_stop(bytes));
    // Every truncation of a valid message is an error, not a read past it.
    for (size_t n = 0; n < bytes.size(); ++n) {
        const Bytes cut(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(n));
        bool threw = false;
        try {
            decode_result(cut);
        } catch (const WireError&) {
            threw = true;
        }
        assert_true(threw);
    }
}

// results.csv from a checkpoint whose chunks arrived out of order: one line
// per input row in input order, ids quoted as CSV needs, the numbers only
// of solved rows, a solved row's warnings in its message, the counts; a
// checkpoint that misses or repeats rows is refused.
void results_writer_puts_rows_in_order(void** state)
{
    (void)state;
    const std::string path = g_tools.scratch + "/w.cwj";
    const JournalIdentity id{0, 0x77, 6};
    CampaignInput in;
    in.ids = {"r0", "r,1", "r2", "r3", "r4", "r5"};
    in.lines = {2, 3, 4, 5, 6, 7};
    in.cases.resize(6);
    in.warnings = {"", "", "warning: column a = 7.2 m is implausible", "", "", ""};
    // Chunks [3, 5), [0, 3), [5, 6) in the order they came back; row 1 failed
    // in the library, row 4 was rejected by the reader (--strict).
    ChunkResult late = sample_result(3, 2), first = sample_result(0, 3), last = sample_result(5, 1);
    for (ChunkResult* c : {&late, &first, &last})
        for (Outcome& o : c->outcomes) o.status = CW_OK, o.message.clear();
    first.outcomes[1].status = CW_ERR_INVALID_INPUT;
    first.outcomes[1].message = "the library's reason";
    late.outcomes[1].status = kStatusRowImplausible;
    late.outcomes[1].message = "line 6: column N = 100 N is implausible";
    {
        Journal j = Journal::create(path, id);
        for (const ChunkResult* c : {&late, &first, &last})
            j.append(c->first_row, c->outcomes.size(), encode_result(*c));
        const MergeSummary m = write_results_csv(j, in, g_tools.scratch + "/results.csv");
        assert_int_equal(m.ok, 4);
        assert_int_equal(m.failed, 2);
        assert_int_equal(m.warned, 1);
        assert_string_equal(m.first_failures[0].c_str(), "id r,1: line 3: the library's reason");
        assert_string_equal(m.first_failures[1].c_str(),
                            "id r4: line 6: column N = 100 N is implausible");
        assert_string_equal(m.first_warnings[0].c_str(),
                            "id r2: line 4: warning: column a = 7.2 m is implausible");
    }
    const auto records = cwtest::read_csv(g_tools.scratch + "/results.csv");
    assert_int_equal(records.size(), 7);
    const auto idx = cwtest::header_index(records[0]);
    for (size_t row = 0; row < 6; ++row) {
        const auto& rec = records[row + 1];
        assert_string_equal(rec[idx.at("id")].c_str(), in.ids[row].c_str());
        const bool ok = row != 1 && row != 4;
        assert_string_equal(rec[idx.at("status")].c_str(),
                            ok ? "ok" : row == 1 ? "CW_ERR_INVALID_INPUT" : "ROW_IMPLAUSIBLE");
        // sample_result's Fx is -100 per row number.
        assert_string_equal(rec[idx.at("Fx")].c_str(),
                            ok ? number_text(-100.0 * static_cast<double>(row)).c_str() : "");
        assert_string_equal(rec[idx.at("message")].c_str(),
                            row == 2   ? in.warnings[2].c_str()
                            : row == 1 ? "the library's reason"
                            : row == 4 ? "line 6: column N = 100 N is implausible"
                                       : "");
    }
    // A gap (row 5 missing) and a repeat (rows 3, 4 twice) are refused.
    for (const std::vector<const ChunkResult*>& chunks :
         {std::vector<const ChunkResult*>{&first, &late},
          std::vector<const ChunkResult*>{&first, &late, &late, &last}}) {
        Journal j = Journal::create(path, id);
        for (const ChunkResult* c : chunks)
            j.append(c->first_row, c->outcomes.size(), encode_result(*c));
        bool refused = false;
        try {
            for_each_row_in_order(j, 6, [](uint64_t, const Outcome&) {});
        } catch (const JournalError&) {
            refused = true;
        }
        assert_true(refused);
    }
}

void journal_resumes_and_drops_a_torn_tail(void** state)
{
    (void)state;
    const std::string path = g_tools.scratch + "/j.cwj";
    const JournalIdentity id{0, 0x1234, 30};
    {
        Journal j = Journal::create(path, id);
        for (uint64_t first : {0u, 10u, 20u}) {
            j.append(first, 10, encode_result(sample_result(first, 10)));
        }
        j.sync();
    }
    {
        Journal j = Journal::open_existing(path, id);
        assert_int_equal(j.records().size(), 3);
        assert_false(j.dropped_torn_tail());
        const ChunkResult r = j.read(j.records()[2]);
        assert_int_equal(r.first_row, 20);
        assert_true(r.outcomes[1].result.Fx == -2100.0);
    }
    // A kill during an append: part of the last record.
    fs::resize_file(path, fs::file_size(path) - 9);
    {
        Journal j = Journal::open_existing(path, id);
        assert_int_equal(j.records().size(), 2);
        assert_true(j.dropped_torn_tail());
        // The next append starts on a record boundary.
        j.append(20, 10, encode_result(sample_result(20, 10)));
    }
    {
        Journal j = Journal::open_existing(path, id);
        assert_int_equal(j.records().size(), 3);
        assert_false(j.dropped_torn_tail());
    }
    // Another input, or a table instead of a campaign: refused, saying so.
    const JournalIdentity other{0, 0x9999, 30}, table{1, 0x1234, 30};
    for (const JournalIdentity& wrong : {other, table}) {
        bool refused = false;
        try {
            Journal::open_existing(path, wrong);
        } catch (const JournalError& e) {
            refused = std::strstr(e.what(), wrong.kind ? "creep-force table" : "another input");
        }
        assert_true(refused);
    }
    // Not a checkpoint at all.
    std::ofstream(g_tools.scratch + "/not.cwj") << "hello";
    bool refused = false;
    try {
        Journal::open_existing(g_tools.scratch + "/not.cwj", id);
    } catch (const JournalError& e) {
        refused = std::strstr(e.what(), "is not a creepwork checkpoint") != nullptr;
    }
    assert_true(refused);
}

} // namespace

int main(int argc, char** argv)
{
    if (!cwtest::set_up(argc, argv, "test_campaign_units", {"scratch"})) return 2;
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(number_text_equals_shortest_exact),
        cmocka_unit_test(csv_reader_follows_rfc4180),
        cmocka_unit_test(chunk_planner_covers_each_row_once),
        cmocka_unit_test(wire_round_trips_and_rejects_damage),
        cmocka_unit_test(journal_resumes_and_drops_a_torn_tail),
        cmocka_unit_test(results_writer_puts_rows_in_order),
    };
    return cw_run_tests(tests, g_tools.test);
}
