#include "core/geometry/accelerator.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <stdexcept>
#include <vector>

#include "base/animated_transform.h"
#include "base/rng.h"
#include "core/geometry/shape_util.h"

namespace kiln {

// Accelerator data
namespace {

struct SceneBVH;

// A definition that moves (Accelerator::AddAnimatedInstance).
struct MotionInstance {
    AnimatedTransform renderFromInstance;  // to the space of the scene holding it
    const SceneBVH* definition = nullptr;
};

// What one Embree geometry stands for; the geometry's user data points at it.
struct GeomRecord {
    enum class Kind { Triangles, User, Instance, Curves, Motion } kind = Kind::User;
    const TriangleMesh* mesh = nullptr;
    const CurveSet* curves = nullptr;
    std::vector<int> triIndices;  // primID -> triangle index; empty when the identity
    std::vector<Shape> shapes;    // User: primID -> shape
    const Material* material = nullptr;
    std::vector<int> lights;   // primID -> index of the light in the scene's list; empty: none
    std::vector<int> windows;  // primID -> SurfaceInteraction::windowIndex; empty: none
    const ThermalEmission* thermal = nullptr;
    MediumInterface media;
    const AlphaMask* alpha = nullptr;        // cut-outs; nullptr: opaque
    bool boundaryOnly = false;               // Triangles: hits only for crossing media
    Transform renderFromInstance;            // Instance
    std::unique_ptr<MotionInstance> motion;  // Motion
};

struct SceneBVH {
    RTCScene scene = nullptr;
    std::vector<std::unique_ptr<GeomRecord>> records;  // indexed by geomID
    Bounds3f bounds;                                   // of everything added
};

// Intersection context carrying the closest user-geometry hit back from the callbacks.
using KilnContext = EmbreeQueryContext;

void UserBounds(const RTCBoundsFunctionArguments* args) {
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    Bounds3f b = rec->shapes[args->primID].Bounds();
    // Pad by a few ulps so reprojected hits on the boundary are not culled.
    Vector3f pad = 1e-6f * Abs(Vector3f(b.pMax) - Vector3f(b.pMin)) +
                   1e-6f * Max(Abs(Vector3f(b.pMin)), Abs(Vector3f(b.pMax)));
    args->bounds_o->lower_x = b.pMin.x - pad.x;
    args->bounds_o->lower_y = b.pMin.y - pad.y;
    args->bounds_o->lower_z = b.pMin.z - pad.z;
    args->bounds_o->upper_x = b.pMax.x + pad.x;
    args->bounds_o->upper_y = b.pMax.y + pad.y;
    args->bounds_o->upper_z = b.pMax.z + pad.z;
}

Ray RayFromEmbree(const RTCRay& r) {
    return Ray(Point3f(r.org_x, r.org_y, r.org_z), Vector3f(r.dir_x, r.dir_y, r.dir_z), r.time);
}

// The query ray as the caller gave it: in scenes with curves rays start tnear back along their
// direction (Impl::curveBackoff, set by Accelerator::Commit), and kiln's own shapes see them
// from tnear on.
Ray QueryRayFromEmbree(const RTCRay& r) {
    Ray ray = RayFromEmbree(r);
    if (r.tnear > 0) ray.o = ray.o + r.tnear * ray.d;
    return ray;
}

// The closest hit of a user-geometry shape beyond which alpha does not cut out (pbrt-v4's
// GeometricPrimitive::Intersect: a cut-out hit continues the ray from there); the uniform
// number of the stochastic test is a hash of the ray from each hit on. A shape has at most a few
// hits along a ray (two for quadrics and bilinear patches); the loop is bounded all the same.
std::optional<ShapeIntersection> UserHit(const GeomRecord& rec, unsigned primID, Ray ray,
                                         Float tMax) {
    const Shape& shape = rec.shapes[primID];
    Float tOffset = 0;
    for (int k = 0; k < 8; ++k) {
        std::optional<ShapeIntersection> si = shape.Intersect(ray, tMax);
        if (!si) return std::nullopt;
        if (!rec.alpha ||
            !rec.alpha->Masked(si->intr, HashToUniform(Hash(ray.o, ray.d, primID, k)))) {
            si->tHit += tOffset;
            return si;
        }
        // Continue from just beyond the cut-out point; t keeps the units of ray.d
        Ray next = si->intr.SpawnRay(ray.d);
        tOffset += si->tHit;
        tMax -= si->tHit;
        if (!(tMax > 0)) return std::nullopt;
        ray = next;
    }
    return std::nullopt;
}

void UserIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    Float tnear = rh->ray.tnear;
    auto si = UserHit(*rec, args->primID, QueryRayFromEmbree(rh->ray), rh->ray.tfar - tnear);
    if (!si || !(si->tHit > 0)) return;
    si->tHit += tnear;  // in the units of the Embree ray
    rh->ray.tfar = si->tHit;
    rh->hit.Ng_x = si->intr.n.x, rh->hit.Ng_y = si->intr.n.y, rh->hit.Ng_z = si->intr.n.z;
    rh->hit.u = si->intr.uv.x, rh->hit.v = si->intr.uv.y;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
        rh->hit.instID[l] = args->context->instID[l];
    reinterpret_cast<KilnContext*>(args->context)->userHit = std::move(si);
}

void UserOccluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    Ray ray = QueryRayFromEmbree(*r);
    Float tMax = r->tfar - r->tnear;
    bool hit = rec->alpha ? UserHit(*rec, args->primID, ray, tMax).has_value()
                          : rec->shapes[args->primID].IntersectP(ray, tMax);
    if (hit) r->tfar = -std::numeric_limits<float>::infinity();
}

// Embree's filter for curves with alpha (as TriangleAlphaFilter below for triangles): the
// hit's interaction gives the texture context.
void CurveAlphaFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    RTCRayN* ray = args->ray;
    unsigned prim = RTCHitN_primID(args->hit, 1, 0);
    Point3f o(RTCRayN_org_x(ray, 1, 0), RTCRayN_org_y(ray, 1, 0), RTCRayN_org_z(ray, 1, 0));
    Vector3f d(RTCRayN_dir_x(ray, 1, 0), RTCRayN_dir_y(ray, 1, 0), RTCRayN_dir_z(ray, 1, 0));
    SurfaceInteraction si =
        rec->curves->InteractionAt(int(prim), RTCHitN_u(args->hit, 1, 0), o, d,
                                   RTCRayN_tfar(ray, 1, 0), RTCRayN_time(ray, 1, 0));
    if (rec->alpha->Masked(si, HashToUniform(Hash(o, d, prim)))) args->valid[0] = 0;
}

// Embree's filter for triangles with alpha (closest-hit and shadow queries alike): rejects a
// candidate hit where the surface is cut out. The uniform number hashes the ray and the
// triangle, so each surface along a ray gets its own.
void TriangleAlphaFilter(const RTCFilterFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    RTCRayN* ray = args->ray;
    RTCHitN* hit = args->hit;
    unsigned prim = RTCHitN_primID(hit, 1, 0);
    int tri = rec->triIndices.empty() ? int(prim) : rec->triIndices[prim];
    Float b1 = Clamp(RTCHitN_u(hit, 1, 0), 0, 1), b2 = Clamp(RTCHitN_v(hit, 1, 0), 0, 1);
    if (b1 + b2 > 1) b1 /= (b1 + b2), b2 = 1 - b1;
    std::array<Float, 3> b = {1 - b1 - b2, b1, b2};
    Float time = RTCRayN_time(ray, 1, 0);
    Interaction it = Triangle(rec->mesh, tri).PointAt(b, time);
    SurfaceInteraction si;
    si.p = it.p;
    si.n = it.n;
    si.uv = it.uv;
    si.time = time;
    si.faceIndex = rec->mesh->faceIndices.empty() ? 0 : rec->mesh->faceIndices[size_t(tri)];
    si.mesh = rec->mesh;
    si.triIndex = tri;
    si.b = b;
    Float u = HashToUniform(Hash(RTCRayN_org_x(ray, 1, 0), RTCRayN_org_y(ray, 1, 0),
                                 RTCRayN_org_z(ray, 1, 0), RTCRayN_dir_x(ray, 1, 0),
                                 RTCRayN_dir_y(ray, 1, 0), RTCRayN_dir_z(ray, 1, 0), tri));
    if (rec->alpha->Masked(si, u)) args->valid[0] = 0;
}

// The full hit rh found on geometry rec, in the space of the scene holding rec: o and d are
// the query ray there. User and motion geometries left their hits in ctx.
std::optional<ShapeIntersection> RecordHit(const GeomRecord& rec, const RTCRayHit& rh,
                                           const KilnContext& ctx, Point3f o, Vector3f d,
                                           Float time) {
    if (rec.kind == GeomRecord::Kind::Motion) return ctx.userHit;  // complete already
    unsigned prim = rh.hit.primID;
    ShapeIntersection si;
    if (rec.kind == GeomRecord::Kind::Triangles) {
        int tri = rec.triIndices.empty() ? int(prim) : rec.triIndices[prim];
        Float b1 = Clamp(rh.hit.u, 0, 1), b2 = Clamp(rh.hit.v, 0, 1);
        if (b1 + b2 > 1) b1 /= (b1 + b2), b2 = 1 - b1;
        Triangle t(rec.mesh, tri);
        si.intr = rec.boundaryOnly ? t.BoundaryInteraction({1 - b1 - b2, b1, b2}, time, -d)
                                   : t.InteractionFromBarycentrics({1 - b1 - b2, b1, b2}, time, -d);
        si.tHit = rh.ray.tfar;
    } else if (rec.kind == GeomRecord::Kind::Curves) {
        si.intr = rec.curves->InteractionAt(int(prim), rh.hit.u, o, d, rh.ray.tfar, time);
        si.tHit = rh.ray.tfar;
    } else {
        if (!ctx.userHit) return std::nullopt;
        si = *ctx.userHit;
    }
    si.intr.material = rec.material;
    si.intr.lightIndex = rec.lights.empty() ? -1 : rec.lights[prim];
    si.intr.windowIndex = rec.windows.empty() ? -1 : rec.windows[prim];
    si.intr.thermal = rec.thermal;
    si.intr.mediumInterface = rec.media;
    return si;
}

// A moving definition as an Embree user geometry (pbrt-v4's AnimatedPrimitive): bounds over
// the whole motion, and each ray traced in the definition's space at the ray's time.
void MotionBoundsCallback(const RTCBoundsFunctionArguments* args) {
    auto* m = static_cast<const GeomRecord*>(args->geometryUserPtr)->motion.get();
    Bounds3f b = m->renderFromInstance.MotionBounds(m->definition->bounds);
    args->bounds_o->lower_x = b.pMin.x, args->bounds_o->lower_y = b.pMin.y;
    args->bounds_o->lower_z = b.pMin.z, args->bounds_o->upper_x = b.pMax.x;
    args->bounds_o->upper_y = b.pMax.y, args->bounds_o->upper_z = b.pMax.z;
}

// The ray in the definition's space at its time; false where the transform there is singular
// or the ray leaves the range Embree traces.
bool MotionRay(const MotionInstance& m, const RTCRay& r, Transform* t, RTCRay* out) {
    *t = m.renderFromInstance.Interpolate(r.time);
    if (t->IsSingular()) return false;
    Point3f o = t->ApplyInverse(Point3f(r.org_x, r.org_y, r.org_z));
    Vector3f d = t->ApplyInverse(Vector3f(r.dir_x, r.dir_y, r.dir_z));
    for (Float v : {o.x, o.y, o.z, d.x, d.y, d.z})
        if (!(std::abs(v) <= 1.844e18f)) return false;
    *out = r;
    out->org_x = o.x, out->org_y = o.y, out->org_z = o.z;
    out->dir_x = d.x, out->dir_y = d.y, out->dir_z = d.z;
    return true;
}

void MotionIntersect(const RTCIntersectFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    auto* rh = reinterpret_cast<RTCRayHit*>(args->rayhit);
    Transform t;
    RTCRayHit inner;
    if (!MotionRay(*rec->motion, rh->ray, &t, &inner.ray)) return;
    inner.hit.geomID = inner.hit.primID = RTC_INVALID_GEOMETRY_ID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
        inner.hit.instID[l] = RTC_INVALID_GEOMETRY_ID;
    const SceneBVH& def = *rec->motion->definition;
    KilnContext innerContext;
    rtcIntersect1(def.scene, &innerContext.context, &inner);
    if (inner.hit.geomID == RTC_INVALID_GEOMETRY_ID || !(inner.ray.tfar < rh->ray.tfar)) return;
    Point3f o(inner.ray.org_x, inner.ray.org_y, inner.ray.org_z);
    Vector3f d(inner.ray.dir_x, inner.ray.dir_y, inner.ray.dir_z);
    std::optional<ShapeIntersection> si =
        RecordHit(*def.records[inner.hit.geomID], inner, innerContext, o, d, inner.ray.time);
    if (!si) return;
    si->intr = TransformInteraction(t, si->intr);
    rh->ray.tfar = inner.ray.tfar;
    rh->hit.Ng_x = si->intr.n.x, rh->hit.Ng_y = si->intr.n.y, rh->hit.Ng_z = si->intr.n.z;
    rh->hit.u = inner.hit.u, rh->hit.v = inner.hit.v;
    rh->hit.primID = args->primID;
    rh->hit.geomID = args->geomID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
        rh->hit.instID[l] = args->context->instID[l];
    reinterpret_cast<KilnContext*>(args->context)->userHit = std::move(si);
}

void MotionOccluded(const RTCOccludedFunctionNArguments* args) {
    if (args->N != 1 || !args->valid[0]) return;
    auto* rec = static_cast<const GeomRecord*>(args->geometryUserPtr);
    auto* r = reinterpret_cast<RTCRay*>(args->ray);
    Transform t;
    RTCRay inner;
    if (!MotionRay(*rec->motion, *r, &t, &inner)) return;
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    rtcOccluded1(rec->motion->definition->scene, &context, &inner);
    if (inner.tfar < 0) r->tfar = -std::numeric_limits<float>::infinity();
}

void ErrorCallback(void*, RTCError code, const char* message) {
    std::fprintf(stderr, "kiln: Embree error %d: %s\n", int(code), message ? message : "");
}

}  // namespace

struct Accelerator::Impl {
    RTCDevice device = nullptr;
    // Bytes Embree holds (its memory monitor), now and at most
    std::atomic<int64_t> embreeBytes{0}, embreePeakBytes{0};
    size_t primitives = 0;  // added to the top-level scene and to instance definitions
    SceneBVH top;
    std::deque<SceneBVH> definitions;  // stable addresses: motion records point at them
    struct PlacedInstance {
        unsigned geomID;  // in top; RTC_INVALID_GEOMETRY_ID for an empty definition
        Transform renderFromInstance;
        Bounds3f definitionBounds;
    };
    std::vector<PlacedInstance> instances;
    bool committed = false;
    // Defeating Embree's curve self-intersection avoidance (see Commit): the largest curve radius
    // at the top level and in instance definitions (their own space), the largest stretch of any
    // instance's transform (Frobenius norm of its linear part, at least its largest singular
    // value), whether motion instances are nested in definitions (two levels of stretch), and
    // the render-space distance rays start back by (set by Commit).
    Float topCurveRadius = 0, definitionCurveRadius = 0, instanceStretch = 1;
    bool nestedInstances = false;
    Float curveBackoff = 0;
    void NoteStretch(const Transform& t) {
        const SquareMatrix4& m = t.Matrix();
        Float f2 = 0;
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) f2 += m.m[r][c] * m.m[r][c];
        instanceStretch = std::max(instanceStretch, std::sqrt(f2));
    }
    // The ray as Embree traces it: from curveBackoff back along d, hits counted from tnear.
    void BackOff(const Ray& ray, Float tMax, Point3f* o, Float* tnear, Float* tfar) const {
        *o = ray.o, *tnear = 0, *tfar = tMax;
        Float len = Length(ray.d);
        if (!(curveBackoff > 0) || !(len > 0)) return;
        *tnear = curveBackoff / len;
        *o = ray.o - *tnear * ray.d;
        *tfar = tMax + *tnear;
    }

    SceneBVH NewScene() {
        SceneBVH s;
        s.scene = rtcNewScene(device);
        rtcSetSceneFlags(s.scene, RTC_SCENE_FLAG_ROBUST);
        rtcSetSceneBuildQuality(s.scene, RTC_BUILD_QUALITY_HIGH);
        return s;
    }
    void Attach(SceneBVH& s, RTCGeometry g, std::unique_ptr<GeomRecord> rec) {
        rtcSetGeometryUserData(g, rec.get());
        rtcCommitGeometry(g);
        rtcAttachGeometryByID(s.scene, g, unsigned(s.records.size()));
        rtcReleaseGeometry(g);
        s.records.push_back(std::move(rec));
    }
    void AddShapes(SceneBVH& s, std::span<const Shape> shapes, const Material* material,
                   std::span<const int> areaLights, const ThermalEmission* thermal,
                   MediumInterface media, const AlphaMask* alpha, std::span<const int> windows = {},
                   bool boundaryOnly = false);
    std::vector<int> RemoveUntraceableInstances();
};

// Adding shapes
void Accelerator::Impl::AddShapes(SceneBVH& s, std::span<const Shape> shapes,
                                  const Material* material, std::span<const int> areaLights,
                                  const ThermalEmission* thermal, MediumInterface media,
                                  const AlphaMask* alpha, std::span<const int> windows,
                                  bool boundaryOnly) {
    primitives += shapes.size();
    for (const Shape& shape : shapes) s.bounds = Union(s.bounds, shape.Bounds());
    bool haveLights = !areaLights.empty();
    // Triangles grouped by mesh (first-seen order), everything else as one user geometry.
    std::vector<std::pair<const TriangleMesh*, std::vector<uint32_t>>> meshes;
    std::vector<size_t> others;
    for (size_t i = 0; i < shapes.size(); ++i) {
        if (const Triangle* t = shapes[i].GetIf<Triangle>()) {
            auto it = std::find_if(meshes.begin(), meshes.end(),
                                   [&](auto& m) { return m.first == t->GetMesh(); });
            if (it == meshes.end()) {
                meshes.push_back({t->GetMesh(), {}});
                it = meshes.end() - 1;
            }
            it->second.push_back(uint32_t(i));
        } else {
            others.push_back(i);
        }
    }
    for (auto& [mesh, idx] : meshes) {
        auto rec = std::make_unique<GeomRecord>();
        rec->kind = GeomRecord::Kind::Triangles;
        rec->mesh = mesh;
        rec->material = material;
        rec->thermal = thermal;
        rec->media = media;
        rec->alpha = alpha;
        rec->boundaryOnly = boundaryOnly && !haveLights && !thermal && windows.empty();
        // All of the mesh's triangles in order (the usual case): Embree shares the mesh's
        // index buffer and no per-triangle index is kept
        bool identity = int(idx.size()) == mesh->nTriangles;
        for (size_t k = 0; k < idx.size() && identity; ++k)
            identity = shapes[idx[k]].GetIf<Triangle>()->TriangleIndex() == int(k);
        if (!identity) {
            rec->triIndices.reserve(idx.size());
            for (uint32_t i : idx)
                rec->triIndices.push_back(shapes[i].GetIf<Triangle>()->TriangleIndex());
        }
        if (haveLights) {
            rec->lights.reserve(idx.size());
            for (uint32_t i : idx) rec->lights.push_back(areaLights[i]);
        }
        if (!windows.empty()) {
            rec->windows.reserve(idx.size());
            for (uint32_t i : idx) rec->windows.push_back(windows[i]);
        }
        idx = {};  // released before the BVH build
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
        rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, mesh->p.data(),
                                   0, sizeof(Point3f), mesh->nVertices);
        if (identity) {
            rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                       mesh->vertexIndices.data(), 0, 3 * sizeof(int),
                                       mesh->nTriangles);
        } else {
            auto* ib = static_cast<unsigned*>(
                rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                        3 * sizeof(unsigned), rec->triIndices.size()));
            for (size_t k = 0; k < rec->triIndices.size(); ++k) {
                auto v = mesh->VertexIndices(rec->triIndices[k]);
                for (int j = 0; j < 3; ++j) ib[3 * k + j] = unsigned(v[j]);
            }
        }
        if (alpha) {
            rtcSetGeometryIntersectFilterFunction(g, TriangleAlphaFilter);
            rtcSetGeometryOccludedFilterFunction(g, TriangleAlphaFilter);
        }
        Attach(s, g, std::move(rec));
    }
    if (!others.empty()) {
        auto rec = std::make_unique<GeomRecord>();
        rec->kind = GeomRecord::Kind::User;
        rec->material = material;
        rec->thermal = thermal;
        rec->media = media;
        rec->alpha = alpha;
        for (size_t i : others) {
            rec->shapes.push_back(shapes[i]);
            if (haveLights) rec->lights.push_back(areaLights[i]);
            if (!windows.empty()) rec->windows.push_back(windows[i]);
        }
        RTCGeometry g = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(g, unsigned(rec->shapes.size()));
        rtcSetGeometryBoundsFunction(g, UserBounds, nullptr);
        rtcSetGeometryIntersectFunction(g, UserIntersect);
        rtcSetGeometryOccludedFunction(g, UserOccluded);
        Attach(s, g, std::move(rec));
    }
}

// Accelerator
Accelerator::Accelerator() : impl(std::make_unique<Impl>()) {
    impl->device = rtcNewDevice(nullptr);
    rtcSetDeviceErrorFunction(impl->device, ErrorCallback, nullptr);
    rtcSetDeviceMemoryMonitorFunction(
        impl->device,
        [](void* user, ssize_t bytes, bool) {
            auto* a = static_cast<Impl*>(user);
            int64_t now = a->embreeBytes.fetch_add(bytes) + bytes;
            int64_t peak = a->embreePeakBytes.load();
            while (now > peak && !a->embreePeakBytes.compare_exchange_weak(peak, now)) {
            }
            return true;
        },
        impl.get());
    impl->top = impl->NewScene();
}

Accelerator::~Accelerator() {
    for (SceneBVH& d : impl->definitions) rtcReleaseScene(d.scene);
    rtcReleaseScene(impl->top.scene);
    rtcReleaseDevice(impl->device);
}

void Accelerator::Add(std::span<const Shape> shapes, const Material* material,
                      std::span<const int> lightIndices, const ThermalEmission* thermal,
                      MediumInterface media, const AlphaMask* alpha,
                      std::span<const int> windowIndices, bool boundaryOnly) {
    if (!lightIndices.empty() && lightIndices.size() != shapes.size())
        throw std::invalid_argument("Accelerator::Add: need one light per shape or none");
    if (!windowIndices.empty() && windowIndices.size() != shapes.size())
        throw std::invalid_argument("Accelerator::Add: need one window index per shape or none");
    impl->AddShapes(impl->top, shapes, material, lightIndices, thermal, media, alpha, windowIndices,
                    boundaryOnly);
}

int Accelerator::NewInstanceDefinition() {
    impl->definitions.push_back(impl->NewScene());
    return int(impl->definitions.size()) - 1;
}

void Accelerator::AddToInstanceDefinition(int definition, std::span<const Shape> shapes,
                                          const Material* material, const ThermalEmission* thermal,
                                          MediumInterface media, const AlphaMask* alpha,
                                          bool boundaryOnly) {
    impl->AddShapes(impl->definitions.at(definition), shapes, material, {}, thermal, media, alpha,
                    {}, boundaryOnly);
}

void Accelerator::AddInstance(int definition, const Transform& renderFromInstance) {
    SceneBVH& def = impl->definitions.at(definition);
    // Every call gets an entry, so that Commit can name instances by their call order
    impl->instances.push_back({RTC_INVALID_GEOMETRY_ID, renderFromInstance, def.bounds});
    if (def.records.empty()) return;
    impl->NoteStretch(renderFromInstance);
    impl->instances.back().geomID = unsigned(impl->top.records.size());
    auto rec = std::make_unique<GeomRecord>();
    rec->kind = GeomRecord::Kind::Instance;
    rec->renderFromInstance = renderFromInstance;
    RTCGeometry g = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(g, def.scene);
    // Column-major 3x4 affine part.
    const SquareMatrix4& m = renderFromInstance.Matrix();
    float xfm[12];
    for (int c = 0; c < 4; ++c)
        for (int r = 0; r < 3; ++r) xfm[3 * c + r] = m.m[r][c];
    rtcSetGeometryTransform(g, 0, RTC_FORMAT_FLOAT3X4_COLUMN_MAJOR, xfm);
    rec->triIndices.push_back(definition);  // the definition this instance places
    impl->Attach(impl->top, g, std::move(rec));
}

void Accelerator::AddAnimatedInstance(int definition, const AnimatedTransform& renderFromInstance,
                                      int parent) {
    const SceneBVH& def = impl->definitions.at(size_t(definition));
    if (def.records.empty()) return;
    SceneBVH& s = parent < 0 ? impl->top : impl->definitions.at(size_t(parent));
    auto rec = std::make_unique<GeomRecord>();
    rec->kind = GeomRecord::Kind::Motion;
    rec->motion = std::make_unique<MotionInstance>(MotionInstance{renderFromInstance, &def});
    impl->NoteStretch(renderFromInstance.Interpolate(0));
    impl->NoteStretch(renderFromInstance.Interpolate(1));
    impl->nestedInstances |= parent >= 0;
    s.bounds = Union(s.bounds, renderFromInstance.MotionBounds(def.bounds));
    RTCGeometry g = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(g, 1);
    rtcSetGeometryBoundsFunction(g, MotionBoundsCallback, nullptr);
    rtcSetGeometryIntersectFunction(g, MotionIntersect);
    rtcSetGeometryOccludedFunction(g, MotionOccluded);
    impl->Attach(s, g, std::move(rec));
}

void Accelerator::AddCurves(const CurveSet& curves, const Material* material,
                            const ThermalEmission* thermal, MediumInterface media,
                            const AlphaMask* alpha, int definition) {
    SceneBVH& s = definition < 0 ? impl->top : impl->definitions.at(size_t(definition));
    int n = curves.NumPrimitives();
    if (n == 0) return;
    impl->primitives += size_t(n);
    s.bounds = Union(s.bounds, curves.Bounds());
    Float radius = 0;
    for (const auto& v : curves.EmbreeVertices()) radius = std::max<Float>(radius, v[3]);
    Float& r = definition < 0 ? impl->topCurveRadius : impl->definitionCurveRadius;
    r = std::max(r, radius);
    auto rec = std::make_unique<GeomRecord>();
    rec->kind = GeomRecord::Kind::Curves;
    rec->curves = &curves;
    rec->material = material;
    rec->thermal = thermal;
    rec->media = media;
    rec->alpha = alpha;
    bool ribbon = curves.Type() == CurveType::Ribbon;
    RTCGeometry g =
        rtcNewGeometry(impl->device, ribbon ? RTC_GEOMETRY_TYPE_NORMAL_ORIENTED_BEZIER_CURVE
                                            : RTC_GEOMETRY_TYPE_FLAT_BEZIER_CURVE);
    rtcSetSharedGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4,
                               curves.EmbreeVertices().data(), 0, 4 * sizeof(float), 4 * size_t(n));
    auto* index = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
        g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT, sizeof(unsigned), size_t(n)));
    for (int i = 0; i < n; ++i) index[i] = unsigned(4 * i);
    if (ribbon) {
        std::vector<Vector3f> normals = curves.EmbreeNormals();
        auto* nb = static_cast<float*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_NORMAL, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), normals.size()));
        for (size_t i = 0; i < normals.size(); ++i)
            nb[3 * i] = normals[i].x, nb[3 * i + 1] = normals[i].y, nb[3 * i + 2] = normals[i].z;
    }
    rtcSetGeometryTessellationRate(g, float(curves.TessellationRate()));
    if (alpha) {
        rtcSetGeometryIntersectFilterFunction(g, CurveAlphaFilter);
        rtcSetGeometryOccludedFilterFunction(g, CurveAlphaFilter);
    }
    impl->Attach(s, g, std::move(rec));
}

std::vector<int> Accelerator::Commit() {
    std::vector<int> skipped = impl->RemoveUntraceableInstances();
    // Large scenes trade a little traversal speed for half the BVH memory
    if (Compact()) {
        for (SceneBVH& d : impl->definitions)
            rtcSetSceneFlags(d.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
        rtcSetSceneFlags(impl->top.scene, RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_COMPACT);
    }
    for (SceneBVH& d : impl->definitions) rtcCommitScene(d.scene);
    rtcCommitScene(impl->top.scene);
    // Embree ignores hits on flat curves closer to the ray origin than twice the curve's radius
    // (its EMBREE_CURVE_SELF_INTERSECTION_AVOIDANCE_FACTOR, 2 in its default build), measured
    // in the space the curve is traced in; pbrt-v4 ignores none, and rays leaving a curve start
    // off it by its width already (Interaction::originError). Starting every ray 2.5 largest
    // radii back (twice, and a margin for rounding), hits counted from the true origin on,
    // keeps every hit beyond the true origin.
    Float stretch = impl->nestedInstances ? impl->instanceStretch * impl->instanceStretch
                                          : impl->instanceStretch;
    impl->curveBackoff =
        2.5f * std::max(impl->topCurveRadius, impl->definitionCurveRadius * stretch);
    impl->committed = true;
    return skipped;
}

// Embree traces an instance in its own space: rays go through the inverse transform, and must
// stay within its range there too. Rays start and end within `reach` of the render-space
// origin (the camera, the scene, and points two scene radii beyond it for infinite and
// distant lights), so an instance's rays stay within
// |inverse linear part| (2 reach) + |inverse translation|.
std::vector<int> Accelerator::Impl::RemoveUntraceableInstances() {
    // The scene: the top-level shapes and the instances that are in range themselves
    std::vector<bool> traceable(instances.size());
    Bounds3f scene = top.bounds;
    for (size_t i = 0; i < instances.size(); ++i) {
        const PlacedInstance& inst = instances[i];
        if (inst.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        Bounds3f b = inst.renderFromInstance(inst.definitionBounds);
        traceable[i] = !inst.renderFromInstance.IsSingular() && InRenderRange(b);
        if (traceable[i]) scene = Union(scene, b);
    }
    auto maxAbs = [](Point3f p) { return std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}); };
    double reach = scene.IsEmpty() ? 0 : 4.0 * std::max(maxAbs(scene.pMin), maxAbs(scene.pMax));
    std::vector<int> skipped;
    for (size_t i = 0; i < instances.size(); ++i) {
        const PlacedInstance& inst = instances[i];
        if (inst.geomID == RTC_INVALID_GEOMETRY_ID) continue;
        if (traceable[i]) {
            const SquareMatrix4& inv = inst.renderFromInstance.InverseMatrix();
            double linear = 0, translation = 0;
            for (int r = 0; r < 3; ++r) {
                linear = std::max(linear, double(std::abs(inv.m[r][0])) + std::abs(inv.m[r][1]) +
                                              std::abs(inv.m[r][2]));
                translation = std::max(translation, double(std::abs(inv.m[r][3])));
            }
            traceable[i] = linear * 2 * reach + translation <= 1e18;  // Embree: 1.844e18
        }
        if (!traceable[i]) {
            rtcDetachGeometry(top.scene, inst.geomID);
            skipped.push_back(int(i));
        }
    }
    return skipped;
}

// Ray queries
static void CheckRayForEmbree(const Ray& ray, Float tMax) {
    auto valid = [](Float v) { return std::abs(v) <= 1.844e18f; };
    if (valid(ray.o.x) && valid(ray.o.y) && valid(ray.o.z) && valid(ray.d.x) && valid(ray.d.y) &&
        valid(ray.d.z) && tMax >= 0)
        return;
    char text[256];
    std::snprintf(text, sizeof(text),
                  "internal error: a ray with origin (%g, %g, %g), direction (%g, %g, %g) and "
                  "tMax %g reached the ray tracer",
                  ray.o.x, ray.o.y, ray.o.z, ray.d.x, ray.d.y, ray.d.z, tMax);
    throw std::logic_error(text);
}

RTCRayHit MakeEmbreeRayHit(const Ray& ray, Float tMax) {
    CheckRayForEmbree(ray, tMax);
    RTCRayHit rh;
    rh.ray.org_x = ray.o.x, rh.ray.org_y = ray.o.y, rh.ray.org_z = ray.o.z;
    rh.ray.dir_x = ray.d.x, rh.ray.dir_y = ray.d.y, rh.ray.dir_z = ray.d.z;
    rh.ray.tnear = 0;
    rh.ray.tfar = tMax;
    rh.ray.time = ray.time;
    rh.ray.mask = ~0u;
    rh.ray.id = 0;
    rh.ray.flags = 0;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rh.hit.primID = RTC_INVALID_GEOMETRY_ID;
    for (unsigned l = 0; l < RTC_MAX_INSTANCE_LEVEL_COUNT; ++l)
        rh.hit.instID[l] = RTC_INVALID_GEOMETRY_ID;
    return rh;
}

std::optional<ShapeIntersection> Accelerator::Intersect(const Ray& ray, Float tMax) const {
    KilnContext ctx;
    Point3f o;
    Float tnear, tfar;
    impl->BackOff(ray, tMax, &o, &tnear, &tfar);
    RTCRayHit rh = MakeEmbreeRayHit(Ray(o, ray.d, ray.time), tfar);
    rh.ray.tnear = tnear;
    rtcIntersect1(impl->top.scene, &ctx.context, &rh);
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return std::nullopt;

    // Hits are found and completed along the ray Embree traced; tHit is the caller's
    const GeomRecord* rec;
    const Transform* renderFromInstance = nullptr;
    Vector3f d = ray.d;
    if (rh.hit.instID[0] != RTC_INVALID_GEOMETRY_ID) {
        const GeomRecord* inst = impl->top.records[rh.hit.instID[0]].get();
        renderFromInstance = &inst->renderFromInstance;
        rec = impl->definitions[size_t(inst->triIndices[0])].records[rh.hit.geomID].get();
        d = renderFromInstance->ApplyInverse(ray.d);
        o = renderFromInstance->ApplyInverse(o);
    } else {
        rec = impl->top.records[rh.hit.geomID].get();
    }
    std::optional<ShapeIntersection> si = RecordHit(*rec, rh, ctx, o, d, ray.time);
    if (si && renderFromInstance) si->intr = TransformInteraction(*renderFromInstance, si->intr);
    if (si) si->tHit -= tnear;
    return si;
}

bool Accelerator::IntersectP(const Ray& ray, Float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    CheckRayForEmbree(ray, tMax);
    Point3f o;
    Float tnear, tfar;
    impl->BackOff(ray, tMax, &o, &tnear, &tfar);
    RTCRay r;
    r.org_x = o.x, r.org_y = o.y, r.org_z = o.z;
    r.dir_x = ray.d.x, r.dir_y = ray.d.y, r.dir_z = ray.d.z;
    r.tnear = tnear;
    r.tfar = tfar;
    r.time = ray.time;
    r.mask = ~0u;
    r.id = 0;
    r.flags = 0;
    rtcOccluded1(impl->top.scene, &context, &r);
    return r.tfar < 0;
}

int64_t Accelerator::EmbreePeakBytes() const { return impl->embreePeakBytes.load(); }

bool Accelerator::Compact() const { return impl->primitives > kCompactPrimitives; }

Bounds3f Accelerator::Bounds() const {
    if (impl->top.records.empty()) return Bounds3f();
    RTCBounds b;
    rtcGetSceneBounds(impl->top.scene, &b);
    if (b.lower_x > b.upper_x) return Bounds3f();
    return Bounds3f(Point3f(b.lower_x, b.lower_y, b.lower_z),
                    Point3f(b.upper_x, b.upper_y, b.upper_z));
}

RTCScene Accelerator::EmbreeScene() const { return impl->top.scene; }

}  // namespace kiln
