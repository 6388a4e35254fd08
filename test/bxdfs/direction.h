// The unit direction at cos theta from +z and azimuth phi (radians) in the shading frame.
#pragma once

#include "base/vecmath.h"

namespace kiln::test {

inline Vector3f Dir(Float cosTheta, Float phi) {
    return SphericalDirection(SafeSqrt(1 - cosTheta * cosTheta), cosTheta, phi);
}

}  // namespace kiln::test
