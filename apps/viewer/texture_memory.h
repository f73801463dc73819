#pragma once
// What the user answered about a scene's missing textures, remembered for the session: per scene
// file, the file picked for a texture name, and the names the user declined to look for (drawn as
// checkerboards from then on). Display-free; the asking is texture_dialog.h.
#include <map>
#include <set>
#include <string>

#include "texture/texture_loader.h"

namespace whitted::viewer {

class TextureMemory {
public:
    // The answers for `scene`, as the load's texture options (overrides, checker names).
    void apply(const std::string& scene, TextureOptions& options) const;
    bool declined(const std::string& scene, const std::string& name) const;
    void decline(const std::string& scene, const std::string& name) { declined_[scene].insert(name); }
    void pick(const std::string& scene, const std::string& name, const std::string& file) {
        picked_[scene][name] = file;
    }

private:
    std::map<std::string, std::map<std::string, std::string>> picked_;  // scene → name → file
    std::map<std::string, std::set<std::string>> declined_;              // scene → names
};

}  // namespace whitted::viewer
