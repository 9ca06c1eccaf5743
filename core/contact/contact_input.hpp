// Validation of a ContactInput, shared by every model: each error names the
// offending input and the rule it breaks (Error(invalid_input)). Models add
// their own requirements (e.g. the exact model needs the uniform grid).
#pragma once

#include "contact/params.hpp"

namespace creepwork {

// Throws Error(invalid_input) naming the first offending input.
void validate_contact_input(const ContactInput& in);
// The friction law's inputs (mu, the rolling speed V), for every model
// whatever its grid. Throws Error(invalid_input) naming the input.
void validate_friction_input(const ContactInput& in);
// The interface layer's inputs (layer_h, layer_G, tau_c0, k_tau), for every
// model (a model without the layer refuses it: the solver). Throws
// Error(invalid_input) naming the input.
void validate_layer_input(const ContactInput& in);
// The first of layer_h, tau_c0, k_tau that is not 0 (the name a refusal
// gives), or nullptr without a layer.
const char* layer_input_name(const ContactInput& in);
// What a grid's kind allows of the input: a gap, the approach prescribed
// and the semi-Hertzian method need a gap grid (a gap grid's models check
// their own inputs). Throws Error(invalid_input).
void validate_grid_input(const GridSpec& grid, const ContactInput& in);

// The building blocks, for the models' own checks.
[[noreturn]] void reject_input(const char* name, double value, const char* rule);
void require_finite(const char* name, double v);
void require_positive(const char* name, double v);
void require_non_negative(const char* name, double v);

} // namespace creepwork
