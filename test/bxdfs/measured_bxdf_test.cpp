// The RGL tensor-file reader, the measured BRDF's tables and MeasuredBxDF against the analytic
// rough conductor its test data are tabulated from (rgl_test_data.h).
#include <gtest/gtest.h>

#include <cstdlib>
#include <cstring>
#include <fstream>
#include <functional>
#include <sstream>

#include "direction.h"
#include "materials/bxdfs/bxdf.h"
#include "materials/bxdfs/measured_bxdf_data.h"
#include "rgl_test_data.h"

using namespace kiln;
using kiln::test::RGLConductor;

namespace {

using test::Dir;

const std::string kCommittedDir = std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/";

// The four wavelengths of the test data (400, 500, 600, 700 nm)
SampledWavelengths NodeWavelengths() { return SampledWavelengths::SampleUniform(0, 400, 800); }

// A small model for the structural tests
RGLConductor Tiny() {
    RGLConductor m;
    m.wavelengths = {450, 650};
    m.eta = {1.2f, 0.3f};
    m.k = {2.3f, 3.5f};
    m.nTheta = 3;
    m.nNormal = 4;
    m.nSample = 4;
    return m;
}

std::vector<TensorFile::NamedField> Decode(const std::string& bytes) {
    TensorFile file = TensorFile::Parse(bytes);
    std::vector<TensorFile::NamedField> fields;
    for (const auto& [name, f] : file.Fields())
        fields.push_back({name, f.dtype, f.shape, std::string(file.Bytes(name))});
    return fields;
}

// The error MeasuredBxDFData gives for fields edited by `edit` ("" if none)
std::string DataError(const std::function<void(std::vector<TensorFile::NamedField>&)>& edit) {
    std::vector<TensorFile::NamedField> fields = Decode(test::WriteRGLConductor(Tiny()));
    edit(fields);
    try {
        MeasuredBxDFData::FromTensor(TensorFile::Parse(TensorFile::Encode(fields)));
    } catch (const TensorFileError& e) {
        return e.what();
    }
    return "";
}

TensorFile::NamedField& Named(std::vector<TensorFile::NamedField>& fields, const std::string& n) {
    for (auto& f : fields)
        if (f.name == n) return f;
    throw std::runtime_error("no field " + n);
}

void SetFloat(TensorFile::NamedField& f, size_t i, float v) {
    std::memcpy(f.data.data() + 4 * i, &v, 4);
}

struct Lobe {
    double l1Error = 0, reference = 0;  // integral |f - f_ref| cos_i and integral f_ref cos_i
};
// Over the hemisphere of wi by a 64 x 256 midpoint rule in (cos theta, phi), all wavelengths
Lobe CompareLobe(const BxDF& a, const BxDF& ref, Vector3f wo) {
    Lobe lobe;
    constexpr int nc = 64, np = 256;
    for (int i = 0; i < nc; ++i)
        for (int j = 0; j < np; ++j) {
            Vector3f wi = Dir((i + 0.5f) / nc, 2 * Pi * (j + 0.5f) / np);
            SampledSpectrum fa = a.f(wo, wi, TransportMode::Radiance);
            SampledSpectrum fr = ref.f(wo, wi, TransportMode::Radiance);
            double w = wi.z * 2 * Pi / (nc * np);
            for (int l = 0; l < NSpectrumSamples; ++l) {
                lobe.l1Error += std::abs(fa[l] - fr[l]) * w / NSpectrumSamples;
                lobe.reference += fr[l] * w / NSpectrumSamples;
            }
        }
    return lobe;
}

// Directional albedo by the BxDF's own sampling on a 128 x 128 stratified grid
SampledSpectrum SampledAlbedo(const BxDF& b, Vector3f wo) {
    SampledSpectrum sum(0.f);
    constexpr int n = 128;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            auto bs = b.Sample_f(wo, 0.5f, Point2f((i + 0.5f) / n, (j + 0.5f) / n));
            if (bs && bs->pdf > 0) sum += bs->f * AbsCosTheta(bs->wi) / bs->pdf;
        }
    return sum / Float(n * n);
}

struct Models {
    MeasuredBxDFData data;
    BxDF measured, analytic;
};
Models Make(const RGLConductor& m) {
    Models r{MeasuredBxDFData::FromTensor(TensorFile::Parse(test::WriteRGLConductor(m))), {}, {}};
    // The analytic model at the four wavelengths of NodeWavelengths(), which must be the file's
    if (m.wavelengths.size() != NSpectrumSamples) throw std::runtime_error("needs 4 wavelengths");
    SampledSpectrum eta, k;
    for (int i = 0; i < NSpectrumSamples; ++i) eta[i] = m.eta[i], k[i] = m.k[i];
    r.analytic = ConductorBxDF(TrowbridgeReitzDistribution(m.alphaX, m.alphaY), eta, k);
    return r;
}

}  // namespace

TEST(TensorFile, RoundTrip) {
    std::vector<float> v{1.5f, -2, 3, 4, 5, 6};
    std::string bytes = TensorFile::Encode(
        {TensorFile::FloatField("a", {2, 3}, v), {"text", TensorFile::DType::UInt8, {5}, "hello"}});
    TensorFile f = TensorFile::Parse(bytes);
    ASSERT_NE(f.Find("a"), nullptr);
    EXPECT_EQ(f.Find("a")->shape, (std::vector<uint64_t>{2, 3}));
    EXPECT_EQ(f.Floats("a"), v);
    EXPECT_EQ(f.Bytes("text"), "hello");
    EXPECT_EQ(f.Find("b"), nullptr);
    EXPECT_THROW(f.Floats("text"), TensorFileError);  // uint8, not float32
}

TEST(TensorFile, HostileInputGivesErrors) {
    auto error = [](const std::string& bytes) -> std::string {
        try {
            TensorFile::Parse(bytes);
        } catch (const TensorFileError& e) {
            return e.what();
        }
        return "";
    };
    const std::string good = test::WriteRGLConductor(Tiny());
    ASSERT_EQ(error(good), "");
    // Every truncation is an error (the data of the last field end the file)
    for (size_t n = 0; n < good.size(); n += (n < 400 ? 1 : 97))
        EXPECT_NE(error(good.substr(0, n)), "") << n;
    EXPECT_NE(error("tensor_file").find("truncated"), std::string::npos);
    std::string bad = good;
    bad[0] = 'T';
    EXPECT_NE(error(bad).find("not a tensor file"), std::string::npos);
    bad = good;
    bad[12] = 2;
    EXPECT_NE(error(bad).find("version 2.0"), std::string::npos);
    bad = good;
    bad[14] = bad[15] = bad[16] = bad[17] = char(0xff);  // 4 billion fields
    EXPECT_NE(error(bad).find("field count"), std::string::npos);
    // First field ("description"): dtype 12, then an offset past the end, then a shape whose
    // byte count overflows 64 bits
    const size_t dtypeAt = 18 + 2 + 11 + 2;
    bad = good;
    bad[dtypeAt] = 12;
    EXPECT_NE(error(bad).find("unknown dtype 12"), std::string::npos);
    bad = good;
    bad[dtypeAt + 8] = char(0x7f);
    EXPECT_NE(error(bad).find("run past the end"), std::string::npos);
    bad = good;
    bad[dtypeAt + 9 + 7] = char(0x40);
    EXPECT_NE(error(bad).find("larger than the file"), std::string::npos);
    std::vector<float> one{1};
    EXPECT_NE(error(TensorFile::Encode({TensorFile::FloatField("x", {1}, one),
                                        TensorFile::FloatField("x", {1}, one)}))
                  .find("appears twice"),
              std::string::npos);
    EXPECT_THROW(TensorFile::Read("/nonexistent/file.bsdf"), TensorFileError);
    EXPECT_THROW(TensorFile::Read("/dev/zero"), TensorFileError);
}

TEST(MeasuredBxDFData, BadStructureGivesErrors) {
    using Fields = std::vector<TensorFile::NamedField>;
    EXPECT_EQ(DataError([](Fields&) {}), "");
    auto has = [](const std::string& s, const std::string& part) {
        return s.find(part) != std::string::npos;
    };
    EXPECT_TRUE(has(
        DataError([](Fields& f) { std::erase_if(f, [](auto& x) { return x.name == "vndf"; }); }),
        "missing field \"vndf\""));
    EXPECT_TRUE(has(DataError([](Fields& f) { Named(f, "ndf").dtype = TensorFile::DType::Int32; }),
                    "\"ndf\" must be float32, not int32"));
    EXPECT_TRUE(has(DataError([](Fields& f) {
                        auto& s = Named(f, "sigma");
                        s.shape = {s.shape[0] * s.shape[1]};
                    }),
                    "\"sigma\" must have 2 dimensions"));
    EXPECT_TRUE(has(DataError([](Fields& f) {
                        auto& s = Named(f, "spectra");
                        std::swap(s.shape[0], s.shape[2]);
                    }),
                    "dimension 0 must be 1"));
    EXPECT_TRUE(has(DataError([](Fields& f) { SetFloat(Named(f, "theta_i"), 2, 0.1f); }),
                    "\"theta_i\" must increase"));
    EXPECT_TRUE(has(DataError([](Fields& f) { SetFloat(Named(f, "vndf"), 5, -1); }),
                    "\"vndf\" has a negative value at index 5"));
    EXPECT_TRUE(has(DataError([](Fields& f) { SetFloat(Named(f, "spectra"), 3, NAN); }),
                    "\"spectra\" has a non-finite value"));
    EXPECT_TRUE(
        has(DataError([](Fields& f) { Named(f, "jacobian").shape = {0}; }), "\"jacobian\""));
    // An anisotropic file that covers half the azimuths (symmetry reduction)
    RGLConductor half = Tiny();
    half.nPhi = 3;
    std::vector<TensorFile::NamedField> fields = Decode(test::WriteRGLConductor(half));
    for (int i = 0; i < 3; ++i) SetFloat(Named(fields, "phi_i"), i, Pi / 2 * i);
    try {
        MeasuredBxDFData::FromTensor(TensorFile::Parse(TensorFile::Encode(fields)));
        ADD_FAILURE() << "symmetry-reduced file accepted";
    } catch (const TensorFileError& e) {
        EXPECT_TRUE(has(e.what(), "must cover 2 pi")) << e.what();
    }
}

// The committed files are what the generator writes (values within float rounding, which
// differs between compilers)
TEST(MeasuredFile, CommittedMatchesGenerator) {
    for (auto [name, model] : {std::pair{"measured-ggx.bsdf", test::KilnTestConductor()},
                               std::pair{"measured-aniso.bsdf", test::KilnTestAnisotropic()}}) {
        SCOPED_TRACE(name);
        const std::string generated = test::WriteRGLConductor(model);
        if (const char* dir = std::getenv("KILN_WRITE_MEASURED_FILES"))
            std::ofstream(std::string(dir) + "/" + name, std::ios::binary) << generated;
        TensorFile committed = TensorFile::Read(kCommittedDir + name);
        TensorFile fresh = TensorFile::Parse(generated);
        ASSERT_EQ(committed.Fields().size(), fresh.Fields().size());
        for (const auto& [field, f] : fresh.Fields()) {
            const TensorFile::Field* c = committed.Find(field);
            ASSERT_NE(c, nullptr) << field;
            EXPECT_EQ(c->shape, f.shape) << field;
            if (f.dtype != TensorFile::DType::Float32) continue;
            std::vector<float> a = committed.Floats(field), b = fresh.Floats(field);
            for (size_t i = 0; i < a.size(); ++i)
                ASSERT_NEAR(a[i], b[i], 1e-4f * std::max(1.f, std::abs(b[i]))) << field << " " << i;
        }
    }
}

// Tabulation error (deterministic): the lobe's relative L1 error was 1.6 % at normal incidence
// to 3.1 % at cos 0.25, the albedo 0.7 % to 1.1 % higher than the model's
TEST(MeasuredBxDF, MatchesAnalyticConductorIsotropic) {
    Models m = Make(test::KilnTestConductor());
    BxDF measured = MeasuredBxDF(&m.data, NodeWavelengths());
    for (Float c : {1.f, 0.8f, 0.5f, 0.25f})
        for (Float phi : {0.3f, -2.5f}) {
            Vector3f wo = Dir(c, phi);
            Lobe lobe = CompareLobe(measured, m.analytic, wo);
            EXPECT_LT(lobe.l1Error / lobe.reference, 0.05) << c;
            SampledSpectrum a = SampledAlbedo(measured, wo), r = SampledAlbedo(m.analytic, wo);
            for (int l = 0; l < NSpectrumSamples; ++l) EXPECT_NEAR(a[l], r[l], 0.02f * r[l]) << c;
        }
}

// Anisotropic (alpha 0.2 x 0.5, 9 azimuths x 6 elevations of wo): lobe L1 error 5 % to 11 %,
// albedo within 5.1 % (largest at cos 0.25 along the smoother axis)
TEST(MeasuredBxDF, MatchesAnalyticConductorAnisotropic) {
    RGLConductor spec;
    spec.alphaX = 0.2f, spec.alphaY = 0.5f, spec.nPhi = 9, spec.nTheta = 6;
    Models m = Make(spec);
    BxDF measured = MeasuredBxDF(&m.data, NodeWavelengths());
    EXPECT_FALSE(m.data.isotropic);
    for (Float c : {1.f, 0.8f, 0.5f, 0.25f})
        for (Float phi : {0.f, 0.9f, 2.f, -2.4f}) {
            Vector3f wo = Dir(c, phi);
            Lobe lobe = CompareLobe(measured, m.analytic, wo);
            EXPECT_LT(lobe.l1Error / lobe.reference, 0.15) << c << " " << phi;
            SampledSpectrum a = SampledAlbedo(measured, wo), r = SampledAlbedo(m.analytic, wo);
            for (int l = 0; l < NSpectrumSamples; ++l)
                EXPECT_NEAR(a[l], r[l], 0.07f * r[l]) << c << " " << phi;
        }
    // The lobe follows the azimuth: normals tilted along y (alpha 0.5) are more frequent than
    // along x (0.2), as in the model
    Vector3f wo = Dir(0.99f, 0.4f);
    for (const BxDF* b : {&measured, &m.analytic})
        EXPECT_GT(b->f(wo, Reflect(wo, Dir(0.99f, Pi / 2)), TransportMode::Radiance)[1],
                  1.3f * b->f(wo, Reflect(wo, Dir(0.99f, 0)), TransportMode::Radiance)[1]);
}

// Sample_f returns f() and PDF() of the direction it draws; the BxDF mirrors through the
// surface, is nearly reciprocal (to tabulation error) and reflects less than it receives
TEST(MeasuredBxDF, SamplingConsistencyReciprocityEnergy) {
    RGLConductor spec;
    spec.alphaX = 0.3f, spec.alphaY = 0.45f, spec.nPhi = 5, spec.nTheta = 5;
    for (const RGLConductor& model : {test::KilnTestConductor(), spec}) {
        Models m = Make(model);
        BxDF b = MeasuredBxDF(&m.data, NodeWavelengths());
        double asym = 0, total = 0;
        for (Float c : {0.95f, 0.6f, 0.3f, 0.05f}) {
            Vector3f wo = Dir(c, 1.1f);
            for (int i = 0; i < 64; ++i) {
                Point2f u((i % 8 + 0.37f) / 8, (i / 8 + 0.61f) / 8);
                auto bs = b.Sample_f(wo, 0.5f, u);
                if (!bs) continue;
                EXPECT_GT(bs->wi.z, 0);
                EXPECT_NEAR(bs->pdf, b.PDF(wo, bs->wi, TransportMode::Radiance), 2e-3f * bs->pdf);
                SampledSpectrum f = b.f(wo, bs->wi, TransportMode::Radiance);
                for (int l = 0; l < NSpectrumSamples; ++l)
                    EXPECT_NEAR(bs->f[l], f[l], 2e-3f * f[l] + 1e-6f);
                // Mirrored through the surface
                auto below = b.Sample_f(-wo, 0.5f, u);
                ASSERT_TRUE(below);
                EXPECT_NEAR(below->wi.z, -bs->wi.z, 1e-5f);
                SampledSpectrum back = b.f(bs->wi, wo, TransportMode::Radiance);
                // (the tables end at 85 degrees: reciprocity is checked above 72)
                if (c >= 0.3f) {
                    asym += std::abs(back[0] - f[0]) * bs->wi.z / bs->pdf;
                    total += f[0] * bs->wi.z / bs->pdf;
                }
            }
            SampledSpectrum albedo = SampledAlbedo(b, wo);
            for (int l = 0; l < NSpectrumSamples; ++l) EXPECT_LT(albedo[l], 1);
            EXPECT_EQ(b.f(wo, Dir(-0.5f, 0), TransportMode::Radiance)[0], 0);
            EXPECT_EQ(b.PDF(wo, Dir(-0.5f, 0), TransportMode::Radiance), 0);
            EXPECT_FALSE(b.Sample_f(wo, 0.5f, Point2f(0.5f, 0.5f), TransportMode::Radiance,
                                    BxDFReflTransFlags::Transmission));
        }
        // Measured: 2 % (isotropic), 7 % (anisotropic, 5 azimuths)
        EXPECT_LT(asym / total, 0.15);
    }
}

// pbrt-v4 takes files with two azimuths as isotropic too: the same BRDF as with one
TEST(MeasuredBxDF, TwoAzimuthsAreIsotropic) {
    RGLConductor two = test::KilnTestConductor();
    two.nPhi = 2;
    Models a = Make(test::KilnTestConductor()), b = Make(two);
    EXPECT_TRUE(b.data.isotropic);
    BxDF fa = MeasuredBxDF(&a.data, NodeWavelengths()),
         fb = MeasuredBxDF(&b.data, NodeWavelengths());
    for (Float phi : {-3.f, -1.f, 0.5f, 2.5f}) {
        Vector3f wo = Dir(0.6f, phi), wi = Dir(0.7f, phi + 2.8f);
        SampledSpectrum x = fa.f(wo, wi, TransportMode::Radiance);
        SampledSpectrum y = fb.f(wo, wi, TransportMode::Radiance);
        for (int l = 0; l < NSpectrumSamples; ++l) EXPECT_NEAR(x[l], y[l], 1e-3f * x[l]) << phi;
        EXPECT_NEAR(fa.PDF(wo, wi, TransportMode::Radiance),
                    fb.PDF(wo, wi, TransportMode::Radiance),
                    1e-3f * fa.PDF(wo, wi, TransportMode::Radiance));
    }
}

// Outside the file's wavelengths the values are those at its ends
TEST(MeasuredBxDF, WavelengthsOutsideTheFileTakeItsEnds) {
    Models m = Make(test::KilnTestConductor());
    BxDF nodes = MeasuredBxDF(&m.data, NodeWavelengths());
    BxDF outside = MeasuredBxDF(&m.data, SampledWavelengths::SampleUniform(0.125f, 0, 1600));
    // 200, 600, 1000, 1400 nm
    Vector3f wo = Dir(0.7f, 0.2f), wi = Dir(0.8f, 3.f);
    SampledSpectrum a = nodes.f(wo, wi, TransportMode::Radiance);
    SampledSpectrum b = outside.f(wo, wi, TransportMode::Radiance);
    EXPECT_FLOAT_EQ(b[0], a[0]);
    EXPECT_FLOAT_EQ(b[1], a[2]);
    EXPECT_FLOAT_EQ(b[2], a[3]);
    EXPECT_FLOAT_EQ(b[3], a[3]);
}
