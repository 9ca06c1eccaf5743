// How far FASTSIM's frictional-work distribution is from Kalker's exact
// theory's, for one contact solved by both on the same uniform grid
// (creepwork compare). Distributions are compared as shapes: each map is
// scaled to unit total first, so a metric measures where the work goes, not
// how much there is (the totals are compared separately).
#pragma once

#include "contact_solver.hpp"

namespace cwcli {

struct WorkComparison {
    // L1 distance sum_k |f_k/F - e_k/E| of the energy-consistent work maps
    // (what wear is computed from): 0 identical, 2 disjoint supports.
    double map_l1_consistent = 0.0;
    // The same for the paper-style maps: FASTSIM's local work (paper eq. 36)
    // against the exact frictional power density D_I (CONTACT's FRIC_POWER).
    double map_l1_paper = 0.0;
    // L1 distance of the lateral work profiles (per strip), unit totals.
    double profile_l1 = 0.0;
    // Share of the exact dissipation sum D_I that falls in elements FASTSIM
    // calls adhesion (where its own work map is zero).
    double exact_power_in_fastsim_adhesion = 0.0;
    // Share of FASTSIM's energy-consistent work in elements the exact theory
    // calls adhesion.
    double fastsim_work_in_exact_adhesion = 0.0;
    // Elements in contact for both models whose states differ.
    int state_differences = 0;
    // Work centroid (energy-consistent map) along the rolling direction, in
    // units of a: +1 the leading edge, -1 the trailing edge.
    double centroid_fastsim = 0.0, centroid_exact = 0.0;
};

// Both solutions must be full solves on the same grid (throws CliError
// otherwise). A map without work (no slip anywhere) has no shape: the
// metrics that need it are NaN (null in JSON, "undefined" in text).
WorkComparison compare_work(const Solution& fastsim, const Solution& exact);

} // namespace cwcli
