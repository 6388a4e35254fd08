#include "base/plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>

namespace kiln {

std::string ExecutableDirectory() {
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return ec ? std::string() : exe.parent_path().string();
}

std::vector<std::string> PluginDirectories() {
    std::vector<std::string> dirs;
    if (std::string exe = ExecutableDirectory(); !exe.empty()) {
        dirs.push_back(exe);
        dirs.push_back((std::filesystem::path(exe).parent_path() / "lib" / "kiln").string());
    }
    dirs.push_back(KILN_PLUGIN_DIR);
    return dirs;
}

std::string PluginDirectory(const std::string& library) {
    std::error_code ec;
    for (const std::string& dir : PluginDirectories())
        if (std::filesystem::exists(std::filesystem::path(dir) / library, ec)) return dir;
    return "";
}

void* PluginSymbol(const std::string& library, const char* symbol) {
    // dlopen is thread-safe and counts references: a library already loaded is not loaded again
    std::string tried;
    void* handle = nullptr;
    for (const std::string& dir : PluginDirectories()) {
        std::string path = dir + "/" + library;
        handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (handle) break;
        const char* why = dlerror();
        tried += "\n  " + path + ": " + (why ? why : "cannot load");
    }
    if (!handle) throw std::runtime_error("cannot load kiln's plugin " + library + tried);
    void* address = dlsym(handle, symbol);
    if (!address) throw std::runtime_error("kiln's plugin " + library + " has no symbol " + symbol);
    return address;
}

}  // namespace kiln
