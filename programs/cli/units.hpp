// Unit systems of the CLI's inputs and outputs. The library itself works in
// whatever consistent units it is given; the CLI always calls it in SI and
// converts at the edges.
//
//   quantity         SI            paper (the units the paper prints)
//   length           m             ft
//   force            N             lbf
//   moment           N m           lbf ft
//   spin             1/m           1/ft
//   stress (G, p)    Pa            psi (lbf/in^2, the customary US modulus unit)
//   flexibility L    m/Pa          ft/psi (displacement per traction, u = L p)
//   work             J/m           lbf ft/ft (per unit rolling distance)
//   work per area    J/m per m^2   lbf ft/ft per ft^2
//   profile w(y)     J/m per m     lbf ft/ft per ft
// 1 lbf = 4.4482216152605 N and 1 ft = 0.3048 m exactly (international
// definitions); 1 psi = 4.4482216152605 N / (0.0254 m)^2.
#pragma once

#include <string>

namespace cwcli {

enum class Quantity {
    length,
    area,
    force,
    moment,
    spin,
    stress,
    flexibility,
    work,
    work_per_area,
    moment_per_area,
    profile,
    dimensionless
};

constexpr double kNewtonPerLbf = 4.4482216152605;
constexpr double kMetrePerFoot = 0.3048;
constexpr double kPascalPerPsi = kNewtonPerLbf / (0.0254 * 0.0254);

class Units {
public:
    static Units si();
    static Units paper();
    // "si" or "paper"; throws CliError naming --units otherwise.
    static Units named(const std::string& name);

    const std::string& name() const { return name_; }
    bool is_si() const { return name_ == "SI"; }

    // SI value of one unit of this system.
    double si_per_unit(Quantity q) const;
    double to_si(Quantity q, double v) const { return v * si_per_unit(q); }
    double from_si(Quantity q, double v) const { return v / si_per_unit(q); }
    std::string label(Quantity q) const;

    // Pictures use the engineer's magnitudes, one set per system: SI as mm,
    // N/mm^2, kN (moment N m, work J/m, per mm^2 or per mm, so a density's
    // unit is its total's per area); paper as in,
    // psi, lbf (moment lbf ft, work lbf ft/ft, per in^2 or per in).
    // Value shown = SI value * factor.
    double plot_factor(Quantity q) const;
    std::string plot_label(Quantity q) const;

    // The unit as a CSV column suffix: "m", "m2", "Pa", "N_m", "J_per_m".
    std::string csv_suffix(Quantity q) const;

private:
    std::string name_;
    double metre_ = 1, newton_ = 1, pascal_ = 1; // SI value of the length, force, stress unit
};

} // namespace cwcli
