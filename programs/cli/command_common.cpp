#include "command_common.hpp"

#include <cstdio>

#include "gnuplot.hpp"
#include "plot_style.hpp"

namespace cwcli {

std::vector<OptionSpec> output_options()
{
    using K = OptionKind;
    return join({{"format", K::choice, {"text", "json"}},
                 {"out", K::text, {}},
                 {"force", K::flag, {}},
                 {"no-plots", K::flag, {}},
                 {"help", K::flag, {}}},
                plot_options());
}

std::vector<OptionSpec> output_options_with_markdown()
{
    std::vector<OptionSpec> specs = output_options();
    for (OptionSpec& s : specs)
        if (s.name == "format") s.choices.push_back("markdown");
    return specs;
}

std::vector<OptionSpec> join(std::vector<OptionSpec> a, const std::vector<OptionSpec>& b)
{
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

bool should_plot(const ParsedOptions& opts, long elements)
{
    if (opts.has("no-plots")) return false;
    if (elements > kMaxPictureElements) {
        std::fprintf(stderr,
                     "creepwork: note: %ld elements are too many to draw (limit %ld); "
                     "writing data files without pictures\n",
                     elements, kMaxPictureElements);
        return false;
    }
    if (gnuplot_available()) return true;
    std::fputs("creepwork: note: gnuplot not found on PATH; writing data files without pictures\n",
               stderr);
    return false;
}

bool parse_or_help(const std::vector<OptionSpec>& specs, int argc, char** argv, int first,
                   const char* usage, ParsedOptions& opts)
{
    // --help wins over any other problem on the line.
    for (int k = first; k < argc; ++k)
        if (std::string(argv[k]) == "--help" || std::string(argv[k]) == "-h") {
            std::fputs(usage, stdout);
            return true;
        }
    opts = parse_options(specs, argc, argv, first);
    return false;
}

} // namespace cwcli
