// What the image tests share.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

#include "core/image/image.h"
#include "spectral/color.h"

namespace kiln::testing {

// A path in the system's temporary directory, unique to this process: kiln_PID_name
inline std::string TempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("kiln_" + std::to_string(getpid()) + "_" + name))
        .string();
}

// The metadata of a tile of a render: time, spp, frame size and pixel bounds, sRGB, scene
inline ImageMetadata TileMetadata() {
    ImageMetadata md;
    md.renderTimeSeconds = 12.5f;
    md.samplesPerPixel = 64;
    md.fullResolution = Point2i(10, 8);
    md.pixelBounds = Bounds2i{{2, 4}, {7, 7}};
    md.colorSpace = &RGBColorSpace::sRGB();
    md.strings["kiln:scene"] = "cornell.pbrt";
    return md;
}

}  // namespace kiln::testing
