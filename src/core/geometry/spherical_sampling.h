// Sampling of spherical triangles (Arvo 1995, "Stratified sampling of spherical triangles"),
// as pbrt-v4 uses for triangle lights: uniform in solid angle about a reference point.
#pragma once

#include <array>

#include "base/vecmath.h"

namespace kiln {

// Solid angle (sr) of the triangle v seen from p (Van Oosterom & Strackee 1983).
Float SphericalTriangleArea(const std::array<Point3f, 3>& v, Point3f p);
// Barycentrics of the point of v seen in a direction uniformly distributed over the spherical
// triangle; *pdf = 1 / solid angle (0 for degenerate triangles).
std::array<Float, 3> SampleSphericalTriangle(const std::array<Point3f, 3>& v, Point3f p, Point2f u,
                                             Float* pdf);
// The u that SampleSphericalTriangle maps to direction w (unit).
Point2f InvertSphericalTriangleSample(const std::array<Point3f, 3>& v, Point3f p, Vector3f w);

}  // namespace kiln
