#pragma once
// Where each flattened thing came from in the scene file: for every instance the chain of
// mastersubgraph / trans / subgraph lines above its object, for every material its object block,
// for every light its block. A side table (the pixel inspector reads it), never touched by ray
// traversal: the instance array stays as small as it was.
//
// Chains share their prefixes: every link names its parent, so an instance costs one index and
// a subgraph used a thousand times adds its own lines once per use, not once per object. A line
// of the file (a site) is stored once, a use of it (a link) in 8 bytes: a scene of a million
// instances through twenty levels of subgraphs keeps its chains in tens of megabytes.
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "base/diagnostic.h"

namespace whitted {

// ImplicitRoot: a Brown/Tufts file's top-level trans blocks, the root no line names (§9.4).
// The Json kinds are a CSCI 1230 file's (§9.5): its top-level `groups`, a group (the innermost one
// holding the object, whose matrix it is), a group naming a template, the template group itself.
enum class LinkKind : unsigned char {
    Mastersubgraph, Trans, Subgraph, ImplicitRoot, JsonRoot, JsonGroup, JsonTemplateUse, JsonTemplate
};
const char* link_keyword(LinkKind kind);  // "mastersubgraph", "trans", "subgraph", "the top-level trans blocks", …


// One line of a chain, resolved for reading.
struct ChainLink {
    LinkKind kind;
    std::string name;  // mastersubgraph / subgraph: the subgraph's name; trans: ""
    SourceLoc loc;     // the keyword (mastersubgraph, trans) or the name after `subgraph`
};

class Provenance {
public:
    static constexpr std::uint32_t kNone = 0xffffffffu;

    // Building (flatten). A site is one line a chain can pass through, made once per line: its
    // keyword's kind, the subgraph's name, the location; a `subgraph` line's site names the
    // `mastersubgraph` site it leads to (`then`), so one link stands for both lines.
    std::uint32_t add_site(LinkKind kind, const std::string& name, const SourceLoc& loc, std::uint32_t then = kNone);
    // A use of `site` below link `parent` (kNone: a chain's top); returns the link's index.
    std::uint32_t add_link(std::uint32_t parent, std::uint32_t site) {
        links_.push_back(Link{parent, site});
        return std::uint32_t(links_.size() - 1);
    }
    // Room for the walk's links and instances at once: no doubling of a large table mid-walk.
    void reserve(std::size_t links, std::size_t instances) {
        links_.reserve(links);
        instance_chain_.reserve(instances);
    }
    void add_instance(std::uint32_t chain) { instance_chain_.push_back(chain); }
    void add_material(const SourceLoc& object, const std::string& texture_file);
    void add_light(const SourceLoc& loc) { lights_.push_back(compact(loc)); }
    // The BVH reorders the instances: instance i is now the one that was at order[i].
    void reorder_instances(const std::vector<std::uint32_t>& order);

    // Reading. Whether anything was recorded for the instance (scenes built by hand have none).
    bool has_instance(std::uint32_t instance) const { return instance < instance_chain_.size(); }
    // The chain above the instance's object, from the root down to the trans block holding it.
    std::vector<ChainLink> chain(std::uint32_t instance) const;
    // The `object` keyword of material `m`'s block (materials are one per object block), the
    // texture file as written there ("" = none).
    SourceLoc material_object(std::uint32_t m) const;
    std::string material_texture(std::uint32_t m) const;
    SourceLoc light(std::size_t l) const;

private:
    struct Loc {
        std::uint32_t file = kNone;  // into files_
        int line = 0, col = 0;
    };
    struct Site {
        Loc loc;
        std::uint32_t name;  // into names_, kNone = none
        std::uint32_t then;  // a `subgraph` line: the site of the mastersubgraph it names
        LinkKind kind;
    };
    struct Link {
        std::uint32_t parent, site;
    };
    Loc compact(const SourceLoc& loc);
    SourceLoc expand(const Loc& loc) const;
    struct Table {
        std::vector<std::string> strings;
        std::unordered_map<std::string, std::uint32_t> index;
        std::uint32_t intern(const std::string& s);
    };

    Table files_, names_;  // file paths; subgraph names and texture files
    std::uint32_t last_file_ = kNone;
    std::vector<Site> sites_;
    std::vector<Link> links_;
    std::vector<std::uint32_t> instance_chain_;  // per instance: its innermost link
    std::vector<Loc> material_objects_, lights_;
    std::vector<std::uint32_t> material_textures_;  // into names_, kNone = no texture
};

}  // namespace whitted
