#include "thermal/emission_model.h"

namespace kiln {

std::optional<EmissionModel> ParseEmissionModel(std::string_view name) {
    if (name == "kirchhoff") return EmissionModel::Kirchhoff;
    if (name == "additive") return EmissionModel::Additive;
    if (name == "diffuse") return EmissionModel::Diffuse;
    if (name == "none") return EmissionModel::None;
    return std::nullopt;
}

std::string_view EmissionModelName(EmissionModel model) {
    switch (model) {
        case EmissionModel::None:
            return "none";
        case EmissionModel::Diffuse:
            return "diffuse";
        case EmissionModel::Additive:
            return "additive";
        case EmissionModel::Kirchhoff:
            return "kirchhoff";
    }
    return "?";
}

}  // namespace kiln
