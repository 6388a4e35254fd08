// libFuzzer target: the small data files of materials. Inputs that start with "tensor_file" are
// RGL measured-BRDF tensor files (materials/bxdfs/tensor_file.h, measured_bxdf_data.h): each
// must end in a TensorFileError or in tables whose BxDF gives finite, non-negative values,
// pdfs and samples, and a finite albedo. Every other input is a spectrum file ("lambda value"
// pairs, comments, commas): each must end in an error or a spectrum whose values are finite
// everywhere. (One target for both keeps the fuzzing time of the sanitizer stage.)
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

#include "materials/bxdfs/measured_albedo.h"
#include "materials/bxdfs/measured_bxdf.h"
#include "spectral/spectrum.h"

namespace {

void Check(bool ok) {
    if (!ok) __builtin_trap();
}

void FuzzTensorFile(const uint8_t* data, size_t size) {
    using namespace kiln;
    MeasuredBxDFData brdf;
    try {
        brdf = MeasuredBxDFData::FromTensor(
            TensorFile::Parse(std::string(reinterpret_cast<const char*>(data), size)));
    } catch (const TensorFileError&) {
        return;
    }
    MeasuredBxDF bxdf(&brdf, SampledWavelengths::SampleUniform(0.3f));
    const std::array<Vector3f, 3> dirs{Normalize(Vector3f(0.3f, -0.2f, 0.9f)),
                                       Normalize(Vector3f(-0.9f, 0.1f, 0.05f)), Vector3f(0, 0, -1)};
    for (Vector3f wo : dirs) {
        for (Vector3f wi : dirs) {
            SampledSpectrum f = bxdf.f(wo, wi, TransportMode::Radiance);
            Check(f.IsFinite() && f.MinComponentValue() >= 0);
            Float pdf = bxdf.PDF(wo, wi, TransportMode::Radiance);
            Check(std::isfinite(pdf) && pdf >= 0);
        }
        for (Point2f u : {Point2f(0.1f, 0.7f), Point2f(0.999f, 0.001f)}) {
            auto bs = bxdf.Sample_f(wo, 0.5f, u);
            if (bs) Check(bs->f.IsFinite() && std::isfinite(bs->pdf) && bs->pdf > 0);
        }
    }
    // The albedo quadrature visits every cell of the vndf grid: only for small grids
    if (size_t(brdf.vndf.NX()) * brdf.vndf.NY() <= 1024)
        for (double a : MeasuredAlbedo(brdf, dirs[0], 1)) Check(std::isfinite(a) && a >= 0);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size >= 11 && std::memcmp(data, "tensor_file", 11) == 0) {
        FuzzTensorFile(data, size);
        return 0;
    }
    std::string text(reinterpret_cast<const char*>(data), size);
    std::string error;
    auto s = kiln::PiecewiseLinearSpectrum::Parse(text, "fuzz.spd", &error);
    if (!s) return 0;
    for (kiln::Float lambda : {0.f, 360.f, 555.5f, 830.f, 1e6f})
        if (!std::isfinite((*s)(lambda))) __builtin_trap();
    if (!std::isfinite(s->MaxValue())) __builtin_trap();
    return 0;
}
