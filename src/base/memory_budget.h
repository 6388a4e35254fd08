// MemoryBudget: the memory a scene may commit (kiln --memory-limit, else the machine's physical
// memory). The large allocations of scene creation (the film, meshes with their share of the
// BVH, curves, images and MIP maps, volume grids) are estimated and charged before they are
// made; one that does not fit is a MemoryLimitError naming the object and its estimate, which
// scene creation reports at the object's file position, instead of a crash or a silent stop.
#pragma once

#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

namespace kiln {

class MemoryLimitError : public std::runtime_error {
  public:
    using std::runtime_error::runtime_error;
};

class MemoryBudget {
  public:
    // Estimates per primitive, for charging before the primitives exist: bytes per triangle
    // (kiln's Triangle and Shape, indices, Embree's BVH: a 5-million-triangle PLY peaked at 189
    // bytes per triangle with Embree's standard BVH and 128 with the compact one that large
    // scenes get, bench/README.md), per mesh vertex (position, normal, uv), per bilinear patch
    // and per curve segment (control points and Embree's BVH; not measured separately).
    static constexpr double kBytesPerTriangle = 200, kBytesPerVertex = 32, kBytesPerPatch = 200,
                            kBytesPerCurveSegment = 200;
    // Per sphere, disk or cylinder: the shape, its two transforms, its record and share of
    // Embree's BVH (1e6 spheres took 0.67 GB in scene creation, beyond their description).
    static constexpr double kBytesPerQuadric = 700;

    // limitBytes 0: the machine's physical memory (no limit if that is unknown).
    explicit MemoryBudget(double limitBytes = 0) { SetLimit(limitBytes); }
    MemoryBudget(const MemoryBudget&) = delete;
    MemoryBudget& operator=(const MemoryBudget&) = delete;

    void SetLimit(double limitBytes);
    // Whether the limit is kiln's --memory-limit (rather than the machine's memory).
    bool Explicit() const { return explicitLimit; }
    double Limit() const { return limit; }
    double Committed() const;
    // Bytes still free under the limit.
    double Remaining() const;

    // Charges an allocation of `bytes` for `what` ("a PLY mesh of 5005448 triangles") before
    // it is made. Thread-safe. Throws MemoryLimitError when the total would pass the limit:
    // "<what> needs <bytes>, which with the <committed> already committed passes <the limit>".
    void Charge(double bytes, const std::string& what);
    // Gives back `bytes` charged earlier (their allocation was freed). Thread-safe.
    void Release(double bytes);

    // "2G", "512M", "1.5GB", "64 MiB", "800000": decimal (k, M, G, T) or binary (Ki, Mi, Gi,
    // Ti) multiples of bytes, optionally followed by B; nullopt unless positive and finite.
    static std::optional<double> ParseSize(std::string_view text);

  private:
    double limit = 0;  // 0: none
    bool explicitLimit = false;
    mutable std::mutex mutex;
    double committed = 0;
};

}  // namespace kiln
