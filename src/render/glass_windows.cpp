#include "render/glass_windows.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace kiln {

GlassWindows::GlassWindows(std::vector<Window> w) : windows(std::move(w)) {
    std::vector<Float> area;
    area.reserve(windows.size());
    for (const Window& window : windows) {
        Float a = window.shape.Area();
        area.push_back(std::isfinite(a) && a > 0 ? a : 0);
    }
    if (std::any_of(area.begin(), area.end(), [](Float a) { return a > 0; }))
        byArea = AliasTable(area);
    else
        windows.clear();
    // One bounding sphere per hot medium, over all of its windows
    std::map<int, Bounds3f> bounds;
    for (const Window& window : windows)
        bounds[window.hot] = Union(bounds[window.hot], window.shape.Bounds());
    for (const Window& window : windows) {
        Point3f c;
        Float r;
        bounds[window.hot].BoundingSphere(&c, &r);
        center.push_back(c);
        radius.push_back(r);
    }
}

Float GlassWindows::KeepProbability(int i, Point3f from) const {
    Float d2 = DistanceSquared(from, center[size_t(i)]), r2 = Sqr(radius[size_t(i)]);
    Float solidAngle = d2 <= r2 ? 4 * Pi : 2 * Pi * (1 - SafeSqrt(1 - r2 / d2));
    return solidAngle > kSolidAngleBudget ? kSolidAngleBudget / solidAngle : 1;
}

int GlassWindows::Choose(Float u, Point3f from, Float* p) const {
    if (windows.empty()) return -1;
    Float pmf = 0, uKeep = 0;
    int i = byArea.Sample(u, &pmf, &uKeep);
    Float keep = KeepProbability(i, from);
    if (!(pmf > 0) || uKeep >= keep) return -1;
    *p = pmf * keep;
    return i;
}

}  // namespace kiln
