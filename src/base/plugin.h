// Plugins: shared libraries of kiln's own (libkiln_oiio.so, libkiln_openvdb.so) that wrap a
// heavy dependency, loaded with dlopen the first time a scene needs them, so that a process
// that does not need OpenImageIO or OpenVDB never loads them.
#pragma once

#include <string>
#include <vector>

namespace kiln {

// The folder of the running executable ("" if /proc/self/exe cannot be read).
std::string ExecutableDirectory();

// The installation prefix kiln's code runs from: <prefix>/bin/kiln, or for the Python module
// <prefix>/lib/pythonX.Y/dist-packages/kiln/_kiln*.so ("" if unknown). In a build tree it names
// a folder that holds no kiln installation.
std::string InstallPrefix();

// Where plugins are looked for, in order: beside the running kiln executable (a build tree),
// in the installed tree (<InstallPrefix()>/lib/kiln: `cmake --install`, the Debian package),
// then the build directory kiln was built in (KILN_PLUGIN_DIR).
std::vector<std::string> PluginDirectories();

// The first of PluginDirectories() that holds `library`; "" if none does.
std::string PluginDirectory(const std::string& library);

// The address of `symbol` in plugin `library` ("libkiln_oiio.so"), loaded once per process and
// never unloaded, from the first of PluginDirectories() where it loads. Throws std::runtime_error
// naming the paths tried and dlerror()'s reason when none loads or the symbol is missing.
// Thread-safe.
void* PluginSymbol(const std::string& library, const char* symbol);

}  // namespace kiln
