// What the image tests share.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <string>

namespace kiln::testing {

// A path in the system's temporary directory, unique to this process: kiln_PID_name
inline std::string TempFile(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("kiln_" + std::to_string(getpid()) + "_" + name))
        .string();
}

}  // namespace kiln::testing
