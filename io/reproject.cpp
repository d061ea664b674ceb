#include "io/reproject.hpp"

#include <proj.h>

#include <cmath>
#include <stdexcept>

#include "io/cityjson_common.hpp"
#include "io/crs.hpp"

namespace mc::io {

using nlohmann::json;

struct Reprojector::Impl {
  PJ_CONTEXT* ctx = nullptr;
  PJ* op = nullptr;
  ~Impl() {
    if (op) proj_destroy(op);
    if (ctx) proj_context_destroy(ctx);
  }
  // The horizontal part of a compound CRS (heights are not transformed).
  PJ* horizontal(const std::string& crs) {
    PJ* c = proj_create(ctx, normalize_crs(crs).c_str());
    if (!c) throw std::runtime_error("unknown CRS '" + crs + "'");
    if (proj_get_type(c) == PJ_TYPE_COMPOUND_CRS) {
      PJ* h = proj_crs_get_sub_crs(ctx, c, 0);
      proj_destroy(c);
      if (!h) throw std::runtime_error("cannot take the horizontal part of '" + crs + "'");
      c = h;
    }
    return c;
  }
};

Reprojector::Reprojector(const std::string& from, const std::string& to) : impl_(std::make_unique<Impl>()) {
  impl_->ctx = proj_context_create();
  if (!impl_->ctx) throw std::runtime_error("cannot create a PROJ context");
  proj_context_set_enable_network(impl_->ctx, 0);  // offline and deterministic: no grid downloads
  proj_log_level(impl_->ctx, PJ_LOG_NONE);
  PJ* src = impl_->horizontal(from);
  PJ* dst = nullptr;
  try {
    dst = impl_->horizontal(to);
  } catch (...) {
    proj_destroy(src);
    throw;
  }
  PJ* raw = proj_create_crs_to_crs_from_pj(impl_->ctx, src, dst, nullptr, nullptr);
  proj_destroy(src);
  proj_destroy(dst);
  if (!raw) throw std::runtime_error("PROJ has no transformation from '" + from + "' to '" + to + "'");
  impl_->op = proj_normalize_for_visualization(impl_->ctx, raw);  // longitude first on both sides
  proj_destroy(raw);
  if (!impl_->op)
    throw std::runtime_error("cannot normalise the axis order from '" + from + "' to '" + to + "'");
}

Reprojector::~Reprojector() = default;

Vec3 Reprojector::apply(const Vec3& p) const {
  if (!is_finite(p)) return p;
  proj_errno_reset(impl_->op);
  const PJ_COORD r = proj_trans(impl_->op, PJ_FWD, proj_coord(p.x, p.y, 0, 0));
  if (proj_errno(impl_->op) != 0 || !std::isfinite(r.xy.x) || !std::isfinite(r.xy.y)) return {NAN, NAN, p.z};
  return {r.xy.x, r.xy.y, p.z};
}

void Reprojector::apply(std::vector<Vec3>& points) const {
  for (Vec3& p : points) {
    const Vec3 q = apply(p);
    if (is_finite(p) && !is_finite(q))
      throw std::runtime_error("PROJ cannot transform the point (" + std::to_string(p.x) + ", " +
                               std::to_string(p.y) + ")");
    p = q;
  }
}

std::string reference_system_url(const std::string& crs) {
  const std::string n = normalize_crs(crs);
  if (n.rfind("EPSG:", 0) == 0) return "https://www.opengis.net/def/crs/EPSG/0/" + n.substr(5);
  return crs;
}

ReprojectedSource::ReprojectedSource(std::unique_ptr<FeatureSource> in, const std::string& to,
                                     std::optional<double> scale, const std::string& from)
    : SourceFilter(std::move(in)) {
  if (!from.empty()) header_.crs = from;
  if (header_.crs.empty())
    throw std::runtime_error(
        "the input has no CRS (metadata.referenceSystem / srsName): name it with --from to reproject");
  proj_ = std::make_unique<Reprojector>(header_.crs, to);
  std::string note;
  const CoordinateSystem cs = coordinate_system(to, false, &note);
  if (!note.empty()) throw std::runtime_error(note);
  json& root = header_.root;
  const Transform t = parse_transform(root, "header");
  const double s = scale.value_or(cs.geographic() ? 1e-8 : 0.001);
  if (t.present || header_.version != "1.0") {
    // The old grid's origin, transformed, rounded down: a new origin near the data.
    const Vec3 o = proj_->apply(t.present ? t.translate : Vec3{0, 0, 0});
    const double unit = cs.geographic() ? 0.01 : 1.0;
    const double zs = t.present ? t.scale.z : 0.001;
    root["transform"] = {
        {"scale", {s, s, zs}},
        {"translate",
         {std::isfinite(o.x) ? std::floor(o.x / unit) * unit : 0.0,
          std::isfinite(o.y) ? std::floor(o.y / unit) * unit : 0.0, t.present ? t.translate.z : 0.0}}};
  }
  if (!root.contains("metadata") || !root["metadata"].is_object()) root["metadata"] = json::object();
  json& md = root["metadata"];
  md["referenceSystem"] = reference_system_url(to);
  md.erase("crs");  // CityJSON 1.0's form of it
  // The extent's four horizontal corners, transformed: a box around the data in the new CRS.
  if (auto e = md.find("geographicalExtent"); e != md.end()) {
    bool ok = e->is_array() && e->size() == 6;
    if (ok)
      for (const auto& v : *e) ok = ok && v.is_number();
    if (ok) {
      const std::vector<double> x = e->get<std::vector<double>>();
      double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
      for (double cx : {x[0], x[3]})
        for (double cy : {x[1], x[4]}) {
          const Vec3 q = proj_->apply({cx, cy, 0});
          lo[0] = std::min(lo[0], q.x), hi[0] = std::max(hi[0], q.x);
          lo[1] = std::min(lo[1], q.y), hi[1] = std::max(hi[1], q.y);
        }
      if (std::isfinite(lo[0]) && std::isfinite(hi[1])) *e = {lo[0], lo[1], x[2], hi[0], hi[1], x[5]};
      else md.erase(e);
    } else {
      md.erase(e);
    }
  }
  header_.crs = normalize_crs(to);
  header_.coords = cs;
  header_.coords_note.clear();
}

bool ReprojectedSource::next(Feature& out) {
  if (!in_->next(out)) return false;
  try {
    proj_->apply(out.vertices);
  } catch (const std::exception& e) { throw ReadError(out.id + ": " + e.what()); }
  return true;
}

}  // namespace mc::io
