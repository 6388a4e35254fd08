// What the emissivity tests share: the material fixture (../materials/material_test_util.h)
// with emissivity tables.
#pragma once

#include "../materials/material_test_util.h"
#include "thermal/material_albedo.h"

namespace kiln::test {

struct ThermalFixture : MaterialFixture {
    EmissivityTables tables;
};

}  // namespace kiln::test
