#include "core/embree_device.hpp"

#include <stdexcept>

namespace mc {

RTCDevice shared_embree_device() {
  static RTCDevice device = [] {
    RTCDevice d = rtcNewDevice(nullptr);
    if (!d) throw std::runtime_error("Embree: cannot create device");
    return d;
  }();
  return device;
}

}  // namespace mc
