// The render command: `kiln SCENE [options]` once the command line is parsed. The scene is
// parsed and created once; one image is rendered, or every frame of --frames, the scene moved
// from frame to frame (Scene::SetAnimation) with a new film each.
#pragma once

#include "app/command_line.h"

namespace kiln {

// Checks every output (app/output_check.h: exit status 2, nothing parsed), then renders and
// writes them; returns the exit status (as RunKiln). Installs the SIGINT and SIGTERM handlers.
int RenderCommand(const CommandLineOptions& options);

}  // namespace kiln
