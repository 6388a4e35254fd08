// Curves (pbrt-v4's "curve" shape): thin strands such as hair, fur and filaments, as cubic
// Bezier segments intersected by Embree's curve primitives.
//
// pbrt-v4's parameters: "point3 P" control points, "string basis" bezier (default) or bspline,
// "integer degree" 3 (default) or 2, "string type" flat (default), cylinder or ribbon, "float
// width" (1) or "width0"/"width1" (interpolated along the whole curve), "normal N" (ribbons:
// one per segment end), "integer splitdepth" (read; Embree subdivides on its own). Every
// segment is converted to a cubic Bezier segment as pbrt-v4 does (quadratics elevated,
// uniform b-splines converted), in render space.
//
// The surfaces are pbrt-v4's: "flat" and "cylinder" are ribbons that always face the ray
// (Embree's flat curves), "cylinder" with a normal turned across the width as a tube's would be
// (from -90 to +90 degrees about the tangent); "ribbon" is oriented by the normals, slerped
// between each segment's end normals (Embree's normal-oriented curves take the normal along a
// cubic Bezier: kiln's passes through the slerp at u = 0, 1/3, 2/3, 1, and its direction stays
// within 0.08 degrees of the slerp for a quarter turn per segment, 1.6 degrees for 170 degrees).
// Embree tessellates flat curves into at most 16 straight pieces per primitive, so segments that
// need more (pbrt-v4's refinement depth, 5 % of the width) are split into 2, 4, ... primitives.
// u runs from 0 to 1 along each segment, v from 0 to 1 across the width (0.5 on the centre
// line), as pbrt-v4's hair material expects; for flat curves v is measured across the straight
// piece Embree intersected, so that it matches the surface hit. The geometric normal is the
// shading normal. Rays leaving a hit start hitWidth * |n|_1 off it (pbrt-v4's error bounds for
// curve hits, Interaction::originError), clear of the curve they leave.
#pragma once

#include <array>
#include <vector>

#include "base/interaction.h"
#include "base/object_arena.h"
#include "base/transform.h"
#include "base/vecmath.h"

namespace kiln {

class ParameterDictionary;
class Diagnostics;
struct FileLoc;

enum class CurveType { Flat, Cylinder, Ribbon };

class CurveSet {
  public:
    // The curve of one "Shape" directive in render space; nullptr when it has no segment.
    // Malformed parameters throw SceneError at their location.
    static const CurveSet* Create(const Transform& renderFromObject, bool reverseOrientation,
                                  const ParameterDictionary& params, const FileLoc& loc,
                                  ObjectArena& arena, Diagnostics& diag);

    CurveSet(CurveType type, bool flipNormal) : type(type), flipNormal(flipNormal) {}
    // A cubic Bezier segment with widths at its ends and, for ribbons, end normals.
    void AddSegment(const std::array<Point3f, 4>& cp, Float width0, Float width1, Normal3f n0 = {},
                    Normal3f n1 = {});

    // Embree's largest tessellation rate is 16 straight pieces per primitive (it clamps larger
    // ones); flat and cylinder segments that need more are split into 2, 4, ... Embree
    // primitives (up to 2^kMaxRefinementDepth pieces in all).
    static constexpr int kMaxTessellationDepth = 4, kMaxRefinementDepth = 8;

    CurveType Type() const { return type; }
    int NumSegments() const { return int(vertices.size() / 4); }
    // The segments: x, y, z, radius (half the width) for 4 control points per segment (radii
    // linear in u, as pbrt-v4's widths).
    const std::vector<std::array<float, 4>>& Vertices() const { return vertices; }
    // Embree's primitives: the segments, or when some are split, the parts of every segment
    // (the same layout as Vertices()); each is the part u0 ... u1 of a segment.
    int NumPrimitives() const { return int(EmbreeVertices().size() / 4); }
    const std::vector<std::array<float, 4>>& EmbreeVertices() const {
        return parts.empty() ? vertices : partVertices;
    }
    // Embree's normal buffer for ribbons (never split): 4 per segment.
    std::vector<Vector3f> EmbreeNormals() const;
    Bounds3f Bounds() const;
    // Straight pieces per primitive of Embree's flat curves (which it tessellates; ribbons it
    // intersects exactly): pbrt-v4's refinement depth, 2^depth pieces with their deviation under
    // 5 % of the width, for the most curved segment, within Embree's range: 4 to 16.
    int TessellationRate() const { return 1 << tessellationDepth; }

    Point3f Position(int segment, Float u) const;
    Vector3f Tangent(int segment, Float u) const;  // dp/du
    Float Width(int segment, Float u) const;
    // The ribbon's normal at u (slerp of the end normals).
    Normal3f RibbonNormal(int segment, Float u) const;

    // The surface interaction of a ray (origin o, direction d, in the space of the buffers)
    // hitting Embree's primitive at its parameter u, distance t along d: pbrt-v4's
    // Curve::InteractionFromIntersection (uv.x is the segment's u).
    SurfaceInteraction InteractionAt(int primitive, Float u, Point3f o, Vector3f d, Float t,
                                     Float time) const;

  private:
    CurveType type;
    bool flipNormal;
    int tessellationDepth = 2;  // log2 of TessellationRate(), 2 to kMaxTessellationDepth
    // When a segment is split: Embree's primitives, each a part of a segment
    struct Part {
        int segment;
        float u0, u1;
    };
    std::vector<Part> parts;
    std::vector<std::array<float, 4>> partVertices;
    void AddPart(int segment, Float u0, Float u1);
    std::vector<std::array<float, 4>> vertices;
    std::vector<Normal3f> endNormals;  // ribbons: 2 per segment
};

// pbrt-v4's basis conversions, exposed for tests: a quadratic Bezier segment as a cubic one,
// and the Bezier control points of a uniform cubic or quadratic b-spline segment.
std::array<Point3f, 4> ElevateQuadraticBezier(const std::array<Point3f, 3>& cp);
std::array<Point3f, 4> CubicBSplineToBezier(const std::array<Point3f, 4>& cp);
std::array<Point3f, 3> QuadraticBSplineToBezier(const std::array<Point3f, 3>& cp);

}  // namespace kiln
