// Plugins: shared libraries of kiln's own (libkiln_oiio.so, libkiln_openvdb.so) that wrap a
// heavy dependency, loaded with dlopen the first time a scene needs them, so that a process
// that does not need OpenImageIO or OpenVDB never loads them.
#pragma once

#include <string>

namespace kiln {

// The address of `symbol` in plugin `library` ("libkiln_oiio.so"), loaded once per process and
// never unloaded. The library is looked for beside the running executable, then in the build
// directory it was built in (KILN_PLUGIN_DIR). Throws std::runtime_error naming the paths tried
// and dlerror()'s reason when neither loads or the symbol is missing. Thread-safe.
void* PluginSymbol(const std::string& library, const char* symbol);

}  // namespace kiln
