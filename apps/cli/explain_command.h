#pragma once
// `whitted explain SCENE IMAGE`: why an image differs from whitted's render of its scene
// (src/compare/explain.h): the classic mistake it matches, the terms that explain the difference,
// the worst regions with the inspector's account of their centre pixels.

namespace whitted::cli {

// Exit codes, as `whitted compare` (idiff's): 0 no difference, 1 warning, 2 the image differs; 3
// the image is not the size asked for with --width/--height, 4 the image cannot be read (or the
// error image written, or memory ran out), 5 bad usage, 6 bad scene; 130 interrupted.
constexpr int kExplainSame = 0, kExplainWarn = 1, kExplainDiffers = 2, kExplainSize = 3, kExplainFile = 4,
              kExplainUsage = 5, kExplainScene = 6;

// Runs the subcommand; argv[0] is "explain". Returns the exit code.
int explain_main(int argc, char** argv);

}  // namespace whitted::cli
