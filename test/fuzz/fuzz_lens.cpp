// libFuzzer target: pbrt-v4 lens files (the realistic camera's "lensfile") on arbitrary text,
// taken through the steps of the scene's realistic camera (camera.cpp CreateRealistic): the
// file parsed (lens_system.h ParseLensFile), the front of the lens within kiln's ray range, the
// paraxial rays of the thick-lens approximation, focusing at 2 m, the exit pupil bounds (256
// points per ring here, 65536 in scenes) and camera rays from a grid of film points and lens
// samples. Every input must end in an error or in a camera whose rays are either refused
// (std::nullopt) or have finite origins, unit directions and finite, non-negative weights.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/camera/realistic_camera.h"

namespace {

void Check(bool ok) {
    if (!ok) __builtin_trap();
}

bool Finite(kiln::Vector3f v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace

using namespace kiln;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string text(reinterpret_cast<const char*>(data), size);
    // The stop's diameter: the first byte (also part of the text) picks it from 0.7 mm to
    // beyond any stop in the file (which then keeps its own); '#', which lens files begin
    // with, gives 5 mm
    Float stopMm = size ? std::pow(10.f, Float(int(data[0]) - '#') / 40 + 0.7f) : 5;
    bool clamped = false;
    std::string error;
    std::optional<std::vector<LensInterface>> interfaces =
        ParseLensFile(text, "fuzz.dat", stopMm, &clamped, &error);
    if (!interfaces) {
        Check(!error.empty());
        return 0;
    }
    LensSystem lens(std::move(*interfaces), Image());
    if (!(lens.FrontZ() < kMaxRenderCoordinate / 2)) return 0;
    const Float diagonal = 0.035f, paraxialHeight = 0.001f * diagonal;
    if (!lens.ThickLensApproximation(paraxialHeight)) return 0;
    std::optional<Float> rear = lens.FocusedRearThickness(2, paraxialHeight);
    if (!rear) return 0;
    Check(std::isfinite(*rear));
    lens.SetRearThickness(*rear);
    const Point2i resolution(8, 6);
    RealisticCamera camera(CameraTransform(Transform()), 0, 1, resolution, diagonal,
                           std::move(lens), 256);
    for (int y = 0; y < resolution.y; ++y)
        for (int x = 0; x < resolution.x; ++x)
            for (int k = 0; k < 4; ++k) {
                CameraSample sample;
                sample.pFilm = Point2f(x + 0.5f, y + 0.5f);
                sample.pLens = Point2f((k + 0.5f) / 4, Float((k * 3) % 4 + 0.5f) / 4);
                SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
                std::optional<CameraRay> r = camera.GenerateRay(sample, lambda);
                if (!r) continue;
                Check(Finite(Vector3f(r->ray.o)) && Finite(r->ray.d));
                Check(std::abs(Length(r->ray.d) - 1) < 1e-3f);
                Check(r->weight.IsFinite() && r->weight.MinComponentValue() >= 0);
            }
    return 0;
}
