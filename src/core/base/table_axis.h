// One axis of a lookup table: sorted node positions and the linear interpolation weights of a
// point between them (tables built at load, looked up per sample).
#pragma once

#include <algorithm>
#include <utility>
#include <vector>

namespace kiln {

class TableAxis {
  public:
    TableAxis() = default;
    // nodes: strictly increasing; one node makes a constant axis.
    explicit TableAxis(std::vector<float> nodes) : nodes(std::move(nodes)) {}

    int Size() const { return int(nodes.size()); }
    float Node(int i) const { return nodes[size_t(i)]; }
    const std::vector<float>& Nodes() const { return nodes; }

    // The interval [node i, node i + 1] holding x (clamped to the axis) and the weight t of
    // node i + 1: value(x) ~ (1 - t) value_i + t value_{i+1}. A one-node axis gives (0, 0).
    std::pair<int, float> Locate(float x) const {
        if (nodes.size() < 2) return {0, 0.f};
        if (!(x > nodes.front())) return {0, 0.f};
        if (x >= nodes.back()) return {Size() - 2, 1.f};
        int i = int(std::upper_bound(nodes.begin(), nodes.end(), x) - nodes.begin()) - 1;
        i = std::clamp(i, 0, Size() - 2);
        float t = (x - nodes[size_t(i)]) / (nodes[size_t(i + 1)] - nodes[size_t(i)]);
        return {i, std::clamp(t, 0.f, 1.f)};
    }
    // Index of the second node of the interval from Locate (i itself for a one-node axis).
    int Next(int i) const { return std::min(i + 1, Size() - 1); }

  private:
    std::vector<float> nodes;
};

}  // namespace kiln
