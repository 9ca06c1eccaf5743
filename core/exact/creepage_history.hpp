// The warm start's prediction of the exact models (exact_model.hpp,
// gap/gap_exact_model.hpp). The solution of one normalised tangential problem is a
// function of its normalised creepages c = (c_xi, c_eta, c_phi) alone. From
// the last solutions q_0 (latest), q_1, q_2 and their c_i, the start for c
// is
//   q_0 + sum_i g_i (q_i - q_0),  g = argmin |c - c_0 - sum_i g_i (c_i - c_0)|,
// a secant step that follows the creepage's drift (a vehicle loop's
// consecutive calls): its error is second order in the change of c instead
// of first (measured: one Newton step fewer). Steps g_i are bounded. The
// history holds for one problem only, named by a key (e.g. a/b, nu and the
// spin offset): a different key drops it.
//
// The secant step's error is smooth along a drift while no element changes
// between slip and adhesion, so it is predicted too: with the element states
// given to remember(), once the newest four solutions have the same states,
// the start is the secant step plus the last secant step's error (the
// solution minus what was predicted for it); once the newest five have them,
// plus the error extrapolated linearly from the last two, 2 e_1 - e_2
// (fewer FFT products a warm step, doc/dev/decisions.md). It is left out as
// soon as an element changes state: across a change the error jumps.
#pragma once

#include <complex>
#include <cstddef>
#include <vector>

namespace creepwork {

class CreepageHistory {
public:
    using Complex = std::complex<double>;
    static constexpr int kKey = 4;

    // Makes every vector n elements long (and drops the history).
    void resize(std::size_t n);
    void clear()
    {
        count_ = 0;
        same_states_ = 0;
        predicted_valid_ = error_valid_ = error_before_valid_ = false;
    }
    // With a history of this key: the prediction for creepages c into q,
    // times scale (returns true; with one solution it is that solution).
    // Otherwise the history is dropped and q left as it is.
    bool predict(const double key[kKey], const double c[3], std::vector<Complex>& q,
                 double scale = 1.0);
    // Adds the solution q of creepages c, kept as scale * q (a new key
    // starts a new history). state (q.size() values, 0 exterior, 1
    // adhesion, 2 slip; or null) enables the error's correction.
    void remember(const double key[kKey], const double c[3], const std::vector<Complex>& q,
                  double scale = 1.0, const signed char* state = nullptr);

private:
    bool same(const double key[kKey]) const;

    std::vector<Complex> q_[3];
    // The last secant step (without correction), its error and the one
    // before, the states of the newest solution, and how many of the newest
    // solutions share them.
    std::vector<Complex> predicted_, error_, error_before_;
    std::vector<signed char> state_;
    bool predicted_valid_ = false, error_valid_ = false, error_before_valid_ = false;
    int same_states_ = 0;
    double c_[3][3] = {};
    double key_[kKey] = {};
    int count_ = 0;
};

} // namespace creepwork
