// kiln_benchtool: the image arithmetic and plotting behind bench/convergence.py, for machines
// without numpy, matplotlib or OpenImageIO's Python bindings (Debian 12 with kiln's packages).
//
//   kiln_benchtool relmse REFERENCE TEST
//       prints "relmse R mse M nonfinite N seconds T" for the first three channels of two
//       images of equal size (T: the test image's renderTimeSeconds attribute, -1 if none):
//       relMSE = mean over pixels and channels of (x - r)^2 / (r^2 + eps), the usual relative
//       MSE (e.g. Rousselle et al. 2011) with eps = 0.01 * mean(r)^2 so that it is independent
//       of the image's exposure; MSE in the images' units squared.
//   kiln_benchtool plot CSV OUT.png [TITLE]
//       log-log chart of relmse against seconds, one line per scene (default strategy)
//       (columns by header name), written through OpenImageIO.
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace OIIO = OIIO_NAMESPACE;

int RelMSE(const std::string& refFile, const std::string& testFile) {
    OIIO::ImageBuf ref(refFile), test(testFile);
    if (!ref.read(0, 0, true, OIIO::TypeDesc::FLOAT) ||
        !test.read(0, 0, true, OIIO::TypeDesc::FLOAT)) {
        std::fprintf(stderr, "kiln_benchtool: cannot read %s or %s: %s%s\n", refFile.c_str(),
                     testFile.c_str(), ref.geterror().c_str(), test.geterror().c_str());
        return 1;
    }
    const OIIO::ImageSpec &rs = ref.spec(), &ts = test.spec();
    if (rs.width != ts.width || rs.height != ts.height || rs.nchannels < 3 || ts.nchannels < 3) {
        std::fprintf(stderr, "kiln_benchtool: %s is %dx%dx%d but %s is %dx%dx%d\n", refFile.c_str(),
                     rs.width, rs.height, rs.nchannels, testFile.c_str(), ts.width, ts.height,
                     ts.nchannels);
        return 1;
    }
    std::vector<float> r(size_t(rs.width) * rs.height * 3), t(r.size());
    ref.get_pixels(OIIO::ROI(rs.x, rs.x + rs.width, rs.y, rs.y + rs.height, 0, 1, 0, 3),
                   OIIO::TypeDesc::FLOAT, r.data());
    test.get_pixels(OIIO::ROI(ts.x, ts.x + ts.width, ts.y, ts.y + ts.height, 0, 1, 0, 3),
                    OIIO::TypeDesc::FLOAT, t.data());
    double mean = 0;
    for (float v : r) mean += v;
    mean /= double(r.size());
    const double eps = std::max(0.01 * mean * mean, 1e-30);
    double rel = 0, mse = 0;
    size_t nonFinite = 0;
    for (size_t i = 0; i < r.size(); ++i) {
        double d = double(t[i]) - double(r[i]);
        if (!std::isfinite(d)) {
            ++nonFinite;
            continue;
        }
        rel += d * d / (double(r[i]) * r[i] + eps);
        mse += d * d;
    }
    size_t n = r.size() - nonFinite;
    // kiln writes its render-loop wall time into the EXR header (src/core/image/image_io.cpp)
    float seconds = ts.get_float_attribute("renderTimeSeconds", -1.0f);
    std::printf("relmse %.9g mse %.9g nonfinite %zu seconds %.9g\n", n ? rel / n : 0.0,
                n ? mse / n : 0.0, nonFinite, double(seconds));
    return 0;
}

// ---------------------------------------------------------------------------------------------
// Plotting

struct Series {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (seconds, relmse), both > 0
};

std::vector<std::string> SplitCSV(const std::string& line) {
    std::vector<std::string> f;
    std::stringstream ss(line);
    std::string item;
    while (std::getline(ss, item, ',')) f.push_back(item);
    return f;
}

bool ReadSeries(const std::string& csv, std::vector<Series>* series) {
    std::ifstream in(csv);
    std::string line;
    if (!std::getline(in, line)) return false;
    std::vector<std::string> header = SplitCSV(line);
    auto column = [&](const std::string& name) {
        auto it = std::find(header.begin(), header.end(), name);
        return it == header.end() ? -1 : int(it - header.begin());
    };
    int cScene = column("scene"), cStrategy = column("strategy"), cSeconds = column("seconds"),
        cRel = column("relmse");
    if (cScene < 0 || cSeconds < 0 || cRel < 0) return false;
    std::map<std::string, size_t> index;
    while (std::getline(in, line)) {
        std::vector<std::string> f = SplitCSV(line);
        if (int(f.size()) != int(header.size())) continue;
        // One line per scene with its default strategy (other strategies are compared in
        // strategies.md; a line each would crowd the chart).
        if (cStrategy >= 0 && f[cStrategy] != "default") continue;
        std::string name = f[cScene];
        double s = std::atof(f[cSeconds].c_str()), e = std::atof(f[cRel].c_str());
        if (!(s > 0 && e > 0)) continue;
        auto [it, added] = index.try_emplace(name, series->size());
        if (added) series->push_back({name, {}});
        (*series)[it->second].points.push_back({s, e});
    }
    return !series->empty();
}

int Plot(const std::string& csv, const std::string& out, const std::string& title) {
    std::vector<Series> series;
    if (!ReadSeries(csv, &series)) {
        std::fprintf(stderr, "kiln_benchtool: no plottable rows in %s\n", csv.c_str());
        return 1;
    }
    // Axis ranges: whole decades around the data.
    double xmin = 1e300, xmax = 0, ymin = 1e300, ymax = 0;
    for (const Series& s : series)
        for (auto [x, y] : s.points) {
            xmin = std::min(xmin, x), xmax = std::max(xmax, x);
            ymin = std::min(ymin, y), ymax = std::max(ymax, y);
        }
    int dx0 = int(std::floor(std::log10(xmin))), dx1 = int(std::ceil(std::log10(xmax)));
    int dy0 = int(std::floor(std::log10(ymin))), dy1 = int(std::ceil(std::log10(ymax)));
    dx1 = std::max(dx1, dx0 + 1), dy1 = std::max(dy1, dy0 + 1);

    const int W = 960, H = 640, left = 90, right = 250, top = 50, bottom = 70;
    const int pw = W - left - right, ph = H - top - bottom;
    OIIO::ImageBuf img(OIIO::ImageSpec(W, H, 3, OIIO::TypeDesc::UINT8));
    const float white[3] = {1, 1, 1}, black[3] = {0, 0, 0}, grid[3] = {0.85f, 0.85f, 0.85f},
                minor[3] = {0.94f, 0.94f, 0.94f};
    OIIO::ImageBufAlgo::fill(img, white);
    auto X = [&](double x) {
        return left + int(std::lround((std::log10(x) - dx0) / (dx1 - dx0) * pw));
    };
    auto Y = [&](double y) {
        return top + ph - int(std::lround((std::log10(y) - dy0) / (dy1 - dy0) * ph));
    };
    auto text = [&](int x, int y, const std::string& s, int size, OIIO::cspan<float> color) {
        // Text needs FreeType and a font in OIIO; the chart is still readable without it.
        OIIO::ImageBufAlgo::render_text(img, x, y, s, size, "DejaVuSans", color);
    };

    // Grid: decades (labelled) and 2..9 within them.
    for (int d = dx0; d <= dx1; ++d) {
        for (int m = 2; d < dx1 && m <= 9; ++m)
            OIIO::ImageBufAlgo::render_line(img, X(m * std::pow(10.0, d)), top,
                                            X(m * std::pow(10.0, d)), top + ph, minor);
        OIIO::ImageBufAlgo::render_line(img, X(std::pow(10.0, d)), top, X(std::pow(10.0, d)),
                                        top + ph, grid);
        text(X(std::pow(10.0, d)) - 14, top + ph + 22, "1e" + std::to_string(d), 16, black);
    }
    for (int d = dy0; d <= dy1; ++d) {
        for (int m = 2; d < dy1 && m <= 9; ++m)
            OIIO::ImageBufAlgo::render_line(img, left, Y(m * std::pow(10.0, d)), left + pw,
                                            Y(m * std::pow(10.0, d)), minor);
        OIIO::ImageBufAlgo::render_line(img, left, Y(std::pow(10.0, d)), left + pw,
                                        Y(std::pow(10.0, d)), grid);
        text(left - 52, Y(std::pow(10.0, d)) + 6, "1e" + std::to_string(d), 16, black);
    }
    OIIO::ImageBufAlgo::render_box(img, left, top, left + pw, top + ph, black);
    text(left + pw / 2 - 80, H - 20, "render time (s, wall)", 18, black);
    text(10, top - 15, "relMSE", 18, black);
    text(left + 80, 30, title, 20, black);

    // Reference slope: error proportional to 1/time, through the first series' first point.
    const float slopeColor[3] = {0.6f, 0.6f, 0.6f};
    {
        auto [x0, y0] = series[0].points.front();
        double x1 = std::pow(10.0, dx1), y1 = y0 * x0 / x1;
        OIIO::ImageBufAlgo::render_line(img, X(x0), Y(y0), X(x1), Y(y1), slopeColor);
    }

    static const std::array<std::array<float, 3>, 8> palette = {{{0.12f, 0.47f, 0.71f},
                                                                 {1.00f, 0.50f, 0.05f},
                                                                 {0.17f, 0.63f, 0.17f},
                                                                 {0.84f, 0.15f, 0.16f},
                                                                 {0.58f, 0.40f, 0.74f},
                                                                 {0.55f, 0.34f, 0.29f},
                                                                 {0.89f, 0.47f, 0.76f},
                                                                 {0.50f, 0.50f, 0.50f}}};
    for (size_t i = 0; i < series.size(); ++i) {
        OIIO::cspan<float> c(palette[i % palette.size()].data(), 3);
        const auto& p = series[i].points;
        for (size_t k = 0; k < p.size(); ++k) {
            int x = X(p[k].first), y = Y(p[k].second);
            OIIO::ImageBufAlgo::render_box(img, x - 3, y - 3, x + 3, y + 3, c, true);
            if (k > 0) {
                int xp = X(p[k - 1].first), yp = Y(p[k - 1].second);
                for (int o = -1; o <= 1; ++o) {  // 3 px wide
                    OIIO::ImageBufAlgo::render_line(img, xp, yp + o, x, y + o, c);
                }
            }
        }
        int ly = top + 20 + 26 * int(i);
        OIIO::ImageBufAlgo::render_box(img, left + pw + 15, ly - 10, left + pw + 35, ly, c, true);
        text(left + pw + 42, ly, series[i].name, 16, black);
    }
    int ly = top + 20 + 26 * int(series.size());
    OIIO::ImageBufAlgo::render_line(img, left + pw + 15, ly - 5, left + pw + 35, ly - 5,
                                    slopeColor);
    text(left + pw + 42, ly, "slope -1", 16, black);

    if (!img.write(out)) {
        std::fprintf(stderr, "kiln_benchtool: cannot write %s: %s\n", out.c_str(),
                     img.geterror().c_str());
        return 1;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> a(argv + 1, argv + argc);
    if (a.size() == 3 && a[0] == "relmse") return RelMSE(a[1], a[2]);
    if ((a.size() == 3 || a.size() == 4) && a[0] == "plot")
        return Plot(a[1], a[2], a.size() == 4 ? a[3] : "kiln convergence");
    std::fprintf(stderr,
                 "usage: kiln_benchtool relmse REFERENCE TEST\n"
                 "       kiln_benchtool plot CSV OUT.png [TITLE]\n");
    return 2;
}
