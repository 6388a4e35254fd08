// LensSystem: a stack of spherical lens interfaces and an aperture stop, traced as pbrt-v4's
// RealisticCamera traces them (Kolb, Mitchell and Hanrahan 1995).
//
// Lengths are in metres. Camera space is pbrt-v4's for this camera: the film lies in the plane
// z = 0 and the lens in front of it towards +z; the scene is beyond the lens. Interfaces are
// listed from the scene side (front) to the film side (rear), as in a lens file. Interface i
// has its vertex on the axis at z_i = sum of the thicknesses of interfaces i..n-1 (so the rear
// interface sits at its own thickness, the film-to-lens distance); its curvature radius is
// positive when its centre of curvature lies towards the film (z_i - radius), 0 for the
// aperture stop (a plane); eta is the refractive index of the medium behind it (towards the
// film), 0 meaning air (1); apertureRadius bounds it radially.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "base/vecmath.h"
#include "core/image/image.h"

namespace kiln {

struct LensInterface {
    Float curvatureRadius;  // m; 0: aperture stop
    Float thickness;        // m, to the next interface towards the film (or to the film)
    Float eta;              // behind the interface; 0 or 1: air
    Float apertureRadius;   // m
};

// Paraxial cardinal points of one side of a lens system: z of the principal plane and of the
// focal point (camera space).
struct CardinalPoints {
    Float principalZ, focalZ;
};

// Axis-aligned 2D bounds that start empty (pbrt-v4's Bounds2f semantics for the exit pupil).
struct PupilBounds {
    Point2f pMin{Infinity, Infinity}, pMax{-Infinity, -Infinity};
    // True when the bounds enclose no area (empty, a point or a segment).
    bool IsDegenerate() const { return !(pMax.x > pMin.x && pMax.y > pMin.y); }
    Float Area() const { return IsDegenerate() ? 0 : (pMax.x - pMin.x) * (pMax.y - pMin.y); }
    bool Inside(Point2f p) const {
        return p.x >= pMin.x && p.x <= pMax.x && p.y >= pMin.y && p.y <= pMax.y;
    }
    void Add(Point2f p) {
        pMin = Point2f(std::min(pMin.x, p.x), std::min(pMin.y, p.y));
        pMax = Point2f(std::max(pMax.x, p.x), std::max(pMax.y, p.y));
    }
    Point2f Lerp(Point2f u) const {
        return Point2f(kiln::Lerp(u.x, pMin.x, pMax.x), kiln::Lerp(u.y, pMin.y, pMax.y));
    }
};

class LensSystem {
  public:
    // interfaces from front to rear; aperture: an optional single-channel mask over the stop
    // (see TraceFromFilm), empty for a circular stop.
    LensSystem(std::vector<LensInterface> interfaces, Image aperture);

    const std::vector<LensInterface>& Interfaces() const { return interfaces; }
    // Film-to-rear-interface distance (the rear interface's thickness), front vertex z, and
    // the rear interface's aperture radius.
    Float RearZ() const { return interfaces.back().thickness; }
    Float FrontZ() const;
    Float RearRadius() const { return interfaces.back().apertureRadius; }
    void SetRearThickness(Float t) { interfaces.back().thickness = t; }

    // Traces a camera-space ray leaving the film towards the lens through every interface
    // (refracting at each, clipped by each aperture). Returns 0 if the ray is blocked (missed
    // or outside an interface, behind the stop, total internal reflection), else the weight
    // of the stop's mask where the ray crosses it (1 for a circular stop) and, if rOut is not
    // null, the camera-space ray leaving the front interface (its direction not normalised).
    // With a mask, the stop passes the mask's bilinear value at ((x / r + 1) / 2,
    // (y / r + 1) / 2), r the stop's radius, 0 outside [0,1]^2 (pbrt-v4).
    Float TraceFromFilm(const Ray& rCamera, Ray* rOut) const;
    // Traces a camera-space ray arriving from the scene through every interface towards the
    // film (circular stop, mask ignored as in pbrt-v4); false if blocked.
    bool TraceFromScene(const Ray& rCamera, Ray* rOut) const;

    // Cardinal points from rays parallel to the axis at height x (pbrt-v4 uses a thousandth of
    // the film's diagonal): [0] the film side's (a ray from the scene), [1] the scene side's (a
    // ray from the film). nullopt if either ray is blocked.
    std::optional<std::array<CardinalPoints, 2>> ThickLensApproximation(Float x) const;
    // The rear interface's thickness that brings a point at focusDistance (m, from the film)
    // into focus under the thick-lens approximation (pbrt-v4's FocusThickLens); nullopt if the
    // paraxial rays are blocked or the distance is too short for the lens.
    std::optional<Float> FocusedRearThickness(Float focusDistance, Float x) const;

    // Bounds, on the plane of the rear interface's vertex, of the points through which rays
    // from the film segment [x0, x1] on the +x axis pass the lens: nSamples points on the
    // segment paired with Halton points (bases 2 and 3) over the square of side 3 times the
    // rear radius, the union of those passing expanded by twice the square's diagonal over
    // sqrt(nSamples) (pbrt-v4's BoundExitPupil, which uses 2^20 samples). Degenerate if none
    // passes. With a stop mask, a ray passes the stop anywhere in the disk around the mask's
    // square (deliberate deviation: pbrt-v4 tests the mask, but the camera rotates the bounds
    // found along +x to each film point's azimuth, and a mask without rotational symmetry
    // then passes rays outside them, which pbrt-v4 never samples: 0.8 % of the light lost 45
    // degrees off the x axis for a pentagon on the double Gauss at f/5). Without a mask the
    // bounds are pbrt-v4's.
    PupilBounds BoundExitPupil(Float x0, Float x1, int nSamples) const;

  private:
    // TraceFromFilm; with maskSupport, a masked stop passes every ray within the disk around
    // the mask's square (weight 1) instead of weighting by the mask.
    Float Trace(const Ray& rCamera, Ray* rOut, bool maskSupport) const;

    std::vector<LensInterface> interfaces;
    Image aperture;  // one channel, rows along y (lens space), empty for a circular stop
};

// The most interfaces a lens file may list (pbrt-v4 sets no limit).
constexpr size_t kMaxLensInterfaces = 1024;

// Reads a pbrt-v4 lens file: numbers separated by white space (commas allowed), '#' comments
// to the end of the line, four per interface (curvature radius, thickness, eta, aperture
// diameter; lengths in mm), front to rear, at most kMaxLensInterfaces. Returns interfaces in metres
// with the aperture *radius*; the stop's diameter is set to stopDiameterMm (mm) unless that exceeds
// the file's (then *clamped is set and the file's is kept, as pbrt-v4). On failure returns nullopt
// with a message (line number for a bad token) in *error.
std::optional<std::vector<LensInterface>> ReadLensFile(const std::string& filename,
                                                       Float stopDiameterMm, bool* clamped,
                                                       std::string* error);
// The same from the file's text (filename only names it in messages).
std::optional<std::vector<LensInterface>> ParseLensFile(const std::string& text,
                                                        const std::string& filename,
                                                        Float stopDiameterMm, bool* clamped,
                                                        std::string* error);

}  // namespace kiln
