#include "data/provenance.h"

#include <algorithm>

namespace whitted {

const char* link_keyword(LinkKind kind) {
    switch (kind) {
        case LinkKind::Mastersubgraph: return "mastersubgraph";
        case LinkKind::Trans: return "trans";
        case LinkKind::Subgraph: return "subgraph";
        case LinkKind::ImplicitRoot: return "the top-level trans blocks";
        case LinkKind::JsonRoot: return "the file's groups";
        case LinkKind::JsonGroup: return "group";
        case LinkKind::JsonTemplateUse: return "group naming template";
        case LinkKind::JsonTemplate: return "template group";
    }
    return "?";
}

std::uint32_t Provenance::Table::intern(const std::string& s) {
    const auto [it, inserted] = index.try_emplace(s, std::uint32_t(strings.size()));
    if (inserted) strings.push_back(s);
    return it->second;
}

Provenance::Loc Provenance::compact(const SourceLoc& loc) {
    // Nearly every location is in the file the last one was in: no hashing for those.
    if (last_file_ == kNone || files_.strings[last_file_] != loc.file) last_file_ = files_.intern(loc.file);
    return Loc{last_file_, loc.line, loc.col};
}

SourceLoc Provenance::expand(const Loc& loc) const {
    SourceLoc out;
    if (loc.file != kNone) out.file = files_.strings[loc.file];
    out.line = loc.line;
    out.col = loc.col;
    return out;
}

std::uint32_t Provenance::add_site(LinkKind kind, const std::string& name, const SourceLoc& loc, std::uint32_t then) {
    const std::uint32_t n = name.empty() ? kNone : names_.intern(name);
    sites_.push_back(Site{compact(loc), n, then, kind});
    return std::uint32_t(sites_.size() - 1);
}

void Provenance::add_material(const SourceLoc& object, const std::string& texture_file) {
    material_objects_.push_back(compact(object));
    material_textures_.push_back(texture_file.empty() ? kNone : names_.intern(texture_file));
}

void Provenance::reorder_instances(const std::vector<std::uint32_t>& order) {
    if (instance_chain_.size() != order.size()) {  // not recorded for these instances: claim nothing
        instance_chain_.clear();
        return;
    }
    std::vector<std::uint32_t> reordered(order.size());
    for (std::size_t i = 0; i < order.size(); ++i) reordered[i] = instance_chain_[order[i]];
    instance_chain_ = std::move(reordered);
}

std::vector<ChainLink> Provenance::chain(std::uint32_t instance) const {
    std::vector<ChainLink> out;
    if (!has_instance(instance)) return out;
    const auto emit = [&](std::uint32_t site) {
        const Site& s = sites_[site];
        out.push_back({s.kind, s.name == kNone ? std::string() : names_.strings[s.name], expand(s.loc)});
    };
    // Bottom up, reversed at the end: a `subgraph` link's mastersubgraph line goes below it.
    for (std::uint32_t l = instance_chain_[instance]; l != kNone; l = links_[l].parent) {
        const std::uint32_t site = links_[l].site;
        if (sites_[site].then != kNone) emit(sites_[site].then);
        emit(site);
    }
    std::reverse(out.begin(), out.end());
    return out;
}

SourceLoc Provenance::material_object(std::uint32_t m) const {
    return m < material_objects_.size() ? expand(material_objects_[m]) : SourceLoc{};
}

std::string Provenance::material_texture(std::uint32_t m) const {
    if (m >= material_textures_.size() || material_textures_[m] == kNone) return "";
    return names_.strings[material_textures_[m]];
}

SourceLoc Provenance::light(std::size_t l) const { return l < lights_.size() ? expand(lights_[l]) : SourceLoc{}; }

}  // namespace whitted
