// CSV files of one solve, in the chosen units, one header line each; every
// column name carries its unit (SI shown; --units paper: ft, psi, lbf ...):
//   fields.csv   one row per element (contact and exterior), i fastest:
//                i,j,x_m,y_m,area_m2,state,pz_Pa,px_wheel_Pa,py_wheel_Pa,sx,sy,
//                mz_wheel_N_m,work_paper_J_per_m,work_consistent_J_per_m
//                state: 0 exterior, 1 adhesion, 2 slip; px, py, mz act on the
//                wheel (the library's sign, whatever --plot-sign says);
//                sx, sy = W/V (dimensionless); work per rolled distance.
//   profile.csv  one row per strip: j,y_m,w_J_per_m_per_m,parabola_J_per_m_per_m
//                (lateral work profile and the equal-area parabola, paper
//                Figs. 8-9).
#pragma once

#include <string>

#include "contact_solver.hpp"
#include "units.hpp"

namespace cwcli {

// The header lines, in the units of u.
std::string field_columns(const Units& u);
std::string profile_columns(const Units& u);

void write_fields_csv(const std::string& path, const Solution& s, const Units& u);
void write_profile_csv(const std::string& path, const Solution& s, const Units& u);

} // namespace cwcli
