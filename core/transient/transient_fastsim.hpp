// Transient rolling in Kalker's simplified theory (FASTSIM's transient form;
// doc/theory/transient.md, "FASTSIM"): model = fastsim in the transient
// handle's parameters. The same contact-fixed frame, steps and handle as
// TransientContact (transient_contact.hpp), with the half-space replaced by
// the simplified theory's local flexibility u = L p (L1 along x, L2 along
// y, each patch's own, as the steady gap FASTSIM's: gap_fastsim_model.hpp).
// Over a step in which the body rolls dq = d dx the particle now at x was
// at x + dq, so with its traction p_prev(x + dq) (linear between the
// elements, exact for d = 0 and d = 1, as the exact model's displacement)
// the slip of the step is
//   S = w + L (p - p_prev(x + dq)),
// w the rigid displacement of the step (creepage times dq, or the shift
// itself when dq = 0; the spin's rotation about the patch's centroid over
// L3, its translation over L1, L2, as the steady march; a shift's
// translation over Ls = pi a (2 - nu) / (4 G), a = sqrt(ab) of the patch
// ellipse: the flexibility whose uniform traction gives Mindlin's stick
// compliance (2 - nu) / (4 G a), where Kalker's rolling L1 is about half
// as compliant: doc/theory/transient.md). Adhesion (S = 0)
// gives the elastic predictor q = p_prev(x + dq) - w / L; where |q| > mu pz
// the element slips with p = mu pz q / |q| (then S = L (p - q) opposes p).
// Every element is explicit: a step is one pass over the contact. With d = 1
// and p_prev the steady traction, a step reproduces it: the steady march
// (start_steady marches each row from its leading edge) is a fixed point.
// Prescribed forces are met by Newton's method with the step's exact
// derivative (piecewise linear in the creepages: dp/dc = dq/dc in adhesion,
// mu pz (I - q q^T/|q|^2)/|q| dq/dc in slip), safeguarded by bisection for
// Fx alone.
//
// The normal problem is solved once (normal_method: exact or semi_hertz).
// Frame, units, state bytes and the trial / commit / rewind rules are
// TransientContact's.
#pragma once

#include <complex>
#include <vector>

#include "contact/params.hpp"
#include "normal/gap_normal.hpp"
#include "transient/transient_base.hpp"

namespace creepwork {

class TransientFastsim : public TransientBase {
public:
    using Complex = std::complex<double>;

    // As TransientContact's (model fastsim; flexibility = given is refused:
    // each patch's flexibilities come from G, nu and its size).
    TransientFastsim(const GridSpec& grid, const ContactInput& in);

    void start_zero();
    const TransientStepResult& start_steady(const TransientStepInput& step);
    const TransientStepResult& step(const TransientStepInput& step);
    void commit();
    std::vector<unsigned char> save() const;
    void restore(const unsigned char* bytes, std::size_t n);

    void copy_traction(double* px, double* py) const;
    void copy_slip(double* sx, double* sy) const;
    void copy_state(int* out) const;
    void copy_pressure(double* out) const;
    // The work of each element over the step [J]: its slip's dissipation
    // -p . S dA (0 in adhesion and outside). The step is explicit (no
    // numerical dissipation), so W_slip = W_step, the map's sum.
    void copy_work(double* out) const;

private:
    struct Patch {
        double L1 = 0, L2 = 0, L3 = 0, xc = 0, yc = 0;
        double Ls = 0; // a shift's flexibility along x and y (Mindlin's compliance)
    };
    void set_patches(const ContactInput& in);
    // One pass with creepages (or shift) c: p_, state_, slip_, and with
    // derivative the derivatives of p_ along c[0] and c[1] (dp_[0], dp_[1]).
    void pass(const double c[3], double dq, bool steady, bool derivative);
    const TransientStepResult& solve(const TransientStepInput& s, bool steady);
    void totals(const double c[3]);

    double mu_ = 0.0, tolerance_ = 0.0, spin_offset_ = 0.0, load_ = 0.0;
    std::vector<double> gap_, pz_;
    GapNormal normal_;
    std::vector<int> patch_of_; // [i + nx j], -1 outside the contact
    std::vector<Patch> patches_;
    std::vector<Complex> p0_, p_, slip_, dp_[2];
    std::vector<signed char> state_;
};

} // namespace creepwork
