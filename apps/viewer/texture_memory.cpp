#include "texture_memory.h"

namespace whitted::viewer {

void TextureMemory::apply(const std::string& scene, TextureOptions& options) const {
    if (auto it = picked_.find(scene); it != picked_.end()) options.overrides = it->second;
    if (auto it = declined_.find(scene); it != declined_.end()) options.checker_names = it->second;
}

bool TextureMemory::declined(const std::string& scene, const std::string& name) const {
    const auto it = declined_.find(scene);
    return it != declined_.end() && it->second.count(name) > 0;
}

}  // namespace whitted::viewer
