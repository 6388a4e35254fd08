#include "app/image_diff.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "app/image_error.h"
#include "core/image/color_encoding.h"
#include "core/image/image_codec.h"

namespace kiln {

namespace {

// RGB of a pixel for the perceptual metric (see the header): channels R, G, B, else the first
// three, else channel 0 as grey.
struct RGBChannels {
    int c[3];
};
RGBChannels PickRGB(const Image& img) {
    int r = img.ChannelIndex("R"), g = img.ChannelIndex("G"), b = img.ChannelIndex("B");
    if (r >= 0 && g >= 0 && b >= 0) return {{r, g, b}};
    if (img.NChannels() >= 3) return {{0, 1, 2}};
    return {{0, 0, 0}};
}

// CIELAB of a linear sRGB/Rec. 709 colour clamped to [0, 1], D65 white (CIE 015:2018 8.2.1).
void LinearSRGBToLab(const float rgb[3], double lab[3]) {
    double v[3];
    for (int i = 0; i < 3; ++i) v[i] = std::clamp(double(rgb[i]), 0.0, 1.0);
    // IEC 61966-2-1:1999 RGB -> XYZ matrix, normalised to the D65 white (Yn = 1).
    double X = 0.4124 * v[0] + 0.3576 * v[1] + 0.1805 * v[2];
    double Y = 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2];
    double Z = 0.0193 * v[0] + 0.1192 * v[1] + 0.9505 * v[2];
    const double Xn = 0.9505, Yn = 1.0, Zn = 1.0890;  // the matrix's white, RGB (1, 1, 1)
    auto f = [](double t) {
        const double d = 6.0 / 29.0;
        return t > d * d * d ? std::cbrt(t) : t / (3 * d * d) + 4.0 / 29.0;
    };
    double fx = f(X / Xn), fy = f(Y / Yn), fz = f(Z / Zn);
    lab[0] = 116 * fy - 16;
    lab[1] = 500 * (fx - fy);
    lab[2] = 200 * (fy - fz);
}

std::string SizeString(const Image& img) {
    std::ostringstream s;
    s << img.Resolution().x << "x" << img.Resolution().y << ", " << img.NChannels()
      << " channels (";
    for (size_t i = 0; i < img.ChannelNames().size(); ++i)
        s << (i ? "," : "") << img.ChannelNames()[i];
    s << ")";
    return s.str();
}

}  // namespace

const std::vector<std::string>& ImageDiffMetricNames() {
    static const std::vector<std::string> names = {"rmse", "relmse", "mae", "psnr", "flip-like"};
    return names;
}

std::optional<double> GetMetric(const ImageDiffMetrics& m, const std::string& name) {
    if (name == "rmse") return m.rmse;
    if (name == "relmse") return m.relmse;
    if (name == "mae") return m.mae;
    if (name == "psnr") return m.psnr;
    if (name == "flip-like") return m.flipLike;
    return std::nullopt;
}

ImageDiffMetrics CompareImages(const Image& a, const Image& b, Image* diffImage) {
    if (a.Resolution() != b.Resolution() || a.ChannelNames() != b.ChannelNames())
        throw std::invalid_argument("images differ in size or channels: " + SizeString(a) + " vs " +
                                    SizeString(b));
    Point2i res = a.Resolution();
    int nc = a.NChannels();
    size_t nPixels = size_t(res.x) * res.y;
    ImageDiffMetrics m;
    if (nPixels == 0 || nc == 0) return m;

    // Pixels with a non-finite value in either image are counted and compared as 0 vs 0.
    std::vector<uint8_t> bad(nPixels, 0);
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x)
            for (int c = 0; c < nc; ++c)
                if (!std::isfinite(a.GetChannel({x, y}, c)) ||
                    !std::isfinite(b.GetChannel({x, y}, c)))
                    bad[size_t(y) * res.x + x] = 1;
    m.nonFinitePixels = std::count(bad.begin(), bad.end(), uint8_t(1));

    // Per value: |A - B| (mae, the largest error and its pixel, the first in scanline order),
    // (A - B)^2 (rmse) and the relative squared error (A - B)^2 / (|B| + eps)^2 (relmse);
    // flagged pixels compare as 0 vs 0
    double sumAbs = 0, sumSq = 0, sumRel = 0;
    std::vector<float> pixelRel(nPixels, 0.f);  // mean relative squared error of each pixel
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            size_t pi = size_t(y) * res.x + x;
            if (bad[pi]) continue;
            double rel = 0;
            for (int c = 0; c < nc; ++c) {
                double va = a.GetChannel({x, y}, c), vb = b.GetChannel({x, y}, c);
                double d = va - vb, ad = std::abs(d), den = std::abs(vb) + kRelMSEEpsilon;
                sumAbs += ad;
                sumSq += d * d;
                rel += d * d / (den * den);
                if (ad > m.maxError) {
                    m.maxError = ad;
                    m.maxErrorPixel = Point2i(x, y);
                }
            }
            sumRel += rel;
            pixelRel[pi] = float(rel / nc);
        }
    const double nValues = double(nPixels) * nc;
    m.mae = sumAbs / nValues;
    m.rmse = std::sqrt(sumSq / nValues);
    m.relmse = sumRel / nValues;
    // A fixed peak of 1 (not the images' largest value) so that a threshold means the same
    // for every image.
    m.psnr = m.rmse > 0 ? 20 * std::log10(1 / m.rmse) : std::numeric_limits<double>::infinity();

    // flip-like: mean deltaE*ab after the display clamp (no OIIO operation does CIELAB).
    RGBChannels ca = PickRGB(a), cb = PickRGB(b);
    double sumDE = 0;
    for (int y = 0; y < res.y; ++y)
        for (int x = 0; x < res.x; ++x) {
            if (bad[size_t(y) * res.x + x]) continue;
            float pa[3], pb[3];
            for (int i = 0; i < 3; ++i) {
                pa[i] = a.GetChannel({x, y}, ca.c[i]);
                pb[i] = b.GetChannel({x, y}, cb.c[i]);
            }
            double la[3], lb[3];
            LinearSRGBToLab(pa, la);
            LinearSRGBToLab(pb, lb);
            sumDE +=
                std::sqrt((la[0] - lb[0]) * (la[0] - lb[0]) + (la[1] - lb[1]) * (la[1] - lb[1]) +
                          (la[2] - lb[2]) * (la[2] - lb[2]));
        }
    m.flipLike = sumDE / double(nPixels);

    if (diffImage) {
        // Per-pixel relative RMS error, log-mapped to [0, 1], through the "inferno" map.
        std::vector<float> t(nPixels);
        for (size_t i = 0; i < nPixels; ++i) {
            float e = std::sqrt(pixelRel[i]);
            float v = e > 0 ? (std::log10(e) + 3) / 3 : 0;
            t[i] = std::clamp(v, 0.f, 1.f);
        }
        std::vector<float> cm = NamedColorMap("inferno", t);
        Image out(PixelFormat::Float, res, {"R", "G", "B"});
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                size_t pi = size_t(y) * res.x + x;
                for (int c = 0; c < 3; ++c) {
                    // Colour-map values are display (sRGB-encoded) values; store linear.
                    float v = bad[pi] ? (c == 1 ? 1.f : 0.f) : SRGBToLinear(cm[3 * pi + c]);
                    out.SetChannel({x, y}, c, v);
                }
            }
        *diffImage = std::move(out);
    }
    return m;
}

std::string ImageDiffUsageText() {
    return "usage: kiln diff A B [--metric rmse|relmse|mae|psnr|flip-like] [--threshold X]\n"
           "                    [--out DIFF.exr|DIFF.png]\n"
           "  compares test image A with reference B; prints every metric as 'name value';\n"
           "  exit 1 if the metric (default relmse) is above X (psnr: below X), 2 on errors\n"
           "   or: kiln diff error --reference REF [--metric mae|mse|relmse] [--errorfile OUT]\n"
           "                    PREFIX   (mean error of every image starting with PREFIX)\n"
           "   or: kiln diff falsecolor IMAGE -o OUT [--maxvalue V] [--plusminus]\n";
}

int RunImageDiff(const std::vector<std::string>& args) {
    // pbrt-v4 imgtool's error and falsecolor (app/image_error.h)
    if (!args.empty() && args[0] == "error")
        return RunImageError(std::vector<std::string>(args.begin() + 1, args.end()));
    if (!args.empty() && args[0] == "falsecolor")
        return RunFalseColor(std::vector<std::string>(args.begin() + 1, args.end()));
    std::vector<std::string> files;
    std::string metric = "relmse", out;
    std::optional<double> threshold;
    auto usage = [](const std::string& msg) {
        std::cerr << "kiln diff: " << msg << "\nsee kiln diff --help\n";
        return 2;
    };
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        bool hasValue = i + 1 < args.size();
        if (a == "-h" || a == "--help") {
            std::cout << ImageDiffUsageText();
            return 0;
        } else if (a == "--metric") {
            if (!hasValue) return usage("--metric needs a value");
            metric = args[++i];
            if (!GetMetric(ImageDiffMetrics{}, metric))
                return usage("unknown metric '" + metric + "'");
        } else if (a == "--threshold") {
            if (!hasValue) return usage("--threshold needs a value");
            const std::string& v = args[++i];
            size_t used = 0;
            try {
                threshold = std::stod(v, &used);
            } catch (const std::exception&) {
                used = 0;
            }
            if (used == 0 || used != v.size() || !std::isfinite(*threshold))
                return usage("--threshold expects a number, got '" + v + "'");
        } else if (a == "--out" || a == "-o") {
            if (!hasValue) return usage(a + " needs a file name");
            out = args[++i];
        } else if (!a.empty() && a[0] == '-' && a.size() > 1) {
            return usage("unknown option '" + a + "'");
        } else {
            files.push_back(a);
        }
    }
    if (files.size() != 2) return usage("expects two images, got " + std::to_string(files.size()));

    Image img[2];
    for (int i = 0; i < 2; ++i) {
        try {
            img[i] = Image::Read(files[i]);
        } catch (const std::exception& e) {
            std::cerr << "kiln diff: error: " << e.what() << "\n";
            return 2;
        }
    }
    if (img[0].Resolution() != img[1].Resolution() ||
        img[0].ChannelNames() != img[1].ChannelNames()) {
        std::cerr << "kiln diff: error: images do not match: " << files[0] << " is "
                  << SizeString(img[0]) << ", " << files[1] << " is " << SizeString(img[1]) << "\n";
        return 2;
    }
    ImageDiffMetrics m;
    Image diff;
    try {
        m = CompareImages(img[0], img[1], out.empty() ? nullptr : &diff);
    } catch (const std::exception& e) {
        std::cerr << "kiln diff: error: " << e.what() << "\n";
        return 2;
    }
    for (const std::string& name : ImageDiffMetricNames())
        std::printf("%s %.9g\n", name.c_str(), *GetMetric(m, name));
    std::printf("maxerror %.9g\n", m.maxError);
    std::printf("nonfinite %lld\n", (long long)m.nonFinitePixels);
    std::fflush(stdout);
    if (!out.empty()) {
        try {
            diff.Write(out);
        } catch (const std::exception& e) {
            std::cerr << "kiln diff: error: " << e.what() << "\n";
            return 2;
        }
    }
    if (!threshold) return 0;
    double v = *GetMetric(m, metric);
    bool pass = metric == "psnr" ? v >= *threshold : v <= *threshold;  // NaN fails
    if (m.nonFinitePixels > 0) pass = false;
    if (!pass)
        std::cerr << "kiln diff: " << metric << " " << v << (metric == "psnr" ? " < " : " > ")
                  << *threshold << (m.nonFinitePixels ? " or non-finite pixels" : "") << "\n";
    return pass ? 0 : 1;
}

}  // namespace kiln
