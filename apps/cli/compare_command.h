#pragma once
// `whitted compare A B`: how far an image is from the reference (src/compare), with idiff's
// thresholds and exit codes.

namespace whitted::cli {

// Exit codes, idiff's: 0 pass, 1 warning, 2 failure, 3 the images differ in size, 4 an image
// cannot be read (or the --diff image written, or memory ran out); 5 bad usage; 130 interrupted.
constexpr int kComparePass = 0, kCompareWarn = 1, kCompareFail = 2, kCompareSize = 3, kCompareFile = 4,
              kCompareUsage = 5;

// Runs the subcommand; argv[0] is "compare". Returns the exit code.
int compare_main(int argc, char** argv);

}  // namespace whitted::cli
