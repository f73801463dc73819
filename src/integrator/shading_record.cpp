#include "integrator/shading_record.h"

namespace whitted {

SecondaryRecord& ShadingRecorder::record(const Pending& p) {
    ShadeNode& n = nodes[std::size_t(p.node)];
    return p.kind == SecondaryKind::Reflect ? n.reflect : n.refract;
}

void ShadingRecorder::hit(const Ray& ray, const Hit& hit, const Surface& s, const glm::vec3& n, bool outside,
                          int depth) {
    if (nodes.size() >= kMaxNodes) {
        open_.push_back(-1);
        return;
    }
    ShadeNode node;
    node.depth = depth;
    node.ray = ray;
    node.hit = hit;
    node.surface = s;
    node.facing_normal = n;
    node.outside = outside;
    nodes.push_back(std::move(node));
    const int index = int(nodes.size() - 1);
    if (!pending_.empty() && pending_.back().node >= 0) record(pending_.back()).node = index;
    open_.push_back(index);
}

void ShadingRecorder::miss(const glm::vec3& bg) {
    if (pending_.empty()) {
        camera_ray_missed = true;
        background = bg;
    }
    // A secondary ray that missed keeps node = -1; secondary_color records the background.
}

void ShadingRecorder::secondary(SecondaryKind kind, SecondaryRecord::Outcome outcome, const Ray& ray,
                                const glm::vec3& weight) {
    const Pending p{open_.back(), kind};
    if (outcome == SecondaryRecord::Outcome::Traced) pending_.push_back(p);
    if (p.node < 0) return;
    SecondaryRecord& r = record(p);
    r.outcome = outcome;
    r.ray = ray;
    r.weight = weight;
}

void ShadingRecorder::secondary_color(const glm::vec3& color, const glm::vec3& contribution) {
    if (pending_.back().node >= 0) {
        SecondaryRecord& r = record(pending_.back());
        r.color = color;
        r.contribution = contribution;
    }
    pending_.pop_back();
}

void ShadingRecorder::done(const glm::vec3& color) {
    if (open_.back() >= 0) nodes[std::size_t(open_.back())].color = color;
    open_.pop_back();
}

}  // namespace whitted
