// GlassWindows: the smooth dielectric surfaces that enclose hot media (melts in glass), as
// windows through which light sampling reaches those media.
//
// Shadow rays do not cross a dielectric, so light sampling cannot find a medium glowing inside
// glass, and paths reach it only by a chance refraction. Behind one smooth interface no
// manifold search is needed: a point s sampled on the window fixes, by refraction, the ray
// into the medium, and the emission along that first inner chord is integrated exactly in a
// uniform medium (Medium::UniformSegmentEmission) and estimated by ratio tracking elsewhere.
// volpath weighs this against the path's own refraction by MIS over the direction to s
// (VolPathLightSampling::SampleWindowLd). Windows are chosen in proportion to their area;
// from a point where the bounding sphere of all windows onto the same medium subtends a solid
// angle Omega above kSolidAngleBudget, the choice is kept only with probability
// kSolidAngleBudget / Omega (paths refract into so large a body often by themselves); the
// point on a window by the shape's own sampling from the receiving point.
#pragma once

#include <optional>
#include <vector>

#include "base/sampling.h"
#include "core/geometry/shape.h"
#include "materials/material.h"

namespace kiln {

class GlassWindows {
  public:
    struct Window {
        Shape shape;
        const Material* material;  // a non-dispersive dielectric
        MediumInterface media;     // the media it separates
        int hot;                   // which of them is the emissive one
    };
    explicit GlassWindows(std::vector<Window> windows);

    int Count() const { return int(windows.size()); }
    const Window& operator[](int i) const { return windows[size_t(i)]; }
    // A window to look through from `from` (-1 if none), with its probability.
    int Choose(Float u, Point3f from, Float* p) const;
    // The probability that Choose returns window i.
    Float PMF(int i, Point3f from) const {
        return i < 0 || i >= Count() ? 0 : byArea.PMF(i) * KeepProbability(i, from);
    }

    static constexpr Float kSolidAngleBudget = 0.1f;  // sr

  private:
    Float KeepProbability(int i, Point3f from) const;

    std::vector<Window> windows;
    AliasTable byArea;
    // The bounding sphere of the windows onto each window's medium (by window)
    std::vector<Point3f> center;
    std::vector<Float> radius;
};

}  // namespace kiln
