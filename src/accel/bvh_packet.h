#pragma once
// Nearest-hit query for a packet of rays traversed together through the 4-wide BVH. Coherent
// rays (neighbouring camera rays) share most of their path through the tree, so one node fetch
// and one branch serve the whole packet, and the box tests of its rays fill the SIMD lanes:
// a single ray's traversal is a chain of dependent steps, a packet's is independent work.
// Any rays are correct (each lane keeps its own nearest distance); only the speed needs coherence.
#include <cstdint>
#include <vector>

#include "accel/bvh.h"

namespace whitted {

// For every lane l whose bit is set in `active`: exactly what
// intersect_nearest(bvh, instances, rays[l], t_min, t_max, hits[l]) returns (the same t,
// instance and part, ties to the lowest instance index); bit l of the result says whether it hit.
// A scene with mesh instances (given `meshes`; its top level is 8-wide, bvh_node.h) is traced one
// lane at a time.
// hits[l] is written only for lanes that hit. No allocation.
unsigned intersect_nearest_packet(const Bvh& bvh, const std::vector<Instance>& instances,
                                  const Ray (&rays)[kPacketSize], unsigned active, float t_min, float t_max,
                                  Hit (&hits)[kPacketSize], const std::vector<MeshBvh>* meshes = nullptr);

}  // namespace whitted
