// Outputs checked before anything is parsed or rendered: a render that cannot write what it was
// asked to write fails at once, not after the render.
#pragma once

#include <string>

namespace kiln {

// Throws std::invalid_argument, naming `path` as the user gave it, unless an image can be
// written there: the name has an extension kiln writes (Image::Write; CanWriteImageFormat),
// its folder exists and this process may create files in it, and it is not a folder. `view`:
// the display view for formats that are written through one (all but EXR, PFM and HDR), empty
// for the film's; it must be one of the config's views (the message lists them).
void CheckImageOutput(const std::string& path, const std::string& view);

// Throws std::invalid_argument unless `view` is empty or a display view (the message lists
// them).
void CheckDisplayView(const std::string& view);

}  // namespace kiln
