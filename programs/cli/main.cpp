// creepwork: command-line front end of libcreepwork, built only on the public
// C ABI (creepwork.h). See usage.cpp for the commands and options.
#include <cstdio>
#include <cstring>
#include <exception>
#include <string>

#include <creepwork/creepwork.h>

#include "cli_error.hpp"
#include "commands.hpp"
#include "options.hpp"

namespace {

// Exactly one line on stderr, whatever the message contains.
void print_error(const std::string& message)
{
    std::string line = message;
    for (char& c : line)
        if (c == '\n' || c == '\r') c = ' ';
    std::fprintf(stderr, "creepwork: %s\n", line.c_str());
}

int dispatch(int argc, char** argv)
{
    using namespace cwcli;
    if (argc < 2) {
        std::fputs(usage_main(), stderr);
        return kExitUsage;
    }
    const std::string command = argv[1];
    if (command == "-h" || command == "--help" || command == "help") {
        std::fputs(usage_main(), stdout);
        return kExitOk;
    }
    if (command == "--version" || command == "version") {
        std::printf("creepwork %d.%d.%d (loaded library %s, ABI %d)\n", CW_VERSION_MAJOR,
                    CW_VERSION_MINOR, CW_VERSION_PATCH, cw_version_string(), cw_abi_version());
        return kExitOk;
    }
    if (cw_abi_version() != CW_ABI_VERSION)
        throw CliError(kExitFailure,
                       "the loaded libcreepwork has another ABI version than this program");
    if (command == "solve") return command_solve(argc, argv, 2);
    if (command == "sweep") return command_sweep(argc, argv, 2);
    if (command == "fit-fig6") return command_fit_fig6(argc, argv, 2);
    if (command == "wear") return command_wear(argc, argv, 2);
    if (command == "campaign") return command_campaign(argc, argv, 2);
    if (command == "compare") return command_compare(argc, argv, 2);
    if (command == "wheelrail") return command_wheelrail(argc, argv, 2);
    if (command == "transient") return command_transient(argc, argv, 2);
    const std::string hint = nearest(command, {"solve", "sweep", "fit-fig6", "wear", "campaign",
                                               "compare", "wheelrail", "transient", "help",
                                               "version"});
    throw CliError(kExitUsage, "'" + command +
                                   "': unknown command (solve, sweep, fit-fig6, wear, campaign, "
                                   "compare, wheelrail, transient" +
                                   (hint.empty() ? std::string("; see --help)")
                                                 : "); did you mean " + hint + "?"));
}

} // namespace

int main(int argc, char** argv)
{
    try {
        return dispatch(argc, argv);
    } catch (const cwcli::CliError& e) {
        print_error(e.what());
        return e.status();
    } catch (const std::exception& e) {
        print_error(std::string("internal error: ") + e.what());
        return cwcli::kExitFailure;
    }
}
