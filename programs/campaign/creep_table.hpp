// Creep-force tables (`creepwork campaign --table`): the campaign's rows
// generated over a grid of a/b, nu and creepages and spin in Kalker's table
// normalisation -- the one CONTACT's USETAB tables use (CONTACT
// src/usetab_table.f90): with c = sqrt(a b) and Kalker's C11, C22, C23
// (Table E.3, cw_kalker_coefficients),
//     xi'  = G c^2 C11 xi_x / (3 mu N)
//     eta' = G c^2 C22 xi_y / (3 mu N)
//     psi' = G c^3 C23 phi  / (mu N)
// and the entries fx = Fx/(mu N), fy = Fy/(mu N), mz = Mz/(mu N c). In
// these variables the forces of Kalker's theories depend on a/b, nu and
// (xi', eta', psi') only, and the linear theory reads fx = -3 xi',
// fy = -3 eta' (forces on the wheel, as everywhere in creepwork).
// Each point is solved on a unit contact (c = 1 m, G = 1 Pa, N = 1 N,
// mu = 1; a = sqrt(a/b), b = 1/sqrt(a/b)), so fx, fy, mz are the solver's
// Fx, Fy, Mz themselves. doc/campaigns.md documents the files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <creepwork/creepwork.h>

#include "campaign_types.hpp"
#include "journal.hpp"

namespace cwcampaign {

struct TableSpec {
    // Axes, each strictly increasing. Points are numbered with psi fastest:
    // k = ipsi + npsi*(ieta + neta*(ixi + nxi*(inu + nnu*iaob))).
    std::vector<double> aob, nu, xi, eta, psi;
    int model = CW_MODEL_FASTSIM;
    int pressure = CW_PRESSURE_PARABOLIC;
    cw_grid grid; // cw_grid_init's defaults unless given
};

// CONTACT's USETAB axes (usetab_table.f90 with itab = 7), sorted and
// without repeats: 24 values of a/b from 1/7 to 200; xi' and eta' 0, 1/7 ..
// 1, 7/6 .. 7 and 7e5 (CONTACT's "infinity", 7/1e-5); psi' the same with
// both signs; nu = 0.28.
TableSpec usetab_axes();

uint64_t table_points(const TableSpec& spec);
// The identity of a table on resume: every axis value and option.
uint64_t table_hash(const TableSpec& spec);
// One case per point, in point order; a/b or nu outside Kalker's table
// makes that point's row rejected (ROW_UNREADABLE) with the library's message.
std::vector<ContactCase> table_cases(const TableSpec& spec);

struct TableSummary {
    uint64_t points = 0, failed = 0;
    std::string first_failure;
};

// DIR/table.csv (aob,nu,xi,eta,psi,status,fx,fy,mz,message: one line per
// point in point order) and DIR/table.json (the axes, the order, the
// normalisation, the model and grid), read from the checkpoint.
TableSummary write_table(const Journal& journal, const TableSpec& spec, const std::string& dir);

} // namespace cwcampaign
