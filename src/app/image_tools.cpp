#include "app/image_tools.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>

#include "app/output_check.h"
#include "core/film/film.h"
#include "core/film/thermal_colormap.h"
#include "core/film/thermal_sensor.h"
#include "core/image/display.h"
#include "core/image/image.h"
#include "render/auto_exposure.h"
#include "spectral/color.h"

namespace kiln {

namespace {

int Usage(const std::string& command, const std::string& message, const char* usage) {
    std::cerr << "kiln " << command << ": " << message << "\nusage: " << usage << "\n";
    return 2;
}

constexpr const char* kConvertUsage =
    "kiln convert IN... -o OUT... [--view Standard|Filmic|ACES|Glow|Raw] [--exposure EV|auto]";
constexpr const char* kInfoUsage = "kiln info IMAGE";

bool IsLinearFormat(const std::string& ext) { return ext == "exr" || ext == "pfm" || ext == "hdr"; }

}  // namespace

int RunConvert(const std::vector<std::string>& args) {
    std::vector<std::string> ins;
    std::string view;
    std::vector<std::string> outs;
    std::optional<std::string> exposure;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&]() -> std::optional<std::string> {
            if (i + 1 >= args.size()) return std::nullopt;
            return args[++i];
        };
        if (a == "-h" || a == "--help") {
            std::cout << "usage: " << kConvertUsage << "\n";
            return 0;
        } else if (a == "-o" || a == "--outfile") {
            auto v = value();
            if (!v) return Usage("convert", a + " needs a file name", kConvertUsage);
            outs.push_back(*v);
        } else if (a == "--view") {
            auto v = value();
            if (!v) return Usage("convert", "--view needs a view", kConvertUsage);
            view = *v;
        } else if (a == "--exposure") {
            auto v = value();
            if (!v) return Usage("convert", "--exposure needs EV stops or auto", kConvertUsage);
            exposure = *v;
            if (*exposure != "auto") {
                size_t used = 0;
                double ev = 0;
                try {
                    ev = std::stod(*exposure, &used);
                } catch (const std::exception&) {
                    used = 0;
                }
                if (used == 0 || used != exposure->size() ||
                    !(std::abs(ev) <= RGBFilm::kMaxExposureEV))
                    return Usage("convert",
                                 "--exposure expects auto or stops within +-" +
                                     std::to_string(int(RGBFilm::kMaxExposureEV)) + ", got '" +
                                     *exposure + "'",
                                 kConvertUsage);
            }
        } else if (!a.empty() && a[0] == '-') {
            return Usage("convert", "unknown option '" + a + "'", kConvertUsage);
        } else {
            ins.push_back(a);
        }
    }
    if (ins.empty()) return Usage("convert", "no input image", kConvertUsage);
    if (outs.empty()) return Usage("convert", "no output (-o OUT)", kConvertUsage);
    try {
        CheckDisplayView(view);
        for (const std::string& out : outs) CheckImageOutput(out, view);
    } catch (const std::invalid_argument& e) {
        std::cerr << "kiln convert: " << e.what() << "\n";
        return 2;
    }
    try {
        // A thermal film's EXR (L and T, no R): the picture of its temperatures
        if (ins.size() == 1) {
            ImageMetadata m;
            Image image = Image::Read(ins[0], &m);
            const int T = image.ChannelIndex("T");
            if (T >= 0 && image.ChannelIndex("L") >= 0 && image.ChannelIndex("R") < 0) {
                for (const std::string& out : outs) {
                    if (IsLinearFormat(FileExtension(out)))
                        throw std::runtime_error(out +
                                                 ": a thermal image (L, T) converts to "
                                                 "picture formats (PNG, JPEG, ...) only");
                    m.strings["kiln:convertedFrom"] = ins[0];
                    // The film's fixed palette span, if it had one
                    std::optional<TemperatureScale> scale;
                    if (auto it = m.strings.find("kiln:thermalscale"); it != m.strings.end())
                        scale = ThermalSensor::ScaleFromSettings(it->second);
                    ThermalPicture(image, T, scale).Write(out, m);
                }
                return 0;
            }
        }
        // The inputs' R, G, B side by side, left to right (the first one's metadata)
        ImageMetadata metadata;
        Image rgb;
        for (const std::string& in : ins) {
            ImageMetadata m;
            Image image = Image::Read(in, &m);
            if (image.ChannelIndex("R") < 0 || image.ChannelIndex("G") < 0 ||
                image.ChannelIndex("B") < 0)
                throw std::runtime_error(in + ": has no R, G, B channels to convert");
            Image part = image.SelectChannels({"R", "G", "B"}).ConvertToFormat(PixelFormat::Float);
            if (!rgb) {
                metadata = m;
                rgb = part;
                continue;
            }
            if (part.Resolution().y != rgb.Resolution().y)
                throw std::runtime_error(in + ": " + std::to_string(part.Resolution().y) +
                                         " rows, the images before it " +
                                         std::to_string(rgb.Resolution().y) +
                                         " (side by side they need the same height)");
            if (m.colorSpace != metadata.colorSpace)
                throw std::runtime_error(in + ": another colour space than " + ins[0]);
            Image joined(PixelFormat::Float,
                         {rgb.Resolution().x + part.Resolution().x, rgb.Resolution().y},
                         {"R", "G", "B"});
            for (int y = 0; y < joined.Resolution().y; ++y)
                for (int x = 0; x < joined.Resolution().x; ++x)
                    for (int c = 0; c < 3; ++c)
                        joined.SetChannel({x, y}, c,
                                          x < rgb.Resolution().x
                                              ? rgb.GetChannel({x, y}, c)
                                              : part.GetChannel({x - rgb.Resolution().x, y}, c));
            rgb = std::move(joined);
            // Parts of a frame no more
            metadata.fullResolution.reset();
            metadata.pixelBounds.reset();
        }
        const RGBColorSpace& colorSpace =
            metadata.colorSpace ? *metadata.colorSpace : RGBColorSpace::sRGB();
        Float ev = 0;
        if (exposure)
            ev = *exposure == "auto" ? AutoExposureEV(rgb, colorSpace) : std::stof(*exposure);
        if (view.empty()) {
            auto v = metadata.strings.find("kiln:view");
            view = v != metadata.strings.end() ? v->second : "Standard";
            CheckDisplayView(view);
        }
        std::string from;
        for (const std::string& in : ins) from += (from.empty() ? "" : " ") + in;
        metadata.strings["kiln:convertedFrom"] = from;
        if (ev != 0) {
            // The exposure the output carries: the render's and this conversion's
            double before = 0;
            if (auto e = metadata.strings.find("kiln:exposureEV"); e != metadata.strings.end())
                try {
                    before = std::stod(e->second);
                } catch (const std::exception&) {
                }
            metadata.strings["kiln:exposureEV"] = std::to_string(before + ev);
        }
        metadata.strings["kiln:view"] = view;
        for (const std::string& out : outs) {
            std::string ext = FileExtension(out);
            if (IsLinearFormat(ext)) {
                Image scaled = rgb;
                Float scale = std::exp2(ev);
                for (int y = 0; y < scaled.Resolution().y; ++y)
                    for (int x = 0; x < scaled.Resolution().x; ++x)
                        for (int c = 0; c < 3; ++c)
                            scaled.SetChannel({x, y}, c, scaled.GetChannel({x, y}, c) * scale);
                scaled.Write(out, metadata);
            } else {
                DisplaySettings settings;
                settings.view = view;
                settings.exposureEV = ev;
                ToDisplayImage(rgb, colorSpace, settings).Write(out, metadata);
            }
        }
    } catch (const std::invalid_argument& e) {
        std::cerr << "kiln convert: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "kiln convert: error: " << e.what() << "\n";
        return 1;
    }
    return 0;
}

int RunInfo(const std::vector<std::string>& args) {
    if (args.size() == 1 && (args[0] == "-h" || args[0] == "--help")) {
        std::cout << "usage: " << kInfoUsage << "\n";
        return 0;
    }
    if (args.size() != 1 || args[0].empty() || args[0][0] == '-')
        return Usage("info", args.empty() ? "no image given" : "expects one image", kInfoUsage);
    const std::string& file = args[0];
    ImageMetadata metadata;
    Image image;
    try {
        image = Image::Read(file, &metadata);
    } catch (const std::exception& e) {
        std::cerr << "kiln info: error: " << e.what() << "\n";
        return 1;
    }
    std::printf("%s\n", file.c_str());
    std::printf("  resolution    %d x %d", image.Resolution().x, image.Resolution().y);
    if (metadata.fullResolution && metadata.pixelBounds) {
        const Bounds2i& b = *metadata.pixelBounds;
        if (*metadata.fullResolution != image.Resolution())
            std::printf(" (pixels [%d, %d) x [%d, %d) of a %d x %d frame)", b.pMin.x, b.pMax.x,
                        b.pMin.y, b.pMax.y, metadata.fullResolution->x, metadata.fullResolution->y);
    }
    std::printf("\n  pixels        %s\n", ToString(image.Format()).c_str());
    // Channels by layer: "R, G, B" and e.g. "S1.R, S1.G, S1.B" -> layer "S1" with R, G, B
    std::vector<std::pair<std::string, std::string>> layers;
    for (const std::string& name : image.ChannelNames()) {
        size_t dot = name.rfind('.');
        std::string layer = dot == std::string::npos ? "" : name.substr(0, dot);
        std::string channel = dot == std::string::npos ? name : name.substr(dot + 1);
        if (!layers.empty() && layers.back().first == layer)
            layers.back().second += ", " + channel;
        else
            layers.emplace_back(layer, channel);
    }
    std::printf("  channels      %d\n", image.NChannels());
    for (const auto& [layer, channels] : layers)
        std::printf("    %-11s %s\n", layer.empty() ? "(main)" : layer.c_str(), channels.c_str());
    if (metadata.samplesPerPixel) std::printf("  spp           %d\n", *metadata.samplesPerPixel);
    if (metadata.renderTimeSeconds)
        std::printf("  render time   %.3f s\n", double(*metadata.renderTimeSeconds));
    if (metadata.colorSpace)
        std::printf("  colour space  %s\n", metadata.colorSpace->Name().c_str());
    for (const auto& [key, value] : metadata.strings)
        if (key.rfind("kiln:", 0) == 0 && key != "kiln:checksum")
            std::printf("  %-13s %s\n", key.substr(5).c_str(), value.c_str());
    return 0;
}

}  // namespace kiln
