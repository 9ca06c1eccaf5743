#include "gap_values.hpp"

#include "../cli_error.hpp"
#include "../gap_input.hpp"
#include "gap_rows.hpp"

namespace cwcampaign {

std::shared_ptr<const std::vector<double>> GapValues::values(const ContactCase& c,
                                                             std::string& message)
{
    auto it = files_.begin();
    while (it != files_.end() && !(it->path == c.gap_file && it->hash == c.gap_hash)) ++it;
    if (it != files_.end()) {
        files_.splice(files_.begin(), files_, it);
    } else {
        if (files_.size() >= max_files_) files_.pop_back();
        Entry e;
        e.path = c.gap_file;
        e.hash = c.gap_hash;
        try {
            cwcli::GapFile g = cwcli::read_gap_file(c.gap_file);
            if (gap_hash(g.grid, g.h) == c.gap_hash)
                e.h = std::make_shared<const std::vector<double>>(std::move(g.h));
            else
                e.error = "gap_file " + c.gap_file +
                          " changed while the campaign ran (its grid or values differ from "
                          "what the input's check read): rerun the campaign";
        } catch (const cwcli::CliError& err) {
            e.error = "gap_file: " + gap_file_message(err.what());
        }
        files_.push_front(std::move(e));
    }
    message = files_.front().error;
    return files_.front().h;
}

} // namespace cwcampaign
