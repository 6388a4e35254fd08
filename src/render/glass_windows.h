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
//
// Under an environment light (WeighAgainstEnvironment), the choice is also kept only with
// probability (G / E)^2 Omega / pi where that is below 1, G the radiance the window's medium
// sends out at most and E the environment's mean radiance (both weighted by xbar + ybar + zbar
// over 360-830 nm): a path that finds a glow of radiance G and solid angle Omega by cosine
// sampling adds about that share of the variance the environment's light has, so a glow dim
// against the sky (hot glass in daylight) costs no shadow rays where it would change little,
// and one bright against it (a gob in a dark room) is sampled in full. Other lights are not
// counted: an environment mostly hidden from the receivers makes windows sampled less than
// they could be (noisier, never biased: MIS weighs with these probabilities).
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "base/sampling.h"
#include "core/geometry/shape.h"
#include "lights/light.h"
#include "materials/material.h"
#include "media/medium.h"

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
    // Weighs each window against the environment's mean radiance (0: none; see above), the
    // glow of its hot medium estimated over the box of its windows (media: the scene's).
    void WeighAgainstEnvironment(std::span<const Medium> media, Float environmentRadiance);
    // The mean radiance of the infinite lights over all directions, weighted as above
    // (W m^-2 sr^-1 nm^-1 per unit weight), from stratified directions and wavelengths.
    static Float EnvironmentRadiance(std::span<const Light> lights,
                                     std::span<const int> infiniteLights);
    bool WeighedAgainstEnvironment() const { return !glowOverEnvironment2.empty(); }

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
    // (G / E)^2 by window; empty: no environment to weigh against
    std::vector<Float> glowOverEnvironment2;
};

}  // namespace kiln
