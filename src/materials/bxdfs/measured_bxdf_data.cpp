#include "materials/bxdfs/measured_bxdf_data.h"

#include <cmath>

#include "base/vecmath.h"

namespace kiln {

namespace {

std::string ShapeText(const std::vector<uint64_t>& shape) {
    std::string s = "[";
    for (size_t i = 0; i < shape.size(); ++i) s += (i ? ", " : "") + std::to_string(shape[i]);
    return s + "]";
}

// The field, which must exist with this dtype and rank
const TensorFile::Field& Require(const TensorFile& file, const std::string& name,
                                 TensorFile::DType dtype, size_t rank) {
    const TensorFile::Field* f = file.Find(name);
    if (!f) throw TensorFileError("missing field \"" + name + "\"");
    if (f->dtype != dtype)
        throw TensorFileError("field \"" + name + "\" must be " + TensorFile::DTypeName(dtype) +
                              ", not " + TensorFile::DTypeName(f->dtype));
    if (f->shape.size() != rank)
        throw TensorFileError("field \"" + name + "\" must have " + std::to_string(rank) +
                              " dimensions, not " + std::to_string(f->shape.size()) + " " +
                              ShapeText(f->shape));
    return *f;
}

// Dimension `dim` of a field must equal `n` (what `what` gives)
void RequireDim(const TensorFile::Field& f, const std::string& name, size_t dim, uint64_t n,
                const std::string& what) {
    if (f.shape[dim] != n)
        throw TensorFileError("field \"" + name + "\" has shape " + ShapeText(f.shape) +
                              ": dimension " + std::to_string(dim) + " must be " +
                              std::to_string(n) + " (" + what + ")");
}

void RequireAtLeast(const TensorFile::Field& f, const std::string& name, size_t dim, uint64_t n) {
    if (f.shape[dim] < n)
        throw TensorFileError("field \"" + name + "\" has shape " + ShapeText(f.shape) +
                              ": dimension " + std::to_string(dim) + " must be at least " +
                              std::to_string(n));
}

// Finite values (and not negative ones when nonNegative)
std::vector<float> Values(const TensorFile& file, const std::string& name, bool nonNegative) {
    std::vector<float> v = file.Floats(name);
    for (size_t i = 0; i < v.size(); ++i)
        if (!std::isfinite(v[i]) || (nonNegative && v[i] < 0))
            throw TensorFileError("field \"" + name + "\" has " +
                                  (std::isfinite(v[i]) ? "a negative" : "a non-finite") +
                                  " value at index " + std::to_string(i));
    return v;
}

// Parameter nodes: at least one, finite, strictly increasing
std::vector<float> Nodes(const TensorFile& file, const std::string& name) {
    std::vector<float> v = Values(file, name, false);
    if (v.empty()) throw TensorFileError("field \"" + name + "\" has no values");
    for (size_t i = 1; i < v.size(); ++i)
        if (!(v[i] > v[i - 1]))
            throw TensorFileError("the values of field \"" + name + "\" must increase (index " +
                                  std::to_string(i) + ")");
    return v;
}

}  // namespace

MeasuredBxDFData MeasuredBxDFData::FromTensor(const TensorFile& file) {
    using DType = TensorFile::DType;
    const auto& theta = Require(file, "theta_i", DType::Float32, 1);
    const auto& phi = Require(file, "phi_i", DType::Float32, 1);
    const auto& lambda = Require(file, "wavelengths", DType::Float32, 1);
    const auto& ndf = Require(file, "ndf", DType::Float32, 2);
    const auto& sigma = Require(file, "sigma", DType::Float32, 2);
    const auto& vndf = Require(file, "vndf", DType::Float32, 4);
    const auto& lum = Require(file, "luminance", DType::Float32, 4);
    const auto& spectra = Require(file, "spectra", DType::Float32, 5);
    const auto& description = Require(file, "description", DType::UInt8, 1);
    const auto& jacobian = Require(file, "jacobian", DType::UInt8, 1);
    RequireDim(jacobian, "jacobian", 0, 1, "one flag");
    (void)description;

    const uint64_t nPhi = phi.shape[0], nTheta = theta.shape[0], nLambda = lambda.shape[0];
    for (int d = 0; d < 2; ++d) {
        RequireAtLeast(ndf, "ndf", d, 2);
        RequireAtLeast(sigma, "sigma", d, 2);
    }
    RequireDim(vndf, "vndf", 0, nPhi, "the size of phi_i");
    RequireDim(vndf, "vndf", 1, nTheta, "the size of theta_i");
    RequireAtLeast(vndf, "vndf", 2, 2);
    RequireAtLeast(vndf, "vndf", 3, 2);
    RequireDim(lum, "luminance", 0, nPhi, "the size of phi_i");
    RequireDim(lum, "luminance", 1, nTheta, "the size of theta_i");
    RequireAtLeast(lum, "luminance", 2, 2);
    RequireDim(lum, "luminance", 3, lum.shape[2], "the square's other dimension");
    RequireDim(spectra, "spectra", 0, nPhi, "the size of phi_i");
    RequireDim(spectra, "spectra", 1, nTheta, "the size of theta_i");
    RequireDim(spectra, "spectra", 2, nLambda, "the size of wavelengths");
    RequireDim(spectra, "spectra", 3, lum.shape[2], "as luminance");
    RequireDim(spectra, "spectra", 4, lum.shape[3], "as luminance");

    MeasuredBxDFData data;
    std::string_view text = file.Bytes("description");
    data.description = std::string(text.substr(0, text.find('\0')));
    data.wavelengths = Nodes(file, "wavelengths");
    std::vector<float> phiNodes = Nodes(file, "phi_i"), thetaNodes = Nodes(file, "theta_i");
    data.isotropic = nPhi <= 2;
    data.azimuths = int(nPhi);
    if (!data.isotropic) {
        // pbrt-v4: the azimuths must span 2 pi (no symmetry reduction)
        const double reduction = std::rint(2 * Pi / (double(phiNodes.back()) - phiNodes.front()));
        if (reduction != 1)
            throw TensorFileError("phi_i spans " +
                                  std::to_string(phiNodes.back() - phiNodes.front()) +
                                  " radians: an anisotropic BRDF must cover 2 pi (symmetry "
                                  "reduction is not supported, as in pbrt-v4)");
    }

    using Kind = PiecewiseLinear2D::Kind;
    data.ndf = PiecewiseLinear2D(Values(file, "ndf", true), int(ndf.shape[1]), int(ndf.shape[0]),
                                 {}, Kind::Values);
    data.sigma = PiecewiseLinear2D(Values(file, "sigma", true), int(sigma.shape[1]),
                                   int(sigma.shape[0]), {}, Kind::Values);
    data.vndf = PiecewiseLinear2D(Values(file, "vndf", true), int(vndf.shape[3]),
                                  int(vndf.shape[2]), {phiNodes, thetaNodes}, Kind::Distribution);
    data.luminance =
        PiecewiseLinear2D(Values(file, "luminance", true), int(lum.shape[3]), int(lum.shape[2]),
                          {phiNodes, thetaNodes}, Kind::Distribution);
    // Negative spectral values (measurement noise) are kept; the BxDF clamps them to 0
    data.spectra = PiecewiseLinear2D(Values(file, "spectra", false), int(spectra.shape[4]),
                                     int(spectra.shape[3]),
                                     {phiNodes, thetaNodes, data.wavelengths}, Kind::Values);
    return data;
}

size_t MeasuredBxDFData::BytesUsed() const {
    return sizeof(*this) + wavelengths.size() * sizeof(float) + ndf.BytesUsed() +
           sigma.BytesUsed() + vndf.BytesUsed() + luminance.BytesUsed() + spectra.BytesUsed();
}

}  // namespace kiln
