#include "normal/pressure_by_load.hpp"

#include "contact/error.hpp"

namespace creepwork {
namespace {

// The linear solve A_CC z = 1 to max |residual| <= 1e-12 (the normal
// problem's own tolerance is 1e-10 on the gap relative to the depth): the
// derivative is then as good as the solution it linearises.
constexpr double kLoadDerivativeTolerance = 1e-12;
constexpr int kLoadDerivativeMaxIterations = 1000;

} // namespace

void pressure_by_load(NormalMethod method, NormalProblem& normal, GridConvolution& conv,
                      const SemiHertz& semi_hertz, const double* pressure, size_t n, double dx,
                      double dy, double* out)
{
    if (method == NormalMethod::semi_hertz) {
        semi_hertz.load_derivative(pressure, out);
        return;
    }
    if (!normal.load_derivative(conv, kLoadDerivativeTolerance, kLoadDerivativeMaxIterations))
        throw Error(ErrorKind::not_converged,
                    "the normal problem's derivative by the normal force did not converge");
    // dq / d(sum q) with sum q = N / (G dx dy) and p = G q: dp/dN = share / (dx dy).
    const std::vector<double>& share = normal.pressure_by_load();
    const double inv_area = 1.0 / (dx * dy);
    for (std::size_t k = 0; k < n; ++k) out[k] = share[k] * inv_area;
}

} // namespace creepwork
