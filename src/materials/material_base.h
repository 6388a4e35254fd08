// What every material holds besides its scattering.
#pragma once

#include "materials/shading_perturbation.h"

namespace kiln {

// What its textures need, decided at creation, and its bump or normal map. (A material's heat,
// kiln's "temperature" and "emission", is the thermal module's: thermal/thermal_properties.h.)
struct MaterialBase {
    bool usesFootprint = false;        // a texture filters or antialiases with the footprint
    bool usesTemperature = false;      // a texture follows the surface's temperature
    ShadingPerturbation perturbation;  // bump or normal map (none for mix and interface)
};

}  // namespace kiln
