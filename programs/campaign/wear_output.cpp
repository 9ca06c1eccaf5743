#include "wear_output.hpp"

#include <stdexcept>

#include "atomic_file.hpp"
#include "journal.hpp"
#include "number_text.hpp"

namespace cwcampaign {

WearProfiles::WearProfiles(const WearSetup& setup) : setup_(setup)
{
    char message[512] = "";
    for (cw_wear_profile*& p : profile_)
        if (cw_wear_profile_create(setup.nodes.data(), setup.nodes.size(), &p, message,
                                   sizeof message) != CW_OK) {
            for (cw_wear_profile* q : profile_) cw_wear_profile_destroy(q);
            throw std::runtime_error(std::string("the wear profile grid: ") + message);
        }
}

WearProfiles::~WearProfiles()
{
    for (cw_wear_profile* p : profile_) cw_wear_profile_destroy(p);
}

void WearProfiles::add_chunk(const ChunkResult& chunk)
{
    for (int body = 0; body < kWearBodies; ++body) {
        const std::vector<uint64_t>& state = chunk.wear_states[body];
        if (state.empty()) continue;
        if (cw_wear_profile_add_state(profile_[body], state.data(), state.size()) != CW_OK)
            throw JournalError("the checkpoint's wear profile of rows from " +
                               std::to_string(chunk.first_row) + ": " +
                               cw_wear_profile_last_error(profile_[body]));
    }
}

cw_wear_profile_totals WearProfiles::totals(int body) const
{
    cw_wear_profile_totals t;
    cw_wear_profile_totals_init(&t);
    cw_wear_profile_get_totals(profile_[body], &t);
    return t;
}

std::vector<std::string> WearProfiles::write(const std::string& dir) const
{
    std::vector<std::string> names;
    const size_t n = setup_.nodes.size();
    std::vector<double> normal(n), height(n);
    for (int body = 0; body < kWearBodies; ++body) {
        if (totals(body).adds == 0) continue;
        cw_wear_profile_get_depth(profile_[body], CW_WEAR_DEPTH_NORMAL, normal.data(), n);
        cw_wear_profile_get_depth(profile_[body], CW_WEAR_DEPTH_HEIGHT, height.data(), n);
        const std::string name = std::string("wear_profile_") + body_name(body) + ".csv";
        AtomicFile out(dir + "/" + name);
        // The columns of `creepwork wear`'s wear_profile.csv (without its
        // parabola comparison).
        std::string text = "k,s_m,depth_normal_m,depth_height_m\n";
        for (size_t k = 0; k < n; ++k) {
            text += std::to_string(k) + ",";
            append_number(text, setup_.nodes[k]);
            text += ',';
            append_number(text, normal[k]);
            text += ',';
            append_number(text, height[k]);
            text += '\n';
            if (text.size() > (1u << 16)) {
                out.write(text);
                text.clear();
            }
        }
        out.write(text);
        out.commit();
        names.push_back(name);
    }
    return names;
}

} // namespace cwcampaign
