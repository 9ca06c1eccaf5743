// The pieces of `creepwork_calibration select-weights` that decide what it
// measures (doc/dev/calibration.md), without its solves:
//  - the folds: every training case in exactly one fold, each fold a third of
//    every combination of creepages, spread over the whole a/b range;
//  - the table a fold's fit makes is read by core's calibration_node(table,
//    a/b), linear in ln(a/b) between nodes (values known by hand);
//  - the objective's weights mean what FitWeights says (case_cost of errors
//    chosen so that each term is known by hand);
//  - the fine reference map is summed onto the map grid cell by cell (the
//    fit compares 160 x 160 maps on the 40 x 40 cells).
#include <algorithm>
#include <cmath>

#include "calibration_fit.hpp"
#include "calibration_select.hpp"
#include "test_support.h"

namespace {

namespace cw = creepwork;

void folds_split_each_combination_across_a_over_b(void**)
{
    const std::vector<cwcal::CalibrationCase> cases = cwcal::make_cases(cwcal::CaseSet::training);
    const std::vector<int> fold = cwcal::fold_of_cases(cases);
    assert_int_equal(fold.size(), 210);
    assert_true(fold == cwcal::fold_of_cases(cases)); // deterministic
    for (int combo : {1, 2, 3, 4, 5, 6, 7}) {
        std::vector<std::pair<double, int>> members; // (a/b, fold)
        int per_fold[cwcal::kSelectFolds] = {};
        for (size_t k = 0; k < cases.size(); ++k)
            if (cases[k].combo == combo) {
                assert_in_range(fold[k], 0, cwcal::kSelectFolds - 1);
                ++per_fold[fold[k]];
                members.push_back({cases[k].a_over_b, fold[k]});
            }
        // 30 cases of each combination: 10 in each fold.
        for (int n : per_fold) assert_int_equal(n, 10);
        // Neighbours in a/b are in different folds, and each fold holds one
        // of the three smallest and one of the three largest a/b.
        std::sort(members.begin(), members.end());
        for (size_t r = 1; r < members.size(); ++r)
            assert_int_not_equal(members[r].second, members[r - 1].second);
        for (int f = 0; f < cwcal::kSelectFolds; ++f) {
            size_t first = members.size(), last = 0;
            for (size_t r = 0; r < members.size(); ++r)
                if (members[r].second == f) {
                    first = std::min(first, r);
                    last = r;
                }
            assert_true(first < size_t(cwcal::kSelectFolds));
            assert_true(last >= members.size() - cwcal::kSelectFolds);
        }
    }
}

// A fold's table is read by core's calibration_node(table, a/b), as the
// built-in one is: every member linear in ln(a/b) between the nodes and
// constant beyond them. A table whose members are known functions of the
// node: member m of node k is 10 m + k, so between nodes k and k + 1 at
// weight w = ln(ab/ab_k)/ln(ab_k+1/ab_k) it is 10 m + k + w.
void fold_table_interpolates_in_ln_a_over_b(void**)
{
    const double nodes[cw::kCalibrationNodes] = {0.2, 0.5, 1.0, 2.0, 5.0};
    cwcal::CalibrationTable t;
    for (int k = 0; k < cw::kCalibrationNodes; ++k)
        t[k] = {nodes[k], 0 + k * 1.0, 10.0 + k, 20.0 + k, 30.0 + k, 40.0 + k,
                50.0 + k, 60.0 + k, 70.0 + k, 80.0 + k};
    struct Probe {
        double ab, position; // position: k + w, clamped to [0, 4]
    } probes[] = {{0.1, 0.0},
                  {0.2, 0.0},
                  {std::sqrt(0.2 * 0.5), 0.5},
                  {1.0, 2.0},
                  {std::sqrt(2.0), 2.5},
                  {2.0 * std::pow(2.5, 0.25), 3.25},
                  {5.0, 4.0},
                  {7.0, 4.0}};
    for (const Probe& q : probes) {
        const cw::CalibrationNode n = cw::calibration_node(t.data(), q.ab);
        const double got[] = {n.alpha_long, n.alpha_lat, n.alpha_spin_x, n.alpha_spin_y, n.fade,
                              n.equalise,   n.edge,      n.blend,        n.blend_half};
        for (int m = 0; m < 9; ++m) assert_close(got[m], 10.0 * m + q.position, 0.0, 1e-12);
    }
}

// Each error at its bound costs 1 (times the map weight for map and
// profile); a force error beyond the limit costs penalty ((dF - limit)/3)^2
// more. dFx 4 % with the limit at 2.5 and penalty 40: (4/3)^2 + 40 (1.5/3)^2
// = 16/9 + 10; Mz 8 % (relative) 1, W 5 % 1, map 0.3 and profile 0.08 at
// weight 1.5: 3.
void case_cost_weights_each_term(void**)
{
    cwcal::CaseErrors e;
    e.dFx = 4.0;
    e.dFy = 0.0;
    e.mz_relative = true;
    e.dMz = 8.0;
    e.has_spin = true;
    e.dW = 5.0;
    e.partial_slip = true;
    e.map_L1 = 0.3;
    e.profile_L1 = 0.08;
    assert_close(cwcal::case_cost(e, cwcal::FitWeights{2.5, 40.0, 1.5}), 16.0 / 9.0 + 10.0 + 2.0 + 3.0,
                 1e-14, 0.0);
    // No penalty below the limit; map weight 1; a small moment in units of
    // 0.5 % of mu N c; no spin, no partial slip: those terms drop.
    e.dFx = 2.4;
    e.mz_relative = false;
    e.dMz = 0.25;
    e.has_spin = false;
    e.partial_slip = false;
    assert_close(cwcal::case_cost(e, cwcal::FitWeights{2.5, 40.0, 1.0}), 0.64 + 0.25, 1e-14, 0.0);
}

// A 160 x 160 map f(i, j) = i + 1000 j summed over 4 x 4 blocks: coarse
// cell (I, J) holds sum over i = 4I..4I+3, j = 4J..4J+3 of f
// = 16 (4I + 1.5) + 16000 (4J + 1.5), exactly (integers below 2^53).
void fine_map_sums_onto_map_cells(void**)
{
    const int n = cwcal::kFineN, m = cwcal::kMapN;
    std::vector<double> fine(size_t(n) * n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) fine[size_t(i) + size_t(j) * n] = i + 1000.0 * j;
    const std::vector<double> map = cwcal::summed_onto_map_grid(fine);
    assert_int_equal(map.size(), size_t(m) * m);
    for (int J = 0; J < m; ++J)
        for (int I = 0; I < m; ++I)
            assert_close(map[size_t(I) + size_t(J) * m], 16.0 * (4 * I + 1.5) + 16000.0 * (4 * J + 1.5),
                         0.0, 0.0);
}

} // namespace

int main(int argc, char** argv)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(folds_split_each_combination_across_a_over_b),
        cmocka_unit_test(fold_table_interpolates_in_ln_a_over_b),
        cmocka_unit_test(case_cost_weights_each_term),
        cmocka_unit_test(fine_map_sums_onto_map_cells),
    };
    return cw_run_tests(tests, argc > 1 ? argv[1] : nullptr);
}
