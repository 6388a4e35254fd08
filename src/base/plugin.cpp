#include "base/plugin.h"

#include <dlfcn.h>

#include <filesystem>
#include <stdexcept>

namespace kiln {

void* PluginSymbol(const std::string& library, const char* symbol) {
    // dlopen is thread-safe and counts references: a library already loaded is not loaded again
    std::error_code ec;
    std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    std::string tried;
    void* handle = nullptr;
    for (const std::string& dir :
         {ec ? std::string() : exe.parent_path().string(), std::string(KILN_PLUGIN_DIR)}) {
        if (dir.empty()) continue;
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
