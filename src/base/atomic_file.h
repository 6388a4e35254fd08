// Writing a file so that a reader never sees half of it and nothing else is touched: the data go
// to a new temporary file in the target's folder, created exclusively under a fresh unique name
// (never an existing file, and never through a planted symbolic link), are written and closed
// with every error checked, and the temporary is then renamed over the target. On any error the
// temporary is removed and the target, if it existed, is untouched.
#pragma once

#include <string>
#include <string_view>

namespace kiln {

// Writes data to path as above, with permissions rw-r--r-- (rwxr-xr-x if executable); throws
// std::runtime_error naming path and the cause.
void WriteFileAtomically(const std::string& path, std::string_view data, bool executable = false);

// Removes the temporaries a writer of path killed mid-write left behind: regular files named
// path.tmp.XXXXXX (six characters), as WriteFileAtomically names them (a file name too long
// for that suffix is shortened first, so that any name that fits can be written).
void RemoveStaleTemporaries(const std::string& path);

// Removes the temporary a WriteFileAtomically call is writing at this moment, if any; safe to
// call from a signal handler (kiln's second Ctrl-C ends the process through it). The name
// sits in static storage, the one place a signal handler can reach.
void RemovePendingTemporaryFile() noexcept;

}  // namespace kiln
