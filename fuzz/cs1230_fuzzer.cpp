// libFuzzer target: any bytes as a Brown CSCI 1230 JSON scene file, through the JSON parser and
// the scene reader. Whatever the input, reading must return (errors as values), never crash,
// read out of bounds or recurse without bound.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cs1230/scene_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    whitted::cs1230::read_scene(text, "/fuzz/scenes/fuzz.json");
    return 0;
}
