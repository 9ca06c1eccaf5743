// The subcommands. Each parses its own options (argv[first..]), writes its
// results and returns the exit status; errors are thrown as CliError.
#pragma once

namespace cwcli {

int command_solve(int argc, char** argv, int first);
int command_sweep(int argc, char** argv, int first);
int command_fit_fig6(int argc, char** argv, int first);
int command_wear(int argc, char** argv, int first);
int command_compare(int argc, char** argv, int first);
int command_wheelrail(int argc, char** argv, int first);
int command_transient(int argc, char** argv, int first);
// Execs creepwork-campaign (programs/campaign/, built only with MPI).
int command_campaign(int argc, char** argv, int first);

// Usage texts (usage.cpp).
const char* usage_main();
const char* usage_solve();
const char* usage_sweep();
const char* usage_fit_fig6();
const char* usage_wear();
const char* usage_compare();
const char* usage_wheelrail();
const char* usage_transient();

} // namespace cwcli
