// creepwork campaign: hands the command line to creepwork-campaign, the MPI
// program installed beside this one (built only where MPI was found). It
// execs rather than spawns: under `mpirun -np R creepwork campaign ...` each
// rank becomes creepwork-campaign with the same environment, so MPI starts
// as if mpirun had started that program, and this program never links MPI.
#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

#include "cli_error.hpp"
#include "commands.hpp"

namespace cwcli {

namespace {

// <directory of this executable>/creepwork-campaign, or "" if not there.
std::string campaign_program()
{
    std::string self(4096, '\0');
    const ssize_t n = readlink("/proc/self/exe", self.data(), self.size() - 1);
    if (n <= 0) return "";
    self.resize(static_cast<size_t>(n));
    const std::string::size_type slash = self.rfind('/');
    const std::string path =
        (slash == std::string::npos ? std::string(".") : self.substr(0, slash)) +
        "/creepwork-campaign";
    return access(path.c_str(), X_OK) == 0 ? path : "";
}

} // namespace

int command_campaign(int argc, char** argv, int first)
{
    const std::string program = campaign_program();
    if (program.empty())
        throw CliError(kExitFailure,
                       "campaign: this creepwork was built without MPI, so creepwork-campaign "
                       "is not beside it; install Open MPI (Debian: libopenmpi-dev openmpi-bin) "
                       "and rebuild (doc/campaigns.md)");
    std::vector<char*> args;
    args.push_back(const_cast<char*>(program.c_str()));
    for (int k = first; k < argc; ++k) args.push_back(argv[k]);
    args.push_back(nullptr);
    execv(program.c_str(), args.data());
    throw CliError(kExitFailure, "campaign: cannot run " + program + ": " + std::strerror(errno));
}

} // namespace cwcli
