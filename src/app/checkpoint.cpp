#include "app/checkpoint.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "core/film/film.h"

namespace kiln {

namespace {

constexpr char kMagic[] = "kiln checkpoint 1\n";

std::string Header(const CheckpointIdentity& id, int completed) {
    std::ostringstream s;
    s << kMagic << "scene " << id.scene << "\nframe " << id.frame << "\nseed " << id.seed
      << "\nspp " << id.spp << "\nbounds " << id.pixelBounds.pMin.x << " " << id.pixelBounds.pMin.y
      << " " << id.pixelBounds.pMax.x << " " << id.pixelBounds.pMax.y << "\ncompleted " << completed
      << "\n\n";
    return s.str();
}

}  // namespace

std::string CheckpointFile(const std::string& output) { return output + ".checkpoint"; }

void WriteCheckpoint(const std::string& file, const CheckpointIdentity& id, int completed,
                     const RGBFilm& film) {
    std::string tmp = file + ".writing";
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        out << Header(id, completed) << film.SaveState();
        out.flush();
        if (!out) throw std::runtime_error(tmp + ": cannot write the checkpoint");
    }
    std::error_code ec;
    std::filesystem::rename(tmp, file, ec);
    if (ec) throw std::runtime_error(file + ": cannot write the checkpoint: " + ec.message());
}

int ReadCheckpoint(const std::string& file, const CheckpointIdentity& id, RGBFilm& film,
                   std::string* why) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return 0;
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
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
        *why = file + " is from another render (scene, frame, seed, spp or pixels differ)";
        return 0;
    }
    if (!film.LoadState(std::string_view(bytes).substr(end + 2))) {
        *why = file + " is damaged (its film state does not fit)";
        return 0;
    }
    return completed;
}

void RemoveCheckpoint(const std::string& file) {
    std::error_code ec;
    std::filesystem::remove(file, ec);
    std::filesystem::remove(file + ".writing", ec);
}

}  // namespace kiln
