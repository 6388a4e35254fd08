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
    // nodes: strictly increasing; one node makes a constant axis. Points are located through
    // evenly spaced bins (four per interval on average) that each name the interval holding
    // their start, so a lookup is a division and a short forward scan.
    explicit TableAxis(std::vector<float> nodes) : nodes(std::move(nodes)) {
        const int n = Size();
        if (n < 2) return;
        const int nBins = 4 * (n - 1);
        binScale = float(nBins / (double(this->nodes.back()) - this->nodes.front()));
        bins.resize(size_t(nBins) + 1);
        int i = 0;
        for (int b = 0; b <= nBins; ++b) {
            float start = this->nodes.front() + b / binScale;
            while (i < n - 2 && this->nodes[size_t(i + 1)] <= start) ++i;
            bins[size_t(b)] = i;
        }
    }

    int Size() const { return int(nodes.size()); }
    float Node(int i) const { return nodes[size_t(i)]; }
    const std::vector<float>& Nodes() const { return nodes; }

    // The interval [node i, node i + 1] holding x (clamped to the axis) and the weight t of
    // node i + 1: value(x) ~ (1 - t) value_i + t value_{i+1}. A one-node axis gives (0, 0).
    std::pair<int, float> Locate(float x) const {
        if (nodes.size() < 2) return {0, 0.f};
        if (!(x > nodes.front())) return {0, 0.f};
        if (x >= nodes.back()) return {Size() - 2, 1.f};
        size_t b = std::min(bins.size() - 1, size_t((x - nodes.front()) * binScale));
        int i = bins[b];
        // The bin's start may round past x: step back, then forward to x's interval
        while (i > 0 && nodes[size_t(i)] > x) --i;
        while (i < Size() - 2 && nodes[size_t(i + 1)] <= x) ++i;
        float t = (x - nodes[size_t(i)]) / (nodes[size_t(i + 1)] - nodes[size_t(i)]);
        return {i, std::clamp(t, 0.f, 1.f)};
    }
    // Index of the second node of the interval from Locate (i itself for a one-node axis).
    int Next(int i) const { return std::min(i + 1, Size() - 1); }

  private:
    std::vector<float> nodes;
    std::vector<int> bins;  // first interval of each bin
    float binScale = 0;     // bins per unit of x
};

}  // namespace kiln
