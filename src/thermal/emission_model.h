// How a hot surface emits: Wilkie & Weidlich 2011's approaches A, B and C (see emissivity.h).
#pragma once

#include <optional>
#include <string_view>

namespace kiln {

enum class EmissionModel {
    None,       // no thermal emission
    Diffuse,    // A: a diffuse blackbody B(lambda, T); the surface does not reflect
    Additive,   // B: B(lambda, T) added to the material's ordinary reflection
    Kirchhoff,  // C: B(lambda, T) (1 - A(w, lambda)) plus ordinary reflection (default)
};
// "kirchhoff", "additive", "diffuse", "none"
std::optional<EmissionModel> ParseEmissionModel(std::string_view name);
std::string_view EmissionModelName(EmissionModel model);

}  // namespace kiln
