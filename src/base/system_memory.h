// The machine's memory, for checking that large allocations (films, meshes) fit before they
// are made, and byte counts for messages.
#pragma once

#include <string>

namespace kiln {

// Physical memory of this machine in bytes (sysconf); 0 if unknown.
double PhysicalMemoryBytes();

// "1.5 GB", "320 MB", "12 kB", "17 bytes" (decimal units).
std::string FormatBytes(double bytes);

}  // namespace kiln
