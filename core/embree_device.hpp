// The process's one Embree device, shared by the ray-casting oracles and the closest-point
// queries: creating one per building would respawn Embree's thread pool each time.
#pragma once
#include <embree3/rtcore.h>

namespace mc {

// Created on first use; thread-safe. Throws std::runtime_error when Embree cannot start.
RTCDevice shared_embree_device();

}  // namespace mc
