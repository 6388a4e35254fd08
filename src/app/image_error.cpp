#include "app/image_error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <stdexcept>

#include "core/image/image.h"
#include "core/image/image_codec.h"

namespace kiln {

namespace {

int Usage(const std::string& use, const std::string& message) {
    std::cerr << "kiln diff " << use << ": " << message << "\nsee kiln diff --help\n";
    return 2;
}

// The error of one value against the reference value, by metric
double Error(const std::string& metric, double a, double b) {
    double d = a - b;
    if (metric == "mae") return std::abs(d);
    if (metric == "mse") return d * d;
    double den = std::abs(b) + kRelMSEEpsilon;
    return d * d / (den * den);
}

// Image files whose path starts with prefix, sorted
std::vector<std::string> MatchingFiles(const std::string& prefix, const std::string& exclude) {
    namespace fs = std::filesystem;
    fs::path p(prefix);
    fs::path folder = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::string start = p.filename().string();
    std::vector<std::string> files;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(folder, ec)) {
        std::string name = e.path().filename().string();
        if (!e.is_regular_file() || name.rfind(start, 0) != 0) continue;
        std::string path = (p.has_parent_path() ? e.path() : fs::path(name)).string();
        if (fs::equivalent(path, exclude, ec)) continue;
        if (!FileExtension(path).empty()) files.push_back(path);
    }
    std::sort(files.begin(), files.end());
    return files;
}

}  // namespace

int RunImageError(const std::vector<std::string>& args) {
    std::string reference, errorFile, metric = "mse", prefix;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](std::string& v) {
            if (i + 1 >= args.size()) return false;
            v = args[++i];
            return true;
        };
        if (a == "--reference") {
            if (!value(reference)) return Usage("error", "--reference needs a file");
        } else if (a == "--errorfile") {
            if (!value(errorFile)) return Usage("error", "--errorfile needs a file");
        } else if (a == "--metric") {
            if (!value(metric)) return Usage("error", "--metric needs a name");
            std::transform(metric.begin(), metric.end(), metric.begin(),
                           [](unsigned char c) { return char(std::tolower(c)); });
            if (metric == "mrse") metric = "relmse";  // imgtool's name
            if (metric != "mae" && metric != "mse" && metric != "relmse")
                return Usage("error", "--metric expects mae, mse or relmse (MRSE)");
        } else if (!a.empty() && a[0] == '-') {
            return Usage("error", "unknown option '" + a + "'");
        } else if (prefix.empty()) {
            prefix = a;
        } else {
            return Usage("error", "expects one file name prefix");
        }
    }
    if (reference.empty()) return Usage("error", "--reference REF is required");
    if (prefix.empty()) return Usage("error", "no file name prefix");
    try {
        Image ref = Image::Read(reference);
        std::vector<std::string> files = MatchingFiles(prefix, reference);
        if (files.empty()) throw std::runtime_error("no image starts with \"" + prefix + "\"");
        Point2i res = ref.Resolution();
        int nc = ref.NChannels();
        std::vector<double> pixelError(size_t(res.x) * res.y, 0.0);
        double sum = 0;
        std::optional<int> spp;
        for (const std::string& file : files) {
            ImageMetadata metadata;
            Image im = Image::Read(file, &metadata);
            if (im.Resolution() != res || im.ChannelNames() != ref.ChannelNames())
                throw std::runtime_error(file + ": resolution or channels differ from " +
                                         reference + "'s");
            if (metadata.samplesPerPixel) {
                if (spp && *spp != *metadata.samplesPerPixel)
                    throw std::runtime_error(file + ": " +
                                             std::to_string(*metadata.samplesPerPixel) +
                                             " spp, the images before it " + std::to_string(*spp));
                spp = metadata.samplesPerPixel;
            }
            double imageSum = 0;
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x) {
                    double e = 0;
                    for (int c = 0; c < nc; ++c)
                        e += Error(metric, im.GetChannel({x, y}, c), ref.GetChannel({x, y}, c));
                    pixelError[size_t(y) * res.x + x] += e / nc / double(files.size());
                    imageSum += e;
                }
            sum += imageSum / (double(res.x) * res.y * nc);
        }
        std::printf("%s estimate = %.9g\nimages %zu\n", metric.c_str(), sum / files.size(),
                    files.size());
        if (!errorFile.empty()) {
            Image errors(PixelFormat::Float, res, {"Y"});
            for (int y = 0; y < res.y; ++y)
                for (int x = 0; x < res.x; ++x)
                    errors.SetChannel({x, y}, 0, Float(pixelError[size_t(y) * res.x + x]));
            errors.Write(errorFile);
        }
    } catch (const std::exception& e) {
        std::cerr << "kiln diff error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

int RunFalseColor(const std::vector<std::string>& args) {
    std::string in, out;
    std::optional<float> maxValue;
    bool plusMinus = false;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if ((a == "-o" || a == "--outfile") && i + 1 < args.size()) {
            out = args[++i];
        } else if (a == "--maxvalue" && i + 1 < args.size()) {
            try {
                maxValue = std::stof(args[++i]);
            } catch (const std::exception&) {
                return Usage("falsecolor", "--maxvalue expects a number");
            }
            if (!(*maxValue > 0) || !std::isfinite(*maxValue))
                return Usage("falsecolor", "--maxvalue must be positive");
        } else if (a == "--plusminus") {
            plusMinus = true;
        } else if (!a.empty() && a[0] == '-') {
            return Usage("falsecolor", "unknown option '" + a + "'");
        } else if (in.empty()) {
            in = a;
        } else {
            return Usage("falsecolor", "expects one image");
        }
    }
    if (in.empty()) return Usage("falsecolor", "no image");
    if (out.empty()) return Usage("falsecolor", "-o OUT is required");
    try {
        Image image = Image::Read(in);
        Point2i res = image.Resolution();
        std::vector<float> mean(size_t(res.x) * res.y);
        float largest = 0;
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                double s = 0;
                for (int c = 0; c < image.NChannels(); ++c) s += image.GetChannel({x, y}, c);
                float m = float(s / image.NChannels());
                mean[size_t(y) * res.x + x] = std::isfinite(m) ? m : 0.f;
                largest = std::max(largest, std::abs(mean[size_t(y) * res.x + x]));
            }
        float scale = maxValue ? *maxValue : (largest > 0 ? largest : 1.f);
        Image picture(PixelFormat::Float, res, {"R", "G", "B"});
        std::vector<float> t(mean.size());
        for (size_t i = 0; i < mean.size(); ++i)
            t[i] = std::clamp(std::abs(mean[i]) / scale, 0.f, 1.f);
        // The colour map's display-encoded (sRGB) colours; the image holds linear values
        std::vector<float> colours = plusMinus ? std::vector<float>() : NamedColorMap("inferno", t);
        auto linear = [](float v) {
            return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
        };
        for (int y = 0; y < res.y; ++y)
            for (int x = 0; x < res.x; ++x) {
                size_t i = size_t(y) * res.x + x;
                // Display-encoded red, green, blue: the colour map's, or for --plusminus green
                // for positive values and red for negative ones
                float display[3];
                if (plusMinus) {
                    display[0] = mean[i] < 0 ? t[i] : 0.f;
                    display[1] = mean[i] > 0 ? t[i] : 0.f;
                    display[2] = 0;
                } else {
                    for (int c = 0; c < 3; ++c) display[c] = colours[3 * i + c];
                }
                for (int c = 0; c < 3; ++c) picture.SetChannel({x, y}, c, linear(display[c]));
            }
        picture.Write(out);
    } catch (const std::exception& e) {
        std::cerr << "kiln diff falsecolor: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

}  // namespace kiln
