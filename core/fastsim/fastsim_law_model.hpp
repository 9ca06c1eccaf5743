// FASTSIM with a friction law of the slip speed at every element: Kalker's
// march (the grid, setup, traction bound and totals of march_model.hpp)
// where each slipping element keeps its predictor's direction and the
// magnitude t = p_n mu(s) at its own slip speed s instead of Coulomb's
// p_n mu. The rolling speed V turns micro-slip into slip speed. Without
// memory the march is the SIMD kernel of march_law.hpp (every ISA the same
// bits); Coulomb's law is FASTSIM's march itself (bitwise FastsimModel's);
// with memory the march is scalar, element after element
// (friction/local_slip.hpp).
//
// Slip speed of an element: its slip over one step h is the elastic
// predictor's displacement less the displacement it keeps, (L1 dq_x, L2 dq_y)
// with dq = (1 - f) q, so s = V (1 - f) |(L1 q_x, L2 q_y)| T / h (T the
// traction unit, mu_s p0).
#pragma once

#include "contact/params.hpp"
#include "friction/friction_memory.hpp"
#include "friction/slip_speed_law.hpp"
#include "fastsim/march_tangent.hpp"
#include "march/march_model.hpp"

namespace creepwork {

class FastsimLawModel : public MarchModel {
public:
    explicit FastsimLawModel(const GridSpec& grid);
    explicit FastsimLawModel(std::shared_ptr<const ContactGrid> grid);

    // The law and the rolling speed V [m/s] > 0 the next solves use; throws
    // Error(invalid_input) naming the input (the law's parameters, V).
    void set_law(const SlipSpeedLaw& law, double V) override;
    // Friction memory along each strip (friction_memory.hpp; distance 0: none,
    // the default): every element's coefficient is mu_m of its slip speed,
    // the previous element's mu and dt = h / V, adhering elements' too
    // (their s is 0). Throws Error(invalid_input) naming the input.
    void set_memory(const FrictionMemory& memory);
    // Element-wise factors on mu (contact/friction_law.hpp): each element's
    // bound is its factor times mu(s) p; the caller keeps them.
    void set_friction_factors(const double* factor) override { take_friction_factors(factor); }

    // input.mu is not read: the traction unit is the law's static
    // coefficient. Full mode: the work of every element from the march's
    // (q', f) (march_work.hpp): the friction dissipation of each slipping
    // element is its traction times its slip, whatever law set the
    // traction, so the map sums to W_macro, is >= 0 and 0 in adhesion.
    SolveTotals solve(const ContactInput& input, SolveMode mode) override;
    // The Jacobian by forward differentiation of the same march (the totals
    // bitwise solve()'s): per slipping element the derivative of t through
    // P = |q'|, the slip-speed factor c (which moves with q' and, through
    // the traction unit, with N) and the law's slope (march_law.hpp); held
    // fixed as in FASTSIM's Jacobian (fastsim_jacobian.hpp), and V. Not
    // with memory (Error naming it).
    SolveTotals solve_jacobian(const ContactInput& input, SolveMode mode,
                               Jacobian& jacobian) override;

    // Over the slipping elements of the last solve (mu_s when none slips):
    // the smallest and largest coefficient, and the Newton steps of all.
    bool friction_range(double& mu_min, double& mu_max) const override
    {
        mu_min = mu_min_;
        mu_max = mu_max_;
        return true;
    }
    double mu_min() const { return mu_min_; }
    double mu_max() const { return mu_max_; }
    int friction_iterations() const { return iterations_; }

private:
    void march_with_law(bool tangents);
    void march_with_memory();
    void prepare(const ContactInput& input);

    SlipSpeedLaw law_;
    FrictionMemory memory_;
    double V_ = 0.0;
    double mu_min_ = 0.0, mu_max_ = 0.0;
    int iterations_ = 0;
    ContactInput input_; // the last solve's, with mu = the law's static coefficient
    // Tangents: rows ux, uy, kappa (fastsim_jacobian reads them) and ln T.
    TangentState tangent_;
    Eigen::ArrayXd ratio_min_, ratio_max_, strip_iterations_; // per strip (march_law.hpp)
};

} // namespace creepwork
