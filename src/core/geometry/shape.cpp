#include "core/geometry/shape.h"

#include "core/geometry/shape_util.h"

namespace kiln {

// Shape dispatch
Bounds3f Shape::Bounds() const {
    return Dispatch([](auto s) { return s->Bounds(); });
}
Float Shape::Area() const {
    return Dispatch([](auto s) { return s->Area(); });
}
std::optional<ShapeSample> Shape::Sample(Point2f u) const {
    return Dispatch([&](auto s) { return s->Sample(u); });
}
Float Shape::PDF(const Interaction& intr) const {
    return Dispatch([&](auto s) { return s->PDF(intr); });
}
std::optional<ShapeSample> Shape::Sample(const ShapeSampleContext& ctx, Point2f u) const {
    return Dispatch([&](auto s) { return s->Sample(ctx, u); });
}
Float Shape::PDF(const ShapeSampleContext& ctx, Vector3f wi) const {
    return Dispatch([&](auto s) { return s->PDF(ctx, wi); });
}
SurfaceInteraction Shape::InteractionAt(Point3f p, Float time, Vector3f wo) const {
    return Dispatch([&](auto s) { return s->InteractionAt(p, time, wo); });
}
std::optional<ShapeSample> Shape::SampleParametric(Point2f u) const {
    return Dispatch([&](auto s) { return s->SampleParametric(u); });
}
Point2f Shape::InvertParametric(Point3f p) const {
    return Dispatch([&](auto s) { return s->InvertParametric(p); });
}
std::pair<Vector3f, Float> Shape::NormalBounds() const {
    constexpr std::pair<Vector3f, Float> all = {Vector3f(0, 0, 1), -1};
    if (const Triangle* t = GetIf<Triangle>()) {
        Interaction c = t->PointAt({1.f / 3, 1.f / 3, 1.f / 3}, 0);
        return {Vector3f(c.n), 1};
    }
    if (const Disk* d = GetIf<Disk>()) {
        Normal3f n = SafeNormalize((*d->renderFromObject)(Normal3f(0, 0, 1)));
        return {Vector3f(d->reverseOrientation ? -n : n), 1};
    }
    return all;  // curved surfaces
}
std::optional<ShapeIntersection> Shape::Intersect(const Ray& ray, Float tMax) const {
    return Dispatch([&](auto s) { return s->Intersect(ray, tMax); });
}
bool Shape::IntersectP(const Ray& ray, Float tMax) const {
    return Dispatch([&](auto s) { return s->IntersectP(ray, tMax); });
}

}  // namespace kiln
