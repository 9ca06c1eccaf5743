// cw_wheelrail_check: the wheel/rail case's implausible inputs and
// placements (core/wheelrail/placement_checks.hpp), as cw_check entries.
#include "capi_check.hpp"
#include "capi_wheelrail_internal.hpp"

extern "C" {

int cw_wheelrail_check(const cw_wheelrail* wheelrail, cw_check* out, size_t len, size_t* found)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    return guarded(&wheelrail->last_error, [&] {
        const std::vector<cw::Implausible> w =
            wr::check_wheelrail(wheelrail->contact.geometry(), wheelrail->inputs);
        std::vector<cw_check> checks(w.size());
        for (size_t k = 0; k < w.size(); ++k) fill_check(w[k], 1, 0, "", checks[k]);
        write_checks(checks, out, len, found);
        return CW_OK;
    });
}

} // extern "C"
