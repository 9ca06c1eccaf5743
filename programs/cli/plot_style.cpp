#include "plot_style.hpp"

namespace cwcli {

std::vector<OptionSpec> plot_options()
{
    using K = OptionKind;
    return {{"plot-sign", K::choice, {"wheel", "rail"}},
            {"plot-axes", K::choice, {"normalised", "physical"}}};
}

PlotStyle read_plot_style(const ParsedOptions& opts, ForceSign run_sign)
{
    PlotStyle s;
    s.sign = run_sign;
    if (opts.has("plot-sign"))
        s.sign = opts.text("plot-sign", "") == "rail" ? ForceSign::rail : ForceSign::wheel;
    s.physical = opts.text("plot-axes", "normalised") == "physical";
    return s;
}

const char* body_name(ForceSign sign)
{
    return sign == ForceSign::rail ? "rail" : "wheel";
}

} // namespace cwcli
