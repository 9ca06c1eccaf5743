// Steady surface temperatures of both bodies of a rolling contact from its
// frictional power density: a pure function of the grid geometry, the heat
// input per element and the bodies' thermal properties (no model, no solver).
// Body 1 is the rail, body 2 the wheel, as CONTACT's TEMP1 and TEMP2.
//
// The model (Ertz & Knothe, Wear 253 (2002) 498-508; CONTACT's m_temperature,
// doc/theory/temperature.md), per grid row along the rolling direction, each
// body a half-space passing under the contact at speed V:
//  - bulk part: both surfaces take the contact temperature
//        T_c = (beta1 T0_1 + beta2 T0_2) / (beta1 + beta2),  beta = sqrt(lambda rho c),
//    on the contact elements of the row; downstream of its last one, each
//    relaxes back towards its own T0 as a surface held at T_c for the
//    contact time and insulated since:
//        T = T0 + (T_c - T0) (2/pi) asin(sqrt(2a / (a + x'))),
//    a the half length of the row's contact span, x' the distance from the
//    span's centre. Ahead of the span, and on exterior elements inside it,
//    T = T0 (a row with several contact segments is one span, as CONTACT).
//  - flash part: the heat q is split so that both surfaces share one
//    temperature in contact, body b taking beta_b/(beta1 + beta2) of it:
//        T_flash = 1/((beta1 + beta2) sqrt(pi V)) integral q/sqrt(x - xi) dxi,
//    the same for both bodies, on every element at or downstream of the heat
//    (thermal/moving_source.hpp: exact for q constant per element).
//
// Discretisation::contact reproduces CONTACT's calc_temp_steady instead:
// its self-element term takes the whole element (2 sqrt(dx/2) instead of
// sqrt(dx/2): O(sqrt dx) too hot), only slip elements heat, body 1's flash
// part is scaled by beta2/beta1 and its T_c swaps beta1 and beta2 (equal
// bodies: no difference), and with rolling_direction = +1 the relaxation
// starts one element further (x' + dx).
#pragma once

#include <vector>

#include "thermal/moving_source.hpp"

namespace creepwork::thermal {

// One body's thermal properties.
struct Body {
    double T0 = 0.0;               // bulk temperature [deg C]
    double heat_capacity = 450.0;  // c [J/(kg K)] (steel)
    double conductivity = 50.0;    // lambda [W/(m K)] (steel)
    double density = 7850.0;       // rho [kg/m^3] (steel)
};

// beta = sqrt(lambda rho c) [W s^1/2 / (m^2 K)], the body's thermal effusivity.
double effusivity(const Body& body);

enum class Discretisation {
    consistent = 0, // exact moving-source integral of the element-wise heat; shared T in contact
    contact = 1,    // CONTACT's calc_temp_steady, for comparison with it
};

struct ThermalParams {
    Body rail;                 // body 1
    Body wheel;                // body 2
    double rolling_speed = 0;  // V [m/s] > 0
    Discretisation discretisation = Discretisation::consistent;
};

// Throws Error(invalid_input) naming the first offending parameter
// (T0_1, heat_capacity_2, ..., rolling_speed, discretisation).
void validate(const ThermalParams& p);

// The heated contact, per element [i + j*nx] (i along x, increasing x).
struct HeatedContact {
    int nx = 0, ny = 0;
    const double* x = nullptr;      // element centre [m]
    const double* y = nullptr;      // element centre [m]
    const double* row_dx = nullptr; // per row j: element length along x [m], > 0
    const int* state = nullptr;     // 0 exterior, 1 adhesion, 2 slip
    const double* q = nullptr;      // frictional power density [W/m^2], >= 0
    int rolling_direction = 1;      // +1: leading edge at +x (material moves to -x); -1 mirrors
};

// The bulk part T_c both surfaces take in contact, as the discretisation
// takes it (the rail's temperature in contact without heat).
double bulk_contact_temperature(const ThermalParams& p);

// The hottest contact element of one body (the maximum over the contact, as
// CONTACT prints it: away from the contact a body is at most its T0).
// Without contact: T = T0, element = -1, x = y = 0.
struct TemperatureMaximum {
    double T = 0.0;
    double x = 0.0, y = 0.0; // its centre [m]
    long element = -1;       // [i + j*nx]; the first in storage order on a tie
};

struct TemperatureTotals {
    TemperatureMaximum rail, wheel;
    double contact_temperature = 0.0; // T_c of the bulk part [deg C]
};

// Holds the kernel and the row buffers for one grid size; compute()
// allocates nothing, so a fixed-point loop (temperature-dependent friction)
// can call it every iteration.
class FlashTemperature {
public:
    // method: how the moving-source sum is taken along a row (automatic: by
    // the row length, thermal/moving_source.hpp).
    FlashTemperature(int nx, int ny,
                     MovingSourceKernel::Method method = MovingSourceKernel::Method::automatic);
    int nx() const { return nx_; }
    int ny() const { return ny_; }

    // T1 (rail) and T2 (wheel) [deg C] per element, nx*ny each. Throws
    // Error(invalid_input) naming a bad parameter or input value.
    TemperatureTotals compute(const HeatedContact& in, const ThermalParams& p, double* T1,
                              double* T2);

private:
    int nx_, ny_;
    MovingSourceKernel kernel_;
    std::vector<double> q_[2], flash_[2]; // two rows in time order
};

} // namespace creepwork::thermal
