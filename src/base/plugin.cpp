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

namespace {

// The shared object holding this code when it is one (the Python module), else empty
std::filesystem::path SharedObjectFile() {
    Dl_info info = {};
    if (dladdr(reinterpret_cast<const void*>(&SharedObjectFile), &info) == 0 || !info.dli_fname)
        return {};
    std::filesystem::path file = info.dli_fname;
    if (file.extension() != ".so") return {};  // the executable
    std::error_code ec;
    std::filesystem::path absolute = std::filesystem::weakly_canonical(file, ec);
    return ec ? file : absolute;
}

}  // namespace

std::string InstallPrefix() {
    if (std::filesystem::path module = SharedObjectFile(); !module.empty()) {
        // <prefix>/lib/pythonX.Y/dist-packages/kiln/_kiln....so
        std::filesystem::path prefix = module;
        for (int i = 0; i < 5; ++i) prefix = prefix.parent_path();
        return prefix.string();
    }
    std::string exe = ExecutableDirectory();
    return exe.empty() ? "" : std::filesystem::path(exe).parent_path().string();
}

std::vector<std::string> PluginDirectories() {
    std::vector<std::string> dirs;
    if (SharedObjectFile().empty())
        if (std::string exe = ExecutableDirectory(); !exe.empty()) dirs.push_back(exe);
    if (std::string prefix = InstallPrefix(); !prefix.empty())
        dirs.push_back((std::filesystem::path(prefix) / "lib" / "kiln").string());
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
