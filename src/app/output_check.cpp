#include "app/output_check.h"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "core/image/display.h"
#include "core/image/image.h"

namespace kiln {

void CheckDisplayView(const std::string& view) {
    if (view.empty()) return;
    for (const std::string& v : DisplayViews())
        if (v == view) return;
    throw std::invalid_argument(UnknownViewMessage(view));
}

void CheckImageOutput(const std::string& path, const std::string& view) {
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) { throw std::invalid_argument(path + ": " + why); };
    if (path.empty()) throw std::invalid_argument("an output file name is empty");
    std::string ext = FileExtension(path);
    if (ext.empty()) fail("no file extension to choose the image format (e.g. .exr, .png)");
    bool writable = false;
    try {
        writable = CanWriteImageFormat(ext);
    } catch (const std::exception& e) {
        fail(std::string("cannot check the format: ") + e.what());
    }
    if (!writable) fail("kiln cannot write ." + ext + " images (EXR, PNG, PFM, JPEG, TIFF, ...)");
    if (ext != "exr" && ext != "pfm" && ext != "hdr") CheckDisplayView(view);
    std::error_code ec;
    fs::path target(path);
    if (fs::is_directory(target, ec)) fail("is a folder");
    fs::path folder = target.parent_path();
    if (folder.empty()) folder = ".";
    if (!fs::exists(folder, ec)) fail("folder \"" + folder.string() + "\" does not exist");
    if (!fs::is_directory(folder, ec)) fail("\"" + folder.string() + "\" is not a folder");
    if (access(folder.c_str(), W_OK | X_OK) != 0)
        fail("cannot create files in \"" + folder.string() + "\": " + std::strerror(errno));
}

}  // namespace kiln
