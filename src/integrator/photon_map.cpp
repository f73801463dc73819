#include "integrator/photon_map.h"

#include <cmath>

namespace whitted {

glm::ivec3 PhotonMap::cell_of(const glm::vec3& p) const {
    const glm::vec3 c = glm::floor(p * inv_cell_);
    // Far outside any scene the cells repeat: the distance test keeps lookups exact.
    const glm::vec3 lim(1e9f);
    const glm::vec3 k = glm::clamp(c, -lim, lim);
    return {int(k.x), int(k.y), int(k.z)};
}

std::uint32_t PhotonMap::bucket(const glm::ivec3& c) const {
    const std::uint32_t h = std::uint32_t(c.x) * 73856093u ^ std::uint32_t(c.y) * 19349663u ^ std::uint32_t(c.z) * 83492791u;
    return (h ^ (h >> 16)) & mask_;
}

void PhotonMap::clear() {
    photons_ = {};
    start_ = {};
}

void PhotonMap::build(std::vector<Photon> photons, float radius) {
    radius_ = radius;
    inv_cell_ = 1.0f / (2.0f * radius);
    std::uint32_t buckets = 1;
    while (buckets < 2 * photons.size() && buckets < (1u << 30)) buckets <<= 1;
    mask_ = buckets - 1;
    start_.assign(std::size_t(buckets) + 1, 0);
    std::vector<std::uint32_t> of(photons.size());
    for (std::size_t i = 0; i < photons.size(); ++i) ++start_[(of[i] = bucket(cell_of(photons[i].position))) + 1];
    for (std::uint32_t b = 0; b < buckets; ++b) start_[b + 1] += start_[b];
    photons_.resize(photons.size());
    std::vector<std::uint32_t> next(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < photons.size(); ++i) photons_[next[of[i]]++] = photons[i];
}

}  // namespace whitted
