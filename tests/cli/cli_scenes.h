#pragma once
// Scenes the CLI tests render.
#include <string>

namespace whitted::test {

inline const char* kSimpleScene = R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)";

// Many mirrors: seconds of work at a big size and depth 12, so an interrupt lands mid-render.
// Glass mirrors (a Whitted tree of 2^depth rays a pixel) below the horizon, nothing above it: the
// upper half of the image renders at once, the lower half takes minutes at --max-depth 12, so a
// signal after a few hundred milliseconds finds tiles rendered and many to go.
inline std::string heavy_scene() {
    std::string text = "camera [ eye 0 0 12 focus 0 0 0 ]\nlight [ position 3 3 10 color 1 1 1 ]\nmastersubgraph root [\n";
    for (int i = 0; i < 400; ++i)
        text += "trans [ translate " + std::to_string(i % 20 - 10) + " " + std::to_string(-1 - (i / 20) % 10) + " " +
                std::to_string(-2 * (i / 200)) + " object sphere [ reflect .9 .9 .9 transparent .5 .5 .5 ior 1.3 ] ]\n";
    return text + "]\n";
}

}  // namespace whitted::test
