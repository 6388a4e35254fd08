// Table axes locate points (through their bins) as a linear scan does, for evenly and
// unevenly spaced nodes.
#include "base/table_axis.h"

#include <gtest/gtest.h>

#include "base/rng.h"

using namespace kiln;

namespace {

// Reference: the interval by linear scan
std::pair<int, float> Scan(const std::vector<float>& nodes, float x) {
    if (!(x > nodes.front())) return {0, 0.f};
    if (x >= nodes.back()) return {int(nodes.size()) - 2, 1.f};
    int i = 0;
    while (i + 2 < int(nodes.size()) && nodes[size_t(i + 1)] <= x) ++i;
    return {i, (x - nodes[size_t(i)]) / (nodes[size_t(i + 1)] - nodes[size_t(i)])};
}

}  // namespace

TEST(TableAxis, EvenAndUnevenNodesLocateLikeAScan) {
    std::vector<float> even, uneven;
    for (int i = 0; i <= 470; ++i) even.push_back(360.f + float(i));
    for (int i = 0; i < 64; ++i) {
        float x = i / 63.f;
        uneven.push_back(x * x);
    }
    RNG rng(1);
    for (const std::vector<float>& nodes : {even, uneven}) {
        TableAxis axis(nodes);
        float lo = nodes.front(), hi = nodes.back();
        for (int k = 0; k < 20000; ++k) {
            float x = lo - 1 + (hi - lo + 2) * rng.UniformFloat();
            if (k % 10 == 0) x = nodes[size_t(k / 10) % nodes.size()];  // exactly on nodes
            auto [i, t] = axis.Locate(x);
            auto [ri, rt] = Scan(nodes, x);
            // On a node, either adjacent interval is right; compare the located value
            float v = (1 - t) * nodes[size_t(i)] + t * nodes[size_t(i + 1)];
            float rv = (1 - rt) * nodes[size_t(ri)] + rt * nodes[size_t(ri + 1)];
            EXPECT_NEAR(v, rv, 1e-4f * (hi - lo)) << x;
            EXPECT_GE(t, 0.f);
            EXPECT_LE(t, 1.f);
        }
    }
}
