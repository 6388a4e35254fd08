// Look-ups into the build-time RGB-to-spectrum coefficient tables.
#include "spectral/rgb_to_spectrum.h"

#include <algorithm>
#include <array>
#include <memory>

#include "spectral/color.h"
#include "spectral/color_space_defs.h"

namespace kiln {

// RGBSigmoidPolynomial
Float RGBSigmoidPolynomial::MaxValue() const {
    Float result = std::max((*this)(Lambda_min), (*this)(Lambda_max));
    // The quadratic's maximum, if it lies inside the visible range: its value there is
    // c2 - c1^2 / (4 c0), computed directly (no rounding of the vertex's wavelength)
    if (c0 < 0) {
        const double lambda = -double(c1) / (2 * double(c0));
        if (lambda >= Lambda_min && lambda <= Lambda_max) {
            const double p = double(c2) - double(c1) * double(c1) / (4 * double(c0));
            result = std::max(result, Float(Sigmoid(p)));
        }
    }
    return result;
}

// RGBToSpectrumTable
RGBSigmoidPolynomial RGBToSpectrumTable::operator()(const RGB& in) const {
    // (Not-a-number components as 0: the table is indexed by them)
    auto unit = [](Float v) { return v > 0 ? std::min<Float>(v, 1) : 0; };
    RGB rgb(unit(in.r), unit(in.g), unit(in.b));

    // Greys have an exact constant spectrum: S(c2) = v with c2 = (v - 1/2) / sqrt(v (1 - v))
    if (rgb.r == rgb.g && rgb.g == rgb.b) {
        Float v = rgb.r;
        if (v <= 0) return RGBSigmoidPolynomial(0, 0, -Infinity);
        if (v >= 1) return RGBSigmoidPolynomial(0, 0, Infinity);
        return RGBSigmoidPolynomial(0, 0, (v - 0.5f) / std::sqrt(v * (1 - v)));
    }

    // Largest component and the other two relative to it
    int maxc = (rgb[0] > rgb[1]) ? ((rgb[0] > rgb[2]) ? 0 : 2) : ((rgb[1] > rgb[2]) ? 1 : 2);
    Float z = rgb[maxc];
    Float x = rgb[(maxc + 1) % 3] * (kRes - 1) / z;
    Float y = rgb[(maxc + 2) % 3] * (kRes - 1) / z;

    // Cell and offsets (z through the smoothstep-remapped nodes)
    int xi = std::min(int(x), kRes - 2), yi = std::min(int(y), kRes - 2);
    int zi = int(FindInterval(kRes, [&](size_t i) { return ZNode(int(i)) < z; }));
    Float dx = x - Float(xi), dy = y - Float(yi);
    Float dz = (z - ZNode(zi)) / (ZNode(zi + 1) - ZNode(zi));

    // Trilinear interpolation of the coefficients
    std::array<Float, 3> c;
    for (int i = 0; i < 3; ++i) {
        auto co = [&](int ox, int oy, int oz) { return Coeff(maxc, zi + oz, yi + oy, xi + ox, i); };
        c[i] = Lerp(
            dz, Lerp(dy, Lerp(dx, co(0, 0, 0), co(1, 0, 0)), Lerp(dx, co(0, 1, 0), co(1, 1, 0))),
            Lerp(dy, Lerp(dx, co(0, 0, 1), co(1, 0, 1)), Lerp(dx, co(0, 1, 1), co(1, 1, 1))));
    }
    return RGBSigmoidPolynomial(c[0], c[1], c[2]);
}

bool RGBToSpectrumTable::HasOwnTable(std::string_view name) {
    return RGBToSpectrumTableData(name) != nullptr;
}

const RGBToSpectrumTable* RGBToSpectrumTable::Get(std::string_view name) {
    // One table object per known colour space (two pointers into the embedded bytes)
    static const auto tables = [] {
        std::array<std::unique_ptr<RGBToSpectrumTable>, kColorSpaceDefinitions.size()> t;
        const unsigned char* srgb = RGBToSpectrumTableData("srgb");
        for (size_t i = 0; i < t.size(); ++i) {
            const unsigned char* data = RGBToSpectrumTableData(kColorSpaceDefinitions[i].name);
            t[i] = std::make_unique<RGBToSpectrumTable>(data ? data : srgb);
        }
        return t;
    }();
    for (size_t i = 0; i < kColorSpaceDefinitions.size(); ++i)
        if (kColorSpaceDefinitions[i].name == name) return tables[i].get();
    return nullptr;
}

}  // namespace kiln
