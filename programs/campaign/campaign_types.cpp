#include "campaign_types.hpp"

namespace cwcampaign {

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
