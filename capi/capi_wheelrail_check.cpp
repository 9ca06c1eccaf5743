// cw_wheelrail_check: the wheel/rail case's implausible inputs and
// placements (core/wheelrail/placement_checks.hpp), as cw_check entries.
#include "capi_check.hpp"
#include "capi_wheelrail_internal.hpp"

extern "C" {

int cw_wheelrail_check(const cw_wheelrail* wheelrail, cw_check* out, size_t len, size_t* found)
{
    if (!wheelrail) return CW_ERR_NULL_POINTER;
    // The handle's last error stays the last solve's unless this call fails:
    // a caller checks after a failed solve and reports both.
    std::string message;
    const int status = guarded(&message, [&] {
        const std::vector<cw::Implausible> w =
            wr::check_wheelrail(wheelrail->contact.geometry(), wheelrail->inputs);
        std::vector<cw_check> checks(w.size());
        for (size_t k = 0; k < w.size(); ++k) fill_check(w[k], 1, 0, "", checks[k]);
        write_checks(checks, out, len, found);
        return CW_OK;
    });
    if (status != CW_OK) wheelrail->last_error = message;
    return status;
}

} // extern "C"
