// The separate contact patches of a solve (cw_patch, cw_solver_get_patches).
#include "capi_internal.hpp"

extern "C" {

int cw_patch_init(cw_patch* patch)
{
    if (!patch) return CW_ERR_NULL_POINTER;
    std::memset(patch, 0, sizeof *patch);
    patch->struct_size = sizeof *patch;
    return CW_OK;
}

int cw_solver_get_patches(const cw_solver* solver, cw_patch* out, size_t len, size_t* count)
{
    if (!solver) return CW_ERR_NULL_POINTER;
    auto* self = const_cast<cw_solver*>(solver);
    return guarded(&self->last_error, [&] {
        require(count, "count");
        const cw::Solver& s = solver->solver;
        require_solution(s, false);
        const std::vector<cw::PatchTotals>& patches = s.patches();
        *count = patches.size();
        if (len == 0) return CW_OK; // a count query; out may be NULL
        require(out, "out");
        const size_t size = out[0].struct_size;
        if (size < sizeof(size_t) || size > kMaxStructSize)
            fail(CW_ERR_STRUCT_SIZE, "out[0].struct_size = " + std::to_string(size) +
                                         " is invalid (call cw_patch_init first)");
        require_length(len, patches.size(), "out");
        auto* bytes = reinterpret_cast<unsigned char*>(out);
        for (size_t k = 0; k < patches.size(); ++k) {
            auto* slot = reinterpret_cast<cw_patch*>(bytes + k * size);
            if (slot->struct_size != size)
                fail(CW_ERR_STRUCT_SIZE, "out[" + std::to_string(k) + "].struct_size = " +
                                             std::to_string(slot->struct_size) +
                                             " differs from out[0].struct_size = " +
                                             std::to_string(size));
        }
        for (size_t k = 0; k < patches.size(); ++k) {
            const cw::PatchTotals& p = patches[k];
            cw_patch c;
            std::memset(&c, 0, sizeof c);
            c.struct_size = sizeof c;
            c.n_contact = p.n_contact;
            c.n_adhesion = p.n_adhesion;
            c.n_slip = p.n_slip;
            c.x_centroid = p.x_centroid;
            c.y_centroid = p.y_centroid;
            c.Fx = p.Fx;
            c.Fy = p.Fy;
            c.Mz = p.Mz;
            c.Fn = p.Fn;
            c.p_max = p.p_max;
            c.W_macro = p.W_macro;
            write_struct(reinterpret_cast<cw_patch*>(bytes + k * size), c);
        }
        return CW_OK;
    });
}

} // extern "C"
