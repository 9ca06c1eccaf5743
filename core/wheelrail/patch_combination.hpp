// Which interpenetration regions are solved together (CONTACT's module 1,
// user guide "Identification of contact patches"; m_wr_locatecp). The
// distance between two regions is that between their bounding boxes in
// track coordinates (x, and the rail's (y, z) at the lateral ends). Regions
// whose weighted contact angles differ by more than a_sep stay separate;
// else regions closer than d_comb are merged, up to d_sep merged as
// sub-patches of one patch (their mutual influence reduced by the factor
// ((d_sep - d) / (d_sep - d_comb))^0.8), and separate regions up to d_turn
// apart have their contact angles turned towards their weighted mean.
#pragma once

#include <vector>

#include "wheelrail/contact_search.hpp"
#include "wheelrail/wheelrail_types.hpp"

namespace creepwork::wheelrail {

// Sorts, merges and turns; on return `regions` holds the true contact
// patches (gap_min < 0) ordered from the field side to the track centre.
void combine_regions(std::vector<Region>& regions, const SearchOptions& opt);

} // namespace creepwork::wheelrail
