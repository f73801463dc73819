#include "cs1230/stage.h"

namespace whitted::cs1230 {

std::optional<Stage> parse_stage(std::string_view name) {
    if (name == "illuminate") return Stage::Illuminate;
    if (name == "intersect") return Stage::Intersect;
    return std::nullopt;
}

const char* stage_name(Stage stage) { return stage == Stage::Intersect ? "intersect" : "illuminate"; }

}  // namespace whitted::cs1230
