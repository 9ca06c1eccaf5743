// The one place of the wheel/rail module that touches the file system: it
// opens a profile file and hands the stream to the parser.
#include <fstream>

#include "contact/error.hpp"
#include "wheelrail/profile_io.hpp"

namespace creepwork::wheelrail {

Profile read_profile_file(const std::string& path, ProfileKind kind, const ProfileReadOptions& options)
{
    std::ifstream in(path);
    if (!in) throw Error(ErrorKind::invalid_input, path + ": cannot open the profile file");
    return read_profile(in, kind, profile_format_of(path), path, options);
}

} // namespace creepwork::wheelrail
