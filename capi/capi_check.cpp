// The policy every door shares, behind the C ABI: plausibility checks of a
// contact's inputs (cw_check, cw_params_check; the rules in
// core/contact/plausibility.hpp), the exact model's default grid and the
// canonical names of inputs and enumeration values.
#include <cctype>
#include <cmath>

#include "capi_check.hpp"
#include "contact/plausibility.hpp"

namespace {

static_assert(static_cast<int>(cw::CheckRule::default_geometry) == CW_CHECK_DEFAULT_GEOMETRY &&
                  static_cast<int>(cw::CheckRule::approach) == CW_CHECK_APPROACH &&
                  static_cast<int>(cw::CheckRule::layer_thickness) == CW_CHECK_LAYER_THICKNESS &&
                  static_cast<int>(cw::CheckRule::profile_origin) == CW_CHECK_PROFILE_ORIGIN,
              "core check rules and the header's CW_CHECK_* differ");

// CONTACT's layout for the exact model (doc/theory/exact.md): the ellipse
// inside a box 1.2 times larger, two guard cells on each side at 20 across.
constexpr double kExactBoxScale = 1.2;

cw::ContactPlausibility plausibility_of(const cw_grid& g, const cw_params& p)
{
    const cw_params d = default_params();
    cw::ContactPlausibility c;
    c.a = p.a;
    c.b = p.b;
    c.normal_force = p.normal_force;
    c.mu = p.mu;
    c.G = p.G;
    c.L1 = p.L1;
    c.L2 = p.L2;
    c.L3 = p.L3;
    c.xi_x = p.xi_x;
    c.xi_y = p.xi_y;
    c.phi = p.phi;
    c.V = p.V;
    if (p.friction_law != CW_FRICTION_COULOMB) {
        c.s_h1 = p.mu_e1 > 0.0 ? p.s_h1 : 0.0;
        c.s_h2 = p.mu_e2 > 0.0 ? p.s_h2 : 0.0;
    }
    c.layer_h = p.layer_h;
    c.layer_G = p.layer_G;
    c.tau_c0 = p.tau_c0;
    c.flexibilities_given = p.flexibility == CW_FLEX_GIVEN;
    c.gap_grid = g.kind == CW_GRID_GAP;
    c.default_geometry = p.a == d.a && p.b == d.b && p.normal_force == d.normal_force;
    if (c.gap_grid) {
        c.dx = g.dx;
        c.dy = g.dy;
        const size_t cells = g.nx > 0 && g.ny > 0 ? size_t(g.nx) * size_t(g.ny) : 0;
        if (p.gap && cells > 0 && p.gap_len >= cells) {
            c.gap = p.gap;
            c.gap_count = cells;
        }
        c.approach_given = p.normal_load == CW_NORMAL_APPROACH;
        c.approach = p.approach;
    }
    return c;
}

// Inputs typed by another name (exact spelling), and the short forms of
// enumeration values (any case, "-" for "_").
const std::pair<const char*, const char*> kInputAliases[] = {{"N", "normal_force"},
                                                             {"spin", "phi"}};
const std::pair<const char*, const char*> kValueAliases[] = {{"strips", "kalker_strips"},
                                                             {"fast", "fastsim"}};

// The names of the enumeration values (the header's CW_ constants without
// their prefix, in lower case).
const char* const kValueNames[] = {"kalker_strips", "uniform",   "gap",        "force",
                                   "approach",      "exact",     "semi_hertz", "parabolic",
                                   "elliptic",      "fastsim",   "calibrated", "from_material",
                                   "given"};

std::string canonical_name(const std::string& typed)
{
    for (const auto& [alias, name] : kInputAliases)
        if (typed == alias) return name;
    std::string folded;
    for (char c : typed)
        folded += c == '-' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const auto& [alias, name] : kValueAliases)
        if (folded == alias) return name;
    for (const char* v : kValueNames)
        if (folded == v) return folded;
    return typed;
}

} // namespace

void creepwork::capi::fill_check(const cw::Implausible& w, size_t contacts, size_t first,
                                 const std::string& where, cw_check& out)
{
    cw_check_init(&out);
    out.rule = static_cast<int>(w.rule);
    copy_message(w.input, out.input, sizeof out.input);
    out.value = w.value;
    copy_message(w.unit, out.unit, sizeof out.unit);
    out.contacts = contacts;
    out.first = first;
    copy_message(w.reason, out.reason, sizeof out.reason);
    copy_message(cw::implausible_message(w, where), out.message, sizeof out.message);
}

void creepwork::capi::write_checks(const std::vector<cw_check>& checks, cw_check* out, size_t len,
                                   size_t* found)
{
    require(found, "found");
    *found = checks.size();
    if (len == 0) return; // a count query; out may be NULL
    require(out, "out");
    const size_t size = out[0].struct_size;
    if (!valid_struct_size(size))
        fail(CW_ERR_STRUCT_SIZE, "out[0].struct_size = " + std::to_string(size) +
                                     " is invalid (call cw_check_init first)");
    require_length(len, checks.size(), "out");
    auto* bytes = reinterpret_cast<unsigned char*>(out);
    for (size_t k = 0; k < checks.size(); ++k)
        if (reinterpret_cast<cw_check*>(bytes + k * size)->struct_size != size)
            fail(CW_ERR_STRUCT_SIZE, "out[" + std::to_string(k) +
                                         "].struct_size differs from out[0].struct_size");
    for (size_t k = 0; k < checks.size(); ++k)
        write_struct(reinterpret_cast<cw_check*>(bytes + k * size), checks[k]);
}

extern "C" {

int cw_grid_init_model(cw_grid* grid, int model)
{
    if (!grid) return CW_ERR_NULL_POINTER;
    if (model != CW_MODEL_FASTSIM && model != CW_MODEL_EXACT && model != CW_MODEL_CALIBRATED)
        return CW_ERR_UNKNOWN_OPTION;
    *grid = default_grid();
    if (model == CW_MODEL_EXACT) {
        grid->kind = CW_GRID_UNIFORM;
        grid->nx = static_cast<int>(std::lround(kExactBoxScale * grid->nx));
        grid->ny = static_cast<int>(std::lround(kExactBoxScale * grid->ny));
        grid->box_scale = kExactBoxScale;
    }
    return CW_OK;
}

int cw_check_init(cw_check* check)
{
    if (!check) return CW_ERR_NULL_POINTER;
    std::memset(check, 0, sizeof *check);
    check->struct_size = sizeof *check;
    return CW_OK;
}

int cw_params_check(const cw_grid* grid, const cw_params* params, size_t count, cw_check* out,
                    size_t len, size_t* found)
{
    std::string ignored;
    return guarded(&ignored, [&] {
        require(grid, "grid");
        require(found, "found");
        const cw_grid g = read_struct(grid, default_grid(), "grid");
        if (count > 0) require(params, "params");
        const size_t stride = count > 0 ? params[0].struct_size : 0;
        if (count > 0 && !valid_struct_size(stride))
            fail(CW_ERR_STRUCT_SIZE, "params[0].struct_size is invalid (call cw_params_init first)");
        // Per row of the rule table: the first finding and how many contacts.
        struct Seen {
            cw::Implausible first;
            size_t index, contacts;
        };
        std::vector<std::pair<int, Seen>> rows;
        std::vector<cw::Implausible> found_now;
        std::vector<int> row_now;
        const auto* bytes = reinterpret_cast<const unsigned char*>(params);
        for (size_t k = 0; k < count; ++k) {
            const auto* pk = reinterpret_cast<const cw_params*>(bytes + k * stride);
            if (pk->struct_size != stride)
                fail(CW_ERR_STRUCT_SIZE, "params[" + std::to_string(k) +
                                             "].struct_size differs from params[0].struct_size");
            const cw_params p = read_struct(pk, default_params(), "params");
            found_now.clear();
            row_now.clear();
            cw::check_contact(plausibility_of(g, p), found_now, row_now);
            for (size_t m = 0; m < found_now.size(); ++m) {
                auto it = std::find_if(rows.begin(), rows.end(),
                                       [&](const auto& r) { return r.first == row_now[m]; });
                if (it == rows.end())
                    rows.push_back({row_now[m], Seen{found_now[m], k, 1}});
                else
                    ++it->second.contacts;
            }
        }
        std::sort(rows.begin(), rows.end(),
                  [](const auto& x, const auto& y) { return x.first < y.first; });
        std::vector<cw_check> checks(rows.size());
        for (size_t m = 0; m < rows.size(); ++m) {
            const Seen& s = rows[m].second;
            const std::string where =
                count > 1 ? " (" + std::to_string(s.contacts) + " of " + std::to_string(count) +
                                " contacts)"
                          : "";
            fill_check(s.first, s.contacts, s.index, where, checks[m]);
        }
        write_checks(checks, out, len, found);
        return CW_OK;
    });
}

int cw_input_name(const char* typed, char* name, size_t name_len)
{
    if (!typed || !name) return CW_ERR_NULL_POINTER;
    std::string ignored;
    return guarded(&ignored, [&] {
        const std::string out = canonical_name(typed);
        if (out.size() + 1 > name_len) {
            if (name_len > 0) name[0] = '\0';
            return CW_ERR_BUFFER_TOO_SMALL;
        }
        std::memcpy(name, out.c_str(), out.size() + 1);
        return CW_OK;
    });
}

} // extern "C"
