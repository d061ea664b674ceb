#include "core/working_frame.hpp"

#include <GeographicLib/Constants.hpp>
#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/TransverseMercator.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mc {

namespace {

// Scale 1 on the central meridian: lengths near the building are true lengths.
const GeographicLib::TransverseMercator& projection() {
  static const GeographicLib::TransverseMercator tm(GeographicLib::Constants::WGS84_a(),
                                                    GeographicLib::Constants::WGS84_f(), 1.0);
  return tm;
}

}  // namespace

std::string CoordinateSystem::describe() const {
  std::ostringstream o;
  o.precision(12);
  switch (kind) {
    case Kind::Metric:
      o << "metres";
      break;
    case Kind::Scaled:
      o << horizontal_unit << " m per horizontal unit";
      break;
    case Kind::Geographic:
      o << "degrees (" << (lat_first ? "latitude, longitude" : "longitude, latitude") << ")";
      break;
    case Kind::Geocentric:
      o << "earth-centred metres";
      break;
  }
  if (kind == Kind::Geocentric) return o.str();
  if (kind != Kind::Metric || vertical_unit != 1) {
    if (vertical_unit == 1) o << ", heights in metres";
    else o << ", " << vertical_unit << " m per height unit";
  }
  return o.str();
}

WorkingFrame::WorkingFrame(const CoordinateSystem& cs, const std::vector<Vec3>& points)
    : kind_(cs.kind), lat_first_(cs.lat_first), hscale_(cs.horizontal_unit), vscale_(cs.vertical_unit) {
  if (kind_ == CoordinateSystem::Kind::Metric) hscale_ = 1;
  if (!cs.projected_per_building()) return;
  hscale_ = 1;
  if (kind_ == CoordinateSystem::Kind::Geocentric) vscale_ = 1, lat_first_ = false;
  Vec3 lo{INFINITY, INFINITY, INFINITY}, hi{-INFINITY, -INFINITY, -INFINITY};
  for (const Vec3& p : points)
    if (is_finite(p)) {
      lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
      hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
  if (!(lo.x <= hi.x)) return;  // no finite point: any origin will do
  const Vec3 c = (lo + hi) * 0.5;
  if (kind_ == CoordinateSystem::Kind::Geocentric) {
    double h = 0;
    GeographicLib::Geocentric::WGS84().Reverse(c.x, c.y, c.z, lat0_, lon0_, h);
  } else {
    // Latitudes lie in [-90, 90]; when the declared order puts longitudes beyond that there, the
    // file wrote the other order.
    auto in_range = [&](int axis) { return std::max(std::abs(lo[axis]), std::abs(hi[axis])) <= 90; };
    const int lat = lat_first_ ? 0 : 1;
    if (!in_range(lat) && in_range(1 - lat)) {
      lat_first_ = !lat_first_;
      swapped_ = true;
    }
    lat0_ = lat_first_ ? c.x : c.y;
    lon0_ = lat_first_ ? c.y : c.x;
  }
  double x0 = 0;
  projection().Forward(lon0_, lat0_, lon0_, x0, y0_);
}

Vec3 WorkingFrame::to_metric(const Vec3& f) const {
  double lat = 0, lon = 0, h = 0;
  switch (kind_) {
    case CoordinateSystem::Kind::Metric:
    case CoordinateSystem::Kind::Scaled:
      return {f.x * hscale_, f.y * hscale_, f.z * vscale_};
    case CoordinateSystem::Kind::Geographic:
      lat = lat_first_ ? f.x : f.y, lon = lat_first_ ? f.y : f.x, h = f.z * vscale_;
      break;
    case CoordinateSystem::Kind::Geocentric:
      GeographicLib::Geocentric::WGS84().Reverse(f.x, f.y, f.z, lat, lon, h);
      break;
  }
  double x = 0, y = 0;
  projection().Forward(lon0_, lat, lon, x, y);
  return {x, y - y0_, h};
}

Vec3 WorkingFrame::to_file(const Vec3& m) const {
  if (!(kind_ == CoordinateSystem::Kind::Geographic || kind_ == CoordinateSystem::Kind::Geocentric))
    return {m.x / hscale_, m.y / hscale_, m.z / vscale_};
  double lat = 0, lon = 0;
  projection().Reverse(lon0_, m.x, m.y + y0_, lat, lon);
  // Reverse() gives longitudes in [-180, 180); keep them on the side of the central meridian.
  if (lon - lon0_ > 180) lon -= 360;
  if (lon - lon0_ < -180) lon += 360;
  if (kind_ == CoordinateSystem::Kind::Geocentric) {
    Vec3 x;
    GeographicLib::Geocentric::WGS84().Forward(lat, lon, m.z, x.x, x.y, x.z);
    return x;
  }
  return lat_first_ ? Vec3{lat, lon, m.z / vscale_} : Vec3{lon, lat, m.z / vscale_};
}

void WorkingFrame::to_metric(std::vector<Vec3>& points) const {
  if (identity()) return;
  for (Vec3& p : points) p = to_metric(p);
}

void WorkingFrame::to_file(std::vector<Vec3>& points) const {
  if (identity()) return;
  for (Vec3& p : points) p = to_file(p);
}

}  // namespace mc
