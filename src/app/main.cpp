// kiln: renders a pbrt-v4 scene file. Everything but option dispatch lives in the library.
#include "app/command_line.h"

int main(int argc, char** argv) { return kiln::RunKiln(argc, argv); }
