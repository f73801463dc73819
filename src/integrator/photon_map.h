#pragma once
// A pass's photons, found by position: a hashed grid of cells 2r wide, so that the sphere of
// radius r around any point overlaps at most 2 × 2 × 2 cells. Built by a stable counting sort on
// the cell's hash: the photons of a bucket keep the order they were traced in, so a lookup sums
// them in the same order for any thread count.
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

namespace whitted {

struct Photon {
    glm::vec3 position;
    glm::vec3 wi;     // unit, toward where the photon came from
    glm::vec3 power;  // flux, before the division by the photons emitted
};

class PhotonMap {
public:
    // Takes the photons and the radius lookups will use.
    void build(std::vector<Photon> photons, float radius);
    void clear();

    float radius() const { return radius_; }
    std::size_t size() const { return photons_.size(); }
    const std::vector<Photon>& photons() const { return photons_; }  // in bucket order
    // The memory the map holds.
    std::size_t bytes() const { return photons_.capacity() * sizeof(Photon) + start_.capacity() * sizeof(std::uint32_t); }

    // Calls f(photon) for every photon closer to p than the radius, in a fixed order.
    template <class F>
    void for_each_near(const glm::vec3& p, F&& f) const {
        if (photons_.empty()) return;
        const glm::ivec3 lo = cell_of(p - glm::vec3(radius_)), hi = cell_of(p + glm::vec3(radius_));
        std::uint32_t seen[8];
        int n = 0;
        const float r2 = radius_ * radius_;
        for (int z = lo.z; z <= hi.z; ++z)
            for (int y = lo.y; y <= hi.y; ++y)
                for (int x = lo.x; x <= hi.x; ++x) {
                    const std::uint32_t b = bucket({x, y, z});
                    bool again = false;  // two cells of one hash: its photons once
                    for (int k = 0; k < n; ++k) again = again || seen[k] == b;
                    if (again) continue;
                    seen[n++] = b;
                    for (std::uint32_t i = start_[b]; i < start_[b + 1]; ++i) {
                        const glm::vec3 d = photons_[i].position - p;
                        if (glm::dot(d, d) < r2) f(photons_[i]);
                    }
                }
    }

private:
    glm::ivec3 cell_of(const glm::vec3& p) const;
    std::uint32_t bucket(const glm::ivec3& c) const;

    std::vector<Photon> photons_;      // by bucket
    std::vector<std::uint32_t> start_;  // bucket b's photons: [start_[b], start_[b + 1])
    float radius_ = 0.0f, inv_cell_ = 1.0f;
    std::uint32_t mask_ = 0;
};

}  // namespace whitted
