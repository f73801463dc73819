// libFuzzer target: any bytes as a scene file, through the lexer, parser and checks.
// Whatever the input, parsing must return (errors as values), never crash or read out of bounds.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "parse/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    whitted::parse_scene_text(text, "fuzz.sc", {false});
    whitted::parse_scene_text(text, "fuzz.sc", {true});  // lenient: the skipping paths
    return 0;
}
