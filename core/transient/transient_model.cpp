#include "transient/transient_model.hpp"

#include "contact/error.hpp"
#include "transient/ellipse_gap.hpp"

namespace creepwork {

TransientModel::TransientModel(const GridSpec& grid, const ContactInput& in)
{
    if (in.model == ModelKind::exact)
        exact_ = std::make_unique<TransientContact>(grid, in);
    else if (in.model == ModelKind::fastsim && grid.kind == GridKind::uniform) {
        // The ellipse's Hertzian gap on the uniform grid's elements, as the
        // exact model's (TransientFastsim copies the gap).
        const EllipseGap e = ellipse_gap(grid, in);
        ContactInput own = in;
        own.gap = e.h.data();
        own.gap_len = e.h.size();
        own.normal_load = NormalLoad::force;
        fastsim_ = std::make_unique<TransientFastsim>(e.grid, own);
    } else if (in.model == ModelKind::fastsim)
        fastsim_ = std::make_unique<TransientFastsim>(grid, in);
    else
        throw Error(ErrorKind::invalid_input,
                    "model is invalid for transient rolling: the exact model (CW_MODEL_EXACT) "
                    "or FASTSIM (CW_MODEL_FASTSIM)");
}

void TransientModel::set_frame(TransientFrame frame)
{
    if (exact_) return exact_->set_frame(frame);
    if (frame == TransientFrame::world)
        throw Error(ErrorKind::invalid_input,
                    "coordinates = CW_COORDINATES_WORLD is invalid for FASTSIM's transient "
                    "form (model = CW_MODEL_FASTSIM): it runs contact-fixed "
                    "(CW_COORDINATES_CONTACT); world-fixed coordinates are the exact model's");
    fastsim_->start_zero();
}

void TransientModel::jacobian(double J[9])
{
    if (exact_) return exact_->jacobian(J);
    throw Error(ErrorKind::invalid_input,
                "the step Jacobian is the exact model's (CW_MODEL_EXACT): FASTSIM's transient "
                "form (model = CW_MODEL_FASTSIM) has none");
}

} // namespace creepwork
