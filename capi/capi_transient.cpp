// Transient rolling: the cw_transient handle over core/transient.
#include "capi_internal.hpp"

#include <cmath>

#include "capi_wear_law.hpp"
#include "contact/contact_input.hpp"
#include "transient/transient_model.hpp"
#include "wear/transient_wear.hpp"

struct cw_transient {
    explicit cw_transient(const cw::GridSpec& g, const cw::ContactInput& in)
        : grid(g), contact(g, in), wear(contact)
    {
    }
    cw::GridSpec grid;
    cw::TransientModel contact; // the exact model's or FASTSIM's
    cw::TransientWear wear;
    double last_dq = 0.0; // of the last step (a steady start: dx)
    bool has_fields = false; // a step or steady start succeeded since the last start
    mutable std::string last_error; // the last call's message, const getters' included
};

namespace {

cw_transient_input default_step()
{
    cw_transient_input s{};
    s.struct_size = sizeof s;
    s.prescribe = CW_PRESCRIBE_CREEPAGES;
    return s;
}

cw::TransientStepInput to_step(const cw_transient_input* step)
{
    require(step, "step");
    const cw_transient_input s = read_struct(step, default_step(), "step");
    if (s.prescribe != CW_PRESCRIBE_CREEPAGES && s.prescribe != CW_PRESCRIBE_FX &&
        s.prescribe != CW_PRESCRIBE_FORCES)
        fail(CW_ERR_UNKNOWN_OPTION, "step->prescribe = " + std::to_string(s.prescribe) +
                                        " is not a CW_PRESCRIBE_* value");
    cw::TransientStepInput in;
    in.dq = s.dq;
    in.xi_x = s.xi_x;
    in.xi_y = s.xi_y;
    in.phi = s.phi;
    in.prescribe_fx = s.prescribe != CW_PRESCRIBE_CREEPAGES;
    in.prescribe_fy = s.prescribe == CW_PRESCRIBE_FORCES;
    in.Fx = s.Fx;
    in.Fy = s.Fy;
    return in;
}

cw_transient_result to_result(const cw::TransientStepResult& r, long steps)
{
    cw_transient_result out{};
    out.struct_size = sizeof out;
    out.xi_x = r.xi_x;
    out.xi_y = r.xi_y;
    out.phi = r.phi;
    out.Fx = r.Fx;
    out.Fy = r.Fy;
    out.Mz = r.Mz;
    out.n_contact = r.n_contact;
    out.n_adhesion = r.n_adhesion;
    out.n_slip = r.n_slip;
    out.W_step = r.W_step;
    out.iterations = r.newton_steps;
    out.force_iterations = r.force_iterations;
    out.residual = r.residual;
    out.steps_committed = steps;
    out.W_slip = r.W_slip;
    return out;
}

// Every number of a result is finite, or the step is refused (no NaN
// leaves the library).
void require_finite_result(const cw_transient_result& r)
{
    const double v[] = {r.xi_x, r.xi_y, r.phi, r.Fx, r.Fy, r.Mz, r.W_step, r.W_slip, r.residual};
    for (double x : v)
        if (!std::isfinite(x)) fail(CW_ERR_NUMERIC, "the step's result is not finite: inputs too extreme");
}

void require_fields(const cw_transient* t)
{
    if (!t->has_fields)
        fail(CW_ERR_NO_SOLUTION, "no step or steady start since the handle was made, started "
                                 "or restored: there are no fields");
}

} // namespace

extern "C" {

int cw_transient_input_init(cw_transient_input* step)
{
    if (!step) return CW_ERR_NULL_POINTER;
    *step = default_step();
    return CW_OK;
}

int cw_transient_result_init(cw_transient_result* result)
{
    if (!result) return CW_ERR_NULL_POINTER;
    std::memset(result, 0, sizeof *result);
    result->struct_size = sizeof *result;
    return CW_OK;
}

int cw_transient_create(const cw_grid* grid, const cw_params* params, cw_transient** transient,
                        char* message, size_t message_len)
{
    return guarded_free(message, message_len, [&] {
        require(transient, "transient");
        *transient = nullptr;
        require(params, "params");
        const cw::GridSpec spec = to_grid(grid);
        if (spec.kind != cw::GridKind::gap && spec.kind != cw::GridKind::uniform)
            fail(CW_ERR_INVALID_INPUT, "grid->kind = " + std::to_string(grid->kind) +
                                           " is invalid for transient rolling: it runs on a "
                                           "gap grid (CW_GRID_GAP) or an ellipse's uniform "
                                           "grid (CW_GRID_UNIFORM)");
        const cw::ContactInput in = to_input(params);
        if (const char* layer = cw::layer_input_name(in))
            fail(CW_ERR_INVALID_INPUT, std::string("params->") + layer +
                                           ": transient rolling has no interface layer (the "
                                           "steady exact model has)");
        if (in.model != cw::ModelKind::exact && in.model != cw::ModelKind::fastsim)
            fail(CW_ERR_INVALID_INPUT, "params->model = " + std::to_string(params->model) +
                                           " is invalid for transient rolling: the exact model "
                                           "(CW_MODEL_EXACT) or FASTSIM (CW_MODEL_FASTSIM)");
        *transient = new cw_transient(spec, in);
        return CW_OK;
    });
}

int cw_transient_destroy(cw_transient* transient)
{
    delete transient;
    return CW_OK;
}

int cw_transient_start_zero(cw_transient* transient)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        transient->contact.start_zero();
        transient->has_fields = false;
        return CW_OK;
    });
}

int cw_transient_start_steady(cw_transient* transient, const cw_transient_input* step,
                              cw_transient_result* result)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        const cw::TransientStepInput in = to_step(step);
        require_result_size(result, "cw_transient_result_init");
        const std::vector<unsigned char> before = transient->contact.save();
        transient->has_fields = false;
        const cw_transient_result r = to_result(transient->contact.start_steady(in), 0);
        try {
            require_finite_result(r);
        } catch (...) {
            transient->contact.restore(before.data(), before.size());
            throw;
        }
        transient->has_fields = true;
        transient->last_dq = transient->contact.dx();
        if (result) write_struct(result, r);
        return CW_OK;
    });
}

int cw_transient_step(cw_transient* transient, const cw_transient_input* step,
                      cw_transient_result* result)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        const cw::TransientStepInput in = to_step(step);
        require_result_size(result, "cw_transient_result_init");
        transient->has_fields = false;
        const cw_transient_result r =
            to_result(transient->contact.step(in), transient->contact.steps_committed());
        try {
            require_finite_result(r);
        } catch (...) {
            transient->contact.rewind();
            throw;
        }
        transient->has_fields = true;
        transient->last_dq = in.dq;
        if (result) write_struct(result, r);
        return CW_OK;
    });
}

int cw_transient_commit(cw_transient* transient)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        if (!transient->contact.has_trial())
            fail(CW_ERR_NO_SOLUTION, "commit: there is no step to commit (cw_transient_step "
                                     "first; a trial is committed once, and rewind drops it)");
        transient->contact.commit();
        return CW_OK;
    });
}

int cw_transient_rewind(cw_transient* transient)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    transient->contact.rewind();
    transient->last_error.clear();
    return CW_OK;
}

int cw_transient_state_size(const cw_transient* transient, size_t* words)
{
    if (!transient || !words) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        *words = transient->contact.save().size() / sizeof(uint64_t);
        return CW_OK;
    });
}

int cw_transient_save(const cw_transient* transient, uint64_t* out, size_t len)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(out, "out");
        const std::vector<unsigned char> bytes = transient->contact.save();
        const size_t words = bytes.size() / sizeof(uint64_t); // save() gives whole words
        if (len < words)
            fail(CW_ERR_BUFFER_TOO_SMALL, "len = " + std::to_string(len) +
                                              " is below the state's " + std::to_string(words) +
                                              " words (cw_transient_state_size)");
        std::memcpy(out, bytes.data(), bytes.size());
        return CW_OK;
    });
}

int cw_transient_restore(cw_transient* transient, const uint64_t* state, size_t len)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(state, "state");
        transient->contact.restore(reinterpret_cast<const unsigned char*>(state),
                                   len * sizeof(uint64_t));
        transient->has_fields = false;
        return CW_OK;
    });
}

int cw_transient_get_field(const cw_transient* transient, int field, double* out, size_t len)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(out, "out");
        require_fields(transient);
        const cw::GridSpec& g = transient->grid;
        const size_t n = static_cast<size_t>(g.nx) * g.ny;
        const cw::TransientModel& c = transient->contact;
        switch (field) {
        case CW_FIELD_X:
        case CW_FIELD_Y:
        case CW_FIELD_PZ:
        case CW_FIELD_PX:
        case CW_FIELD_PY:
        case CW_FIELD_SX:
        case CW_FIELD_SY:
        case CW_FIELD_WORK_CONSISTENT: break;
        default:
            fail(CW_ERR_UNKNOWN_OPTION,
                 "field = " + std::to_string(field) +
                     " is not a field of transient rolling (CW_FIELD_X, _Y, _PZ, _PX, _PY, "
                     "_SX, _SY, _WORK_CONSISTENT)");
        }
        require_length(len, n, "out");
        if (field == CW_FIELD_X || field == CW_FIELD_Y) {
            for (int j = 0; j < g.ny; ++j)
                for (int i = 0; i < g.nx; ++i)
                    out[i + static_cast<size_t>(g.nx) * j] =
                        field == CW_FIELD_X ? g.x0 + i * g.dx : g.y0 + j * g.dy;
        } else if (field == CW_FIELD_PZ) {
            c.copy_pressure(out);
        } else if (field == CW_FIELD_WORK_CONSISTENT) {
            c.copy_work(out);
        } else if (field == CW_FIELD_PX || field == CW_FIELD_PY) {
            c.copy_traction(field == CW_FIELD_PX ? out : nullptr,
                            field == CW_FIELD_PY ? out : nullptr);
        } else {
            c.copy_slip(field == CW_FIELD_SX ? out : nullptr, field == CW_FIELD_SY ? out : nullptr);
        }
        return CW_OK;
    });
}

int cw_transient_get_state(const cw_transient* transient, int* out, size_t len)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(out, "out");
        require_fields(transient);
        require_length(len, static_cast<size_t>(transient->grid.nx) * transient->grid.ny, "out");
        transient->contact.copy_state(out);
        return CW_OK;
    });
}

int cw_transient_set_coordinates(cw_transient* transient, int coordinates)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        if (coordinates != CW_COORDINATES_CONTACT && coordinates != CW_COORDINATES_WORLD)
            fail(CW_ERR_UNKNOWN_OPTION, "coordinates = " + std::to_string(coordinates) +
                                            " is not CW_COORDINATES_CONTACT or "
                                            "CW_COORDINATES_WORLD");
        transient->contact.set_frame(coordinates == CW_COORDINATES_WORLD
                                         ? cw::TransientFrame::world
                                         : cw::TransientFrame::contact);
        transient->has_fields = false;
        return CW_OK;
    });
}

int cw_transient_jacobian(cw_transient* transient, double* jacobian, size_t len)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(jacobian, "jacobian");
        require_fields(transient);
        require_length(len, CW_TRANSIENT_JACOBIAN_LEN, "jacobian");
        double J[CW_TRANSIENT_JACOBIAN_LEN];
        transient->contact.jacobian(J);
        for (double v : J)
            if (!std::isfinite(v))
                fail(CW_ERR_NUMERIC, "the step's Jacobian is not finite: inputs too extreme");
        std::memcpy(jacobian, J, sizeof J);
        return CW_OK;
    });
}

int cw_transient_add_wear(cw_transient* transient, const cw_wear_params* params,
                          double* step_mass)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        require(params, "params");
        const creepwork::wear::WearLaw law = to_wear_law(params, -1.0);
        require_fields(transient);
        const double mass = transient->wear.add(transient->contact, transient->last_dq, law)
                                .mass_per_pass;
        if (step_mass) *step_mass = mass;
        return CW_OK;
    });
}

int cw_transient_get_wear(const cw_transient* transient, double* mass_map, size_t len,
                          double* mass)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    return guarded(&transient->last_error, [&] {
        const std::vector<double>& m = transient->wear.mass_map();
        if (mass_map) {
            require_length(len, m.size(), "mass_map");
            std::copy(m.begin(), m.end(), mass_map);
        }
        if (mass) *mass = transient->wear.mass();
        return CW_OK;
    });
}

int cw_transient_reset_wear(cw_transient* transient)
{
    if (!transient) return CW_ERR_NULL_POINTER;
    transient->wear.reset();
    transient->last_error.clear();
    return CW_OK;
}

const char* cw_transient_last_error(const cw_transient* transient)
{
    return transient ? transient->last_error.c_str() : "transient is NULL";
}

} // extern "C"
