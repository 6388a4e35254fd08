// The gbuffer film in renders (pbrt-v4's GBufferFilm): a tilted plane whose channels are known
// in closed form, and pbrt-v4's gbuffer EXRs of a small scene (test/regression/pbrt_features).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "render_test_util.h"

namespace kiln {
namespace {

using testing::RenderFile;
using testing::RenderText;

// The plane z = z0 + a x + b y of camera space, seen from a camera at (1, 2, -3) looking along
// +z (camera space = world space moved by -(1, 2, -3)), a quad with corners at x, y = +-4 and
// (u, v) = ((x + 4) / 8, (y + 4) / 8), a constant shading normal; pixel centres only.
constexpr double z0 = 5, a = 0.3, b = -0.2, fovDegrees = 40;
constexpr int res = 16;
const double kNs[3] = {0, 0.6, -0.8};

std::string PlaneScene(const std::string& space) {
    std::ostringstream s;
    s << "Option \"bool disablepixeljitter\" true\n"
      << "LookAt 1 2 -3  1 2 0  0 1 0\n"
      << "Camera \"perspective\" \"float fov\" " << fovDegrees << "\n"
      << "Film \"gbuffer\" \"integer xresolution\" " << res << " \"integer yresolution\" " << res
      << " \"string coordinatesystem\" \"" << space << "\"\n"
      << "Sampler \"independent\" \"integer pixelsamples\" 4\n"
      << "WorldBegin\n"
      << "Material \"diffuse\" \"rgb reflectance\" [0.5 0.5 0.5]\n"
      << "Shape \"trianglemesh\" \"point3 P\" [";
    for (auto [x, y] : {std::pair{-4, -4}, {4, -4}, {4, 4}, {-4, 4}})
        s << x + 1 << " " << y + 2 << " " << z0 + a * x + b * y - 3 << "  ";
    s << "] \"point2 uv\" [0 0  1 0  1 1  0 1] \"normal N\" [";
    for (int i = 0; i < 4; ++i) s << kNs[0] << " " << kNs[1] << " " << kNs[2] << "  ";
    s << "] \"integer indices\" [0 1 2  0 2 3]\n";
    return s.str();
}

// Camera-space hit of the ray through raster point (x, y) (pbrt-v4's perspective camera: screen
// [-1, 1]^2 for a square film, y up).
std::array<double, 3> PlaneHit(double x, double y) {
    double T = std::tan(fovDegrees / 2 * Pi / 180);
    double sx = (-1 + 2 * x / res) * T, sy = (1 - 2 * y / res) * T;
    double t = z0 / (1 - a * sx - b * sy);
    return {t * sx, t * sy, t};
}

double Channel(const Image& im, Point2i p, const std::string& name) {
    int c = im.ChannelIndex(name);
    EXPECT_GE(c, 0) << name;
    return c < 0 ? 0 : im.GetChannel(p, c);
}

TEST(GBufferRender, TiltedPlaneMatchesClosedForm) {
    const double offset[3] = {1, 2, -3};  // world = camera + offset
    double len = std::sqrt(1 + a * a + b * b);
    const double n[3] = {a / len, b / len, -1 / len};  // towards the camera
    for (const std::string space : {"camera", "world"}) {
        Image im = RenderText(PlaneScene(space)).scene->job->film->GetImage(nullptr);
        const bool world = space == "world";
        for (int y = 0; y < res; ++y)
            for (int x = 0; x < res; ++x) {
                Point2i px(x, y);
                std::array<double, 3> p = PlaneHit(x + 0.5, y + 0.5);
                std::array<double, 3> px1 = PlaneHit(x + 1.5, y + 0.5);
                std::array<double, 3> py1 = PlaneHit(x + 0.5, y + 1.5);
                const char* axes[3] = {"X", "Y", "Z"};
                for (int k = 0; k < 3; ++k) {
                    double want = p[k] + (world ? offset[k] : 0);
                    EXPECT_NEAR(Channel(im, px, std::string("P.") + axes[k]), want, 1e-4 * z0)
                        << space << " " << x << "," << y;
                    EXPECT_NEAR(Channel(im, px, std::string("N.") + axes[k]), n[k], 1e-4);
                    EXPECT_NEAR(Channel(im, px, std::string("Ns.") + axes[k]), kNs[k], 1e-4);
                }
                // One pixel's change of depth (no jitter: differentials not scaled)
                EXPECT_NEAR(Channel(im, px, "dzdx"), std::abs(px1[2] - p[2]), 1e-4)
                    << x << "," << y;
                EXPECT_NEAR(Channel(im, px, "dzdy"), std::abs(py1[2] - p[2]), 1e-4)
                    << x << "," << y;
                EXPECT_NEAR(Channel(im, px, "u"), (p[0] + 4) / 8, 1e-5);
                EXPECT_NEAR(Channel(im, px, "v"), (p[1] + 4) / 8, 1e-5);
                EXPECT_NEAR(Channel(im, px, "Albedo.G"), 0.5, 0.03);
                // No light: every sample is black
                EXPECT_EQ(Channel(im, px, "Variance.G"), 0);
            }
    }
}

// Differences of kiln's gbuffer channels from pbrt-v4's (references rendered by pbrt-v4 at 256
// spp, pbrt_features/README.md): the same channel names; geometric channels equal within
// half-float precision except where a silhouette or the horizon cuts the pixel (a mixture
// that depends on the samples); the variance channels' image means equal within their
// sampling noise.
void CompareWithPbrt(const std::string& name) {
    const std::string dir = std::string(KILN_SOURCE_DIR) + "/test/regression/pbrt_features/";
    RenderOptions options;
    options.samplesPerPixel = 64;
    Image ours = RenderFile(dir + name + ".pbrt", options).scene->job->film->GetImage(nullptr);
    Image ref = Image::Read(dir + "references/" + name + ".exr");
    std::vector<std::string> a = ours.ChannelNames(), b = ref.ChannelNames();
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    ASSERT_EQ(a, b);
    ASSERT_EQ(ours.Resolution(), ref.Resolution());
    const int nPixels = ours.Resolution().x * ours.Resolution().y;
    for (const char* ch : {"P.X", "P.Y", "P.Z", "N.X", "N.Y", "N.Z", "Ns.X", "Ns.Y", "Ns.Z", "u",
                           "v", "dzdx", "dzdy", "Albedo.R", "Albedo.G", "Albedo.B"}) {
        int off = 0;
        double worst = 0;
        for (int y = 0; y < ours.Resolution().y; ++y)
            for (int x = 0; x < ours.Resolution().x; ++x) {
                double k = Channel(ours, {x, y}, ch), r = Channel(ref, {x, y}, ch);
                double tol = 0.01 * (1 + std::abs(r));
                if (std::abs(k - r) > tol)
                    ++off;
                else
                    worst = std::max(worst, std::abs(k - r));
            }
        EXPECT_LE(off, nPixels / 8) << name << " " << ch;
    }
    for (const char* ch : {"Variance.R", "Variance.G", "Variance.B", "RelativeVariance.R",
                           "RelativeVariance.G", "RelativeVariance.B"}) {
        double k = 0, r = 0;
        for (int y = 0; y < ours.Resolution().y; ++y)
            for (int x = 0; x < ours.Resolution().x; ++x) {
                k += Channel(ours, {x, y}, ch);
                r += Channel(ref, {x, y}, ch);
            }
        EXPECT_GT(r, 0) << ch;
        EXPECT_NEAR(k / r, 1, 0.15) << name << " " << ch;
    }
}

TEST(GBufferRender, MatchesPbrtV4CameraSpace) { CompareWithPbrt("gbuffer"); }
TEST(GBufferRender, MatchesPbrtV4WorldSpace) { CompareWithPbrt("gbuffer-world"); }

}  // namespace
}  // namespace kiln
