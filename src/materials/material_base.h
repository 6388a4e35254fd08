// What every material holds besides its scattering.
#pragma once

#include "materials/shading_perturbation.h"
#include "materials/thermal_properties.h"

namespace kiln {

// Its heat (thermal_properties.h), and what its textures need, decided at creation.
struct MaterialBase {
    ThermalProperties thermal;
    bool usesFootprint = false;        // a texture filters or antialiases with the footprint
    ShadingPerturbation perturbation;  // bump or normal map (none for mix and interface)
};

}  // namespace kiln
