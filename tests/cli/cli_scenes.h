#pragma once
// Scenes the CLI tests render.
#include <string>

namespace whitted::test {

inline const char* kSimpleScene = R"(camera [ eye 0 0 5 focus 0 0 0 ]
light [ position 2 2 5 color 1 1 1 ]
mastersubgraph root [ trans [ object sphere [ diffuse 1 0 0 ] ] ]
)";

// Many mirrors: seconds of work at a big size, so an interrupt lands mid-render (at depth 1 a tile
// takes milliseconds, so that some are done by then: a render with none done writes nothing).
inline std::string heavy_scene() {
    std::string text = "camera [ eye 0 0 12 focus 0 0 0 ]\nlight [ position 3 3 10 color 1 1 1 ]\nmastersubgraph root [\n";
    for (int i = 0; i < 400; ++i)
        text += "trans [ translate " + std::to_string(i % 20 - 10) + " " + std::to_string(i / 20 - 10) +
                " 0 object sphere [ reflect .9 .9 .9 transparent .5 .5 .5 ior 1.3 ] ]\n";
    return text + "]\n";
}

}  // namespace whitted::test
