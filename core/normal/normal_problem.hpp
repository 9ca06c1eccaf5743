// The discrete normal contact problem of Kalker's exact theory
// (doc/theory/exact-discretisation.md rule 4; CONTACT's
// m_solvpn.f90:normcg):
// pressures pn >= 0 and the approach pen such that
//   h_I - pen + sum_J cf33(I - J) pn_J / G  = 0 where pn_I > 0, >= 0 elsewhere,
// with either the normal force prescribed, dx dy sum pn = N (pen unknown),
// or the approach pen prescribed. Two gaps:
//  - solve(): the Hertzian gap h = A x^2 + B y^2 of the semi-axes a, b
//    (contact/hertz.hpp), force prescribed. Normalised: lengths in units of dx,
//    pressures in units of the Hertz maximum p0 = 3N/(2 pi a b), gaps in
//    units of p0 dx / G. Then q = pn/p0 depends only on the grid and a/b
//    (nu enters as a common factor 1 - nu), so one solution serves every N,
//    G and creepage.
//  - solve_gap(): any gap the caller gives, in units of dx, with q = pn / G,
//    force or approach prescribed (contacts of any shape, gap_normal.hpp).
//
// Method: an active-set iteration whose linear problems (a symmetric
// positive definite system on the contact set with the force as a linear
// constraint) are solved by projected conjugate gradients, preconditioned by
// the inverse of the periodic extension of the kernel (one FFT pair; cf.
// Vollebregt, J. Comput. Phys. 257 (2014) 333-351, who uses an FFT-based
// preconditioner in CONTACT's NormCG). It converges in about a dozen
// iterations whatever the grid size. Starts from the Hertz pressure on the
// elements whose centre lies inside the ellipse, or from a given solution.
//
// With a second convolution (set_box_convolution) the conjugate gradients
// run their products on the smallest box holding the contact set (the
// fields vanish outside the set, and only their values on it are read), the
// preconditioner that box's FFT size's circulant; each pass's complementarity
// check still takes the product on the whole grid.
#pragma once

#include <vector>

#include "halfspace/exact_geometry.hpp"
#include "halfspace/grid_convolution.hpp"

namespace creepwork {

struct NormalSolveInfo {
    int iterations = 0;      // conjugate-gradient iterations (each two FFT products)
    int active_set_passes = 0;
    int products = 0;        // FFT products, on the contact set's box or the whole grid
    double residual = 0;     // final max |gap| on the contact set, relative to the approach
    bool converged = false;
};

class NormalProblem {
public:
    explicit NormalProblem(int nx, int ny); // all workspaces

    // conv must hold the coefficients of this geometry (rho, nu). With
    // start = true the previous solution (same geometry) is the first
    // guess. tolerance: on max |gap| / approach over the contact set.
    NormalSolveInfo solve(const ExactGeometry& geom, GridConvolution& conv, bool start,
                          double tolerance, int max_iterations);

    // Any gap h [i + nx j] in units of dx (nx ny values), q = pn / G.
    // force = true: sum q = value (N / (G dx dy)), the approach is found;
    // false: the approach is value (in dx) and sum q follows. start (nx ny
    // values, q >= 0, not all zero) is the first guess of q; only its
    // contact set and shape matter when the force is prescribed. The
    // tolerance is on max |gap| / depth over the contact set, depth = the
    // approach less the smallest h. Approach below every h: no contact,
    // converged, q = 0. first_tolerance (> tolerance) solves the passes that
    // still change the contact set only that far: the set settles as well,
    // and one last pass at the tolerance finishes.
    // start_product (or null): A start on the whole grid (the units of h),
    // taken for the first pass's product when no element of start is
    // negative (one FFT product fewer; other bits than the product's).
    NormalSolveInfo solve_gap(GridConvolution& conv, const double* h, const double* start,
                              bool force, double value, double tolerance, int max_iterations,
                              double first_tolerance = 0.0,
                              const double* start_product = nullptr);
    // After a converged solve: A q on the whole grid (the units of h), the
    // last pass's product.
    const std::vector<double>& product() const { return u_; }

    // box: a convolution of the same largest grid (ConvolutionUse::normal)
    // for the products on the contact set's box, or nullptr (the default:
    // every product on the whole grid). Its coefficients follow conv's.
    void set_box_convolution(GridConvolution* box) { box_ = box; }

    // q = pn / p0 per element [i + nx j] (0 outside the contact set).
    const std::vector<double>& pressure() const { return q_; }
    // The derivative of the last converged solution's pressure by its total,
    // dq / d(sum q), per element [i + nx j] (sums to 1; 0 off the contact
    // set), at the contact set C the solve found: on C the problem is
    // A_CC q = pen - h, so dq = z d(pen) with A_CC z = 1, and dq / d(sum q)
    // = z / sum z, whichever of the force and the approach was prescribed.
    // z by the solve's preconditioned conjugate gradients to max |A z - 1|
    // <= tolerance on C. conv as for the solve. Returns false if they did
    // not converge in max_iterations (or there is no contact).
    bool load_derivative(GridConvolution& conv, double tolerance, int max_iterations);
    const std::vector<double>& pressure_by_load() const { return dq_; }
    // Of the last successful load_derivative: sum z = d(sum q) / d(pen), the
    // total's derivative by the approach (in units of dx).
    double load_by_approach() const { return load_by_approach_; }
    // The approach in units of p0 dx / G.
    double approach() const { return pen_; }
    int n_contact() const { return n_contact_; }

private:
    // The active-set passes from q_ (h_ set): with the force prescribed
    // (fixed_sum, sum q = load) or the approach pen_ prescribed. Residuals
    // are measured against |pen - h_floor|.
    void active_set(GridConvolution& conv, bool fixed_sum, double load, double h_floor,
                    double tolerance, double first_tolerance, int max_iterations,
                    NormalSolveInfo& info);
    // u_current: u_ holds A q_ where it is read (the pass just took it).
    bool conjugate_gradients(GridConvolution& conv, bool fixed_sum, bool u_current, double target,
                             double tolerance, int max_iterations, NormalSolveInfo& info);
    void project(std::vector<double>& v) const; // zero mean on the set, zero off it
    // out = A in (inverse: the preconditioner) where out is read: on the
    // contact set's box with box_, else on the whole grid.
    // Counted in products_.
    void set_product(GridConvolution& conv, const std::vector<double>& in,
                     std::vector<double>& out, bool inverse);
    void grid_product(GridConvolution& conv); // u_ = A q_ on the whole grid, counted
    void fit_box(GridConvolution& conv); // box_ to the bounding box of the set

    int n_, nx_;
    std::vector<double> h_, q_, u_, r_, z_, p_, ap_, box_in_, box_out_, dq_;
    GridConvolution* box_ = nullptr;
    int box_i0_ = 0, box_j0_ = 0, box_nx_ = 0, box_ny_ = 0;
    std::vector<char> active_;
    int n_active_ = 0;
    int n_contact_ = 0;
    double pen_ = 0.0;
    double load_by_approach_ = 0.0;
    int products_ = 0; // FFT products since the solve began
    const double* start_product_ = nullptr; // solve_gap's, for the first pass
};

} // namespace creepwork
