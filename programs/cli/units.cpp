#include "units.hpp"

#include "cli_error.hpp"

namespace cwcli {

Units Units::si()
{
    Units u;
    u.name_ = "SI";
    return u;
}

Units Units::paper()
{
    Units u;
    u.name_ = "paper";
    u.metre_ = kMetrePerFoot;
    u.newton_ = kNewtonPerLbf;
    u.pascal_ = kPascalPerPsi;
    return u;
}

Units Units::named(const std::string& name)
{
    if (name == "si" || name == "SI") return si();
    if (name == "paper") return paper();
    throw usage_error("--units", "expected si|paper, got '" + name + "'");
}

double Units::si_per_unit(Quantity q) const
{
    switch (q) {
    case Quantity::length: return metre_;
    case Quantity::area: return metre_ * metre_;
    case Quantity::force: return newton_;
    case Quantity::moment: return newton_ * metre_;
    case Quantity::spin: return 1.0 / metre_;
    case Quantity::stress: return pascal_;
    case Quantity::flexibility: return metre_ / pascal_;
    case Quantity::work: return newton_; // force * length / length rolled
    case Quantity::work_per_area: return newton_ / (metre_ * metre_);
    case Quantity::moment_per_area: return newton_ / metre_;
    case Quantity::profile: return newton_ / metre_;
    case Quantity::dimensionless: return 1.0;
    }
    return 1.0;
}

std::string Units::label(Quantity q) const
{
    const bool si = is_si();
    switch (q) {
    case Quantity::length: return si ? "m" : "ft";
    case Quantity::area: return si ? "m^2" : "ft^2";
    case Quantity::force: return si ? "N" : "lbf";
    case Quantity::moment: return si ? "N m" : "lbf ft";
    case Quantity::spin: return si ? "1/m" : "1/ft";
    case Quantity::stress: return si ? "Pa" : "psi";
    case Quantity::flexibility: return si ? "m/Pa" : "ft/psi";
    case Quantity::work: return si ? "J/m" : "lbf ft/ft";
    case Quantity::work_per_area: return si ? "J/m per m^2" : "lbf ft/ft per ft^2";
    case Quantity::moment_per_area: return si ? "N m per m^2" : "lbf ft per ft^2";
    case Quantity::profile: return si ? "J/m per m" : "lbf ft/ft per ft";
    case Quantity::dimensionless: return "-";
    }
    return "";
}

double Units::plot_factor(Quantity q) const
{
    const bool si = is_si();
    const double small_length = si ? 1e-3 : 0.0254; // mm or in, in metres
    switch (q) {
    case Quantity::length: return 1.0 / small_length;
    case Quantity::force: return si ? 1e-3 : 1.0 / newton_;
    case Quantity::stress: return si ? 1e-6 : 1.0 / pascal_;
    case Quantity::work_per_area: return small_length * small_length / newton_;
    case Quantity::moment_per_area: // the moment's unit (N m, lbf ft) per mm^2 or in^2
        return small_length * small_length / (newton_ * metre_);
    case Quantity::profile: return small_length / newton_;
    default: return 1.0 / si_per_unit(q);
    }
}

std::string Units::plot_label(Quantity q) const
{
    const bool si = is_si();
    switch (q) {
    case Quantity::length: return si ? "mm" : "in";
    case Quantity::force: return si ? "kN" : "lbf";
    case Quantity::stress: return si ? "N/mm^2" : "psi";
    case Quantity::work_per_area: return si ? "J/m per mm^2" : "lbf ft/ft per in^2";
    case Quantity::moment_per_area: return si ? "N m per mm^2" : "lbf ft per in^2";
    case Quantity::profile: return si ? "J/m per mm" : "lbf ft/ft per in";
    default: return label(q);
    }
}

std::string Units::csv_suffix(Quantity q) const
{
    std::string s = label(q);
    if (s == "-") return "";
    std::string out;
    for (size_t k = 0; k < s.size(); ++k) {
        if (s.compare(k, 5, " per ") == 0) {
            out += "_per_";
            k += 4;
        } else if (s[k] == ' ') {
            out += '_';
        } else if (s[k] == '/') {
            out += "_per_";
        } else if (s[k] != '^') {
            out += s[k];
        }
    }
    return out;
}

} // namespace cwcli
