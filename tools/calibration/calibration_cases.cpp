#include "calibration_cases.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "contact/kalker_coefficients.hpp"

namespace cwcal {
namespace {

// SplitMix64: a fixed, portable generator, so the sets never change.
struct Random {
    uint64_t state;
    double uniform()
    {
        uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        z ^= z >> 31;
        return double(z >> 11) * 0x1p-53;
    }
    double sign() { return uniform() < 0.5 ? -1.0 : 1.0; }
};

// The contact shared by every case: c = sqrt(ab) = 6 mm, N = 10 kN, mu = 0.3,
// G = 82 GPa (steel). Only a/b, nu and the normalised creepages matter.
constexpr double kC = 6e-3, kN = 10e3, kMu = 0.3, kG = 82e9;

// The combinations of creepages: each alone, spin with each, all three.
constexpr int kCombos[] = {1, 2, 4, 5, 6, 7, 3};

CalibrationCase make_case(const std::string& id, double ab, double nu, double level, int combo,
                          Random& r)
{
    CalibrationCase k;
    k.id = id;
    k.a_over_b = ab;
    k.nu = nu;
    k.level = level;
    k.combo = combo;
    creepwork::ContactInput& in = k.input;
    in.a = kC * std::sqrt(ab);
    in.b = kC / std::sqrt(ab);
    in.normal_force = kN;
    in.mu = kMu;
    in.G = kG;
    in.nu = nu;
    const creepwork::CreepCoefficients C = creepwork::kalker_coefficients(ab, nu);
    const double muN = kMu * kN;
    const double sat[3] = {muN / (kG * kC * kC * C.C11), muN / (kG * kC * kC * C.C22),
                           muN / (kG * kC * kC * kC * C.C23)};
    // Weights of the creepages present, unit Euclidean norm.
    double w[3] = {0, 0, 0}, norm = 0;
    for (int q = 0; q < 3; ++q)
        if (combo & (1 << q)) {
            w[q] = 0.3 + 0.7 * r.uniform();
            norm += w[q] * w[q];
        }
    norm = std::sqrt(norm);
    double v[3];
    for (int q = 0; q < 3; ++q) v[q] = level * w[q] / norm * sat[q] * r.sign();
    in.xi_x = v[0];
    in.xi_y = v[1];
    in.phi = v[2];
    return k;
}

} // namespace

const char* set_name(CaseSet set) { return set == CaseSet::training ? "training" : "evaluation"; }

std::vector<CalibrationCase> make_cases(CaseSet set)
{
    std::vector<CalibrationCase> cases;
    if (set == CaseSet::training) {
        // 210 cases: a/b, nu and the level drawn log-/uniformly over the
        // whole range, each combination of creepages in turn.
        Random r{20261123};
        for (int n = 0; n < 210; ++n) {
            const double ab = 0.2 * std::pow(25.0, r.uniform());
            const double nu = 0.5 * r.uniform();
            const double level = 0.01 * std::pow(300.0, r.uniform());
            cases.push_back(make_case("train" + std::to_string(n), ab, nu, level,
                                      kCombos[n % 7], r));
        }
    } else {
        // 105 cases: a/b on five fixed values (0.2, 0.5, 1, 2, 5), nu on
        // three (0, 0.28, 0.5), levels stratified over 1 % .. 300 %, each
        // combination of creepages; signs drawn.
        Random r{77};
        const double abs[] = {0.2, 0.5, 1.0, 2.0, 5.0};
        const double nus[] = {0.0, 0.28, 0.5};
        int n = 0;
        for (int combo_index = 0; combo_index < 7; ++combo_index)
            for (int q = 0; q < 15; ++q, ++n) {
                const double ab = abs[(q + combo_index) % 5];
                const double nu = nus[(q / 5 + combo_index) % 3];
                // 15 levels per combination, log-spaced over 1 % .. 300 %.
                const double level = 0.01 * std::pow(300.0, (q + r.uniform()) / 15.0);
                cases.push_back(make_case("eval" + std::to_string(n), ab, nu, level,
                                          kCombos[combo_index], r));
            }
    }
    return cases;
}

} // namespace cwcal
