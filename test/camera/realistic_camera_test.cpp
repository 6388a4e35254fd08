// The realistic camera: lens file reading, tracing through a thick singlet against the
// lensmaker's equation, thick-lens focusing (rays from one film point meet at one scene point
// at "focusdistance"), exit pupil bounds that hold every ray that passes, the weight's
// normalisation, aperture masks and creation from scene parameters.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "base/rng.h"
#include "core/camera/aperture_mask.h"
#include "core/camera/camera.h"
#include "core/camera/lens_system.h"
#include "core/parser/parameter_dictionary.h"

namespace kiln {
namespace {

// A biconvex singlet of crown glass: radii +50 and -50 mm, 5 mm thick, n 1.5, 20 mm across,
// behind a stop 5 mm in front of it (mm, pbrt-v4 lens-file rows, front to rear).
constexpr const char* kSinglet =
    "# radius thickness eta aperture (mm)\n"
    "0      5   1   10\n"
    "50     5   1.5 20\n"
    "-50    40  1   20\n";
// Lensmaker's equation for it: 1/f = (n - 1) (1/R1 - 1/R2 + (n - 1) d / (n R1 R2)), and the
// back focal distance f (1 - (n - 1) d / (n R1)), mm.
constexpr double kN = 1.5, kR1 = 50, kR2 = -50, kD = 5;
const double kFocal = 1 / ((kN - 1) * (1 / kR1 - 1 / kR2 + (kN - 1) * kD / (kN * kR1 * kR2)));
const double kBackFocal = kFocal * (1 - (kN - 1) * kD / (kN * kR1));

// The double-Gauss 50 mm f/2 of H. Tronnier's US patent 2,673,491, as tabulated in W. J. Smith,
// Modern Lens Design (1992), p. 312, scaled from 100 mm to 50 mm focal length.
constexpr const char* kDoubleGauss =
    "29.475  3.76  1.67  25.2\n"
    "84.83   0.12  1     25.2\n"
    "19.275  4.025 1.67  23\n"
    "40.77   3.275 1.699 23\n"
    "12.75   5.705 1     18\n"
    "0       4.5   0     17.1\n"
    "-14.495 1.18  1.603 17\n"
    "40.77   6.065 1.658 20\n"
    "-20.385 0.19  1     20\n"
    "437.065 3.22  1.717 20\n"
    "-39.73  0     1     20\n";

LensSystem Lens(const char* text, Float stopMm) {
    std::string error;
    auto interfaces = ParseLensFile(text, "lens", stopMm, nullptr, &error);
    EXPECT_TRUE(interfaces.has_value()) << error;
    return LensSystem(interfaces ? *interfaces : std::vector<LensInterface>{}, Image());
}

TEST(LensFile, ParsesRowsInMetresAndSetsTheStop) {
    bool clamped = true;
    std::string error;
    auto l = ParseLensFile(kSinglet, "singlet.dat", 4, &clamped, &error);
    ASSERT_TRUE(l.has_value()) << error;
    ASSERT_EQ(l->size(), 3u);
    EXPECT_FALSE(clamped);
    EXPECT_FLOAT_EQ((*l)[0].apertureRadius, 0.002f);  // the stop: aperturediameter 4 mm
    EXPECT_FLOAT_EQ((*l)[1].curvatureRadius, 0.05f);
    EXPECT_FLOAT_EQ((*l)[1].apertureRadius, 0.01f);
    EXPECT_FLOAT_EQ((*l)[2].thickness, 0.04f);
    // A stop wider than the file's is clamped to it
    l = ParseLensFile(kSinglet, "singlet.dat", 30, &clamped, &error);
    ASSERT_TRUE(l.has_value());
    EXPECT_TRUE(clamped);
    EXPECT_FLOAT_EQ((*l)[0].apertureRadius, 0.005f);
    // Bad files: a count not a multiple of four, a word, nothing
    EXPECT_FALSE(ParseLensFile("1 2 3 4 5", "a.dat", 1, nullptr, &error));
    EXPECT_NE(error.find("four values"), std::string::npos) << error;
    EXPECT_FALSE(ParseLensFile("1 2 3\nx 4", "b.dat", 1, nullptr, &error));
    EXPECT_NE(error.find("line 2"), std::string::npos) << error;
    EXPECT_FALSE(ParseLensFile("# nothing\n", "c.dat", 1, nullptr, &error));
    EXPECT_FALSE(ParseLensFile("10 1 1.5 -3", "d.dat", 1, nullptr, &error));
    std::string many;
    for (size_t i = 0; i <= kMaxLensInterfaces; ++i) many += "0 1 1 10\n";
    EXPECT_FALSE(ParseLensFile(many, "e.dat", 1, nullptr, &error));
    EXPECT_NE(error.find("more than"), std::string::npos) << error;
}

TEST(LensSystem, SingletMatchesTheLensmakersEquation) {
    LensSystem lens = Lens(kSinglet, 10);
    auto c = lens.ThickLensApproximation(3.5e-5f);
    ASSERT_TRUE(c.has_value());
    // Film side: focal length from the principal plane, focal point from the rear vertex
    double f = (*c)[0].principalZ - (*c)[0].focalZ;
    EXPECT_NEAR(f * 1000, kFocal, 1e-3 * kFocal);
    double bfd = lens.RearZ() - (*c)[0].focalZ;
    EXPECT_NEAR(bfd * 1000, kBackFocal, 1e-3 * kFocal);
    // Scene side: symmetric lens, same focal length
    double f1 = (*c)[1].focalZ - (*c)[1].principalZ;
    EXPECT_NEAR(f1 * 1000, kFocal, 1e-3 * kFocal);
    // A ray parallel to the axis crosses it at the focal point (paraxial heights)
    Ray in(Point3f(1e-4f, 0, 1), Vector3f(0, 0, -1));
    Ray out;
    ASSERT_TRUE(lens.TraceFromScene(in, &out));
    Float tAxis = -out.o.x / out.d.x;
    EXPECT_NEAR(out(tAxis).z, (*c)[0].focalZ, 1e-3 * kFocal / 1000);
}

// The point that minimises the summed squared distance to the rays (unit directions).
Point3f NearestPoint(const std::vector<Ray>& rays, double* rms) {
    // In double throughout: the rays are nearly parallel, so 1 - d_z^2 must not cancel
    double A[3][3] = {}, b[3] = {};
    for (const Ray& r : rays) {
        double d[3] = {r.d.x, r.d.y, r.d.z};
        double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        for (double& c : d) c /= len;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                double m = (i == j) - d[i] * d[j];
                A[i][j] += m;
                b[i] += m * r.o[j];
            }
    }
    // Cramer's rule
    auto det3 = [](double m[3][3]) {
        return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
               m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
               m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    };
    double det = det3(A), x[3];
    for (int k = 0; k < 3; ++k) {
        double M[3][3];
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) M[i][j] = j == k ? b[i] : A[i][j];
        x[k] = det3(M) / det;
    }
    Point3f p{Float(x[0]), Float(x[1]), Float(x[2])};
    double sum = 0;
    for (const Ray& r : rays) {
        double d[3] = {r.d.x, r.d.y, r.d.z}, v[3] = {x[0] - r.o.x, x[1] - r.o.y, x[2] - r.o.z};
        double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]), vd = 0, v2 = 0;
        for (int k = 0; k < 3; ++k) {
            d[k] /= len;
            vd += v[k] * d[k];
            v2 += v[k] * v[k];
        }
        sum += std::max(0.0, v2 - vd * vd);
    }
    *rms = std::sqrt(sum / rays.size());
    return p;
}

// The rms distance of the rays' crossings of the plane z = const from their centroid.
double SpreadOnPlane(const std::vector<Ray>& rays, double z) {
    std::vector<std::pair<double, double>> pts;
    double cx = 0, cy = 0;
    for (const Ray& r : rays) {
        double t = (z - r.o.z) / r.d.z;
        pts.emplace_back(r.o.x + t * r.d.x, r.o.y + t * r.d.y);
        cx += pts.back().first / rays.size();
        cy += pts.back().second / rays.size();
    }
    double sum = 0;
    for (auto [x, y] : pts) sum += Sqr(x - cx) + Sqr(y - cy);
    return std::sqrt(sum / rays.size());
}

// Rays from one film point through a small stop (so that spherical aberration stays well
// below the tolerance) meet at one point on the plane at focusdistance: the point nearest all
// rays lies there, the rays pass it far closer than the stop's size, and for a film point off
// the axis it lies on the far side of the axis (the lens inverts). A singlet and the double
// Gauss.
TEST(LensSystem, FocusingImagesTheFocusPlaneOnTheFilm) {
    struct Case {
        const char* name;
        const char* text;
        std::vector<Float> heights;  // film points' distances from the axis, m
    };
    // The singlet on the axis only: its image field is curved (Petzval), so an off-axis film
    // point focuses closer than focusdistance; the double Gauss has a flat field
    for (const Case& cs :
         {Case{"singlet", kSinglet, {0}}, Case{"double Gauss", kDoubleGauss, {0, 0.002f, -0.001f}}})
        for (Float focus : {0.5f, 2.f, 10.f}) {
            const Float stopMm = 0.25f;
            LensSystem lens = Lens(cs.text, stopMm);
            std::optional<Float> rear = lens.FocusedRearThickness(focus, 3.5e-5f);
            ASSERT_TRUE(rear.has_value()) << cs.name;
            lens.SetRearThickness(*rear);
            for (Float h : cs.heights) {
                Point3f pFilm(h, 0, 0);
                // Rays through the pupil (its bounds, found as the camera finds them)
                PupilBounds b = lens.BoundExitPupil(std::abs(h), std::abs(h), 1 << 18);
                ASSERT_FALSE(b.IsDegenerate());
                std::vector<Ray> rays;
                RNG rng(3);
                while (rays.size() < 200) {
                    Point2f u = b.Lerp(Point2f(rng.UniformFloat(), rng.UniformFloat()));
                    Point3f pRear(h < 0 ? -u.x : u.x, u.y, lens.RearZ());
                    Ray out;
                    if (lens.TraceFromFilm(Ray(pFilm, pRear - pFilm), &out) > 0)
                        rays.push_back(out);
                }
                double rms;
                Point3f p = NearestPoint(rays, &rms);
                // On the axis the paraxial focus is exact: the rays meet at focusdistance
                if (h == 0) {
                    EXPECT_NEAR(p.z, focus, 0.01 * focus) << cs.name;
                }
                // Off the axis too the rays' spread is smallest there: on the planes at 0.8
                // and 1.25 times the distance it is over ten times larger (the spread grows
                // with the relative distance from where they meet; field curvature moves that
                // point by about 1 % at 10 m for the double Gauss 2 mm off the axis, 5 % 4 mm off)
                double atFocus = SpreadOnPlane(rays, focus);
                EXPECT_LT(atFocus, 0.1 * SpreadOnPlane(rays, 0.8 * focus))
                    << cs.name << " focus " << focus << " h " << h;
                EXPECT_LT(atFocus, 0.1 * SpreadOnPlane(rays, 1.25 * focus))
                    << cs.name << " focus " << focus << " h " << h;
                // The lens inverts: the point lies on the far side of the axis
                if (h != 0) {
                    EXPECT_LT(p.x * h, 0) << cs.name;
                }
            }
        }
    // Too close to focus: no solution
    LensSystem lens = Lens(kSinglet, 2);
    EXPECT_FALSE(lens.FocusedRearThickness(0.1f, 3.5e-5f).has_value());
}

// Every ray that passes the lens starts through its film segment's exit pupil bounds.
TEST(LensSystem, ExitPupilBoundsHoldEveryPassingRay) {
    LensSystem lens = Lens(kDoubleGauss, 17);
    lens.SetRearThickness(*lens.FocusedRearThickness(5, 3.5e-5f));
    const Float diagonal = 0.035f;
    RNG rng(11);
    int passed = 0;
    for (int ring : {0, 20, 40, 63}) {
        Float x0 = ring / 64.f * diagonal / 2, x1 = (ring + 1) / 64.f * diagonal / 2;
        PupilBounds b = lens.BoundExitPupil(x0, x1, 1 << 16);
        ASSERT_FALSE(b.IsDegenerate()) << ring;
        Float rr = lens.RearRadius();
        for (int i = 0; i < 40000; ++i) {
            Point3f pFilm(Lerp(rng.UniformFloat(), x0, x1), 0, 0);
            Point2f p((3 * rng.UniformFloat() - 1.5f) * rr, (3 * rng.UniformFloat() - 1.5f) * rr);
            if (lens.TraceFromFilm(Ray(pFilm, Point3f(p.x, p.y, lens.RearZ()) - pFilm), nullptr) >
                0) {
                ++passed;
                ASSERT_TRUE(b.Inside(p)) << "ring " << ring << " point " << p.x << " " << p.y;
            }
        }
    }
    EXPECT_GT(passed, 10000);
}

std::string WriteTempFile(const std::string& name, const std::string& text) {
    std::string path = (std::filesystem::temp_directory_path() /
                        ("kiln_realistic_" + std::to_string(::getpid()) + "_" + name))
                           .string();
    std::ofstream(path) << text;
    return path;
}

ParsedParameter Param(const std::string& type, const std::string& name, std::vector<Float> floats,
                      std::vector<std::string> strings = {}) {
    ParsedParameter p;
    p.type = type;
    p.name = name;
    p.floats = std::move(floats);
    p.strings = std::move(strings);
    return p;
}

Camera MakeRealistic(ObjectArena& arena, Diagnostics& diag, ParsedParameterVector params,
                     Point2i res = Point2i(24, 16)) {
    ParameterDictionary dict(std::move(params), nullptr);
    return Camera::Create("realistic", dict, CameraTransform(), res, 0.035f, FileLoc(), arena,
                          diag);
}

// The weight is an unbiased estimate of the integral of mask * cos^4 / d^2 over the rear
// plane's passing points, whatever the pupil bounds: its mean over lens samples matches that
// integral on a fine grid, with a circular stop and with a pentagonal mask at a film point off
// the x axis (where pbrt-v4's bounds, found along +x and rotated, would miss part of the
// pentagon's pupil).
TEST(RealisticCamera, WeightEstimatesThePupilIntegral) {
    std::string singlet = WriteTempFile("singlet.dat", kSinglet);
    std::string dgauss = WriteTempFile("dgauss.dat", kDoubleGauss);
    for (const char* aperture : {"", "pentagon"}) {
        ObjectArena arena;
        Diagnostics diag(nullptr);
        // The singlet at f/8.5; the double Gauss at f/5 with the pentagon
        bool masked = *aperture;
        ParsedParameterVector params = {
            Param("string", "lensfile", {}, {masked ? dgauss : singlet}),
            Param("float", "aperturediameter", {masked ? 10.f : 6.f}),
            Param("float", "focusdistance", {masked ? 1.f : 2.f})};
        if (masked) params.push_back(Param("string", "aperture", {}, {aperture}));
        Camera cam = MakeRealistic(arena, diag, params);
        ASSERT_TRUE(cam.Is<RealisticCamera>());
        const RealisticCamera& rc = *cam.GetIf<RealisticCamera>();
        SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
        for (Point2f pRaster : {Point2f(12, 8), Point2f(2.5f, 14.5f), Point2f(4.5f, 0.5f)}) {
            // Monte Carlo over the lens samples (stratified)
            const int n = 256;
            double sum = 0;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) {
                    CameraSample s;
                    s.pFilm = pRaster;
                    s.pLens = Point2f((i + 0.5f) / n, (j + 0.5f) / n);
                    std::optional<CameraRay> r = cam.GenerateRay(s, lambda);
                    sum += r ? r->weight[0] : 0;
                }
            double mean = sum / (n * n);
            // The integral on a grid over the whole rear square
            Point3f pFilm = rc.FilmPoint(pRaster);
            const LensSystem& lens = rc.Lens();
            const int g = 400;
            Float rr = lens.RearRadius(), cell = 3 * rr / g, d = lens.RearZ();
            double integral = 0;
            for (int i = 0; i < g; ++i)
                for (int j = 0; j < g; ++j) {
                    Point3f pRear(-1.5f * rr + (i + 0.5f) * cell, -1.5f * rr + (j + 0.5f) * cell,
                                  d);
                    Vector3f w = pRear - pFilm;
                    integral += lens.TraceFromFilm(Ray(pFilm, w), nullptr) *
                                Sqr(Sqr(Normalize(w).z)) / Sqr(d) * Sqr(cell);
                }
            EXPECT_GT(integral, 0);
            EXPECT_NEAR(mean, integral, 0.005 * integral)
                << aperture << " " << pRaster.x << " " << pRaster.y;
            // An f/8.5 lens passes about pi / (4 N^2) of the radiance on the axis
            if (pRaster.x == 12 && !masked) {
                EXPECT_NEAR(mean, Pi / (4 * Sqr(kFocal / 6)), 0.1 * mean);
            }
        }
    }
    std::remove(singlet.c_str());
    std::remove(dgauss.c_str());
}

TEST(RealisticCamera, ImageIsUprightAndRaysLeaveTheLens) {
    std::string file = WriteTempFile("dg.dat", kDoubleGauss);
    ObjectArena arena;
    Diagnostics diag(nullptr);
    Camera cam = MakeRealistic(
        arena, diag,
        {Param("string", "lensfile", {}, {file}), Param("float", "aperturediameter", {4})});
    std::remove(file.c_str());
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    CameraSample s;
    s.pLens = Point2f(0.5f, 0.5f);
    // Pixel (2, 2) is at the image's top left: its ray goes up and left (camera -x, +y)
    s.pFilm = Point2f(2, 2);
    std::optional<CameraRay> r = cam.GenerateRay(s, lambda);
    ASSERT_TRUE(r.has_value());
    EXPECT_LT(r->ray.d.x, 0);
    EXPECT_GT(r->ray.d.y, 0);
    EXPECT_GT(r->ray.d.z, 0.9f);
    EXPECT_NEAR(Length(r->ray.d), 1, 1e-5);
    EXPECT_GT(r->ray.o.z, cam.GetIf<RealisticCamera>()->Lens().RearZ());
    // Footprints exist (minimum differentials found)
    Vector3f dpdx, dpdy;
    cam.Approximate_dp_dxy(Point3f(0, 0, 10), Normal3f(0, 0, -1), 0, 1, &dpdx, &dpdy);
    EXPECT_GT(Length(dpdx), 0);
    EXPECT_GT(Length(dpdy), 0);
}

TEST(RealisticCamera, CreationErrorsAndWarnings) {
    std::string file = WriteTempFile("s.dat", kSinglet);
    ObjectArena arena;
    Diagnostics diag(nullptr);
    // Missing lens file, unreadable lens file, bad values
    EXPECT_THROW(MakeRealistic(arena, diag, {}), SceneError);
    EXPECT_THROW(MakeRealistic(arena, diag, {Param("string", "lensfile", {}, {file + ".none"})}),
                 SceneError);
    EXPECT_THROW(MakeRealistic(arena, diag,
                               {Param("string", "lensfile", {}, {file}),
                                Param("float", "focusdistance", {-1})}),
                 SceneError);
    EXPECT_THROW(MakeRealistic(arena, diag,
                               {Param("string", "lensfile", {}, {file}),
                                Param("float", "focusdistance", {0.05f})}),
                 SceneError);  // closer than the lens can focus
    EXPECT_THROW(MakeRealistic(arena, diag,
                               {Param("string", "lensfile", {}, {file}),
                                Param("string", "aperture", {}, {"hexagon-not-a-file.png"})}),
                 SceneError);
    // A stop wider than the lens's: a warning, clamped
    EXPECT_EQ(diag.WarningCount(), 0);
    MakeRealistic(
        arena, diag,
        {Param("string", "lensfile", {}, {file}), Param("float", "aperturediameter", {50})});
    EXPECT_EQ(diag.WarningCount(), 1);
    std::remove(file.c_str());
}

// An aperture image file (resolved like other file parameters): its RGB mean is the mask. A
// mask open only in its left half (image x < w/2) passes the rays through the stop's -x half,
// and the camera's mean weight equals the circular stop's (the mask is normalised to it).
TEST(RealisticCamera, ApertureImageFile) {
    std::string lensFile = WriteTempFile("s2.dat", kSinglet);
    std::string imageFile = WriteTempFile("half.exr", "");
    Image half(PixelFormat::Float, Point2i(16, 16), {"R", "G", "B"});
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 8; ++x)
            for (int c = 0; c < 3; ++c) half.SetChannel({x, y}, c, 1);
    half.Write(imageFile);
    SampledWavelengths lambda = SampledWavelengths::SampleVisible(0.5f);
    double mean[2];
    for (int masked = 0; masked < 2; ++masked) {
        ObjectArena arena;
        Diagnostics diag(nullptr);
        ParsedParameterVector params = {Param("string", "lensfile", {}, {lensFile}),
                                        Param("float", "aperturediameter", {6})};
        if (masked) params.push_back(Param("string", "aperture", {}, {imageFile}));
        Camera cam = MakeRealistic(arena, diag, params);
        const LensSystem& lens = cam.GetIf<RealisticCamera>()->Lens();
        double sum = 0;
        const int n = 128;
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                CameraSample s;
                s.pFilm = Point2f(12, 8);
                s.pLens = Point2f((i + 0.5f) / n, (j + 0.5f) / n);
                std::optional<CameraRay> r = cam.GenerateRay(s, lambda);
                if (!r) continue;
                sum += r->weight[0];
                // The singlet's stop is its front interface, where the ray leaves the lens:
                // on the mask's open side, or within half a texel of it (bilinear filtering:
                // 3 mm / 16); the stop reaches to +3 mm
                if (masked) {
                    EXPECT_LT(r->ray.o.x, 0.0002f);
                }
            }
        mean[masked] = sum / (n * n);
        EXPECT_GT(lens.FrontZ(), 0);
    }
    EXPECT_NEAR(mean[1], mean[0], 0.02 * mean[0]);
    std::remove(lensFile.c_str());
    std::remove(imageFile.c_str());
}

// Each built-in stop shape passes as much light as the circular stop it replaces (pbrt-v4's
// normalisation), and the shapes differ where they should.
TEST(ApertureMask, BuiltinShapesAreNormalisedToTheCircle) {
    for (const char* name : {"gaussian", "square", "pentagon", "star"}) {
        std::optional<Image> m = BuiltinApertureMask(name);
        ASSERT_TRUE(m.has_value()) << name;
        ASSERT_TRUE(NormalizeApertureMask(&*m));
        EXPECT_NEAR(m->Average(0), PiOver4, 1e-4) << name;
        // Open at the centre, closed at the corners
        EXPECT_GT(m->BilerpChannel(Point2f(0.5f, 0.5f), 0), 0) << name;
        EXPECT_EQ(m->BilerpChannel(Point2f(0.01f, 0.01f), 0), 0) << name;
    }
    EXPECT_FALSE(BuiltinApertureMask("hexagon").has_value());
    // The pentagon's vertex is on +y before the flip, so after it on -y: open at (0.5, 0.12)
    // (lens y = -0.76) and closed at (0.5, 0.88)
    std::optional<Image> p = BuiltinApertureMask("pentagon");
    NormalizeApertureMask(&*p);
    EXPECT_GT(p->BilerpChannel(Point2f(0.5f, 0.12f), 0), 0);
    EXPECT_EQ(p->BilerpChannel(Point2f(0.5f, 0.88f), 0), 0);
}

}  // namespace
}  // namespace kiln
