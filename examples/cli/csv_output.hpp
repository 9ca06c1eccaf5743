// CSV files of one solve, in the chosen units, one header line each:
//   fields.csv   one row per element (contact and exterior), i fastest:
//                i,j,x,y,area,state,pz,px,py,sx,sy,mz,work_paper,work_consistent
//                state: 0 exterior, 1 adhesion, 2 slip; px, py, mz on the wheel.
//   profile.csv  one row per strip: j,y,w,parabola (lateral work profile and
//                the equal-area parabola, paper Figs. 8-9).
#pragma once

#include <string>

#include "contact_solver.hpp"
#include "units.hpp"

namespace cwcli {

extern const char* const kFieldColumns; // the header of fields.csv

void write_fields_csv(const std::string& path, const Solution& s, const Units& u);
void write_profile_csv(const std::string& path, const Solution& s, const Units& u);

} // namespace cwcli
