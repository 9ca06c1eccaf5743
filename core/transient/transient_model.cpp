#include "transient/transient_model.hpp"

#include "contact/error.hpp"

namespace creepwork {

TransientModel::TransientModel(const GridSpec& grid, const ContactInput& in)
{
    if (in.model == ModelKind::exact)
        exact_ = std::make_unique<TransientContact>(grid, in);
    else if (in.model == ModelKind::fastsim)
        fastsim_ = std::make_unique<TransientFastsim>(grid, in);
    else
        throw Error(ErrorKind::invalid_input,
                    "model is invalid for transient rolling: the exact model (CW_MODEL_EXACT) "
                    "or FASTSIM (CW_MODEL_FASTSIM)");
}

} // namespace creepwork
