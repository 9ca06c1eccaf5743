// The tables of doc/validation/friction.md, printed by the code they
// measure (scripts/doc-tables.sh regenerates them):
//   creepwork_friction_tables polach      Polach's model, dry and wet sets
//   creepwork_friction_tables tractcurv   FASTSIM with a law against CONTACT's
//                                         tractcurv series 3 and 4
//   creepwork_friction_tables sliding     full sliding against the closed form
// tractcurv reads tests/data/contact_tractcurv.csv under
// $CREEPWORK_SOURCE_DIR (or the directory given after the table's name).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "contact/contact_grid.hpp"
#include "core_test_support.hpp"
#include "fastsim/fastsim_law_model.hpp"
#include "friction/global_slip.hpp"
#include "friction/polach_model.hpp"
#include "solver.hpp"
#include "tractcurv_contact.hpp"

namespace cw = creepwork;

namespace {

// F/Q of Polach's model on tractcurv's contact with Kalker's C11 = 3.765.
double polach_ratio(double mu0, double A, double B, double kA, double kS, double xi)
{
    cw::PolachInput in;
    in.Q = cwtest::kTractcurvN;
    in.a = 6.304e-3;
    in.b = 12.61e-3;
    in.G = 82e9;
    in.C11 = 3.765;
    in.xi_x = xi;
    in.V = cwtest::kTractcurvV;
    in.law = cw::polach_law(mu0, A, B);
    in.k_A = kA;
    in.k_S = kS;
    return -cw::polach_forces(in).Fx / in.Q;
}

void polach()
{
    struct Set {
        const char* name;
        double mu0, A, B, kA, kS;
    } sets[] = {{"dry", 0.55, 0.40, 0.60, 1.00, 0.40}, {"wet", 0.30, 0.40, 0.20, 0.30, 0.10}};
    std::printf("| set | mu0 | A | B [s/m] | k_A | k_S | 0.1 %% | 0.4 %% | 2 %% | 10 %% | 25 %% | peak |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Set& s : sets) {
        std::printf("| %s | %.2f | %.2f | %.2f | %.2f | %.2f |", s.name, s.mu0, s.A, s.B, s.kA, s.kS);
        for (double xi : {0.001, 0.004, 0.02, 0.10, 0.25})
            std::printf(" %.4f |", polach_ratio(s.mu0, s.A, s.B, s.kA, s.kS, xi));
        double lo = 0.005, hi = 0.2; // golden section for the peak
        const double g = 0.5 * (std::sqrt(5.0) - 1.0);
        for (int it = 0; it < 80; ++it) {
            const double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
            if (polach_ratio(s.mu0, s.A, s.B, s.kA, s.kS, x1) < polach_ratio(s.mu0, s.A, s.B, s.kA, s.kS, x2))
                lo = x1;
            else
                hi = x2;
        }
        std::printf(" %.4f at %.2f %% |\n", polach_ratio(s.mu0, s.A, s.B, s.kA, s.kS, lo), 100 * lo);
    }
}

cw::SlipSpeedLaw series4_law()
{
    cw::SlipSpeedLaw law;
    law.kind = cw::SlipSpeedLawKind::exponential;
    law.mu_kin = 0.1368;
    law.mu_e1 = 0.2232;
    law.s_h1 = 0.990;
    return law;
}
const cw::SlopeReduction kSpiryagin{0.54, 0.02, 0.62};

void tractcurv(const std::string& source)
{
    const cwtest::CsvTable t = cwtest::read_csv(source + "/tests/data/contact_tractcurv.csv");
    const cw::GridSpec spec = cwtest::tractcurv_grid();
    const cw::ContactGrid grid(spec);
    cw::Solver s(spec);
    std::printf("| series | creepwork | rows | largest \\|ours - CONTACT\\| of \\|Fx\\|/(mu_s N) | "
                "slip elements as CONTACT's |\n|---|---|---|---|---|\n");
    for (int series : {3, 4}) {
        int rows = 0, same = 0;
        double worst = 0.0;
        for (size_t r = 0; r < t.rows.size(); ++r) {
            if (t.number(r, "series") != series) continue;
            cw::ContactInput in = cwtest::tractcurv_contact(t.number(r, "CKSI"));
            double mu_s = 0.33;
            if (series == 3) {
                in.mu = mu_s;
            } else {
                mu_s = 0.36;
                in = cw::global_slip_input(in, grid, series4_law(), kSpiryagin, cwtest::kTractcurvV);
            }
            const cw::SolveTotals& tot = s.solve(in);
            worst = std::max(worst, std::fabs(tot.Fx / (mu_s * cwtest::kTractcurvN) -
                                              t.number(r, "FX_over_FSTAT_FN")));
            same += tot.n_slip == int(t.number(r, "NSLIP"));
            ++rows;
        }
        std::printf("| %d | %s | %d | %.1e | %d of %d |\n", series,
                    series == 3 ? "FASTSIM, Coulomb 0.33"
                                : "FASTSIM, global slip speed, Spiryagin's reduction",
                    rows, worst, same, rows);
    }
}

void sliding(const std::string& source)
{
    const cwtest::CsvTable t = cwtest::read_csv(source + "/tests/data/contact_tractcurv.csv");
    const cw::GridSpec spec = cwtest::tractcurv_grid();
    const cw::ContactGrid grid(spec);
    cw::Solver s(spec);
    cw::FastsimLawModel local(spec);
    local.set_law(series4_law(), cwtest::kTractcurvV);
    std::printf("| xi_x | A + (1 - A) exp(-B xi V) | CONTACT series 4 | global slip | local law |\n"
                "|---|---|---|---|---|\n");
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const double xi = t.number(r, "CKSI");
        if (t.number(r, "series") != 4 || xi < 0.1) continue;
        const cw::ContactInput in = cwtest::tractcurv_contact(xi);
        const double N = cwtest::kTractcurvN;
        const double g = -s.solve(cw::global_slip_input(in, grid, series4_law(), kSpiryagin,
                                                        cwtest::kTractcurvV)).Fx / (0.36 * N);
        const double l = -local.solve(in, cw::SolveMode::forces_only).Fx / (0.36 * N);
        std::printf("| %.1f %% | %.4f | %s | %.4f | %.4f |\n", 100 * xi,
                    0.38 + 0.62 * std::exp(-0.7 * xi * cwtest::kTractcurvV),
                    t.text(r, "FX_over_FSTAT_FN").substr(1).c_str(), g, l);
    }
}

} // namespace

int main(int argc, char** argv)
{
    const char* env = std::getenv("CREEPWORK_SOURCE_DIR");
    const std::string source = argc > 2 ? argv[2] : env ? env : ".";
    if (argc > 1 && !std::strcmp(argv[1], "polach")) {
        polach();
    } else if (argc > 1 && !std::strcmp(argv[1], "tractcurv")) {
        tractcurv(source);
    } else if (argc > 1 && !std::strcmp(argv[1], "sliding")) {
        sliding(source);
    } else {
        std::fprintf(stderr, "usage: creepwork_friction_tables polach|tractcurv|sliding [SOURCE_DIR]\n");
        return 2;
    }
    return 0;
}
