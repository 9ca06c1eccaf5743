// What every model of the contact hands back, per element: the field names,
// element states and solve modes shared by the models and the C ABI.
// Fields are exported in the caller's layout: element (i, j) at [i + j*nx],
// i along x (increasing x), j along y (increasing y) -- column-major, i
// fastest, so a Fortran array (nx, ny) maps directly.
#pragma once

namespace creepwork {

enum class Field {
    x,               // element centre x [m]
    y,               // element centre y [m]
    area,            // element area [m^2]
    pz,              // normal pressure [Pa]
    px,              // tangential traction on the wheel, x [Pa]
    py,              // tangential traction on the wheel, y [Pa]
    sx,              // micro-slip W_x/V [-] (model slip, 0 in adhesion)
    sy,              // micro-slip W_y/V [-]
    mz,              // moment contribution (x py - y px) area [N m]
    work_paper,      // paper's local work per unit rolling distance [J/m]
    work_consistent, // energy-consistent local work [J/m]
};

enum class ElementState { exterior = 0, adhesion = 1, slip = 2 };

enum class SolveMode {
    forces_only, // totals, tractions and states; no slip or work fields
    full,        // also micro-slip, moment, both work maps and the profile
};

// How a model's export writes a field's value v into out: copy_field
// stores it, add_field adds it scaled (one export loop serves both).
struct StoreField {
    void operator()(double* out, double v) const { *out = v; }
};
struct AddScaledField {
    double scale;
    void operator()(double* out, double v) const { *out += scale * v; }
};

// Fields that exist only after a SolveMode::full solve.
inline bool field_needs_work(Field f)
{
    return f == Field::sx || f == Field::sy || f == Field::work_paper ||
           f == Field::work_consistent;
}

} // namespace creepwork
