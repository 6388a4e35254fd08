// kiln_rgb2spec_gen: builds the RGB-to-spectrum coefficient tables at build time.
//
// For every RGB of a 3 x 64^3 grid (pbrt-v4's layout; see rgb_to_spectrum.h) it finds the
// sigmoid polynomial s(l) = S(A l'^2 + B l' + C), l' = (l - 360 nm) / 470 nm, whose colour
// matches the RGB, as Jakob & Hanika (2019) do: Levenberg-Marquardt (damped Gauss-Newton) on
// the CIELAB difference, with the spectrum's XYZ taken against the CIE 1931 observer under the
// colour space's illuminant (1 nm sums over 360-830 nm, the same sums kiln's SpectrumToXYZ
// uses), each solve warm-started from its neighbour along z. Coefficients are stored for
// lambda in nm (pbrt-v4's convention). Output, in OUTPUT_DIR: per colour space a C++ file
// rgb2spec_kiln_rgb2spec_<space>.cpp holding the table's bytes (64 z nodes, then the
// coefficients, as native floats), and rgb2spec_tables.cpp defining RGBToSpectrumTableData.
//
// Usage: kiln_rgb2spec_gen OUTPUT_DIR SPACE [SPACE...]   (SPACE: srgb, dci-p3, rec2020, ...)
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "spectral/cie.h"
#include "spectral/color_space_defs.h"
#include "spectral/named_spectra_data.h"

namespace kiln {
namespace {

constexpr int kRes = 64;
constexpr int kN = cie::kNumCMFSamples;  // 1 nm samples, 360-830 nm
constexpr double kLambdaMin = 360, kLambdaMax = 830;

using Vec3 = std::array<double, 3>;
using Mat3 = std::array<Vec3, 3>;

// Small linear algebra
Vec3 Mul(const Mat3& m, const Vec3& v) {
    Vec3 r{};
    for (int i = 0; i < 3; ++i) r[i] = m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2];
    return r;
}
bool Solve3(Mat3 a, Vec3 b, Vec3& x) {
    // Gaussian elimination with partial pivoting
    for (int c = 0; c < 3; ++c) {
        int p = c;
        for (int r = c + 1; r < 3; ++r)
            if (std::abs(a[r][c]) > std::abs(a[p][c])) p = r;
        if (std::abs(a[p][c]) < 1e-300) return false;
        std::swap(a[c], a[p]);
        std::swap(b[c], b[p]);
        for (int r = c + 1; r < 3; ++r) {
            double f = a[r][c] / a[c][c];
            for (int k = c; k < 3; ++k) a[r][k] -= f * a[c][k];
            b[r] -= f * b[c];
        }
    }
    for (int c = 2; c >= 0; --c) {
        double s = b[c];
        for (int k = c + 1; k < 3; ++k) s -= a[c][k] * x[k];
        x[c] = s / a[c][c];
    }
    return true;
}
Mat3 Inverse(const Mat3& m) {
    Mat3 r;
    for (int j = 0; j < 3; ++j) {
        Vec3 e{}, col{};
        e[j] = 1;
        Solve3(m, e, col);
        for (int i = 0; i < 3; ++i) r[i][j] = col[i];
    }
    return r;
}

// Illuminant of a colour space: its named table, linearly interpolated at 1 nm (its ends held
// constant, as pbrt-v4's FromInterleaved does). Scale is irrelevant here.
std::vector<double> Illuminant(std::string_view name) {
    for (const NamedSpectrumTable& t : PbrtNamedSpectrumTables()) {
        if (t.name != name) continue;
        const auto& d = t.interleaved;
        const size_t n = d.size() / 2;
        std::vector<double> v(kN);
        for (int i = 0; i < kN; ++i) {
            double l = kLambdaMin + i;
            if (l <= d[0]) {
                v[i] = d[1];
                continue;
            }
            if (l >= d[2 * (n - 1)]) {
                v[i] = d[2 * (n - 1) + 1];
                continue;
            }
            size_t k = 0;
            while (d[2 * (k + 1)] < l) ++k;
            double t0 = (l - d[2 * k]) / (d[2 * (k + 1)] - d[2 * k]);
            v[i] = (1 - t0) * d[2 * k + 1] + t0 * d[2 * (k + 1) + 1];
        }
        return v;
    }
    std::fprintf(stderr, "rgb2spec_gen: no illuminant %s\n", std::string(name).c_str());
    std::exit(1);
}

// XYZ = sum_i w[.][i] s(lambdaN[i]): a quadrature of the colour-matching integral.
struct Quadrature {
    std::array<std::vector<double>, 3> w;
    std::vector<double> lambdaN;  // normalised wavelength per node, [0, 1]
};

// The colorimetry of one colour space: XYZ weights, white, RGB -> XYZ.
struct Colorimetry {
    // fine: kiln's own 1 nm sums. coarse: nodes every 5 nm with weights that make the sum exact
    // for spectra linear between the nodes (the fine weights spread onto hat functions), used
    // for the bulk of the iterations, which the fine sums then polish (5x fewer evaluations).
    Quadrature fine, coarse;
    Vec3 white;
    Mat3 xyzFromRGB;

    explicit Colorimetry(const ColorSpaceDefinition& cs) {
        std::vector<double> illum = Illuminant(cs.illuminant);
        double norm = 0;
        for (int i = 0; i < kN; ++i) norm += cie::kY[i] * illum[i];
        const float* cmf[3] = {cie::kX, cie::kY, cie::kZ};
        constexpr int kStep = 5, kNc = (kN - 1) / kStep + 1;
        white = {0, 0, 0};
        fine.lambdaN.resize(kN);
        coarse.lambdaN.resize(kNc);
        for (int i = 0; i < kN; ++i) fine.lambdaN[i] = i / (kLambdaMax - kLambdaMin);
        for (int k = 0; k < kNc; ++k) coarse.lambdaN[k] = k * kStep / (kLambdaMax - kLambdaMin);
        for (int c = 0; c < 3; ++c) {
            fine.w[c].resize(kN);
            coarse.w[c].assign(kNc, 0.0);
            for (int i = 0; i < kN; ++i) {
                const double wi = cmf[c][i] * illum[i] / norm;
                fine.w[c][i] = wi;
                white[c] += wi;
                const int k = i / kStep, r = i % kStep;
                coarse.w[c][k] += wi * (kStep - r) / kStep;
                if (r != 0) coarse.w[c][k + 1] += wi * r / kStep;
            }
        }
        // Primaries at unit luminance, scaled to sum to the white (as RGBColorSpace does)
        auto fromxy = [](double x, double y) { return Vec3{x / y, 1, (1 - x - y) / y}; };
        Vec3 P[3] = {fromxy(cs.rx, cs.ry), fromxy(cs.gx, cs.gy), fromxy(cs.bx, cs.by)};
        Mat3 m;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) m[i][j] = P[j][i];
        Vec3 C = Mul(Inverse(m), white);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) xyzFromRGB[i][j] = m[i][j] * C[j];
    }

    // CIELAB of xyz relative to the white, and its derivative d Lab / d XYZ.
    Vec3 Lab(const Vec3& xyz, Mat3* dLab) const {
        constexpr double d = 6.0 / 29, d3 = d * d * d;
        double f[3], df[3];
        for (int c = 0; c < 3; ++c) {
            double t = xyz[c] / white[c];
            if (t > d3) {
                f[c] = std::cbrt(t);
                df[c] = 1 / (3 * f[c] * f[c]) / white[c];
            } else {
                f[c] = t / (3 * d * d) + 4.0 / 29;
                df[c] = 1 / (3 * d * d) / white[c];
            }
        }
        if (dLab) {
            *dLab = {{{0, 116 * df[1], 0},
                      {500 * df[0], -500 * df[1], 0},
                      {0, 200 * df[1], -200 * df[2]}}};
        }
        return {116 * f[1] - 16, 500 * (f[0] - f[1]), 200 * (f[1] - f[2])};
    }

    // XYZ of the sigmoid polynomial c (normalised wavelength) and d XYZ / d c.
    static Vec3 Spectrum(const Quadrature& q, const Vec3& c, Mat3* dXYZ) {
        Vec3 xyz{};
        Mat3 J{};
        const size_t n = q.lambdaN.size();
        for (size_t i = 0; i < n; ++i) {
            const double l = q.lambdaN[i];
            const double p = (c[0] * l + c[1]) * l + c[2];
            const double r = 1 / std::sqrt(1 + p * p);
            const double s = 0.5 + 0.5 * p * r, ds = 0.5 * r * r * r;
            const double g[3] = {ds * l * l, ds * l, ds};
            for (int k = 0; k < 3; ++k) {
                xyz[k] += q.w[k][i] * s;
                if (dXYZ)
                    for (int m = 0; m < 3; ++m) J[k][m] += q.w[k][i] * g[m];
            }
        }
        if (dXYZ) *dXYZ = J;
        return xyz;
    }
};

// Levenberg-Marquardt on the CIELAB residual with quadrature q, from c; returns the final
// residual norm (Lab units). Stops at convergence, or when progress stalls (colours outside
// the set of reflectances, which no sigmoid reaches).
double Solve(const Colorimetry& cm, const Quadrature& q, const Vec3& target, Vec3& c,
             int maxIterations) {
    auto residual = [&](const Vec3& cc, Mat3* J) {
        Mat3 dXYZ, dLab;
        Vec3 lab = cm.Lab(Colorimetry::Spectrum(q, cc, &dXYZ), &dLab);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                (*J)[i][j] =
                    dLab[i][0] * dXYZ[0][j] + dLab[i][1] * dXYZ[1][j] + dLab[i][2] * dXYZ[2][j];
        return Vec3{lab[0] - target[0], lab[1] - target[1], lab[2] - target[2]};
    };
    auto norm2 = [](const Vec3& r) { return r[0] * r[0] + r[1] * r[1] + r[2] * r[2]; };

    double mu = 1e-6;
    Mat3 J;
    Vec3 r = residual(c, &J);
    double e = norm2(r);
    int stalled = 0;
    for (int it = 0; it < maxIterations && e > 1e-10; ++it) {
        // Normal equations (J^T J + mu diag) delta = J^T r
        Mat3 A{};
        Vec3 g{};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                for (int k = 0; k < 3; ++k) A[i][j] += J[k][i] * J[k][j];
            for (int k = 0; k < 3; ++k) g[i] += J[k][i] * r[k];
        }
        bool improved = false;
        for (int tries = 0; tries < 12 && !improved; ++tries) {
            Mat3 Ad = A;
            for (int i = 0; i < 3; ++i) Ad[i][i] += mu * std::max(A[i][i], 1e-12);
            Vec3 delta{};
            if (!Solve3(Ad, g, delta)) {
                mu *= 10;
                continue;
            }
            Vec3 cn = {c[0] - delta[0], c[1] - delta[1], c[2] - delta[2]};
            // Keep the polynomial bounded (as rgb2spec_opt does)
            double mx = std::max({std::abs(cn[0]), std::abs(cn[1]), std::abs(cn[2])});
            if (mx > 1000)
                for (double& v : cn) v *= 1000 / mx;
            Mat3 Jn;
            Vec3 rn = residual(cn, &Jn);
            double en = norm2(rn);
            if (en < e) {
                stalled = (en > 0.999 * e) ? stalled + 1 : 0;
                c = cn, r = rn, J = Jn, e = en;
                mu = std::max(mu * 0.1, 1e-12);
                improved = true;
            } else {
                mu *= 10;
            }
        }
        if (!improved || stalled >= 5) break;
    }
    return std::sqrt(e);
}

// The coefficients of rgb, warm-started from c: coarse iterations, then fine ones. Colours the
// coarse fit misses by more than 1 CIELAB unit are not reflectances; polishing them with the
// fine sums would change nothing visible, so they keep the coarse fit.
double Fit(const Colorimetry& cm, const Vec3& rgb, Vec3& c) {
    const Vec3 target = cm.Lab(Mul(cm.xyzFromRGB, rgb), nullptr);
    const double coarseResidual = Solve(cm, cm.coarse, target, c, 100);
    if (coarseResidual > 1) return coarseResidual;
    return Solve(cm, cm.fine, target, c, 20);
}

double SmoothStep(double x) { return x * x * (3 - 2 * x); }

// Fills one colour space's table: kRes z nodes then [3][kRes][kRes][kRes][3] coefficients.
// Fit statistics: the worst CIELAB residual among colours the sigmoids reach (residual below 1),
// and how many colours they do not reach (outside the set of reflectances: saturated corners
// of wide gamuts).
struct FitStats {
    double worstReached = 0;
    long unreached = 0;
};

std::vector<float> BuildTable(const ColorSpaceDefinition& cs, FitStats* stats) {
    const Colorimetry cm(cs);
    std::vector<float> out(kRes + 3 * kRes * kRes * kRes * 3);
    std::vector<double> zNodes(kRes);
    for (int k = 0; k < kRes; ++k) {
        zNodes[k] = SmoothStep(SmoothStep(k / double(kRes - 1)));
        out[k] = float(zNodes[k]);
    }
    float* coeffs = out.data() + kRes;

    std::atomic<int> next{0};
    std::vector<FitStats> perThread(std::max(1u, std::thread::hardware_concurrency()));
    auto work = [&](int tid) {
        for (int task; (task = next++) < 3 * kRes;) {
            const int l = task / kRes, j = task % kRes;
            const double y = j / double(kRes - 1);
            for (int i = 0; i < kRes; ++i) {
                const double x = i / double(kRes - 1);
                auto solve = [&](int k, Vec3& c) {
                    const double b = zNodes[k];
                    Vec3 rgb;
                    rgb[l] = b, rgb[(l + 1) % 3] = x * b, rgb[(l + 2) % 3] = y * b;
                    double res = Fit(cm, rgb, c);
                    if (b > 1e-3) {
                        FitStats& st = perThread[tid];
                        if (res < 1)
                            st.worstReached = std::max(st.worstReached, res);
                        else
                            ++st.unreached;
                    }
                    // Store for lambda in nm: A l'^2 + B l' + C, l' = (lambda - c0) c1
                    const double c0 = kLambdaMin, c1 = 1 / (kLambdaMax - kLambdaMin);
                    float* o = coeffs + 3 * (((l * kRes + k) * kRes + j) * kRes + i);
                    o[0] = float(c[0] * c1 * c1);
                    o[1] = float(c[1] * c1 - 2 * c[0] * c0 * c1 * c1);
                    o[2] = float(c[2] - c[1] * c0 * c1 + c[0] * (c0 * c1) * (c0 * c1));
                };
                // March up and down in z from a start, each solve warm-started from the last
                const int start = kRes / 5;
                Vec3 c{0, 0, 0};
                for (int k = start; k < kRes; ++k) solve(k, c);
                c = {0, 0, 0};
                for (int k = start - 1; k >= 0; --k) solve(k, c);
            }
        }
    };
    std::vector<std::thread> threads;
    for (size_t t = 0; t < perThread.size(); ++t) threads.emplace_back(work, int(t));
    for (auto& t : threads) t.join();
    for (const FitStats& st : perThread) {
        stats->worstReached = std::max(stats->worstReached, st.worstReached);
        stats->unreached += st.unreached;
    }
    return out;
}

std::string Identifier(std::string_view name) {
    std::string id = "kiln_rgb2spec_";
    for (char ch : name) id += (ch == '-') ? '_' : ch;
    return id;
}

// Writes one table as a C++ file holding its bytes in a string literal: compilers read a long
// string literal far faster than a braced list of numbers (about 1 s for 9.4 MB with GCC, against
// 13 s). Printable characters are written as themselves, others as 3-digit octal escapes (which
// end after 3 digits, so any character may follow).
bool WriteTableSource(const std::string& path, const std::string& id,
                      const std::vector<float>& table) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(table.data());
    const size_t n = table.size() * sizeof(float);
    std::string text;
    text.reserve(3 * n);
    text += "// Generated by kiln_rgb2spec_gen at build time: do not edit, do not commit.\n";
    text += "extern const unsigned char " + id + "[" + std::to_string(n + 1) + "];\n";
    text += "const unsigned char " + id + "[" + std::to_string(n + 1) + "] =\n\"";
    for (size_t i = 0; i < n; ++i) {
        const unsigned char b = bytes[i];
        if (b >= 0x20 && b < 0x7f && b != '"' && b != '\\' && b != '?') {
            text += char(b);
        } else {
            char esc[5];
            std::snprintf(esc, sizeof(esc), "\\%03o", unsigned(b));
            text += esc;
        }
        if (i % 64 == 63 && i + 1 < n) text += "\"\n\"";
    }
    text += "\";\n";
    std::ofstream f(path, std::ios::binary);
    f << text;
    return bool(f);
}

}  // namespace
}  // namespace kiln

int main(int argc, char** argv) {
    using namespace kiln;
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s OUTPUT_DIR SPACE [SPACE...]\n", argv[0]);
        return 1;
    }
    const std::string dir = argv[1];
    const auto tStart = std::chrono::steady_clock::now();
    std::vector<std::string> built;
    for (int a = 2; a < argc; ++a) {
        const ColorSpaceDefinition* cs = nullptr;
        for (const auto& d : kColorSpaceDefinitions)
            if (d.name == argv[a]) cs = &d;
        if (!cs) {
            std::fprintf(stderr, "rgb2spec_gen: unknown colour space %s\n", argv[a]);
            return 1;
        }
        auto t0 = std::chrono::steady_clock::now();
        FitStats stats;
        std::vector<float> table = BuildTable(*cs, &stats);
        const std::string path = dir + "/rgb2spec_" + Identifier(argv[a]) + ".cpp";
        if (!WriteTableSource(path, Identifier(argv[a]), table)) {
            std::fprintf(stderr, "rgb2spec_gen: cannot write %s\n", path.c_str());
            return 1;
        }
        double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        std::printf(
            "rgb2spec_gen: %s: %.1f s; worst CIELAB residual %.3g; %ld of %d colours "
            "not reflectances (residual > 1)\n",
            argv[a], secs, stats.worstReached, stats.unreached, 3 * kRes * kRes * kRes);
        std::fflush(stdout);
        built.push_back(argv[a]);
    }

    // The look-up: a pointer to the embedded bytes, read in place (no copy: only the pages a
    // render touches are ever loaded)
    std::ofstream cpp(dir + "/rgb2spec_tables.cpp");
    cpp << "// Generated by kiln_rgb2spec_gen at build time: do not edit, do not commit.\n"
           "#include <string_view>\n\n";
    for (const std::string& name : built)
        cpp << "extern const unsigned char " << Identifier(name) << "[];\n";
    cpp << "\nnamespace kiln {\n\n"
           "const unsigned char* RGBToSpectrumTableData(std::string_view name) {\n";
    for (const std::string& name : built)
        cpp << "    if (name == \"" << name << "\") return " << Identifier(name) << ";\n";
    cpp << "    return nullptr;\n}\n\n}  // namespace kiln\n";
    double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - tStart).count();
    std::printf("rgb2spec_gen: %zu tables in %.1f s\n", built.size(), total);
    return cpp ? 0 : 1;
}
