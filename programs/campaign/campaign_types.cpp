#include "campaign_types.hpp"

#include <cstring>
#include <tuple>

namespace cwcampaign {

namespace {

// The bits of what shapes a grid beyond kind, nx, ny: the box scale of a
// uniform grid, the origin and spacing of a gap grid. Comparing bits, a
// grid is reused exactly when the library would build the same one.
std::array<uint64_t, 4> shape_bits(const cw_grid& g)
{
    std::array<uint64_t, 4> bits{};
    if (g.kind == CW_GRID_UNIFORM) std::memcpy(&bits[0], &g.box_scale, sizeof(double));
    if (g.kind == CW_GRID_GAP) {
        std::memcpy(&bits[0], &g.x0, sizeof(double));
        std::memcpy(&bits[1], &g.y0, sizeof(double));
        std::memcpy(&bits[2], &g.dx, sizeof(double));
        std::memcpy(&bits[3], &g.dy, sizeof(double));
    }
    return bits;
}

} // namespace

bool same_grid_shape(const cw_grid& a, const cw_grid& b)
{
    return a.kind == b.kind && a.nx == b.nx && a.ny == b.ny && shape_bits(a) == shape_bits(b);
}

bool grid_shape_less(const cw_grid& a, const cw_grid& b)
{
    const std::array<uint64_t, 4> sa = shape_bits(a), sb = shape_bits(b);
    return std::tie(a.kind, a.nx, a.ny, sa) < std::tie(b.kind, b.nx, b.ny, sb);
}

const char* status_name(int status)
{
    if (status == CW_OK) return "ok";
    if (status == kStatusRowUnreadable) return "ROW_UNREADABLE";
    if (status == kStatusRowImplausible) return "ROW_IMPLAUSIBLE";
    // The names of the header's own list, so a new code needs no edit here.
#define CW_CAMPAIGN_STATUS_NAME_(name, value, message) \
    if (status == value) return #name;
    CW_STATUS_LIST(CW_CAMPAIGN_STATUS_NAME_)
#undef CW_CAMPAIGN_STATUS_NAME_
    return "UNKNOWN_STATUS";
}

const char* body_name(int body) { return body == kWheel ? "wheel" : "rail"; }

} // namespace cwcampaign
