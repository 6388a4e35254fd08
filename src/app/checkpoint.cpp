#include "app/checkpoint.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>

#include "base/atomic_file.h"
#include "base/file_reading.h"
#include "base/rng.h"
#include "core/film/film.h"

namespace kiln {

namespace {

constexpr char kMagic[] = "kiln checkpoint 3\n";

std::string Header(const CheckpointIdentity& id, int completed) {
    std::ostringstream s;
    s << kMagic << "scene " << id.scene << "\noptions " << id.options << "\nframe " << id.frame
      << "\nseed " << id.seed << "\nspp " << id.spp << "\nbounds " << id.pixelBounds.pMin.x << " "
      << id.pixelBounds.pMin.y << " " << id.pixelBounds.pMax.x << " " << id.pixelBounds.pMax.y
      << "\ncompleted " << completed << "\n\n";
    return s.str();
}

}  // namespace

std::string CheckpointFile(const std::string& output) { return output + ".checkpoint"; }

std::string CheckpointChecksumLine(std::string_view contents) {
    char line[40];
    std::snprintf(line, sizeof(line), "checksum %016llx\n",
                  static_cast<unsigned long long>(HashBytes(contents.data(), contents.size())));
    return line;
}

void WriteCheckpoint(const std::string& file, const CheckpointIdentity& id, int completed,
                     const RGBFilm& film) {
    try {
        std::string contents = Header(id, completed) + film.SaveState();
        WriteFileAtomically(file, contents + CheckpointChecksumLine(contents));
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("cannot write the checkpoint: ") + e.what());
    }
}

int ReadCheckpoint(const std::string& file, const CheckpointIdentity& id, RGBFilm& film,
                   std::string* why) {
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(file, ec))) return 0;
    // Only a regular file no larger than this film's state and a header (not a directory, a
    // FIFO or a device, which would never end)
    std::string bytes, error;
    uint64_t maxBytes = film.SaveState().size() + 4096;
    if (!ReadFileBytes(file, &bytes, &error, maxBytes)) {
        *why = file + ": " + error;
        return 0;
    }
    return RestoreCheckpoint(std::move(bytes), file, id, film, why);
}

int RestoreCheckpoint(std::string bytes, const std::string& file, const CheckpointIdentity& id,
                      RGBFilm& film, std::string* why) {
    // The checksum of all before it
    constexpr size_t kChecksumLine = kCheckpointChecksumLineBytes;
    if (bytes.size() < kChecksumLine ||
        bytes.compare(bytes.size() - kChecksumLine, kChecksumLine,
                      CheckpointChecksumLine(
                          std::string_view(bytes).substr(0, bytes.size() - kChecksumLine))) != 0) {
        *why = bytes.compare(0, sizeof(kMagic) - 1, kMagic) == 0
                   ? file + " is damaged (its checksum does not match)"
                   : file + " is not a kiln checkpoint (of this version)";
        return 0;
    }
    bytes.resize(bytes.size() - kChecksumLine);
    size_t end = bytes.find("\n\n");
    if (bytes.compare(0, sizeof(kMagic) - 1, kMagic) != 0 || end == std::string::npos) {
        *why = file + " is not a kiln checkpoint";
        return 0;
    }
    // The header must be this render's, for some number of completed samples
    std::string header = bytes.substr(0, end + 2);
    size_t at = header.find("completed ");
    int completed = at == std::string::npos ? 0 : std::atoi(header.c_str() + at + 10);
    if (completed <= 0 || completed >= id.spp || header != Header(id, completed)) {
        *why = file + " is from another render (scene, options, frame, seed, spp or pixels differ)";
        return 0;
    }
    if (!film.LoadState(std::string_view(bytes).substr(end + 2))) {
        *why =
            file + " is damaged (its film state does not fit, or holds values kiln never writes)";
        return 0;
    }
    return completed;
}

void RemoveCheckpoint(const std::string& file) {
    // Only a checkpoint kiln could have written: a regular file (not what else has the name),
    // and the temporaries of writes that a kill interrupted
    std::error_code ec;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(file, ec)))
        std::filesystem::remove(file, ec);
    RemoveStaleTemporaries(file);
}

}  // namespace kiln
