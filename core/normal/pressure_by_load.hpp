// The derivative of a gap model's pressure by the normal force, dp/dN per
// element, at the last normal solve's solution: of the exact normal problem
// (NormalProblem::load_derivative: the discrete problem linearised at its
// contact set) or of the semi-Hertzian method (SemiHertz::load_derivative:
// its closed form at its depth). The same derivative whether the force or
// the approach was prescribed: along the solution, by the force it carries.
#pragma once

#include <cstddef>

#include "contact/params.hpp"
#include "halfspace/grid_convolution.hpp"
#include "normal/normal_problem.hpp"
#include "normal/semi_hertz.hpp"

namespace creepwork {

// pressure [Pa] and out [1/m^2]: n = nx ny elements of dx x dy [m], the
// layout (and frame) of the normal solve. conv: the exact problem's. Throws
// Error(not_converged) if the exact problem's linear solve fails.
void pressure_by_load(NormalMethod method, NormalProblem& normal, GridConvolution& conv,
                      const SemiHertz& semi_hertz, const double* pressure, std::size_t n, double dx,
                      double dy, double* out);

} // namespace creepwork
