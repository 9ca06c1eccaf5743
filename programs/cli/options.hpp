// Command-line options of one subcommand: "--name value", "--name=value" or
// a bare "--flag". Parsing is strict -- unknown options, missing values,
// repeats, trailing garbage in numbers, NaN and Inf are all errors naming the
// option -- so a typo can never silently fall back to a default. An unknown
// option gets the nearest known one suggested. Option names are exact
// (--N is the load, --nx the grid); values of choice options are not case
// sensitive anywhere (--units SI, --grid Uniform), and are stored in the
// spelling of the spec.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace cwcli {

enum class OptionKind { number, integer, choice, flag, text };

struct OptionSpec {
    std::string name; // without the leading "--"
    OptionKind kind;
    std::vector<std::string> choices; // OptionKind::choice only
    std::vector<std::string> aliases = {}; // other names of the option (--phi for --spin)
};

class ParsedOptions {
public:
    bool has(const std::string& name) const { return values_.count(name) != 0; }
    double number(const std::string& name, double fallback) const;
    int integer(const std::string& name, int fallback) const;
    std::string text(const std::string& name, const std::string& fallback) const;
    // The option's name as the user typed it (an alias, or name itself).
    std::string typed(const std::string& name) const;

    // Filled by parse_options; values are already checked against their kind.
    std::map<std::string, std::string> values_;
    std::map<std::string, std::string> typed_; // spec name -> the name typed
};

// Parses argv[first..argc). Throws CliError(kExitUsage) naming the option.
ParsedOptions parse_options(const std::vector<OptionSpec>& specs, int argc, char** argv, int first);

// The choice typed names, in the choice's spelling, or "": not case
// sensitive, "-" for "_", and the library's other spellings of an
// enumeration value (cw_input_name: fast for fastsim, strips for
// kalker_strips).
std::string match_choice(const std::string& typed, const std::vector<std::string>& choices);

// The candidate nearest to word (edit distance, ignoring case and '_' vs
// '-'), or "" when none is within a third of word's length (at least 1).
std::string nearest(const std::string& word, const std::vector<std::string>& candidates);

// Strict conversions, exposed for tests of the parser's rules.
bool parse_finite_double(const std::string& text, double& value);
bool parse_int(const std::string& text, int& value);

// A number echoed back to the user: the shortest text that reads back as v
// (std::to_chars), so 0.6 prints as 0.6 and 1e30 as 1e+30.
std::string round_trip_text(double v);

} // namespace cwcli
