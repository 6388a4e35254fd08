#include "base/system_memory.h"

#include <unistd.h>

#include <cstdio>

namespace kiln {

double PhysicalMemoryBytes() {
    long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || pageSize <= 0) return 0;
    return double(pages) * double(pageSize);
}

std::string FormatBytes(double bytes) {
    const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
    int u = 0;
    while (bytes >= 1000 && u < 5) bytes /= 1000, ++u;
    char s[32];
    std::snprintf(s, sizeof(s), u == 0 ? "%.0f %s" : "%.3g %s", bytes, units[u]);
    return s;
}

}  // namespace kiln
