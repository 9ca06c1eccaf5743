// Helpers for the exact model's tests: CONTACT's exact rows
// (tests/data/contact_exact_dev.csv, CONTACT method a, commit
// d431cdb) as solver inputs, in CONTACT's units (mm, N, N/mm^2; the library
// is unit-consistent).
#pragma once

#include <string>
#include <vector>

#include "core_test_support.hpp"

namespace cwtest {

struct ExactRow {
    std::string id;      // case_id/N
    std::string case_id;
    int N = 0;           // elements across the ellipse
    creepwork::GridSpec grid;
    creepwork::ContactInput input;
    double FX, FY, MZ, fric_power, fric_macro, pmax, approach;
    int n_adh, n_slip, n_contact;
};

inline std::vector<ExactRow> exact_rows(int only_N = 0)
{
    const CsvTable t = read_csv(test_data_path("contact_exact_dev.csv"));
    std::vector<ExactRow> rows;
    for (size_t r = 0; r < t.rows.size(); ++r) {
        ExactRow row;
        row.case_id = t.text(r, "case_id");
        row.N = int(t.number(r, "grid_N"));
        if (only_N && row.N != only_N) continue;
        row.id = row.case_id + "/" + std::to_string(row.N);
        row.grid = uniform_grid(int(t.number(r, "MX")), int(t.number(r, "MY")),
                                t.number(r, "SCALE"));
        creepwork::ContactInput& in = row.input;
        in.model = creepwork::ModelKind::exact;
        in.a = t.number(r, "a_mm");
        in.b = t.number(r, "b_mm");
        in.normal_force = t.number(r, "FN_N");
        in.mu = t.number(r, "mu");
        in.G = t.number(r, "G_N_per_mm2");
        in.nu = t.number(r, "nu");
        in.xi_x = t.number(r, "cksi");
        in.xi_y = t.number(r, "ceta");
        in.phi = t.number(r, "cphi_rad_per_mm");
        in.spin_offset = t.number(r, "facphi");
        row.FX = t.number(r, "FX_N");
        row.FY = t.number(r, "FY_N");
        row.MZ = t.number(r, "MZ_Nmm");
        row.fric_power = t.number(r, "FRIC_POWER_W");
        row.fric_macro = t.number(r, "FRIC_POWER_macro_W");
        row.pmax = t.number(r, "pmax_grid_N_per_mm2");
        row.approach = t.number(r, "approach_mm");
        row.n_adh = int(t.number(r, "n_adh"));
        row.n_slip = int(t.number(r, "n_slip"));
        row.n_contact = int(t.number(r, "n_contact"));
        rows.push_back(row);
    }
    return rows;
}

// The benchmark contact of doc/performance.md (SI units): a = 7.17 mm, b = 5.42 mm,
// N = 100 kN, mu = 0.3, G = 82 GPa, nu = 0.28, partial slip.
inline creepwork::ContactInput bench_contact()
{
    creepwork::ContactInput in;
    in.model = creepwork::ModelKind::exact;
    in.a = 7.17e-3;
    in.b = 5.42e-3;
    in.normal_force = 100e3;
    in.mu = 0.3;
    in.G = 82e9;
    in.nu = 0.28;
    in.xi_x = 6e-4;
    in.xi_y = 3e-4;
    in.phi = 0.2;
    return in;
}

// MX = MY = N + 4 over box scale (N + 4)/N: two guard cells, as CONTACT's rows.
inline creepwork::GridSpec guarded_grid(int N)
{
    return uniform_grid(N + 4, N + 4, (N + 4.0) / N);
}

} // namespace cwtest
